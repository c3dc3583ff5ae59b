//! The Python binding, `glshade._glshade`: the scene as native objects, the arrays the package's
//! intake prepared borrowed and checked, the GIL released, the core called, the result handed
//! back. No arithmetic happens here.

// pyo3 extracts every argument by value; the borrows are what these functions own.
#![allow(clippy::needless_pass_by_value)]
// `shade` and `render` mirror the Python signatures, GL's enable flags included.
#![allow(clippy::fn_params_excessive_bools)]

use numpy::{PyReadonlyArray2, PyUntypedArrayMethods};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

mod arrays;
mod camera;
mod faces;
mod gltf;
mod normals;
mod relief;
mod render;
mod runtime;
mod scene;
mod shading;
mod threejs;

/// A row-major (4, 4) array (as numpy prints matrices) as a column-major `DMat4`.
fn matrix(m: &PyReadonlyArray2<'_, f64>, name: &str) -> PyResult<glam::DMat4> {
    let values: &[f64] = m
        .as_slice()
        .ok()
        .filter(|_| m.is_c_contiguous())
        .unwrap_or(&[]);
    let rows: [f64; 16] = values
        .try_into()
        .ok()
        .filter(|_| m.shape() == [4, 4])
        .ok_or_else(|| {
            PyValueError::new_err(format!(
                "{name} must be a C-contiguous (4, 4) array, got shape {}",
                arrays::shape_text(m.shape())
            ))
        })?;
    Ok(glam::DMat4::from_cols_array(&rows).transpose())
}

/// The native part of glshade; use the `glshade` package, whose intake prepares the arguments.
#[pymodule(gil_used = false)]
mod _glshade {
    #[pymodule_export]
    use super::camera::{look_at, orthographic, perspective};
    #[pymodule_export]
    use super::gltf::{describe_gltf, shade_gltf, GltfScene};
    #[pymodule_export]
    use super::normals::{crease_normals, face_normals, vertex_normals};
    #[pymodule_export]
    use super::relief::{blend, hillshade, shade_normals};
    #[pymodule_export]
    use super::render::render;
    #[pymodule_export]
    use super::scene::{Lights, Material, Scene};
    #[pymodule_export]
    use super::shading::{describe, lean_directional, shade, stream};
    #[pymodule_export]
    use super::threejs::{describe_threejs, shade_threejs, ThreejsScene};

    use pyo3::prelude::*;

    #[pymodule_init]
    fn init(m: &Bound<'_, PyModule>) -> PyResult<()> {
        m.add("__version__", env!("CARGO_PKG_VERSION"))?;
        m.add("MAX_SIZE", crate::render::raster::MAX_SIZE)?;
        Ok(())
    }
}
