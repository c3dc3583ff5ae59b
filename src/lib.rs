//! glshade: the lighting equations of real-time graphics over arrays of vertices, exactly and in
//! parallel.
//!
//! The core knows nothing of Python: it reads slices of `[T; 3]` rows (`T` = `f32` or `f64`) and
//! GL state as plain data, and writes RGBA rows. The optional `python` feature adds the binding.
//!
//! Conventions: right-handed eye coordinates, lights and viewer given in eye space, GL 2.1
//! defaults (§2.14.1, every light's diffuse and specular white as for `GL_LIGHT0`: see
//! "Defaults" on the documentation's Shading arrays page, docs/pages/guide/shading.md), colours
//! clamped to [0, 1] once, at the end.
//!
//! The API is what the crate root re-exports: the entry points [`shade`], [`shade_uninit`],
//! [`describe`] and [`render`], which take a scene of any shading model ([`Model`],
//! [`RenderModel`]), [`face_normals`], [`vertex_normals`] and [`crease_normals`], the camera
//! matrices [`look_at`], [`perspective`] and [`orthographic`], and the types of their
//! arguments; the state of the models outside GL in [`metallic_roughness`] and [`mesh_phong`],
//! and matplotlib's relief shading in [`light_source`].
//! [`Real`] is implemented for `f32` and `f64` only (its supertraits are internal).
//!
//! # Models
//!
//! Each shading model has one name per place; this table maps them (the Python package's
//! `glshade._model` has the same):
//!
//! | model | state (`src/<state>/`) | kernel (`src/lighting/<model>/`) | Python | native scene |
//! |---|---|---|---|---|
//! | OpenGL 2.1's fixed function | `gl` | `fixed_function` | `glshade.Scene` | `Scene` |
//! | glTF metallic-roughness (pyrender) | `gltf` | `metallic_roughness` | `glshade.gltf.Scene` | `GltfScene` |
//! | three.js `MeshPhongMaterial` | `threejs` | `mesh_phong` | `glshade.threejs.Scene` | `ThreejsScene` |
//!
//! The crate's modules [`metallic_roughness`] and [`mesh_phong`] are named after the model
//! and hold its state and options.
//!
//! # Layers
//!
//! One folder per subsystem, top to bottom; each uses only the layers below it (a test,
//! `tests::layers`, reads the sources and checks it):
//!
//! | layer | what it is |
//! |---|---|
//! | `python` | the binding (feature `python`): validates, releases the GIL, calls the core |
//! | `lab` | the streaming floor of `bench shade` (with `python`); the lab's experiments (feature `lab`) |
//! | `render` | camera, clipping, rasterisation, visibility, the shading passes |
//! | `relief` | matplotlib's relief shading of elevation grids: hillshade, blends |
//! | `normals` | face, vertex and corner (creased) normals, the vertex-to-face adjacency |
//! | `lighting` | the models side by side (`fixed_function`, `metallic_roughness`, `mesh_phong`) and what they share: the model interface, the parallel driver, the block vocabulary, float64 widening |
//! | `gl` | GL state: lights, materials, the scene, per-vertex colours |
//! | `gltf` | glTF state: the metallic-roughness material, punctual lights, the scene |
//! | `threejs` | three.js state: `MeshPhongMaterial`, its lights, the scene |
//! | `numbers` | `exp`/`ln` over lanes, `Real`, matrix helpers |
//! | `simd` | `f32`/`f64` behind one trait, the lanes of each instruction set, dispatch |
//! | `memory` | fallible allocation, zeroed scratch pages, memory to be written |
//! | `errors` | the error type, stopping a call |

// The inner loop of kernel work compiles one kernel for one instruction set: the other shapes
// and the other sets' lanes are unused there.
#![cfg_attr(feature = "single-kernel", allow(dead_code))]

#[cfg(feature = "python")]
mod python;

#[cfg(any(feature = "python", feature = "lab"))]
#[cfg_attr(not(feature = "python"), allow(dead_code))] // the binding is its only caller
mod lab;

mod render;

mod relief;

mod normals;

mod lighting;

mod gl;

mod gltf;

mod threejs;

mod numbers;

mod simd;

mod memory;

mod errors;

#[cfg(test)]
mod tests;

pub use errors::error::{Error, ErrorKind};
pub use errors::stop::Stop;
pub use gl::light::{Light, LIGHT_ROW_LEN};
pub use gl::material::{ColorMaterial, ColorMaterialMode, Face, Material, MATERIAL_ROW_LEN};
pub use gl::scene::{Scene, Specular, ValidScene};
pub use gl::vertex_colors::VertexColors;
pub use lighting::accuracy::Accuracy;
pub use lighting::clamp::ColorClamp;
pub use lighting::fixed_function::options::ShadeOptions;
pub use lighting::model::{describe, shade, shade_uninit, Model};

/// The glTF 2.0 metallic-roughness model as pyrender evaluates it: its scene, material and
/// punctual lights (world coordinates, `f64`) and its options. [`shade`], [`shade_uninit`],
/// [`describe`] and [`render`] are the crate's, which take every model.
pub mod metallic_roughness {
    pub use crate::gltf::light::{Light, Punctual};
    pub use crate::gltf::material::Material;
    pub use crate::gltf::scene::{Scene, ValidScene};
    pub use crate::lighting::metallic_roughness::options::{ColorRole, Options};
    pub use crate::lighting::model::{describe, shade, shade_uninit};
    pub use crate::render::render;
}
/// three.js' `MeshPhongMaterial` as release 111 (and, with physically correct lights, the
/// current release) evaluates it: its scene, material and lights (world coordinates, `f64`)
/// and its options. [`shade`], [`shade_uninit`], [`describe`] and [`render`] are the crate's,
/// which take every model.
pub mod mesh_phong {
    pub use crate::lighting::mesh_phong::options::Options;
    pub use crate::lighting::model::{describe, shade, shade_uninit};
    pub use crate::render::render;
    pub use crate::threejs::light::{Kind, Light};
    pub use crate::threejs::material::{MeshPhongMaterial, Side};
    pub use crate::threejs::scene::{Scene, ValidScene, Viewer};
}
pub use normals::crease::crease_normals;
pub use normals::{face_normals, vertex_normals, Weighting};
/// matplotlib's relief shading (`matplotlib.colors.LightSource`) of elevation grids and normal
/// maps, in `f64`: `hillshade`, `shade_normals` (here [`intensity`](light_source::intensity)),
/// and the blends of an intensity with an RGB image.
pub mod light_source {
    pub use crate::relief::blend::{blend, Blend};
    pub use crate::relief::hillshade::{hillshade, intensity};
}
pub use numbers::real::Real;
pub use render::camera::{look_at, orthographic, perspective, Camera};
pub use render::mesh::{Draw, Mesh, Textured};
pub use render::options::{Provoking, RenderOptions, Shading};
pub use render::placement::Placement;
pub use render::points::{render_points, PointShape, PointStyle, MAX_POINT_SIZE};
pub use render::raster::{Cull, Viewport};
pub use render::shader::RenderModel;
pub use render::texture::{Filter, Texels, Texture, Wrap};
pub use render::transfer::Transfer;
pub use render::{render, render_draws, render_views};
