//! The binding of `render`.

use numpy::{
    Element, PyArrayMethods, PyReadonlyArray1, PyReadonlyArray2, PyReadonlyArray3, PyUntypedArray,
    PyUntypedArrayMethods,
};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

use super::arrays::{float_of, read, rows, vertex_colors, zeros, Float};
use super::gltf::GltfScene;
use super::runtime::{run, to_pyerr};
use super::scene::Scene;
use super::threejs::ThreejsScene;
use super::{faces, matrix};
use crate::gl::material::ColorMaterial;
use crate::lighting::prepare::ColorClamp;
use crate::numbers::real::Real;
use crate::render::camera::Camera;
use crate::render::mesh::{Mesh, Textured};
use crate::render::passes::Provoking;
use crate::render::raster::{Cull, Viewport};
use crate::render::texture::{Filter, Texture, Wrap};
use crate::render::{render_mesh_phong, render_metallic_roughness, RenderOptions, Shading};

/// The scene of a render: GL's, glTF's metallic-roughness one or three.js'.
#[derive(FromPyObject)]
pub enum AnyScene<'py> {
    /// `glshade.Scene`'s native scene.
    Gl(Bound<'py, Scene>),
    /// `glshade.gltf.Scene`'s native scene.
    Gltf(Bound<'py, GltfScene>),
    /// `glshade.threejs.Scene`'s native scene.
    Threejs(Bound<'py, ThreejsScene>),
}

/// A render's texture as the binding takes it: float32 RGBA texels (height, width, 4), the
/// texture coordinates (n, 2) of the vertices' dtype, the filter and the wrap modes.
pub struct TextureArgs<'py> {
    texels: PyReadonlyArray3<'py, f32>,
    uv: Bound<'py, PyUntypedArray>,
    filter: Filter,
    wrap: [Wrap; 2],
}

fn render_typed<'py, T: Element + Real>(
    py: Python<'py>,
    scene: &AnyScene<'py>,
    camera: &Camera,
    options: &RenderOptions,
    vertices: &Bound<'py, PyUntypedArray>,
    faces: &Bound<'py, PyUntypedArray>,
    normals: Option<&Bound<'py, PyUntypedArray>>,
    colors: Option<&Bound<'py, PyUntypedArray>>,
    texture: Option<&TextureArgs<'py>>,
) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyAny>)> {
    let vertices = read::<T>(vertices, "vertices")?;
    let normals = normals.map(|a| read::<T>(a, "normals")).transpose()?;
    let colors = colors.map(|a| read::<T>(a, "colors")).transpose()?;
    let uv = texture.map(|t| read::<T>(&t.uv, "uv")).transpose()?;
    let faces = faces::copy(faces)?;
    let textured = match (texture, &uv) {
        (Some(t), Some(uv)) => {
            let shape = t.texels.shape();
            Some(Textured {
                uv: rows::<T, 2>(uv, "uv")?,
                texture: Texture {
                    width: shape[1],
                    height: shape[0],
                    texels: t.texels.as_slice().map_err(|_| {
                        PyValueError::new_err("texture must be C-contiguous and aligned")
                    })?,
                    filter: t.filter,
                    wrap: t.wrap,
                },
            })
        }
        _ => None,
    };
    let mesh = Mesh {
        vertices: rows::<T, 3>(&vertices, "vertices")?,
        faces: &faces,
        normals: normals
            .as_ref()
            .map(|n| rows::<T, 3>(n, "normals"))
            .transpose()?,
        colors: colors.as_ref().map(vertex_colors).transpose()?,
        textured,
    };
    let Viewport { width, height } = options.viewport;
    options.viewport.validate().map_err(to_pyerr)?;
    let image = zeros::<T>(py, &[height, width, 4])?;
    let depth = zeros::<T>(py, &[height, width])?;
    {
        let (mut image, mut depth) = (image.readwrite(), depth.readwrite());
        let (image, depth) = (image.as_slice_mut()?, depth.as_slice_mut()?);
        match scene {
            AnyScene::Gl(scene) => {
                let scene = &scene.get().state;
                run(py, true, |stop| {
                    crate::render::render(scene, &mesh, camera, options, image, depth, stop)
                })?;
            }
            AnyScene::Gltf(scene) => {
                let scene = &scene.get().state;
                run(py, true, |stop| {
                    render_metallic_roughness(scene, &mesh, camera, options, image, depth, stop)
                })?;
            }
            AnyScene::Threejs(scene) => {
                let scene = &scene.get().state;
                run(py, true, |stop| {
                    render_mesh_phong(scene, &mesh, camera, options, image, depth, stop)
                })?;
            }
        }
    }
    Ok((image.into_any(), depth.into_any()))
}

/// Renders a mesh; see `glshade.render`, whose intake prepared the arrays (float32 or float64
/// of one dtype, int64 faces, float64 matrices). Returns the (height, width, 4) image and the
/// (height, width) depth, of the vertices' dtype.
#[pyfunction]
#[pyo3(signature = (
    vertices, faces, scene, *, view, projection, model, width, height, shading, provoking_vertex,
    normals, colors, color_material, color_material_face, normalize, rescale_normal, cull,
    background, clamp, texture, uv, texture_filter, texture_wrap
))]
pub fn render<'py>(
    py: Python<'py>,
    vertices: &Bound<'py, PyUntypedArray>,
    faces: &Bound<'py, PyUntypedArray>,
    scene: AnyScene<'py>,
    view: PyReadonlyArray2<'py, f64>,
    projection: PyReadonlyArray2<'py, f64>,
    model: PyReadonlyArray2<'py, f64>,
    width: usize,
    height: usize,
    shading: &str,
    provoking_vertex: &str,
    normals: Option<&Bound<'py, PyUntypedArray>>,
    colors: Option<&Bound<'py, PyUntypedArray>>,
    color_material: Option<&str>,
    color_material_face: &str,
    normalize: bool,
    rescale_normal: bool,
    cull: &str,
    background: PyReadonlyArray1<'py, f64>,
    clamp: bool,
    texture: Option<PyReadonlyArray3<'py, f32>>,
    uv: Option<Bound<'py, PyUntypedArray>>,
    texture_filter: &str,
    texture_wrap: (String, String),
) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyAny>)> {
    let texture = match (texture, uv) {
        (Some(texels), Some(uv)) => Some(TextureArgs {
            texels,
            uv,
            filter: Filter::parse(texture_filter).map_err(to_pyerr)?,
            wrap: [
                Wrap::parse(&texture_wrap.0).map_err(to_pyerr)?,
                Wrap::parse(&texture_wrap.1).map_err(to_pyerr)?,
            ],
        }),
        (None, None) => None,
        _ => {
            return Err(PyValueError::new_err(
                "texture and uv go together: give both or neither",
            ))
        }
    };
    let camera = Camera {
        view: matrix(&view, "view")?,
        projection: matrix(&projection, "projection")?,
    };
    let background: [f64; 4] = background.as_slice()?.try_into().map_err(|_| {
        PyValueError::new_err(format!(
            "background must have 4 values, got shape {}",
            super::arrays::shape_text(background.shape())
        ))
    })?;
    let options = RenderOptions {
        viewport: Viewport { width, height },
        shading: Shading::parse(shading).map_err(to_pyerr)?,
        provoking: Provoking::parse(provoking_vertex).map_err(to_pyerr)?,
        cull: Cull::parse(cull).map_err(to_pyerr)?,
        model: matrix(&model, "model")?,
        background,
        normalize,
        rescale_normal,
        color_material: color_material
            .map(|mode| ColorMaterial::parse(mode, color_material_face))
            .transpose()
            .map_err(to_pyerr)?,
        clamp: ColorClamp::from(clamp),
    };
    let scene = &scene;
    match float_of(vertices, "vertices")? {
        Float::F32 => render_typed::<f32>(
            py,
            scene,
            &camera,
            &options,
            vertices,
            faces,
            normals,
            colors,
            texture.as_ref(),
        ),
        Float::F64 => render_typed::<f64>(
            py,
            scene,
            &camera,
            &options,
            vertices,
            faces,
            normals,
            colors,
            texture.as_ref(),
        ),
    }
}
