//! The binding of `shade` and `describe`.

use numpy::{Element, PyReadonlyArray2, PyUntypedArray, PyUntypedArrayMethods};
use pyo3::prelude::*;

use std::mem::MaybeUninit;

use super::arrays::{filled, float_named, float_of, read, rows, vertex_colors, write, Float};
use super::matrix;
use super::runtime::{run, to_pyerr};
use super::scene::Scene;
use crate::errors::error::Error;
use crate::errors::stop::Stop;
use crate::gl::material::ColorMaterial;
use crate::gl::vertex_colors::VertexColors;
use crate::lab::lean::Safeguards;
use crate::lighting::prepare::{Accuracy, ColorClamp, ShadeOptions};
use crate::lighting::shade::as_uninit;
use crate::numbers::real::Real;

/// Vertex-light products above which a call answers Ctrl-C while it runs (about a millisecond
/// of work: below it, the helper thread that watches for signals would cost more than it saves).
const LONG_CALL: usize = 1 << 17;

/// Computes one call's colours with `compute` (its arrays, the memory to fill, the stop) into
/// `out` or a new array of shape ([planes,] ..., 4); `lights` sizes the work for Ctrl-C.
#[allow(clippy::too_many_arguments)]
pub(crate) fn shade_arrays<'py, T: Element + Real>(
    py: Python<'py>,
    positions: &Bound<'py, PyUntypedArray>,
    normals: &Bound<'py, PyUntypedArray>,
    colors: Option<&Bound<'py, PyUntypedArray>>,
    out: Option<&Bound<'py, PyUntypedArray>>,
    planes: usize,
    lights: usize,
    compute: impl Fn(
            &[[T; 3]],
            &[[T; 3]],
            Option<VertexColors<'_, T>>,
            &mut [MaybeUninit<T>],
            &Stop,
        ) -> Result<(), Error>
        + Sync,
) -> PyResult<Bound<'py, PyAny>> {
    let positions = read::<T>(positions, "positions")?;
    let normals = read::<T>(normals, "normals")?;
    let colors = colors.map(|c| read::<T>(c, "colors")).transpose()?;
    let (p, n) = (
        rows::<T, 3>(&positions, "positions")?,
        rows::<T, 3>(&normals, "normals")?,
    );
    let vertex_colors = colors.as_ref().map(vertex_colors).transpose()?;
    let leading = &normals.shape()[..normals.ndim() - 1];
    let mut shape: Vec<usize> = Vec::with_capacity(leading.len() + 2);
    if planes > 1 {
        shape.push(planes);
    }
    shape.extend_from_slice(leading);
    shape.push(4);
    let long = n.len().saturating_mul(lights + 1) > LONG_CALL;
    if let Some(out) = out {
        let colors: &[T] = vertex_colors.as_ref().map_or(&[], |c| c.data);
        let inputs = [
            ("positions", p.as_flattened()),
            ("normals", n.as_flattened()),
            ("colors", colors),
        ];
        let mut rw = write::<T>(out, &shape, &inputs)?;
        let dst = rw.as_slice_mut()?;
        run(py, long, |stop| {
            compute(p, n, vertex_colors, as_uninit(dst), stop)
        })?;
        return Ok(out.clone().into_any());
    }
    let array = filled::<T>(py, &shape, |dst| {
        run(py, long, |stop| compute(p, n, vertex_colors, dst, stop))
    })?;
    Ok(array.into_any())
}

fn shade_typed<'py, T: Element + Real>(
    py: Python<'py>,
    scene: &Scene,
    options: &ShadeOptions,
    positions: &Bound<'py, PyUntypedArray>,
    normals: &Bound<'py, PyUntypedArray>,
    colors: Option<&Bound<'py, PyUntypedArray>>,
    out: Option<&Bound<'py, PyUntypedArray>>,
) -> PyResult<Bound<'py, PyAny>> {
    let scene = &scene.state;
    let (planes, lights) = (scene.output_count(), scene.lights.len());
    shade_arrays::<T>(
        py,
        positions,
        normals,
        colors,
        out,
        planes,
        lights,
        |p, n, c, dst, stop| {
            crate::lighting::shade::shade_uninit(scene, p, n, c, options, dst, stop)
        },
    )
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
    clamp: bool,
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
        clamp: ColorClamp::from(clamp),
    })
}

/// Lights the vertices of `scene`; see `glshade.shade`, whose intake prepared the arrays
/// (float32 or float64 of one dtype, C-contiguous, positions and normals of one shape
/// (..., 3), colours (..., 3|4), `out` checked against the inputs). The options are keywords, so
/// no positional order ties the Python call to this signature.
#[pyfunction]
#[pyo3(signature = (
    positions, normals, scene, *, modelview, normalize, rescale_normal, colors, color_material,
    color_material_face, accuracy, strict, clamp, out
))]
pub fn shade<'py>(
    py: Python<'py>,
    positions: &Bound<'py, PyUntypedArray>,
    normals: &Bound<'py, PyUntypedArray>,
    scene: &Bound<'py, Scene>,
    modelview: Option<PyReadonlyArray2<'py, f64>>,
    normalize: bool,
    rescale_normal: bool,
    colors: Option<&Bound<'py, PyUntypedArray>>,
    color_material: Option<&str>,
    color_material_face: &str,
    accuracy: &str,
    strict: bool,
    clamp: bool,
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
        clamp,
    )?;
    let scene = scene.get();
    match float_of(positions, "positions")? {
        Float::F32 => shade_typed::<f32>(py, scene, &options, positions, normals, colors, out),
        Float::F64 => shade_typed::<f64>(py, scene, &options, positions, normals, colors, out),
    }
}

/// One line saying what `shade` computes for `scene` with these options in `dtype`
/// ("float32" or "float64"); see `glshade.Scene.plan`.
#[pyfunction]
#[pyo3(signature = (
    scene, *, modelview, normalize, rescale_normal, color_material, color_material_face, accuracy,
    strict, clamp, dtype
))]
pub fn describe(
    scene: &Bound<'_, Scene>,
    modelview: Option<PyReadonlyArray2<'_, f64>>,
    normalize: bool,
    rescale_normal: bool,
    color_material: Option<&str>,
    color_material_face: &str,
    accuracy: &str,
    strict: bool,
    clamp: bool,
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
        clamp,
    )?;
    let scene = &scene.get().state;
    match float_named(dtype)? {
        Float::F32 => crate::lighting::shade::describe::<f32>(scene, &options),
        Float::F64 => crate::lighting::shade::describe::<f64>(scene, &options),
    }
    .map_err(to_pyerr)
}

fn stream_typed<'py, T: Element + Real>(
    py: Python<'py>,
    positions: &Bound<'py, PyUntypedArray>,
    normals: &Bound<'py, PyUntypedArray>,
    read_positions: bool,
) -> PyResult<Bound<'py, PyAny>> {
    let positions = read::<T>(positions, "positions")?;
    let normals = read::<T>(normals, "normals")?;
    let (p, n) = (
        rows::<T, 3>(&positions, "positions")?,
        rows::<T, 3>(&normals, "normals")?,
    );
    let array = filled::<T>(py, &[n.len(), 4], |dst| {
        run(py, false, |stop| {
            crate::lab::stream::stream(p, n, read_positions, dst, stop)
        })
    })?;
    Ok(array.into_any())
}

/// The streaming floor of `shade` (for `bench shade`): a new (n, 4) array written with the
/// same tasks, reads and stores as `shade` on C-contiguous (n, 3) float32 or float64
/// `normals` (and `positions` when `read_positions`), and no lighting: RGBA = (n, Σp or 1).
#[pyfunction]
pub fn stream<'py>(
    py: Python<'py>,
    positions: &Bound<'py, PyUntypedArray>,
    normals: &Bound<'py, PyUntypedArray>,
    read_positions: bool,
) -> PyResult<Bound<'py, PyAny>> {
    match float_of(normals, "normals")? {
        Float::F32 => stream_typed::<f32>(py, positions, normals, read_positions),
        Float::F64 => stream_typed::<f64>(py, positions, normals, read_positions),
    }
}

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

/// The lean bound of one directional light (for `examples/lean_directional.py`): a new (n, 4)
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
