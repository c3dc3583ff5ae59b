//! glshade: the lighting equations of real-time graphics over arrays of vertices, exactly and in
//! parallel.
//!
//! The core knows nothing of Python: it reads slices of `[T; 3]` rows (`T` = `f32` or `f64`) and
//! GL state as plain data, and writes RGBA rows. The optional `python` feature adds the binding.
//!
//! Conventions: right-handed eye coordinates, lights and viewer given in eye space, GL 2.1
//! defaults (`notes/gl_semantics.md`), colours clamped to [0, 1] once, at the end.

mod adjacency;
pub mod error;
pub mod light;
pub mod material;
pub mod normals;
mod pages;
pub mod prepare;
pub mod real;
pub mod scene;
pub mod shade;
mod triangle;

pub use error::{Error, ErrorKind};
pub use light::Light;
pub use material::{ColorMaterial, ColorMaterialMode, Face, Material};
pub use normals::{face_normals, vertex_normals, Weighting};
pub use prepare::ShadeOptions;
pub use scene::{Scene, Specular};
pub use shade::{shade, VertexColors};

#[cfg(feature = "python")]
mod python;
