//! A scene lit by `MeshPhongMaterial`: its lights, the material, the camera and the renderer's
//! light convention.

use std::ops::Deref;

use crate::errors::error::Error;
use crate::threejs::light::Light;
use crate::threejs::material::MeshPhongMaterial;

/// Where the view vector points.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Viewer {
    /// A perspective camera at this position: v = normalize(camera − p).
    Position([f64; 3]),
    /// An orthographic camera: v is this direction (the camera's +z axis, towards the viewer;
    /// normalised, nonzero), the shader's `isOrthographic` branch.
    Direction([f64; 3]),
}

/// Lights, material, camera and light convention, in world coordinates.
#[derive(Clone, Debug, PartialEq)]
pub struct Scene {
    /// The lights: every kind sums in three.js' order (point, spot, directional lights, then
    /// ambient and hemisphere lights), each kind in this order.
    pub lights: Vec<Light>,
    /// The material of every vertex.
    pub material: MeshPhongMaterial,
    /// The camera.
    pub viewer: Viewer,
    /// `WebGLRenderer.physicallyCorrectLights` (three.js r111; the only convention since r155):
    /// when false (r111's default, "legacy" lights), every irradiance is multiplied by π, and
    /// a decay applies only within a finite `distance`, as (1 − d/distance)^decay.
    pub physically_correct_lights: bool,
}

impl Default for Scene {
    /// No lights, the default material, a camera at the origin and physically correct lights.
    fn default() -> Self {
        Self {
            lights: Vec::new(),
            material: MeshPhongMaterial::default(),
            viewer: Viewer::Position([0.0; 3]),
            physically_correct_lights: true,
        }
    }
}

impl Scene {
    /// Checks every light, the material and the camera.
    ///
    /// # Errors
    /// The first failure of [`Light::validate`] or [`MeshPhongMaterial::validate`], or a value
    /// error for a camera position that is not finite or a view direction that is not finite
    /// and nonzero.
    pub fn validated(self) -> Result<ValidScene, Error> {
        for (i, light) in self.lights.iter().enumerate() {
            light.validate(i)?;
        }
        self.material.validate()?;
        match self.viewer {
            Viewer::Position(p) if !p.iter().all(|x| x.is_finite()) => {
                return Err(Error::value(format!(
                    "camera_position must be finite, got {p:?}"
                )))
            }
            Viewer::Direction(d) if !d.iter().all(|x| x.is_finite()) || d == [0.0; 3] => {
                return Err(Error::value(format!(
                    "view_direction must be finite and nonzero, got {d:?}"
                )))
            }
            _ => {}
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
