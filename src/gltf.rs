//! glTF 2.0 state: what the metallic-roughness model reads besides positions and normals, as
//! plain data checked once: the material's factors ([`material::Material`]), the punctual lights
//! of `KHR_lights_punctual` ([`light::Light`]) and the scene with its ambient light and camera
//! ([`scene::Scene`]). Everything is in world coordinates, as pyrender's shader takes it.
//!
//! Uses [`crate::errors`] only.

pub mod light;
pub mod material;
pub mod scene;
