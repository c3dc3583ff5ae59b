//! A glTF 2.0 metallic-roughness material (`pbrMetallicRoughness` and `emissiveFactor`),
//! without textures.

use crate::errors::error::Error;

/// The factors of a metallic-roughness material, as `f64`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Material {
    /// `baseColorFactor`: linear RGBA in [0, 1].
    pub base_color: [f64; 4],
    /// `metallicFactor` in [0, 1].
    pub metallic: f64,
    /// `roughnessFactor` (perceptual roughness) in [0, 1]; the model raises it to 0.04.
    pub roughness: f64,
    /// The emitted linear RGB, ≥ 0 (`emissiveFactor`, with `KHR_materials_emissive_strength`
    /// folded in where it exceeds 1).
    pub emissive: [f64; 3],
}

impl Default for Material {
    /// glTF's defaults: white, fully metallic, fully rough, no emission.
    fn default() -> Self {
        Self {
            base_color: [1.0; 4],
            metallic: 1.0,
            roughness: 1.0,
            emissive: [0.0; 3],
        }
    }
}

impl Material {
    /// Checks every factor against glTF's range.
    ///
    /// # Errors
    /// A value error naming the factor, its range and the value found.
    pub fn validate(&self) -> Result<(), Error> {
        let unit = |x: &f64| (0.0..=1.0).contains(x);
        if !self.base_color.iter().all(unit) {
            return Err(Error::value(format!(
                "base_color must be in [0, 1], got {:?}",
                self.base_color
            )));
        }
        for (name, x) in [("metallic", self.metallic), ("roughness", self.roughness)] {
            if !unit(&x) {
                return Err(Error::value(format!("{name} must be in [0, 1], got {x}")));
            }
        }
        if !self.emissive.iter().all(|x| *x >= 0.0 && x.is_finite()) {
            return Err(Error::value(format!(
                "emissive must be finite and >= 0, got {:?}",
                self.emissive
            )));
        }
        Ok(())
    }
}
