//! The binding of `face_normals` and `vertex_normals`.

use numpy::{Element, PyArrayMethods, PyUntypedArray};
use pyo3::prelude::*;

use super::arrays::{float_of, read, rows, zeros, Float};
use super::faces;
use super::runtime::{run, to_pyerr};
use crate::normals::Weighting;
use crate::numbers::real::Real;

/// Faces above which a call answers Ctrl-C while it runs (see `shading::LONG_CALL`).
const LONG_CALL: usize = 1 << 15;

fn normals_typed<'py, T: Element + Real>(
    py: Python<'py>,
    vertices: &Bound<'py, PyUntypedArray>,
    faces: &Bound<'py, PyUntypedArray>,
    weighting: Option<Weighting>,
) -> PyResult<Bound<'py, PyAny>> {
    let vertices = read::<T>(vertices, "vertices")?;
    let v = rows::<T, 3>(&vertices, "vertices")?;
    let f = faces::copy(faces)?;
    let count = if weighting.is_some() {
        v.len()
    } else {
        f.len()
    };
    let array = zeros::<T>(py, &[count, 3])?;
    let mut rw = array.readwrite();
    let out = rw.as_slice_mut()?.as_chunks_mut::<3>().0;
    let f = &f[..];
    run(py, f.len() > LONG_CALL, |stop| match weighting {
        Some(w) => crate::normals::vertex_normals(v, f, w, out, stop),
        None => crate::normals::face_normals(v, f, out, stop),
    })?;
    drop(rw);
    Ok(array.into_any())
}

/// The unit normal of every face, (m, 3) of the vertices' dtype; see `glshade.face_normals`.
#[pyfunction]
pub fn face_normals<'py>(
    py: Python<'py>,
    vertices: &Bound<'py, PyUntypedArray>,
    faces: &Bound<'py, PyUntypedArray>,
) -> PyResult<Bound<'py, PyAny>> {
    match float_of(vertices, "vertices")? {
        Float::F32 => normals_typed::<f32>(py, vertices, faces, None),
        Float::F64 => normals_typed::<f64>(py, vertices, faces, None),
    }
}

/// The normal of every vertex, (n, 3) of the vertices' dtype; see `glshade.vertex_normals`.
#[pyfunction]
pub fn vertex_normals<'py>(
    py: Python<'py>,
    vertices: &Bound<'py, PyUntypedArray>,
    faces: &Bound<'py, PyUntypedArray>,
    weighting: &str,
) -> PyResult<Bound<'py, PyAny>> {
    let weighting = Some(Weighting::parse(weighting).map_err(to_pyerr)?);
    match float_of(vertices, "vertices")? {
        Float::F32 => normals_typed::<f32>(py, vertices, faces, weighting),
        Float::F64 => normals_typed::<f64>(py, vertices, faces, weighting),
    }
}
