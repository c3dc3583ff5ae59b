//! The Python binding, `glshade._glshade`: borrow and check the arrays, release the GIL, call the
//! core, hand the result back. No arithmetic happens here.

// pyo3 extracts every argument by value; the borrows are what these functions own.
#![allow(clippy::needless_pass_by_value)]
// `shade` mirrors the Python signature, GL's enable flags included.
#![allow(clippy::fn_params_excessive_bools)]

use numpy::{
    Element, PyArray1, PyArrayDescrMethods, PyArrayDyn, PyArrayMethods, PyReadonlyArray1,
    PyReadonlyArray2, PyUntypedArray, PyUntypedArrayMethods,
};
use pyo3::exceptions::{PyIndexError, PyTypeError, PyValueError};
use pyo3::prelude::*;

use crate::error::{Error, ErrorKind};
use crate::light::{Light, LIGHT_ROW_LEN};
use crate::material::{ColorMaterial, Material, MATERIAL_ROW_LEN};
use crate::normals::Weighting;
use crate::prepare::ShadeOptions;
use crate::real::Real;
use crate::scene::{Scene, Specular};
use crate::shade::VertexColors;

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
    )?;
    scene.validate().map_err(to_pyerr)
}

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
    let cast = |a: &Bound<'py, PyUntypedArray>, name: &str| -> PyResult<PyReadonlyArray2<'py, T>> {
        let typed = a.cast::<numpy::PyArray2<T>>().map_err(|_| {
            PyTypeError::new_err(format!(
                "{name} must be a 2-d array of {} like positions, got a {}-d array of {}",
                numpy::dtype::<T>(py),
                a.ndim(),
                a.dtype()
            ))
        })?;
        Ok(typed.readonly())
    };
    let positions = cast(positions, "positions")?;
    let normals = cast(normals, "normals")?;
    let colors = colors.map(|c| cast(c, "colors")).transpose()?;
    let n = positions.shape()[0];
    let (p, nr) = (
        rows::<T, 3>(&positions, "positions")?,
        rows::<T, 3>(&normals, "normals")?,
    );
    let vertex_colors = match &colors {
        Some(c) if c.shape()[1] == 3 => Some(VertexColors {
            data: rows::<T, 3>(c, "colors")?.as_flattened(),
            width: 3,
        }),
        Some(c) if c.shape()[1] == 4 => Some(VertexColors {
            data: rows::<T, 4>(c, "colors")?.as_flattened(),
            width: 4,
        }),
        Some(c) => {
            return Err(PyValueError::new_err(format!(
                "colors must have shape ({n}, 3) or ({n}, 4), got {:?}",
                c.shape()
            )))
        }
        None => None,
    };
    let planes = call.scene.output_count();
    let shape: Vec<usize> = if planes == 1 {
        vec![n, 4]
    } else {
        vec![planes, n, 4]
    };
    let run =
        |dst: &mut [T]| crate::shade::shade(&call.scene, p, nr, vertex_colors, &call.options, dst);
    let Some(out) = out else {
        let mut dst = vec![T::ZERO; planes * n * 4];
        py.detach(|| run(&mut dst)).map_err(to_pyerr)?;
        return Ok(PyArray1::from_vec(py, dst).reshape(shape)?.into_any());
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

/// Lights the vertices; see `glshade.shade` for the arguments, which arrive here already
/// coerced (C-contiguous float32 or float64 arrays, light and material tables as float64).
#[pyfunction]
#[pyo3(signature = (
    positions, normals, lights, material, back_material, global_ambient, viewer, two_side,
    separate_specular, specular, modelview, normalize, rescale_normal, colors, color_material,
    color_material_face, out
))]
fn shade<'py>(
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
    modelview: Option<PyReadonlyArray2<'py, f64>>,
    normalize: bool,
    rescale_normal: bool,
    colors: Option<&Bound<'py, PyUntypedArray>>,
    color_material: Option<&str>,
    color_material_face: &str,
    out: Option<&Bound<'py, PyUntypedArray>>,
) -> PyResult<Bound<'py, PyAny>> {
    let modelview = match &modelview {
        Some(m) => {
            let r = rows::<f64, 4>(m, "modelview")?;
            if r.len() != 4 {
                return Err(PyValueError::new_err(format!(
                    "modelview must have shape (4, 4), got {:?}",
                    m.shape()
                )));
            }
            Some(glam::DMat4::from_cols_array_2d(&[r[0], r[1], r[2], r[3]]).transpose())
        }
        None => None,
    };
    let color_material = color_material
        .map(|mode| ColorMaterial::parse(mode, color_material_face))
        .transpose()
        .map_err(to_pyerr)?;
    let scene = scene_from(
        &lights,
        &material,
        &back_material,
        &global_ambient,
        &viewer,
        two_side,
        separate_specular,
        specular,
    )?;
    let call = Call {
        scene,
        options: ShadeOptions {
            modelview,
            normalize,
            rescale_normal,
            color_material,
        },
    };
    match float_of(py, positions, "positions")? {
        Float::F32 => shade_typed::<f32>(py, &call, positions, normals, colors, out),
        Float::F64 => shade_typed::<f64>(py, &call, positions, normals, colors, out),
    }
}

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
    let mut out = vec![[T::ZERO; 3]; rows_out];
    py.detach(|| match weighting {
        Some(w) => crate::normals::vertex_normals(v, f, w, &mut out),
        None => crate::normals::face_normals(v, f, &mut out),
    })
    .map_err(to_pyerr)?;
    Ok(PyArray1::from_vec(py, out.into_flattened())
        .reshape([rows_out, 3])?
        .into_any())
}

/// The unit normal of every face, (m, 3) of the vertices' dtype; see `glshade.face_normals`.
#[pyfunction]
fn face_normals<'py>(
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
fn vertex_normals<'py>(
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

/// The native part of glshade; use the `glshade` package, which coerces arguments.
#[pymodule(gil_used = false)]
mod _glshade {
    #[pymodule_export]
    use super::{
        check_lights, check_material, check_scene, face_normals, output_names, shade,
        vertex_normals,
    };

    use pyo3::prelude::*;

    #[pymodule_init]
    fn init(m: &Bound<'_, PyModule>) -> PyResult<()> {
        m.add("LIGHT_LAYOUT", crate::light::LIGHT_LAYOUT.to_vec())?;
        m.add("MATERIAL_LAYOUT", crate::material::MATERIAL_LAYOUT.to_vec())?;
        m.add("__version__", env!("CARGO_PKG_VERSION"))?;
        Ok(())
    }
}
