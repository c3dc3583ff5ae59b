//! What a `MeshPhongMaterial` call computes, decided once per call like the GL plan
//! ([`crate::lighting::fixed_function::plan`]): lights without colour skipped, the direct lights in three.js'
//! order, positions read only where a point or spot light shines or a perspective camera
//! sees a direct light's highlight, and one or two sides.

use std::fmt;

use crate::lighting::model::write_reads;
use crate::lighting::world::PunctualKind as Kind;
use crate::threejs::light::Kind as LightKind;
use crate::threejs::scene::{Scene, Viewer};

/// Which terms of the model a call evaluates.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Plan {
    /// The direct lights that shine (colour × intensity ≠ 0), as (index in the scene, kind):
    /// point lights, then spot lights, then directional lights, as `lights_fragment_begin`
    /// sums them.
    pub lights: Vec<(usize, Kind)>,
    /// The hemisphere lights that shine, by index.
    pub hemispheres: Vec<usize>,
    /// Some ambient light shines.
    pub ambient: bool,
    /// The material emits.
    pub emission: bool,
    /// Positions are read: a point or spot light shines, or a directional light with a
    /// perspective camera (the view vector).
    pub positions: bool,
    /// Sides written: 2 for a double-sided material, else 1.
    pub sides: usize,
}

impl Plan {
    /// The least `scene` needs computed.
    pub fn new(scene: &Scene) -> Self {
        let shines = |i: &usize| {
            let light = &scene.lights[*i];
            light.intensity != 0.0 && light.color.iter().any(|&c| c != 0.0)
        };
        let of_kind = |kind: Kind| {
            (0..scene.lights.len())
                .filter(shines)
                .filter(move |&i| match scene.lights[i].kind {
                    LightKind::Directional { .. } => kind == Kind::Directional,
                    LightKind::Point { .. } => kind == Kind::Point,
                    LightKind::Spot { .. } => kind == Kind::Spot,
                    _ => false,
                })
                .map(move |i| (i, kind))
        };
        let lights: Vec<(usize, Kind)> = of_kind(Kind::Point)
            .chain(of_kind(Kind::Spot))
            .chain(of_kind(Kind::Directional))
            .collect();
        // A hemisphere light adds its ground colour even with a black sky.
        let hemispheres = (0..scene.lights.len())
            .filter(|&i| {
                let light = &scene.lights[i];
                match light.kind {
                    LightKind::Hemisphere { ground_color, .. } => {
                        light.intensity != 0.0
                            && light.color.iter().chain(&ground_color).any(|&c| c != 0.0)
                    }
                    _ => false,
                }
            })
            .collect();
        let ambient = (0..scene.lights.len())
            .filter(shines)
            .any(|i| scene.lights[i].kind == LightKind::Ambient);
        let m = &scene.material;
        let perspective = matches!(scene.viewer, Viewer::Position(_));
        let positions = lights
            .iter()
            .any(|&(_, kind)| kind != Kind::Directional || perspective);
        Self {
            lights,
            hemispheres,
            ambient,
            emission: m.emissive_intensity != 0.0 && m.emissive.iter().any(|&e| e != 0.0),
            positions,
            sides: m.side.count(),
        }
    }
}

impl fmt::Display for Plan {
    /// One line: what is read and which terms run.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write_reads(f, self.positions, "")?;
        for (i, kind) in &self.lights {
            let kind = kind.terms("falloff", "smoothstep cone");
            write!(f, "; light {i} {kind}: Lambert + Blinn-Phong with Fresnel")?;
        }
        for i in &self.hemispheres {
            write!(f, "; light {i} hemisphere")?;
        }
        if self.ambient {
            f.write_str("; ambient")?;
        }
        if self.emission {
            f.write_str("; emission")?;
        }
        if self.sides == 2 {
            f.write_str("; two sides")?;
        }
        Ok(())
    }
}
