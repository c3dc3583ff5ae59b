//! The Python binding, `glshade._glshade`: borrow and check the arrays, release the GIL, call the
//! core, hand the result back. No arithmetic happens here.

// pyo3 extracts every argument by value; the borrows are what these functions own.
#![allow(clippy::needless_pass_by_value)]
// `shade` mirrors the Python signature, GL's enable flags included.
#![allow(clippy::fn_params_excessive_bools)]

use numpy::{
    Element, PyArrayDescrMethods, PyArrayMethods, PyReadonlyArray1, PyReadonlyArray2,
    PyUntypedArray, PyUntypedArrayMethods,
};
use pyo3::exceptions::{PyIndexError, PyTypeError, PyValueError};
use pyo3::prelude::*;

use crate::error::{Error, ErrorKind};
use crate::light::{Light, LIGHT_ROW_LEN};
use crate::material::{Material, MATERIAL_ROW_LEN};
use crate::scene::{Scene, Specular};
use crate::shade::VertexColors;

mod camera;
mod normals;
mod render;
mod shading;

fn to_pyerr(e: Error) -> PyErr {
    match e.kind {
        ErrorKind::Value => PyValueError::new_err(e.message),
        ErrorKind::Index => PyIndexError::new_err(e.message),
    }
}

/// The rows of a C-contiguous (n, K) array, without copying.
fn rows<'a, T: Element, const K: usize>(
    a: &'a PyReadonlyArray2<'_, T>,
    name: &str,
) -> PyResult<&'a [[T; K]]> {
    let shape = a.shape();
    if shape[1] != K {
        return Err(PyValueError::new_err(format!(
            "{name} must have {K} columns, got shape {shape:?}"
        )));
    }
    if !a.is_c_contiguous() {
        return Err(PyValueError::new_err(format!(
            "{name} must be C-contiguous"
        )));
    }
    Ok(a.as_slice()?.as_chunks::<K>().0)
}

fn lights_from(table: &PyReadonlyArray2<'_, f64>) -> PyResult<Vec<Light>> {
    Ok(rows::<f64, LIGHT_ROW_LEN>(table, "lights")?
        .iter()
        .map(Light::from_row)
        .collect())
}

fn material_from(row: &PyReadonlyArray1<'_, f64>, name: &str) -> PyResult<Material> {
    let values: &[f64; MATERIAL_ROW_LEN] = row.as_slice()?.try_into().map_err(|_| {
        PyValueError::new_err(format!(
            "{name} must have {MATERIAL_ROW_LEN} values, got {}",
            row.len()
        ))
    })?;
    Ok(Material::from_row(values))
}

fn vec4(v: &PyReadonlyArray1<'_, f64>, name: &str) -> PyResult<[f64; 4]> {
    v.as_slice()?
        .try_into()
        .map_err(|_| PyValueError::new_err(format!("{name} must have 4 values, got {}", v.len())))
}

fn vec3(v: &PyReadonlyArray1<'_, f64>, name: &str) -> PyResult<glam::DVec3> {
    let values: [f64; 3] = v.as_slice()?.try_into().map_err(|_| {
        PyValueError::new_err(format!("{name} must have 3 values, got {}", v.len()))
    })?;
    Ok(glam::DVec3::from_array(values))
}

/// A row-major (4, 4) array (as numpy prints matrices) as a column-major `DMat4`.
fn matrix(m: &PyReadonlyArray2<'_, f64>, name: &str) -> PyResult<glam::DMat4> {
    let r = rows::<f64, 4>(m, name)?;
    let r: &[[f64; 4]; 4] = r.try_into().map_err(|_| {
        PyValueError::new_err(format!(
            "{name} must have shape (4, 4), got {:?}",
            m.shape()
        ))
    })?;
    Ok(glam::DMat4::from_cols_array_2d(r).transpose())
}

/// A 2-d array of `T`, or a `TypeError` naming `name` and the dtype it should share with `like`.
fn typed<'py, T: Element>(
    array: &Bound<'py, PyUntypedArray>,
    name: &str,
    like: &str,
) -> PyResult<PyReadonlyArray2<'py, T>> {
    let typed = array.cast::<numpy::PyArray2<T>>().map_err(|_| {
        PyTypeError::new_err(format!(
            "{name} must be a 2-d array of {} like {like}, got a {}-d array of {}",
            numpy::dtype::<T>(array.py()),
            array.ndim(),
            array.dtype()
        ))
    })?;
    Ok(typed.readonly())
}

/// Per-vertex colours of width 3 or 4 for `GL_COLOR_MATERIAL`.
fn vertex_colors<'a, T: Element>(
    colors: &'a PyReadonlyArray2<'_, T>,
    n: usize,
) -> PyResult<VertexColors<'a, T>> {
    match colors.shape()[1] {
        3 => Ok(VertexColors {
            data: rows::<T, 3>(colors, "colors")?.as_flattened(),
            width: 3,
        }),
        4 => Ok(VertexColors {
            data: rows::<T, 4>(colors, "colors")?.as_flattened(),
            width: 4,
        }),
        _ => Err(PyValueError::new_err(format!(
            "colors must have shape ({n}, 3) or ({n}, 4), got {:?}",
            colors.shape()
        ))),
    }
}

/// The computation type an input array selects.
enum Float {
    F32,
    F64,
}

fn float_of(py: Python<'_>, array: &Bound<'_, PyUntypedArray>, name: &str) -> PyResult<Float> {
    let dtype = array.dtype();
    if dtype.is_equiv_to(&numpy::dtype::<f32>(py)) {
        Ok(Float::F32)
    } else if dtype.is_equiv_to(&numpy::dtype::<f64>(py)) {
        Ok(Float::F64)
    } else {
        Err(PyTypeError::new_err(format!(
            "{name} must be float32 or float64, got {dtype}"
        )))
    }
}

/// Checks a light table (one row per light, laid out as `LIGHT_LAYOUT`); raises `ValueError`.
#[pyfunction]
fn check_lights(lights: PyReadonlyArray2<'_, f64>) -> PyResult<()> {
    for (i, light) in lights_from(&lights)?.iter().enumerate() {
        light.validate(i).map_err(to_pyerr)?;
    }
    Ok(())
}

/// Checks a material row (laid out as `MATERIAL_LAYOUT`); raises `ValueError` naming `name`.
#[pyfunction]
fn check_material(material: PyReadonlyArray1<'_, f64>, name: &str) -> PyResult<()> {
    material_from(&material, name)?
        .validate(name)
        .map_err(to_pyerr)
}

/// The names of the colours `shade` returns for a light model, in output order.
#[pyfunction]
fn output_names(two_side: bool, separate_specular: bool) -> Vec<&'static str> {
    let scene = Scene {
        two_side,
        separate_specular,
        ..Scene::default()
    };
    scene.output_names().to_vec()
}

fn scene_from(
    lights: &PyReadonlyArray2<'_, f64>,
    material: &PyReadonlyArray1<'_, f64>,
    back_material: &PyReadonlyArray1<'_, f64>,
    global_ambient: &PyReadonlyArray1<'_, f64>,
    viewer: &PyReadonlyArray1<'_, f64>,
    two_side: bool,
    separate_specular: bool,
    specular: &str,
    specular_gate: bool,
) -> PyResult<Scene> {
    Ok(Scene {
        lights: lights_from(lights)?,
        material: material_from(material, "material")?,
        back_material: material_from(back_material, "back_material")?,
        global_ambient: vec4(global_ambient, "global_ambient")?,
        viewer: vec4(viewer, "viewer")?,
        two_side,
        separate_specular,
        specular: Specular::parse(specular).map_err(to_pyerr)?,
        specular_gate,
    })
}

/// Checks a whole scene as `shade` would; raises `ValueError` naming the offending parameter.
#[pyfunction]
fn check_scene(
    lights: PyReadonlyArray2<'_, f64>,
    material: PyReadonlyArray1<'_, f64>,
    back_material: PyReadonlyArray1<'_, f64>,
    global_ambient: PyReadonlyArray1<'_, f64>,
    viewer: PyReadonlyArray1<'_, f64>,
    specular: &str,
    specular_gate: bool,
) -> PyResult<()> {
    let scene = scene_from(
        &lights,
        &material,
        &back_material,
        &global_ambient,
        &viewer,
        false,
        false,
        specular,
        specular_gate,
    )?;
    scene.validate().map_err(to_pyerr)
}

/// The native part of glshade; use the `glshade` package, which coerces arguments.
#[pymodule(gil_used = false)]
mod _glshade {
    #[pymodule_export]
    use super::camera::{look_at, orthographic, perspective};
    #[pymodule_export]
    use super::normals::{face_normals, vertex_normals};
    #[pymodule_export]
    use super::render::render;
    #[pymodule_export]
    use super::shading::{describe, shade};
    #[pymodule_export]
    use super::{check_lights, check_material, check_scene, output_names};

    use pyo3::prelude::*;

    #[pymodule_init]
    fn init(m: &Bound<'_, PyModule>) -> PyResult<()> {
        m.add("LIGHT_LAYOUT", crate::light::LIGHT_LAYOUT.to_vec())?;
        m.add("MATERIAL_LAYOUT", crate::material::MATERIAL_LAYOUT.to_vec())?;
        m.add("__version__", env!("CARGO_PKG_VERSION"))?;
        Ok(())
    }
}
