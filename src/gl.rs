//! GL state: what the lighting equation reads besides positions and normals, as plain data
//! checked once: lights ([`light::Light`], `GL_LIGHTi`), materials and `COLOR_MATERIAL`
//! ([`material`]), the light model and the whole scene ([`scene::Scene`]), and per-vertex
//! colours ([`vertex_colors::VertexColors`]).
//!
//! Uses [`crate::errors`] only.

pub mod light;
pub mod material;
pub mod scene;
pub mod vertex_colors;
