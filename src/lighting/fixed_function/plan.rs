//! What a scene needs computed, decided once per call, like the state key of Mesa's
//! fixed-function vertex program (`src/mesa/main/ffvertex_prog.c`).
//!
//! The kernel tests these flags once per block of vertices (uniform branches), so a term a
//! scene does not need costs one predictable branch per block and nothing per vertex. Leaving
//! a term out never changes a result: the tests' `Plan::general` computes every term for every
//! light and must give the same bits (a test checks every feature subset).

use std::fmt;

use crate::gl::material::ColorMaterialMode;
use crate::gl::scene::Specular;
use crate::lighting::fixed_function::prepare::{Prepared, Source, Viewer};
use crate::lighting::model::write_reads;
use crate::numbers::real::Real;

/// The largest shininess the lean arithmetic takes: (n·ĥ)^s of a normal with |n|² ≤ 2 stays
/// below 2^64.
pub const LEAN_EXPONENT_MAX: f64 = 128.0;

/// The least constant attenuation k0 of a light without k1 and k2 the lean arithmetic takes,
/// 2^-60: its attenuation 1/k0 then stays below 2^60, as a distance in range gives.
pub const LEAN_ATTENUATION_MIN: f64 = 8.673_617_379_884_035e-19;

/// The terms one light contributes.
#[allow(clippy::struct_excessive_bools)] // one flag per term, like Mesa's state key
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LightPlan {
    /// a_cli ≠ 0: the ambient term.
    pub ambient: bool,
    /// d_cli ≠ 0: the diffuse term.
    pub diffuse: bool,
    /// s_cli ≠ 0 and some side has a specular material: the specular term.
    pub specular: bool,
    /// A positional light with (k0, k1, k2) ≠ (1, 0, 0): the attenuation quotient.
    pub attenuated: bool,
    /// What the light is (not a choice of the plan: eq. 2.4 and 2.5 decide it).
    pub kind: LightKind,
    /// A positional light with a range (Luna's; not GL's).
    pub range: bool,
    /// A spot light with a soft edge (learnopengl's; not GL's).
    pub soft_edge: bool,
}

impl LightPlan {
    /// The light has a range or a soft spot edge: not a GL light.
    pub fn edges(self) -> bool {
        self.range || self.soft_edge
    }

    /// The light is positional (a point or a spot).
    pub fn positional(self) -> bool {
        matches!(self.kind, LightKind::Positional { .. })
    }
}

/// How a light's direction and weight are obtained.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LightKind {
    /// VP and the spot factor are per-light constants; so is ĥ under an infinite viewer.
    Directional {
        /// ĥ is a per-light constant.
        constant_halfway: bool,
    },
    /// VP and the distance per vertex.
    Positional {
        /// The spot cone is evaluated per vertex.
        spot: bool,
    },
}

/// The terms one side (front or back) needs.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SidePlan {
    /// s_cm ≠ 0 or tracked by the vertex colour: the side has a specular term at all.
    pub specular: bool,
    /// s_rm ≠ 0: the specular power needs ĥ (or R) and `exp`/`ln`; at 0 it is 0⁰ = 1.
    pub power: bool,
}

/// Which parts of the lighting equation a call evaluates.
#[allow(clippy::struct_excessive_bools)]
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Plan {
    /// One entry per light, in summation order.
    pub lights: Vec<LightPlan>,
    /// Front, then back (the back is used with two-sided lighting only).
    pub sides: [SidePlan; 2],
    /// Positions are read: some light is positional or the viewer is local.
    pub positions: bool,
    /// The unit normal n̂ is computed for every block (`normalize`, or a Blinn power with a
    /// per-vertex ĥ); a power of a constant ĥ needs it only in blocks with a normal far from
    /// unit length.
    pub unit_normal: bool,
    /// |n| is computed, as |n|² − 1 (exactly) and, far from unit length, ln |n|: a Blinn power on
    /// normals that are not normalised, (n·ĥ)^s = |n|^s (n̂·ĥ)^s.
    pub normal_length: bool,
    /// The vertex-to-eye direction VP_e is computed per vertex (local viewer and a specular term).
    pub view: bool,
    /// Every light's ambient, diffuse and specular colours are grey (r, g and b the same
    /// bits), so the light sums' three channels are the same numbers: a kernel may sum one.
    pub grey: bool,
    /// A float32 kernel tries the lean arithmetic first, block by block (every shininess at
    /// most [`LEAN_EXPONENT_MAX`], every constant attenuation at least
    /// [`LEAN_ATTENUATION_MIN`]); the careful path runs the blocks it does not hold.
    pub lean: bool,
}

impl Plan {
    /// The least a call with `prepared` must compute.
    pub fn new<T: Real>(prepared: &Prepared<T>) -> Self {
        let sides_used = prepared.sides;
        let tracked = |mode: fn(ColorMaterialMode) -> bool, side: usize| {
            prepared
                .color_material
                .is_some_and(|cm| cm.applies_to(side == 1) && mode(cm.mode))
        };
        let sides: [SidePlan; 2] = std::array::from_fn(|side| {
            let m = &prepared.materials[side];
            let specular = side < sides_used
                && (nonzero(&m.specular[..3])
                    || tracked(|mode| mode == ColorMaterialMode::Specular, side));
            SidePlan {
                specular,
                power: specular && m.shininess != T::ZERO,
            }
        });
        let any_specular = sides.iter().any(|s| s.specular);
        let lights: Vec<LightPlan> = prepared
            .lights
            .iter()
            .map(|light| LightPlan {
                ambient: nonzero(&light.ambient),
                diffuse: nonzero(&light.diffuse),
                specular: any_specular && nonzero(&light.specular),
                attenuated: match light.source {
                    Source::Positional { attenuation, .. } => {
                        attenuation != [T::ONE, T::ZERO, T::ZERO]
                    }
                    Source::Directional { .. } => false,
                },
                kind: match light.source {
                    Source::Directional { halfway, .. } => LightKind::Directional {
                        constant_halfway: halfway.is_some(),
                    },
                    Source::Positional { spot, .. } => LightKind::Positional {
                        spot: spot.is_some(),
                    },
                },
                range: matches!(light.source, Source::Positional { range: Some(_), .. }),
                soft_edge: matches!(
                    light.source,
                    Source::Positional { spot: Some(s), .. } if s.edge.is_some()
                ),
            })
            .collect();
        let lit_specular = |light: &LightPlan| light.specular;
        let power = sides.iter().any(|s| s.power) && lights.iter().any(lit_specular);
        let positional = prepared
            .lights
            .iter()
            .any(|l| matches!(l.source, Source::Positional { .. }));
        let local = matches!(prepared.viewer, Viewer::Local(_));
        let normal_length = !prepared.normalize && power && prepared.specular == Specular::Blinn;
        let constant = LightKind::Directional {
            constant_halfway: true,
        };
        let per_vertex_halfway = lights.iter().any(|l| l.specular && l.kind != constant);
        Self {
            positions: positional || local,
            unit_normal: prepared.normalize || (normal_length && per_vertex_halfway),
            normal_length,
            view: local && power,
            lights,
            sides,
            grey: prepared
                .lights
                .iter()
                .all(|l| grey(&l.ambient) && grey(&l.diffuse) && grey(&l.specular)),
            lean: prepared.materials[..sides_used]
                .iter()
                .all(|m| m.shininess.to_f64() <= LEAN_EXPONENT_MAX)
                && prepared.lights.iter().all(|l| match l.source {
                    // A constant attenuation 1/k0 of at most 2^60, as the distances give.
                    Source::Positional { attenuation: k, .. } => {
                        k[1] != T::ZERO || k[2] != T::ZERO || k[0].to_f64() >= LEAN_ATTENUATION_MIN
                    }
                    Source::Directional { .. } => true,
                }),
        }
    }

    /// Some light has an ambient term: the sum Σ w·a_cli is formed at all.
    pub fn ambient(&self) -> bool {
        self.lights.iter().any(|light| light.ambient)
    }

    /// Every term of every light, whether the scene needs it or not: the reference the
    /// specialised plans are checked against, bit for bit.
    #[cfg(test)]
    pub fn general<T: Real>(prepared: &Prepared<T>) -> Self {
        let least = Self::new(prepared);
        let all = |light: &LightPlan| LightPlan {
            ambient: true,
            diffuse: true,
            specular: true,
            attenuated: matches!(light.kind, LightKind::Positional { .. }),
            kind: light.kind,
            range: light.range,
            soft_edge: light.soft_edge,
        };
        let side = SidePlan {
            specular: true,
            power: true,
        };
        Self {
            lights: least.lights.iter().map(all).collect(),
            sides: [side; 2],
            // What is read is not a choice of the plan: a NaN in an unread position must not
            // change the output (see `shade`), so the general plan reads the same arrays.
            positions: least.positions,
            unit_normal: true,
            normal_length: !prepared.normalize,
            view: matches!(prepared.viewer, Viewer::Local(_)),
            grey: least.grey,
            lean: least.lean,
        }
    }
}

/// r, g and b are the same bits (+0 and −0 are not).
fn grey<T: Real>(c: &[T; 3]) -> bool {
    let bits = c.map(|x| x.to_f64().to_bits());
    bits[0] == bits[1] && bits[1] == bits[2]
}

fn nonzero<T: Real>(c: &[T]) -> bool {
    c.iter().any(|&x| x != T::ZERO)
}

impl fmt::Display for Plan {
    /// One line: what is read and which terms each light computes.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write_reads(f, self.positions, "")?;
        let normal = match (self.unit_normal, self.normal_length) {
            (true, true) => "; n̂ and ln|n|",
            (true, false) => "; n̂",
            (false, true) => "; |n|² − 1 (n̂ and ln|n| in blocks far from unit length)",
            (false, false) => "",
        };
        f.write_str(normal)?;
        if self.view {
            f.write_str("; VP_e per vertex")?;
        }
        for (i, light) in self.lights.iter().enumerate() {
            let kind = match light.kind {
                LightKind::Directional {
                    constant_halfway: true,
                } => "directional (VP, ĥ constant)",
                LightKind::Directional { .. } => "directional (VP constant)",
                LightKind::Positional { spot: true } => "positional spot",
                LightKind::Positional { spot: false } => "positional",
            };
            let terms: Vec<&str> = [
                (light.ambient, "ambient"),
                (light.diffuse, "diffuse"),
                (light.specular, "specular"),
                (light.attenuated, "attenuation"),
                (light.soft_edge, "soft edge"),
                (light.range, "range"),
            ]
            .iter()
            .filter(|(on, _)| *on)
            .map(|(_, name)| *name)
            .collect();
            let terms = if terms.is_empty() {
                "nothing".to_owned()
            } else {
                terms.join("+")
            };
            write!(f, "; light {i} {kind}: {terms}")?;
        }
        Ok(())
    }
}
