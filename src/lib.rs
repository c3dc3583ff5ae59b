//! glshade: the lighting equations of real-time graphics over arrays of vertices, exactly and in
//! parallel.
//!
//! The core knows nothing of Python: it reads slices of `[T; 3]` rows (`T` = `f32` or `f64`) and
//! GL state as plain data, and writes RGBA rows. The optional `python` feature adds the binding.
//!
//! Conventions: right-handed eye coordinates, lights and viewer given in eye space, GL 2.1
//! defaults (§2.14.1, every light's diffuse and specular white as for `GL_LIGHT0`: see the
//! README's Defaults), colours clamped to [0, 1] once, at the end.
//!
//! The API is what the crate root re-exports: the entry points [`shade`], [`shade_uninit`],
//! [`describe`], [`face_normals`], [`vertex_normals`] and [`render`], the camera matrices
//! [`look_at`], [`perspective`] and [`orthographic`], and the types of their arguments.
//! [`Real`] is implemented for `f32` and `f64` only (its supertraits are internal).
//!
//! Layering, bottom up (each group, between semicolons, uses only the groups before it):
//! `error`, `float` (the scalar trait); `alloc`, `stop`, `light`, `material`, `clip`, `lanes`
//! (the `Lanes` trait and the register sets); `pages`, `scene`, `raster`, `elementary`
//! (`exp`/`ln` over lanes); `adjacency`, `real` (a float tied to its lanes), `power` (the spot
//! and specular powers); `prepare`, `dispatch` (the run-time instruction set), `triangle`,
//! `visibility`; `plan`, `normals`, `camera`; `kernel` (the equation over lanes); `shade`,
//! `mesh`; `passes`; `render`.

#[cfg(test)]
mod normal_range_tests;
mod normals;
#[cfg(test)]
mod property_tests;
#[cfg(test)]
mod range_tests;
mod render;
#[cfg(test)]
mod robust_tests;
#[cfg(test)]
mod shape_tests;
#[cfg(test)]
mod specialisation_tests;

pub use errors::error::{Error, ErrorKind};
pub use errors::stop::Stop;
pub use gl::light::{Light, LIGHT_ROW_LEN};
pub use gl::material::{ColorMaterial, ColorMaterialMode, Face, Material, MATERIAL_ROW_LEN};
pub use gl::scene::{Scene, Specular, ValidScene};
pub use gl::vertex_colors::VertexColors;
pub use lighting::prepare::{Accuracy, ShadeOptions};
pub use lighting::shade::{describe, shade, shade_uninit};
pub use normals::{face_normals, vertex_normals, Weighting};
pub use numbers::real::Real;
pub use render::camera::{look_at, orthographic, perspective, Camera};
pub use render::mesh::Mesh;
pub use render::raster::{Cull, Viewport};
pub use render::{render, RenderOptions, Shading};

mod errors;

mod memory;

mod simd;

mod numbers;

mod gl;

mod lighting;

#[cfg(feature = "lab")]
#[cfg_attr(not(feature = "python"), allow(dead_code))] // the binding is its only caller
mod lab;

#[cfg(feature = "python")]
mod python;
