//! The binding of `shade` and `describe`, for every model, and of the streaming floor.

use std::mem::MaybeUninit;

use numpy::{Element, PyReadonlyArray2, PyUntypedArray, PyUntypedArrayMethods};
use pyo3::prelude::*;

use super::arrays::{filled, float_named, float_of, read, rows, vertex_colors, write, Float};
use super::model::{AnyScene, BindingModel, OnModel, Settings};
use super::runtime::{run, to_pyerr};
use crate::errors::error::Error;
use crate::errors::stop::Stop;
use crate::gl::vertex_colors::VertexColors;
use crate::lighting::model::{describe as describe_model, shade_uninit};
use crate::memory::uninit::as_uninit;
use crate::numbers::real::Real;

/// Vertex-light products above which a call answers Ctrl-C while it runs (about a millisecond
/// of work: below it, the helper thread that watches for signals would cost more than it saves).
const LONG_CALL: usize = 1 << 17;

/// Computes one call's colours with `compute` (its arrays, the memory to fill, the stop) into
/// `out` or a new array of shape ([planes,] ..., 4); `lights` sizes the work for Ctrl-C.
#[allow(clippy::too_many_arguments)]
fn shade_arrays<'py, T: Element + Real>(
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

/// The work of one `shade` call, done with whichever model the scene is.
struct ShadeWork<'a, 'py> {
    py: Python<'py>,
    settings: &'a Settings<'py>,
    positions: &'a Bound<'py, PyUntypedArray>,
    normals: &'a Bound<'py, PyUntypedArray>,
    colors: Option<&'a Bound<'py, PyUntypedArray>>,
    out: Option<&'a Bound<'py, PyUntypedArray>>,
}

impl<'py> ShadeWork<'_, 'py> {
    /// The call on arrays of `T` with `scene`'s model.
    fn typed<T: Element + Real, M: BindingModel>(self, scene: &M) -> PyResult<Bound<'py, PyAny>> {
        let options = M::options(self.settings)?;
        shade_arrays::<T>(
            self.py,
            self.positions,
            self.normals,
            self.colors,
            self.out,
            scene.outputs(),
            scene.light_count(),
            |p, n, c, dst, stop| shade_uninit(scene, p, n, c, &options, dst, stop),
        )
    }
}

impl<'py> OnModel for ShadeWork<'_, 'py> {
    type Output = PyResult<Bound<'py, PyAny>>;
    fn call<M: BindingModel>(self, scene: &M) -> Self::Output {
        match float_of(self.positions, "positions")? {
            Float::F32 => self.typed::<f32, M>(scene),
            Float::F64 => self.typed::<f64, M>(scene),
        }
    }
}

/// Lights the vertices of `scene`, a native scene of any model; see `glshade.shade`, whose
/// intake prepared the arrays (float32 or float64 of one dtype, C-contiguous, positions and
/// normals of one shape (..., 3), colours (..., 3|4), `out` checked against the inputs) and
/// passes GL's options (`modelview` to `strict`) for a `glshade.Scene` only. The options are
/// keywords, so no positional order ties the Python call to this signature.
#[pyfunction]
#[pyo3(signature = (
    positions, normals, scene, *, colors, accuracy, clamp, out, modelview=None, normalize=false,
    rescale_normal=false, color_material=None, color_material_face="front_and_back",
    strict=false
))]
pub fn shade<'py>(
    py: Python<'py>,
    positions: &Bound<'py, PyUntypedArray>,
    normals: &Bound<'py, PyUntypedArray>,
    scene: AnyScene<'py>,
    colors: Option<&Bound<'py, PyUntypedArray>>,
    accuracy: &'py str,
    clamp: bool,
    out: Option<&Bound<'py, PyUntypedArray>>,
    modelview: Option<PyReadonlyArray2<'py, f64>>,
    normalize: bool,
    rescale_normal: bool,
    color_material: Option<&'py str>,
    color_material_face: &'py str,
    strict: bool,
) -> PyResult<Bound<'py, PyAny>> {
    let settings = Settings {
        accuracy,
        clamp,
        modelview,
        normalize,
        rescale_normal,
        color_material,
        color_material_face,
        strict,
    };
    scene.with(ShadeWork {
        py,
        settings: &settings,
        positions,
        normals,
        colors,
        out,
    })
}

/// The description of one `describe` call, made with whichever model the scene is.
struct DescribeWork<'a, 'py> {
    settings: &'a Settings<'py>,
    dtype: Float,
}

impl OnModel for DescribeWork<'_, '_> {
    type Output = PyResult<String>;
    fn call<M: BindingModel>(self, scene: &M) -> Self::Output {
        let options = M::options(self.settings)?;
        match self.dtype {
            Float::F32 => describe_model::<f32, M>(scene, &options),
            Float::F64 => describe_model::<f64, M>(scene, &options),
        }
        .map_err(to_pyerr)
    }
}

/// One line saying what `shade` computes for `scene` (a native scene of any model) with these
/// options on arrays of `dtype` ("float32" or "float64"); see `Scene.plan`.
#[pyfunction]
#[pyo3(signature = (
    scene, *, dtype, accuracy, clamp, modelview=None, normalize=false, rescale_normal=false,
    color_material=None, color_material_face="front_and_back", strict=false
))]
pub fn describe<'py>(
    scene: AnyScene<'py>,
    dtype: &str,
    accuracy: &'py str,
    clamp: bool,
    modelview: Option<PyReadonlyArray2<'py, f64>>,
    normalize: bool,
    rescale_normal: bool,
    color_material: Option<&'py str>,
    color_material_face: &'py str,
    strict: bool,
) -> PyResult<String> {
    let settings = Settings {
        accuracy,
        clamp,
        modelview,
        normalize,
        rescale_normal,
        color_material,
        color_material_face,
        strict,
    };
    scene.with(DescribeWork {
        settings: &settings,
        dtype: float_named(dtype)?,
    })
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
