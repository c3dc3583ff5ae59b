//! A scene lit by the metallic-roughness model: its lights, one material, the ambient light and
//! the camera's position.

use std::ops::Deref;

use crate::errors::error::Error;
use crate::gltf::light::Light;
use crate::gltf::material::Material;

/// Lights, material, ambient light and camera, in world coordinates.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Scene {
    /// The lights, in summation order.
    pub lights: Vec<Light>,
    /// The material of every vertex.
    pub material: Material,
    /// pyrender's `ambient_light`: linear RGB ≥ 0, added as base colour × ambient.
    pub ambient_light: [f64; 3],
    /// Where the camera is (pyrender's `cam_pos`): the view vector points there.
    pub camera_position: [f64; 3],
}

impl Scene {
    /// Checks every light, the material, the ambient light and the camera position.
    ///
    /// # Errors
    /// The first failure of [`Light::validate`] or [`Material::validate`], or a value error
    /// for a negative or non-finite `ambient_light` or a non-finite `camera_position`.
    pub fn validated(self) -> Result<ValidScene, Error> {
        for (i, light) in self.lights.iter().enumerate() {
            light.validate(i)?;
        }
        self.material.validate()?;
        if !self
            .ambient_light
            .iter()
            .all(|x| *x >= 0.0 && x.is_finite())
        {
            return Err(Error::value(format!(
                "ambient_light must be finite and >= 0, got {:?}",
                self.ambient_light
            )));
        }
        if !self.camera_position.iter().all(|x| x.is_finite()) {
            return Err(Error::value(format!(
                "camera_position must be finite, got {:?}",
                self.camera_position
            )));
        }
        Ok(ValidScene(self))
    }
}

/// A [`Scene`] that passed [`Scene::validated`]; it reads as the scene through `Deref`.
#[derive(Clone, Debug, PartialEq)]
pub struct ValidScene(Scene);

impl Deref for ValidScene {
    type Target = Scene;
    fn deref(&self) -> &Scene {
        &self.0
    }
}
