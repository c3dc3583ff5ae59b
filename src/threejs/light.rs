//! One three.js light as `WebGLLights` hands it to the shaders: its colour already times its
//! intensity, its direction from its position and target.

use crate::errors::error::Error;

/// What the light is and where it is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Kind {
    /// `AmbientLight`: the same irradiance from everywhere.
    Ambient,
    /// `HemisphereLight`: the sky colour (the light's `color`) above, `ground_color` below,
    /// mixed by 0.5·n·d + 0.5.
    Hemisphere {
        /// d, towards the sky: the light's position (normalised; three.js' default is +y).
        direction: [f64; 3],
        /// `groundColor`, linear RGB ≥ 0.
        ground_color: [f64; 3],
    },
    /// `DirectionalLight`: parallel light from the direction `position − target`.
    Directional {
        /// `position − target.position`, towards the light (normalised, nonzero).
        direction: [f64; 3],
    },
    /// `PointLight`.
    Point {
        /// Where the light is.
        position: [f64; 3],
        /// `distance`: the light's reach (0: unlimited).
        distance: f64,
        /// `decay`: the falloff's exponent.
        decay: f64,
    },
    /// `SpotLight`: a point light within a cone around `position − target`.
    Spot {
        /// Where the light is.
        position: [f64; 3],
        /// `position − target.position`: the cone's axis, towards the light (normalised).
        direction: [f64; 3],
        /// `distance`: the light's reach (0: unlimited).
        distance: f64,
        /// `decay`: the falloff's exponent.
        decay: f64,
        /// `angle`, radians in (0, π/2]: no light beyond it.
        angle: f64,
        /// `penumbra` in [0, 1]: the share of the cone over which the light fades.
        penumbra: f64,
    },
}

/// A light: its kind and place, colour and intensity.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Light {
    /// Kind, position and direction.
    pub kind: Kind,
    /// Linear RGB ≥ 0 (a hemisphere light's sky colour).
    pub color: [f64; 3],
    /// `intensity` ≥ 0: every colour of the light is multiplied by it.
    pub intensity: f64,
}

impl Light {
    /// The spot's `(coneCos, penumbraCos)`, as `WebGLLights` computes them; `None` for other
    /// lights.
    pub fn cone(&self) -> Option<(f64, f64)> {
        match self.kind {
            Kind::Spot {
                angle, penumbra, ..
            } => Some((angle.cos(), (angle * (1.0 - penumbra)).cos())),
            _ => None,
        }
    }

    /// Checks light number `index`.
    ///
    /// # Errors
    /// A value error naming the parameter and light when a value is not finite, a colour,
    /// the intensity, a distance or a decay is negative, a direction is zero, or a spot's
    /// angle is not in (0, π/2] or its penumbra not in [0, 1].
    pub fn validate(&self, index: usize) -> Result<(), Error> {
        let bad = |name: &str, expected: &str, found: String| {
            Err(Error::value(format!(
                "{name} of light {index} must be {expected}, got {found}"
            )))
        };
        let color = |c: &[f64; 3]| c.iter().all(|x| x.is_finite() && *x >= 0.0);
        let finite = |v: &[f64; 3]| v.iter().all(|x| x.is_finite());
        let direction = |d: &[f64; 3]| finite(d) && *d != [0.0; 3];
        let scalar = |x: f64| x.is_finite() && x >= 0.0;
        if !color(&self.color) {
            return bad("color", "finite and >= 0", format!("{:?}", self.color));
        }
        if !scalar(self.intensity) {
            return bad("intensity", "finite and >= 0", self.intensity.to_string());
        }
        match self.kind {
            Kind::Ambient => {}
            Kind::Hemisphere {
                direction: d,
                ground_color,
            } => {
                if !color(&ground_color) {
                    return bad(
                        "ground_color",
                        "finite and >= 0",
                        format!("{ground_color:?}"),
                    );
                }
                if !direction(&d) {
                    return bad("position", "finite and nonzero", format!("{d:?}"));
                }
            }
            Kind::Directional { direction: d } => {
                if !direction(&d) {
                    return bad("position - target", "finite and nonzero", format!("{d:?}"));
                }
            }
            Kind::Point {
                position,
                distance,
                decay,
            } => {
                if !finite(&position) {
                    return bad("position", "finite", format!("{position:?}"));
                }
                if !scalar(distance) {
                    return bad("distance", "finite and >= 0", distance.to_string());
                }
                if !scalar(decay) {
                    return bad("decay", "finite and >= 0", decay.to_string());
                }
            }
            Kind::Spot {
                position,
                direction: d,
                distance,
                decay,
                angle,
                penumbra,
            } => {
                if !finite(&position) {
                    return bad("position", "finite", format!("{position:?}"));
                }
                if !direction(&d) {
                    return bad("position - target", "finite and nonzero", format!("{d:?}"));
                }
                if !scalar(distance) {
                    return bad("distance", "finite and >= 0", distance.to_string());
                }
                if !scalar(decay) {
                    return bad("decay", "finite and >= 0", decay.to_string());
                }
                if !(angle > 0.0 && angle <= std::f64::consts::FRAC_PI_2) {
                    return bad("angle", "in (0, pi/2]", angle.to_string());
                }
                if !(0.0..=1.0).contains(&penumbra) {
                    return bad("penumbra", "in [0, 1]", penumbra.to_string());
                }
            }
        }
        Ok(())
    }
}
