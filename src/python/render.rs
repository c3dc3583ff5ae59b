//! The binding of `render`.

use numpy::{
    Element, PyArrayMethods, PyReadonlyArray1, PyReadonlyArray2, PyReadonlyArray3, PyUntypedArray,
    PyUntypedArrayMethods,
};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

use super::arrays::matrix;
use super::arrays::{float_of, read, rows, shape_text, vertex_colors, zeros, Float};
use super::faces;
use super::model::{AnyScene, BindingModel, OnModel};
use super::runtime::{run, to_pyerr};
use crate::gl::material::ColorMaterial;
use crate::lighting::clamp::ColorClamp;
use crate::numbers::real::Real;
use crate::render::camera::Camera;
use crate::render::mesh::{Mesh, Textured};
use crate::render::options::{Provoking, RenderOptions, Shading};
use crate::render::raster::{Cull, Viewport};
use crate::render::texture::{Filter, Texture, Wrap};

/// A render's image and depth, of the vertices' dtype.
type Rendered<'py> = PyResult<(Bound<'py, PyAny>, Bound<'py, PyAny>)>;

/// A render's texture as the binding takes it: float32 RGBA texels (height, width, 4), the
/// texture coordinates (n, 2) of the vertices' dtype, the filter and the wrap modes.
pub struct TextureArgs<'py> {
    texels: PyReadonlyArray3<'py, f32>,
    uv: Bound<'py, PyUntypedArray>,
    filter: Filter,
    wrap: [Wrap; 2],
}

fn render_typed<'py, T: Element + Real, M: BindingModel>(
    py: Python<'py>,
    scene: &M,
    camera: &Camera,
    options: &RenderOptions,
    vertices: &Bound<'py, PyUntypedArray>,
    faces: &Bound<'py, PyUntypedArray>,
    normals: Option<&Bound<'py, PyUntypedArray>>,
    colors: Option<&Bound<'py, PyUntypedArray>>,
    texture: Option<&TextureArgs<'py>>,
) -> Rendered<'py> {
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
        run(py, true, |stop| {
            crate::render::render(scene, &mesh, camera, options, image, depth, stop)
        })?;
    }
    Ok((image.into_any(), depth.into_any()))
}

/// Renders a mesh lit by `scene`, a native scene of any model; see `glshade.render`, whose
/// intake prepared the arrays (float32 or float64 of one dtype, int64 faces, float64 matrices)
/// and passes GL's options (`color_material` to `rescale_normal`) for a `glshade.Scene` only.
/// Returns the (height, width, 4) image and the (height, width) depth, of the vertices' dtype.
#[pyfunction]
#[pyo3(signature = (
    vertices, faces, scene, *, view, projection, model, width, height, shading, provoking_vertex,
    normals, colors, cull, background, clamp, texture, uv, texture_filter, texture_wrap,
    color_material=None, color_material_face="front_and_back", normalize=true,
    rescale_normal=false
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
    cull: &str,
    background: PyReadonlyArray1<'py, f64>,
    clamp: bool,
    texture: Option<PyReadonlyArray3<'py, f32>>,
    uv: Option<Bound<'py, PyUntypedArray>>,
    texture_filter: &str,
    texture_wrap: (String, String),
    color_material: Option<&str>,
    color_material_face: &str,
    normalize: bool,
    rescale_normal: bool,
) -> Rendered<'py> {
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
            shape_text(background.shape())
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
    scene.with(RenderWork {
        py,
        camera: &camera,
        options: &options,
        vertices,
        faces,
        normals,
        colors,
        texture: texture.as_ref(),
    })
}

/// The work of one `render` call, done with whichever model the scene is.
struct RenderWork<'a, 'py> {
    py: Python<'py>,
    camera: &'a Camera,
    options: &'a RenderOptions,
    vertices: &'a Bound<'py, PyUntypedArray>,
    faces: &'a Bound<'py, PyUntypedArray>,
    normals: Option<&'a Bound<'py, PyUntypedArray>>,
    colors: Option<&'a Bound<'py, PyUntypedArray>>,
    texture: Option<&'a TextureArgs<'py>>,
}

impl<'py> RenderWork<'_, 'py> {
    /// The render on vertices of `T` with `scene`'s model.
    fn typed<T: Element + Real, M: BindingModel>(self, scene: &M) -> Rendered<'py> {
        render_typed::<T, M>(
            self.py,
            scene,
            self.camera,
            self.options,
            self.vertices,
            self.faces,
            self.normals,
            self.colors,
            self.texture,
        )
    }
}

impl<'py> OnModel for RenderWork<'_, 'py> {
    type Output = Rendered<'py>;
    fn call<M: BindingModel>(self, scene: &M) -> Self::Output {
        match float_of(self.vertices, "vertices")? {
            Float::F32 => self.typed::<f32, M>(scene),
            Float::F64 => self.typed::<f64, M>(scene),
        }
    }
}
