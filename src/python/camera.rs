//! The binding of the camera matrices (`gluLookAt`, `gluPerspective`, `glOrtho`).

use numpy::{PyArray1, PyArrayMethods};
use pyo3::prelude::*;

use super::runtime::to_pyerr;

/// A `DMat4` as a row-major (4, 4) float64 array, as numpy prints matrices.
fn to_numpy(py: Python<'_>, m: glam::DMat4) -> PyResult<Bound<'_, PyAny>> {
    let rows = m.transpose().to_cols_array().to_vec();
    Ok(PyArray1::from_vec(py, rows).reshape([4, 4])?.into_any())
}

/// `gluLookAt`: the (4, 4) view matrix of a camera at `eye` looking at `target`.
#[pyfunction]
pub fn look_at(
    py: Python<'_>,
    eye: [f64; 3],
    target: [f64; 3],
    up: [f64; 3],
) -> PyResult<Bound<'_, PyAny>> {
    let m =
        crate::render::camera::look_at(eye.into(), target.into(), up.into()).map_err(to_pyerr)?;
    to_numpy(py, m)
}

/// `gluPerspective`: the (4, 4) projection matrix (`fovy` in degrees).
#[pyfunction]
pub fn perspective(
    py: Python<'_>,
    fovy: f64,
    aspect: f64,
    near: f64,
    far: f64,
) -> PyResult<Bound<'_, PyAny>> {
    let m = crate::render::camera::perspective(fovy, aspect, near, far).map_err(to_pyerr)?;
    to_numpy(py, m)
}

/// `glOrtho`: the (4, 4) projection matrix of a box of eye coordinates.
#[pyfunction]
pub fn orthographic(
    py: Python<'_>,
    left: f64,
    right: f64,
    bottom: f64,
    top: f64,
    near: f64,
    far: f64,
) -> PyResult<Bound<'_, PyAny>> {
    let m = crate::render::camera::orthographic(left, right, bottom, top, near, far)
        .map_err(to_pyerr)?;
    to_numpy(py, m)
}
