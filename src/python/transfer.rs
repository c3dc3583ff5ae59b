//! The binding of the transfer functions: a float array encoded in place, as a render encodes
//! its pixels, so `glshade.srgb_encode` and a render give the same bits on every machine
//! (numpy's own power differs by an ulp where it runs SIMD code of its own).

use numpy::{Element, PyArrayDyn, PyArrayMethods, PyUntypedArray};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

use super::arrays::{float_of, Float};
use super::runtime::{run, to_pyerr};
use crate::render::transfer::Transfer;
use crate::simd::float::Float as Real;

/// Encodes `values` in place with `transfer` (`"linear"`, `"srgb"` or `"gamma2.2"`, each
/// extended to negative values as sign(x)·f(|x|)): every value, or with `rgba` the first three
/// of every four (an (..., 4) array's alpha as it is). `values` is a writeable, C-contiguous
/// float32 or float64 array of any shape.
#[pyfunction]
#[pyo3(signature = (values, transfer, *, rgba))]
pub fn encode(
    py: Python<'_>,
    values: Bound<'_, PyUntypedArray>,
    transfer: &str,
    rgba: bool,
) -> PyResult<()> {
    let transfer = Transfer::parse(transfer).map_err(to_pyerr)?;
    match float_of(&values, "values")? {
        Float::F32 => encode_typed::<f32>(py, &values, transfer, rgba),
        Float::F64 => encode_typed::<f64>(py, &values, transfer, rgba),
    }
}

fn encode_typed<T: Element + Real>(
    py: Python<'_>,
    values: &Bound<'_, PyUntypedArray>,
    transfer: Transfer,
    rgba: bool,
) -> PyResult<()> {
    let array = values.cast::<PyArrayDyn<T>>()?;
    let mut writeable = array.try_readwrite().map_err(|_| {
        PyValueError::new_err("values must be writeable and not borrowed elsewhere")
    })?;
    let slice = writeable
        .as_slice_mut()
        .map_err(|_| PyValueError::new_err("values must be C-contiguous"))?;
    if rgba && slice.len() % 4 != 0 {
        return Err(PyValueError::new_err(format!(
            "values must hold RGBA rows of 4 with rgba=True, got {} values",
            slice.len()
        )));
    }
    run(py, false, |_| {
        if rgba {
            for pixel in slice.chunks_exact_mut(4) {
                for c in &mut pixel[..3] {
                    *c = transfer.encode(*c);
                }
            }
        } else {
            for c in slice.iter_mut() {
                *c = transfer.encode(*c);
            }
        }
        Ok(())
    })
}
