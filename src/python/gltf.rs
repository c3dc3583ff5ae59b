//! The native scene of the metallic-roughness model (glTF state), built from the rows
//! `glshade.gltf` passes.

use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

use super::runtime::to_pyerr;
use crate::gltf::light::{Light, Punctual};
use crate::gltf::material::Material;
use crate::gltf::scene::{Scene, ValidScene};

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
