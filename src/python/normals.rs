//! The binding of `face_normals` and `vertex_normals`.

use numpy::{
    Element, PyArray2, PyArrayMethods, PyReadonlyArray2, PyUntypedArray, PyUntypedArrayMethods,
};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

use super::{float_of, rows, to_pyerr, Float};
use crate::normals::Weighting;
use crate::real::Real;

fn normals_typed<'py, T: Element + Real>(
    py: Python<'py>,
    vertices: &Bound<'py, PyUntypedArray>,
    faces: &PyReadonlyArray2<'py, i64>,
    weighting: Option<Weighting>,
) -> PyResult<Bound<'py, PyAny>> {
    let vertices = vertices
        .cast::<numpy::PyArray2<T>>()
        .map_err(|_| {
            PyValueError::new_err(format!(
                "vertices must be a 2-d array, got {}-d",
                vertices.ndim()
            ))
        })?
        .readonly();
    let v = rows::<T, 3>(&vertices, "vertices")?;
    let f = rows::<i64, 3>(faces, "faces")?;
    let rows_out = if weighting.is_some() {
        v.len()
    } else {
        f.len()
    };
    // numpy's allocator backs large arrays with huge pages: far fewer page faults than a Vec.
    let array = PyArray2::<T>::zeros(py, [rows_out, 3], false);
    {
        let mut guard = array.readwrite();
        let out = guard.as_slice_mut()?.as_chunks_mut::<3>().0;
        py.detach(|| match weighting {
            Some(w) => crate::normals::vertex_normals(v, f, w, out),
            None => crate::normals::face_normals(v, f, out),
        })
        .map_err(to_pyerr)?;
    }
    Ok(array.into_any())
}

/// The unit normal of every face, (m, 3) of the vertices' dtype; see `glshade.face_normals`.
#[pyfunction]
pub fn face_normals<'py>(
    py: Python<'py>,
    vertices: &Bound<'py, PyUntypedArray>,
    faces: PyReadonlyArray2<'py, i64>,
) -> PyResult<Bound<'py, PyAny>> {
    match float_of(py, vertices, "vertices")? {
        Float::F32 => normals_typed::<f32>(py, vertices, &faces, None),
        Float::F64 => normals_typed::<f64>(py, vertices, &faces, None),
    }
}

/// The normal of every vertex, (n, 3) of the vertices' dtype; see `glshade.vertex_normals`.
#[pyfunction]
pub fn vertex_normals<'py>(
    py: Python<'py>,
    vertices: &Bound<'py, PyUntypedArray>,
    faces: PyReadonlyArray2<'py, i64>,
    weighting: &str,
) -> PyResult<Bound<'py, PyAny>> {
    let weighting = Some(Weighting::parse(weighting).map_err(to_pyerr)?);
    match float_of(py, vertices, "vertices")? {
        Float::F32 => normals_typed::<f32>(py, vertices, &faces, weighting),
        Float::F64 => normals_typed::<f64>(py, vertices, &faces, weighting),
    }
}
