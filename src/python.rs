//! The Python binding, `glshade._glshade`: the scene as native objects, the arrays the package's
//! intake prepared borrowed and checked, the GIL released, the core called, the result handed
//! back. No arithmetic happens here.

// pyo3 extracts every argument by value; the borrows are what these functions own.
#![allow(clippy::needless_pass_by_value)]
// `shade` and `render` mirror the Python signatures, GL's enable flags included.
#![allow(clippy::fn_params_excessive_bools)]

use pyo3::prelude::*;

mod arrays;
mod camera;
mod faces;
mod gltf;
#[cfg(feature = "lab")]
mod lean;
mod model;
mod normals;
mod points;
mod relief;
mod render;
mod runtime;
mod scene;
mod shading;
mod threejs;
mod transfer;

/// The native part of glshade; use the `glshade` package, whose intake prepares the arguments.
#[pymodule(gil_used = false)]
mod _glshade {
    #[pymodule_export]
    use super::camera::{look_at, orthographic, perspective};
    #[pymodule_export]
    use super::gltf::GltfScene;
    #[pymodule_export]
    use super::normals::{crease_normals, face_normals, vertex_normals};
    #[pymodule_export]
    use super::points::render_points;
    #[pymodule_export]
    use super::relief::{blend, hillshade, shade_normals};
    #[pymodule_export]
    use super::render::{render, render_draws};
    #[pymodule_export]
    use super::scene::{Lights, Material, Scene};
    #[pymodule_export]
    use super::shading::{describe, shade, stream};
    #[pymodule_export]
    use super::threejs::ThreejsScene;
    #[pymodule_export]
    use super::transfer::encode;

    use pyo3::prelude::*;

    #[pymodule_init]
    fn init(m: &Bound<'_, PyModule>) -> PyResult<()> {
        m.add("__version__", env!("CARGO_PKG_VERSION"))?;
        m.add("MAX_SIZE", crate::render::raster::MAX_SIZE)?;
        // The lab's instruments are in a build with the `lab` feature only, not in the wheel.
        #[cfg(feature = "lab")]
        m.add_function(wrap_pyfunction!(super::lean::lean_directional, m)?)?;
        Ok(())
    }
}
