//! What a metallic-roughness call computes, decided once per call like the GL plan
//! ([`crate::lighting::fixed_function::plan`]): lights without radiance are skipped, the diffuse part runs only
//! for a material with c_diff ≠ 0, positions are read only when some light shines, and the
//! constant part (ambient and emission) is added only when it is not zero.

use std::fmt;

use crate::gltf::light::Punctual;
use crate::gltf::scene::Scene;
use crate::lighting::model::write_reads;
use crate::lighting::world::PunctualKind as Kind;

/// Which terms of the model a call evaluates.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Plan {
    /// The lights that shine (colour × intensity ≠ 0): their index in the scene and kind.
    pub lights: Vec<(usize, Kind)>,
    /// The material has a diffuse part (metallic < 1 and a base colour that is not black).
    pub diffuse: bool,
    /// base colour × ambient light + emission is not zero.
    pub constant: bool,
    /// Positions are read: some light shines (the view vector needs them).
    pub positions: bool,
}

impl Plan {
    /// The least `scene` needs computed; `diffuse` says whether the prepared surface has a
    /// diffuse part.
    pub fn new(scene: &Scene, diffuse: bool) -> Self {
        let lights: Vec<(usize, Kind)> = scene
            .lights
            .iter()
            .enumerate()
            .filter(|(_, light)| light.intensity != 0.0 && light.color.iter().any(|&c| c != 0.0))
            .map(|(i, light)| {
                let kind = match light.punctual {
                    Punctual::Directional { .. } => Kind::Directional,
                    Punctual::Point { .. } => Kind::Point,
                    Punctual::Spot { .. } => Kind::Spot,
                };
                (i, kind)
            })
            .collect();
        let m = &scene.material;
        let ambient = (0..3).any(|i| m.base_color[i] * scene.ambient_light[i] != 0.0);
        let emission = m.emissive.iter().any(|&e| e != 0.0);
        Self {
            positions: !lights.is_empty(),
            diffuse: diffuse && !lights.is_empty(),
            constant: ambient || emission,
            lights,
        }
    }
}

impl fmt::Display for Plan {
    /// One line: what is read and which terms run.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write_reads(f, self.positions, "; v per vertex")?;
        let terms = if self.diffuse {
            "diffuse+specular"
        } else {
            "specular"
        };
        for (i, kind) in &self.lights {
            let kind = kind.terms("1/d²", "cone");
            write!(f, "; light {i} {kind}: {terms}")?;
        }
        if self.constant {
            f.write_str("; ambient and emission")?;
        }
        Ok(())
    }
}
