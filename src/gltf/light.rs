//! One punctual light of `KHR_lights_punctual` (directional, point or spot), placed in world
//! coordinates, as pyrender lights a metallic-roughness material with it.

use crate::errors::error::Error;

/// pyrender's least `cos(inner) − cos(outer)` (renderer.py): a spot with equal cones has an
/// edge 0.001 wide in the cosine instead of a step.
const LEAST_CONE_WIDTH: f64 = 0.001;

/// What the light is and where it is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Punctual {
    /// Light travelling along `direction` (any nonzero length): it comes from −direction.
    Directional {
        /// The direction the light travels (a node's −z axis in glTF).
        direction: [f64; 3],
    },
    /// Light from a point, falling off as 1/d².
    Point {
        /// Where the light is.
        position: [f64; 3],
    },
    /// A point light limited to a cone around `direction`.
    Spot {
        /// Where the light is.
        position: [f64; 3],
        /// The cone's axis, the direction the light travels (normalised before use).
        direction: [f64; 3],
        /// `innerConeAngle`, radians: full intensity within it.
        inner_cone_angle: f64,
        /// `outerConeAngle`, radians: no light beyond it.
        outer_cone_angle: f64,
    },
}

/// A punctual light: its kind and place, colour and intensity.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Light {
    /// Kind, position and direction.
    pub punctual: Punctual,
    /// Linear RGB, ≥ 0.
    pub color: [f64; 3],
    /// `intensity` ≥ 0 (lux for directional lights, candela for point and spot lights).
    pub intensity: f64,
}

impl Light {
    /// The spot's `(scale, offset)`: the cone factor is `clamp(cos θ · scale + offset, 0, 1)²`
    /// for the angle θ from the axis, as pyrender computes `light_angle_scale` and
    /// `light_angle_offset`; `None` for other lights.
    pub fn cone(&self) -> Option<(f64, f64)> {
        match self.punctual {
            Punctual::Spot {
                inner_cone_angle,
                outer_cone_angle,
                ..
            } => {
                let scale =
                    1.0 / (inner_cone_angle.cos() - outer_cone_angle.cos()).max(LEAST_CONE_WIDTH);
                Some((scale, -outer_cone_angle.cos() * scale))
            }
            _ => None,
        }
    }

    /// Checks light number `index`.
    ///
    /// # Errors
    /// A value error naming the parameter and light when a value is not finite, the colour or
    /// intensity is negative, a direction is zero, or the cone angles are not
    /// 0 ≤ inner ≤ outer ≤ π/2.
    pub fn validate(&self, index: usize) -> Result<(), Error> {
        let bad = |name: &str, expected: &str, found: String| {
            Err(Error::value(format!(
                "{name} of light {index} must be {expected}, got {found}"
            )))
        };
        let finite = |v: &[f64]| v.iter().all(|x| x.is_finite());
        if !(finite(&self.color) && self.color.iter().all(|&x| x >= 0.0)) {
            return bad("color", "finite and >= 0", format!("{:?}", self.color));
        }
        if !(self.intensity.is_finite() && self.intensity >= 0.0) {
            return bad(
                "intensity",
                "finite and >= 0",
                format!("{}", self.intensity),
            );
        }
        let (position, direction) = match self.punctual {
            Punctual::Directional { direction } => (None, Some(direction)),
            Punctual::Point { position } => (Some(position), None),
            Punctual::Spot {
                position,
                direction,
                inner_cone_angle: inner,
                outer_cone_angle: outer,
            } => {
                if !(0.0 <= inner && inner <= outer && outer <= std::f64::consts::FRAC_PI_2) {
                    return bad(
                        "the cone angles",
                        "0 <= inner_cone_angle <= outer_cone_angle <= pi/2",
                        format!("inner {inner}, outer {outer}"),
                    );
                }
                (Some(position), Some(direction))
            }
        };
        if let Some(p) = position {
            if !finite(&p) {
                return bad("position", "finite", format!("{p:?}"));
            }
        }
        if let Some(d) = direction {
            if !finite(&d) || d == [0.0; 3] {
                return bad("direction", "finite and nonzero", format!("{d:?}"));
            }
        }
        Ok(())
    }
}
