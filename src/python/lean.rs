//! The binding of the lab's lean bound of one directional light (`benches/lean_directional.py`),
//! in a build with the `lab` feature only: the wheel does not carry it.

use numpy::{Element, PyUntypedArray};
use pyo3::prelude::*;

use super::arrays::{filled, float_of, read, rows, Float};
use super::runtime::run;
use super::scene::Scene;
use crate::lab::lean::Safeguards;
use crate::numbers::real::Real;

fn lean_directional_typed<'py, T: Element + Real>(
    py: Python<'py>,
    scene: &Bound<'py, Scene>,
    normals: &Bound<'py, PyUntypedArray>,
    safeguards: Safeguards,
) -> PyResult<Bound<'py, PyAny>> {
    let scene = &scene.get().state;
    let normals = read::<T>(normals, "normals")?;
    let n = rows::<T, 3>(&normals, "normals")?;
    let array = filled::<T>(py, &[n.len(), 4], |dst| {
        run(py, false, |stop| {
            crate::lab::lean::lean_directional(scene, n, safeguards, dst, stop)
        })
    })?;
    Ok(array.into_any())
}

/// The lean bound of one directional light (for `benches/lean_directional.py`): a new (n, 4)
/// array, `scene`'s one directional light (infinite viewer, Blinn, shininess 32) on
/// C-contiguous (n, 3) float32 or float64 `normals` with none of the fast mode's safeguards
/// but those named (`nan`, `power`, `saturate`), through `shade`'s tasks, reads and stores.
#[pyfunction]
#[pyo3(signature = (scene, normals, *, nan=false, power=false, saturate=false))]
pub fn lean_directional<'py>(
    py: Python<'py>,
    scene: &Bound<'py, Scene>,
    normals: &Bound<'py, PyUntypedArray>,
    nan: bool,
    power: bool,
    saturate: bool,
) -> PyResult<Bound<'py, PyAny>> {
    let safeguards = Safeguards {
        nan,
        power,
        saturate,
    };
    match float_of(normals, "normals")? {
        Float::F32 => lean_directional_typed::<f32>(py, scene, normals, safeguards),
        Float::F64 => lean_directional_typed::<f64>(py, scene, normals, safeguards),
    }
}
