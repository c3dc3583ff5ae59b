//! The binding of `shade`.

use std::mem::MaybeUninit;

use numpy::{
    Element, PyArrayDyn, PyArrayMethods, PyReadonlyArray1, PyReadonlyArray2, PyUntypedArray,
    PyUntypedArrayMethods,
};
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;

use super::{float_of, matrix, rows, scene_from, to_pyerr, typed, vertex_colors, Float};
use crate::material::ColorMaterial;
use crate::prepare::{Accuracy, ShadeOptions};
use crate::real::Real;
use crate::scene::Scene;

/// Every argument of `shade` that does not depend on the dtype.
struct Call {
    scene: Scene,
    options: ShadeOptions,
}

fn shade_typed<'py, T: Element + Real>(
    py: Python<'py>,
    call: &Call,
    positions: &Bound<'py, PyUntypedArray>,
    normals: &Bound<'py, PyUntypedArray>,
    colors: Option<&Bound<'py, PyUntypedArray>>,
    out: Option<&Bound<'py, PyUntypedArray>>,
) -> PyResult<Bound<'py, PyAny>> {
    let positions = typed::<T>(positions, "positions", "positions")?;
    let normals = typed::<T>(normals, "normals", "positions")?;
    let colors = colors
        .map(|c| typed::<T>(c, "colors", "positions"))
        .transpose()?;
    let n = positions.shape()[0];
    let (p, nr) = (
        rows::<T, 3>(&positions, "positions")?,
        rows::<T, 3>(&normals, "normals")?,
    );
    let vertex_colors = colors.as_ref().map(|c| vertex_colors(c, n)).transpose()?;
    let planes = call.scene.output_count();
    let shape: Vec<usize> = if planes == 1 {
        vec![n, 4]
    } else {
        vec![planes, n, 4]
    };
    let run =
        |dst: &mut [T]| crate::shade::shade(&call.scene, p, nr, vertex_colors, &call.options, dst);
    let Some(out) = out else {
        let array = filled_array(py, &shape, |dst| {
            crate::shade::shade_uninit(&call.scene, p, nr, vertex_colors, &call.options, dst)
        })?;
        return Ok(array.into_any());
    };
    let array = out.cast::<PyArrayDyn<T>>().map_err(|_| {
        PyTypeError::new_err(format!(
            "out must be an array of {}, got {}",
            numpy::dtype::<T>(py),
            out.dtype()
        ))
    })?;
    if array.shape() != shape.as_slice() {
        return Err(PyValueError::new_err(format!(
            "out must have shape {shape:?}, got {:?}",
            array.shape()
        )));
    }
    let mut rw = array
        .try_readwrite()
        .map_err(|e| PyValueError::new_err(format!("out: {e}")))?;
    let dst = rw
        .as_slice_mut()
        .map_err(|_| PyValueError::new_err("out must be C-contiguous and writeable"))?;
    py.detach(|| run(dst)).map_err(to_pyerr)?;
    Ok(array.clone().into_any())
}

/// A new C-contiguous array of `shape` from numpy's allocator, filled by `write` with the GIL
/// released. It starts uninitialised, as numpy's own ufunc outputs do (numpy also advises huge
/// pages for large arrays): clearing it first would cost a pass over memory as long as
/// shading one light.
#[allow(unsafe_code)]
fn filled_array<'py, T: Element>(
    py: Python<'py>,
    shape: &[usize],
    write: impl FnOnce(&mut [MaybeUninit<T>]) -> Result<(), crate::Error> + Send,
) -> PyResult<Bound<'py, PyArrayDyn<T>>> {
    // SAFETY: the array reaches Python only after `write` returned Ok, which means it wrote
    // every element; on an error it is dropped unread.
    let array = unsafe { PyArrayDyn::<T>::new(py, shape, false) };
    // SAFETY: the fresh array is C-contiguous and nothing else refers to its data yet;
    // MaybeUninit<T> has T's layout and may hold anything.
    let dst = unsafe { std::slice::from_raw_parts_mut(array.data().cast(), array.len()) };
    py.detach(|| write(dst)).map_err(to_pyerr)?;
    Ok(array)
}

/// The options of a `shade` call from the binding's arguments.
fn options_from(
    modelview: Option<&PyReadonlyArray2<'_, f64>>,
    normalize: bool,
    rescale_normal: bool,
    color_material: Option<&str>,
    color_material_face: &str,
    accuracy: &str,
    strict: bool,
) -> PyResult<ShadeOptions> {
    let modelview = modelview.map(|m| matrix(m, "modelview")).transpose()?;
    let color_material = color_material
        .map(|mode| ColorMaterial::parse(mode, color_material_face))
        .transpose()
        .map_err(to_pyerr)?;
    Ok(ShadeOptions {
        modelview,
        normalize,
        rescale_normal,
        color_material,
        accuracy: Accuracy::parse(accuracy).map_err(to_pyerr)?,
        strict,
    })
}

/// Lights the vertices; see `glshade.shade` for the arguments, which arrive here already
/// coerced (C-contiguous float32 or float64 arrays, light and material tables as float64).
#[pyfunction]
#[pyo3(signature = (
    positions, normals, lights, material, back_material, global_ambient, viewer, two_side,
    separate_specular, specular, specular_gate, modelview, normalize, rescale_normal, colors,
    color_material, color_material_face, accuracy, strict, out
))]
pub fn shade<'py>(
    py: Python<'py>,
    positions: &Bound<'py, PyUntypedArray>,
    normals: &Bound<'py, PyUntypedArray>,
    lights: PyReadonlyArray2<'py, f64>,
    material: PyReadonlyArray1<'py, f64>,
    back_material: PyReadonlyArray1<'py, f64>,
    global_ambient: PyReadonlyArray1<'py, f64>,
    viewer: PyReadonlyArray1<'py, f64>,
    two_side: bool,
    separate_specular: bool,
    specular: &str,
    specular_gate: bool,
    modelview: Option<PyReadonlyArray2<'py, f64>>,
    normalize: bool,
    rescale_normal: bool,
    colors: Option<&Bound<'py, PyUntypedArray>>,
    color_material: Option<&str>,
    color_material_face: &str,
    accuracy: &str,
    strict: bool,
    out: Option<&Bound<'py, PyUntypedArray>>,
) -> PyResult<Bound<'py, PyAny>> {
    let options = options_from(
        modelview.as_ref(),
        normalize,
        rescale_normal,
        color_material,
        color_material_face,
        accuracy,
        strict,
    )?;
    let scene = scene_from(
        &lights,
        &material,
        &back_material,
        &global_ambient,
        &viewer,
        two_side,
        separate_specular,
        specular,
        specular_gate,
    )?;
    let call = Call { scene, options };
    match float_of(py, positions, "positions")? {
        Float::F32 => shade_typed::<f32>(py, &call, positions, normals, colors, out),
        Float::F64 => shade_typed::<f64>(py, &call, positions, normals, colors, out),
    }
}

/// One line saying what `shade` computes for this scene and these options in `dtype`
/// ("float32" or "float64"); see `glshade.Scene.plan`.
#[pyfunction]
#[pyo3(signature = (
    lights, material, back_material, global_ambient, viewer, two_side, separate_specular,
    specular, specular_gate, modelview, normalize, rescale_normal, color_material,
    color_material_face, accuracy, strict, dtype
))]
pub fn describe(
    lights: PyReadonlyArray2<'_, f64>,
    material: PyReadonlyArray1<'_, f64>,
    back_material: PyReadonlyArray1<'_, f64>,
    global_ambient: PyReadonlyArray1<'_, f64>,
    viewer: PyReadonlyArray1<'_, f64>,
    two_side: bool,
    separate_specular: bool,
    specular: &str,
    specular_gate: bool,
    modelview: Option<PyReadonlyArray2<'_, f64>>,
    normalize: bool,
    rescale_normal: bool,
    color_material: Option<&str>,
    color_material_face: &str,
    accuracy: &str,
    strict: bool,
    dtype: &str,
) -> PyResult<String> {
    let options = options_from(
        modelview.as_ref(),
        normalize,
        rescale_normal,
        color_material,
        color_material_face,
        accuracy,
        strict,
    )?;
    let scene = scene_from(
        &lights,
        &material,
        &back_material,
        &global_ambient,
        &viewer,
        two_side,
        separate_specular,
        specular,
        specular_gate,
    )?;
    match dtype {
        "float32" => crate::shade::describe::<f32>(&scene, &options),
        "float64" => crate::shade::describe::<f64>(&scene, &options),
        _ => {
            return Err(PyValueError::new_err(format!(
                "dtype must be 'float32' or 'float64', got '{dtype}'"
            )))
        }
    }
    .map_err(to_pyerr)
}
