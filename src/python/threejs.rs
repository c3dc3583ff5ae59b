//! The binding of `MeshPhongMaterial`: its native scene and `shade_threejs`,
//! `describe_threejs`.

use numpy::{Element, PyReadonlyArray2, PyUntypedArray};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

use super::arrays::{float_named, float_of, Float};
use super::matrix;
use super::runtime::to_pyerr;
use super::shading::shade_arrays;
use crate::lighting::mesh_phong::shade::{describe, shade_uninit, Options};
use crate::lighting::prepare::ColorClamp;
use crate::numbers::real::Real;
use crate::threejs::light::{Kind, Light};
use crate::threejs::material::{MeshPhongMaterial, Side};
use crate::threejs::scene::{Scene, ValidScene, Viewer};

/// One light as `glshade.threejs` passes it: kind ("ambient", "hemisphere", "directional",
/// "point" or "spot"), colour, intensity, position, direction (position − target; a hemisphere
/// light's position), ground colour, distance, decay, angle and penumbra.
type LightRow = (
    String,
    [f64; 3],
    f64,
    [f64; 3],
    [f64; 3],
    [f64; 3],
    f64,
    f64,
    f64,
    f64,
);

/// A light from its row.
fn light(row: LightRow) -> PyResult<Light> {
    let (
        name,
        color,
        intensity,
        position,
        direction,
        ground_color,
        distance,
        decay,
        angle,
        penumbra,
    ) = row;
    let kind = match name.as_str() {
        "ambient" => Kind::Ambient,
        "hemisphere" => Kind::Hemisphere {
            direction,
            ground_color,
        },
        "directional" => Kind::Directional { direction },
        "point" => Kind::Point {
            position,
            distance,
            decay,
        },
        "spot" => Kind::Spot {
            position,
            direction,
            distance,
            decay,
            angle,
            penumbra,
        },
        _ => {
            return Err(PyValueError::new_err(format!(
                "a light's kind must be 'ambient', 'hemisphere', 'directional', 'point' or \
                 'spot', got {name:?}"
            )))
        }
    };
    Ok(Light {
        kind,
        color,
        intensity,
    })
}

/// A `MeshPhongMaterial` scene, checked; see `glshade.threejs.Scene`.
#[pyclass(frozen, module = "glshade._glshade")]
pub struct ThreejsScene {
    pub(crate) state: ValidScene,
}

#[pymethods]
impl ThreejsScene {
    /// The scene of these lights, material parameters, camera and light convention. Raises
    /// `ValueError` naming a bad value.
    #[new]
    #[pyo3(signature = (
        *, lights, color, specular, shininess, emissive, emissive_intensity, opacity, side,
        camera_position, view_direction, physically_correct_lights
    ))]
    #[allow(clippy::too_many_arguments)]
    fn new(
        lights: Vec<LightRow>,
        color: [f64; 3],
        specular: [f64; 3],
        shininess: f64,
        emissive: [f64; 3],
        emissive_intensity: f64,
        opacity: f64,
        side: &str,
        camera_position: [f64; 3],
        view_direction: Option<[f64; 3]>,
        physically_correct_lights: bool,
    ) -> PyResult<Self> {
        let side = match side {
            "front" => Side::Front,
            "back" => Side::Back,
            "double" => Side::Double,
            _ => {
                return Err(PyValueError::new_err(format!(
                    "side must be 'front', 'back' or 'double', got {side:?}"
                )))
            }
        };
        let scene = Scene {
            lights: lights.into_iter().map(light).collect::<PyResult<_>>()?,
            material: MeshPhongMaterial {
                color,
                specular,
                shininess,
                emissive,
                emissive_intensity,
                opacity,
                side,
            },
            viewer: view_direction.map_or(Viewer::Position(camera_position), Viewer::Direction),
            physically_correct_lights,
        };
        Ok(Self {
            state: scene.validated().map_err(to_pyerr)?,
        })
    }
}

fn options(model: Option<&PyReadonlyArray2<'_, f64>>, clamp: bool) -> PyResult<Options> {
    Ok(Options {
        model: model.map(|m| matrix(m, "model")).transpose()?,
        clamp: ColorClamp::from(clamp),
    })
}

fn shade_typed<'py, T: Element + Real>(
    py: Python<'py>,
    scene: &ValidScene,
    options: &Options,
    positions: &Bound<'py, PyUntypedArray>,
    normals: &Bound<'py, PyUntypedArray>,
    colors: Option<&Bound<'py, PyUntypedArray>>,
    out: Option<&Bound<'py, PyUntypedArray>>,
) -> PyResult<Bound<'py, PyAny>> {
    let (planes, lights) = (scene.material.side.count(), scene.lights.len());
    shade_arrays::<T>(
        py,
        positions,
        normals,
        colors,
        out,
        planes,
        lights,
        |p, n, c, dst, stop| shade_uninit(scene, p, n, c, options, dst, stop),
    )
}

/// Lights the vertices with `MeshPhongMaterial`; see `glshade.shade`, whose intake prepared
/// the arrays as for the GL model. A double-sided material gives (2, ..., 4): front, back.
#[pyfunction]
#[pyo3(signature = (positions, normals, scene, *, colors, model, clamp, out))]
pub fn shade_threejs<'py>(
    py: Python<'py>,
    positions: &Bound<'py, PyUntypedArray>,
    normals: &Bound<'py, PyUntypedArray>,
    scene: &Bound<'py, ThreejsScene>,
    colors: Option<&Bound<'py, PyUntypedArray>>,
    model: Option<PyReadonlyArray2<'py, f64>>,
    clamp: bool,
    out: Option<&Bound<'py, PyUntypedArray>>,
) -> PyResult<Bound<'py, PyAny>> {
    let options = options(model.as_ref(), clamp)?;
    let scene = &scene.get().state;
    match float_of(positions, "positions")? {
        Float::F32 => shade_typed::<f32>(py, scene, &options, positions, normals, colors, out),
        Float::F64 => shade_typed::<f64>(py, scene, &options, positions, normals, colors, out),
    }
}

/// One line saying what `shade_threejs` computes for `scene` in `dtype` ("float32" or
/// "float64").
#[pyfunction]
#[pyo3(signature = (scene, *, model, clamp, dtype))]
pub fn describe_threejs(
    scene: &Bound<'_, ThreejsScene>,
    model: Option<PyReadonlyArray2<'_, f64>>,
    clamp: bool,
    dtype: &str,
) -> PyResult<String> {
    let options = options(model.as_ref(), clamp)?;
    let scene = &scene.get().state;
    match float_named(dtype)? {
        Float::F32 => describe::<f32>(scene, &options),
        Float::F64 => describe::<f64>(scene, &options),
    }
    .map_err(to_pyerr)
}
