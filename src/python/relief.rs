//! The binding of relief shading: `hillshade`, `shade_normals` and `blend` of
//! `glshade.relief.LightSource`, whose intake made every array float64 and C-contiguous.

use numpy::{PyArrayMethods, PyUntypedArray, PyUntypedArrayMethods};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

use super::arrays::{read, rows, zeros};
use super::runtime::run;
use crate::relief::blend::{blend as blend_pixels, Blend};
use crate::relief::hillshade::{hillshade as hillshade_grid, intensity};

/// Values above which a call answers Ctrl-C while it runs.
const LONG_CALL: usize = 1 << 18;

/// The intensity map of a (rows, cols) float64 elevation grid; see
/// `glshade.relief.LightSource.hillshade`.
#[pyfunction]
#[pyo3(signature = (elevation, *, vert_exag, dx, dy, direction, fraction))]
pub fn hillshade<'py>(
    py: Python<'py>,
    elevation: &Bound<'py, PyUntypedArray>,
    vert_exag: f64,
    dx: f64,
    dy: f64,
    direction: [f64; 3],
    fraction: f64,
) -> PyResult<Bound<'py, PyAny>> {
    let grid = read::<f64>(elevation, "elevation")?;
    let shape = grid.shape().to_vec();
    if shape.len() != 2 {
        return Err(PyValueError::new_err(format!(
            "elevation must be 2-D, got {} dimensions",
            shape.len()
        )));
    }
    let values = grid.as_slice()?;
    let result = zeros::<f64>(py, &shape)?;
    let mut out = result.readwrite();
    let dst = out.as_slice_mut()?;
    let (r, c) = (shape[0], shape[1]);
    run(py, values.len() > LONG_CALL, |stop| {
        hillshade_grid(
            values, r, c, vert_exag, dx, dy, direction, fraction, dst, stop,
        )
    })?;
    drop(out);
    Ok(result.into_any())
}

/// The intensity map of (..., 3) float64 unit normals; see
/// `glshade.relief.LightSource.shade_normals`.
#[pyfunction]
#[pyo3(signature = (normals, *, direction, fraction))]
pub fn shade_normals<'py>(
    py: Python<'py>,
    normals: &Bound<'py, PyUntypedArray>,
    direction: [f64; 3],
    fraction: f64,
) -> PyResult<Bound<'py, PyAny>> {
    let given = read::<f64>(normals, "normals")?;
    let n = rows::<f64, 3>(&given, "normals")?;
    let shape = &given.shape()[..given.ndim() - 1];
    let result = zeros::<f64>(py, shape)?;
    let mut out = result.readwrite();
    let dst = out.as_slice_mut()?;
    run(py, n.len() > LONG_CALL, |stop| {
        intensity(n, direction, fraction, dst, stop)
    })?;
    drop(out);
    Ok(result.into_any())
}

/// The blend of (..., 3) float64 colours with (...) float64 intensities by `mode` ("hsv",
/// "soft" or "overlay"); see `glshade.relief.LightSource.blend_hsv` and the others.
#[pyfunction]
#[pyo3(signature = (rgb, intensity, *, mode, hsv))]
pub fn blend<'py>(
    py: Python<'py>,
    rgb: &Bound<'py, PyUntypedArray>,
    intensity: &Bound<'py, PyUntypedArray>,
    mode: &str,
    hsv: [f64; 4],
) -> PyResult<Bound<'py, PyAny>> {
    let colors = read::<f64>(rgb, "rgb")?;
    let c = rows::<f64, 3>(&colors, "rgb")?;
    let levels = read::<f64>(intensity, "intensity")?;
    let i = levels.as_slice()?;
    let mode = match mode {
        "hsv" => Blend::Hsv {
            min_val: hsv[0],
            max_val: hsv[1],
            min_sat: hsv[2],
            max_sat: hsv[3],
        },
        "soft" => Blend::SoftLight,
        "overlay" => Blend::Overlay,
        _ => {
            return Err(PyValueError::new_err(format!(
                "blend_mode must be 'hsv', 'soft' or 'overlay', got '{mode}'"
            )))
        }
    };
    let result = zeros::<f64>(py, colors.shape())?;
    let mut out = result.readwrite();
    let dst = out.as_slice_mut()?.as_chunks_mut::<3>().0;
    run(py, c.len() > LONG_CALL, |stop| {
        blend_pixels(c, i, mode, dst, stop)
    })?;
    drop(out);
    Ok(result.into_any())
}
