//! glshade: the lighting equations of real-time graphics over arrays of vertices, exactly and in
//! parallel.
//!
//! The core knows nothing of Python: it reads slices of `[T; 3]` rows (`T` = `f32` or `f64`) and
//! GL state as plain data, and writes RGBA rows. The optional `python` feature adds the binding.
//!
//! Conventions: right-handed eye coordinates, lights and viewer given in eye space, GL 2.1
//! defaults (`notes/gl_semantics.md`), colours clamped to [0, 1] once, at the end.

mod adjacency;
mod alloc;
pub mod camera;
pub mod clip;
pub mod dispatch;
pub mod elementary;
pub mod error;
pub mod kernel;
pub mod lanes;
pub mod light;
pub mod material;
#[cfg(test)]
mod normal_range_tests;
pub mod normals;
mod pages;
pub mod passes;
pub mod plan;
pub mod prepare;
#[cfg(test)]
mod property_tests;
#[cfg(test)]
mod range_tests;
pub mod raster;
pub mod real;
pub mod render;
#[cfg(test)]
mod robust_tests;
pub mod scene;
pub mod shade;
#[cfg(test)]
mod specialisation_tests;
pub mod stop;
mod triangle;
pub mod visibility;

pub use camera::Camera;
pub use error::{Error, ErrorKind};
pub use light::Light;
pub use material::{ColorMaterial, ColorMaterialMode, Face, Material};
pub use normals::{face_normals, vertex_normals, Weighting};
pub use plan::Plan;
pub use prepare::{Accuracy, ShadeOptions};
pub use raster::{Cull, Viewport};
pub use render::{render, Mesh, RenderOptions, Shading};
pub use scene::{Scene, Specular, ValidScene};
pub use shade::{describe, shade, shade_uninit, VertexColors};
pub use stop::Stop;

#[cfg(feature = "python")]
mod python;
