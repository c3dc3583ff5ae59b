//! The binding of the metallic-roughness model: its native scene and `shade_gltf`,
//! `describe_gltf`.

use numpy::{Element, PyReadonlyArray2, PyUntypedArray};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

use super::arrays::{float_named, float_of, Float};
use super::matrix;
use super::runtime::to_pyerr;
use super::shading::shade_arrays;
use crate::gltf::light::{Light, Punctual};
use crate::gltf::material::Material;
use crate::gltf::scene::{Scene, ValidScene};
use crate::lighting::metallic_roughness::shade::{describe, shade_uninit, Options};
use crate::lighting::prepare::ColorClamp;
use crate::numbers::real::Real;

/// One light as `glshade.gltf` passes it: kind ("directional", "point" or "spot"), colour,
/// intensity, position, direction, inner and outer cone angles.
type LightRow = (String, [f64; 3], f64, [f64; 3], [f64; 3], f64, f64);

/// A metallic-roughness scene, checked; see `glshade.gltf.Scene`.
#[pyclass(frozen, module = "glshade._glshade")]
pub struct GltfScene {
    pub(crate) state: ValidScene,
}

#[pymethods]
impl GltfScene {
    /// The scene of these lights, material factors, ambient light and camera position.
    /// Raises `ValueError` naming a bad value.
    #[new]
    #[pyo3(signature = (
        *, lights, base_color, metallic, roughness, emissive, ambient_light, camera_position
    ))]
    fn new(
        lights: Vec<LightRow>,
        base_color: [f64; 4],
        metallic: f64,
        roughness: f64,
        emissive: [f64; 3],
        ambient_light: [f64; 3],
        camera_position: [f64; 3],
    ) -> PyResult<Self> {
        let lights = lights
            .into_iter()
            .map(
                |(kind, color, intensity, position, direction, inner, outer)| {
                    let punctual = match kind.as_str() {
                        "directional" => Punctual::Directional { direction },
                        "point" => Punctual::Point { position },
                        "spot" => Punctual::Spot {
                            position,
                            direction,
                            inner_cone_angle: inner,
                            outer_cone_angle: outer,
                        },
                        _ => {
                            return Err(PyValueError::new_err(format!(
                                "a light's kind must be 'directional', 'point' or 'spot', got \
                             {kind:?}"
                            )))
                        }
                    };
                    Ok(Light {
                        punctual,
                        color,
                        intensity,
                    })
                },
            )
            .collect::<PyResult<Vec<Light>>>()?;
        let scene = Scene {
            lights,
            material: Material {
                base_color,
                metallic,
                roughness,
                emissive,
            },
            ambient_light,
            camera_position,
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
        ..Options::default()
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
    let lights = scene.lights.len();
    shade_arrays::<T>(
        py,
        positions,
        normals,
        colors,
        out,
        1,
        lights,
        |p, n, c, dst, stop| shade_uninit(scene, p, n, c, options, dst, stop),
    )
}

/// Lights the vertices with the metallic-roughness model; see `glshade.shade`, whose intake
/// prepared the arrays as for the GL model.
#[pyfunction]
#[pyo3(signature = (positions, normals, scene, *, colors, model, clamp, out))]
pub fn shade_gltf<'py>(
    py: Python<'py>,
    positions: &Bound<'py, PyUntypedArray>,
    normals: &Bound<'py, PyUntypedArray>,
    scene: &Bound<'py, GltfScene>,
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

/// One line saying what `shade_gltf` computes for `scene` in `dtype` ("float32" or "float64").
#[pyfunction]
#[pyo3(signature = (scene, *, model, clamp, dtype))]
pub fn describe_gltf(
    scene: &Bound<'_, GltfScene>,
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
