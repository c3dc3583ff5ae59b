//! three.js' `MeshPhongMaterial` without maps: colours, shininess, opacity and side.

use crate::errors::error::Error;

/// Which side of a triangle the material draws (three.js' `side`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Side {
    /// `FrontSide`: the normal as given.
    #[default]
    Front,
    /// `BackSide`: the normal negated (the shader's `FLIP_SIDED`).
    Back,
    /// `DoubleSide`: both, the back with the normal negated (`DOUBLE_SIDED`): two colours.
    Double,
}

impl Side {
    /// The colours a vertex gets: 2 for `Double` (front, back), else 1.
    pub fn count(self) -> usize {
        if self == Self::Double {
            2
        } else {
            1
        }
    }
}

/// The parameters of a `MeshPhongMaterial`, as `f64`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MeshPhongMaterial {
    /// `color`: the diffuse colour, linear RGB ≥ 0.
    pub color: [f64; 3],
    /// `specular`: Schlick's f0, linear RGB ≥ 0.
    pub specular: [f64; 3],
    /// `shininess` ≥ 0: the Blinn-Phong exponent.
    pub shininess: f64,
    /// `emissive`, linear RGB ≥ 0.
    pub emissive: [f64; 3],
    /// `emissiveIntensity` ≥ 0: multiplies `emissive`.
    pub emissive_intensity: f64,
    /// `opacity` in [0, 1]: the output's alpha.
    pub opacity: f64,
    /// `side`.
    pub side: Side,
}

impl Default for MeshPhongMaterial {
    /// three.js' defaults: white, specular 0x111111 (17/255 per channel), shininess 30, no
    /// emission, opaque, front side.
    fn default() -> Self {
        Self {
            color: [1.0; 3],
            specular: [17.0 / 255.0; 3],
            shininess: 30.0,
            emissive: [0.0; 3],
            emissive_intensity: 1.0,
            opacity: 1.0,
            side: Side::Front,
        }
    }
}

impl MeshPhongMaterial {
    /// Checks every parameter.
    ///
    /// # Errors
    /// A value error naming the parameter, its range and the value found.
    pub fn validate(&self) -> Result<(), Error> {
        let colors = [
            ("color", self.color),
            ("specular", self.specular),
            ("emissive", self.emissive),
        ];
        for (name, c) in colors {
            if !c.iter().all(|x| x.is_finite() && *x >= 0.0) {
                return Err(Error::value(format!(
                    "{name} must be finite and >= 0, got {c:?}"
                )));
            }
        }
        let scalars = [
            ("shininess", self.shininess),
            ("emissive_intensity", self.emissive_intensity),
        ];
        for (name, x) in scalars {
            if !(x.is_finite() && x >= 0.0) {
                return Err(Error::value(format!(
                    "{name} must be finite and >= 0, got {x}"
                )));
            }
        }
        if !(0.0..=1.0).contains(&self.opacity) {
            return Err(Error::value(format!(
                "opacity must be in [0, 1], got {}",
                self.opacity
            )));
        }
        Ok(())
    }
}
