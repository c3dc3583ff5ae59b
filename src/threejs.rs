//! three.js state: what `MeshPhongMaterial` reads besides positions and normals, as plain data
//! checked once: the material ([`material::MeshPhongMaterial`]), the lights three.js passes
//! to its shaders ([`light::Light`]: ambient, hemisphere, directional, point and spot) and the
//! scene with the camera and the renderer's light convention ([`scene::Scene`]). Everything is
//! in world coordinates (three.js moves it all to view space, which changes no dot product).
//!
//! Uses [`crate::errors`] only.

pub mod light;
pub mod material;
pub mod scene;
