//! The native scene of `MeshPhongMaterial` (three.js state), built from the rows
//! `glshade.threejs` passes.

use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

use super::runtime::to_pyerr;
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
