//! The binding of `render`: one mesh (`render`) or several in one frame (`render_draws`),
//! through the same typed path.

use numpy::{
    Element, PyArrayMethods, PyReadonlyArray1, PyReadonlyArray2, PyReadonlyArray3,
    PyReadonlyArrayDyn, PyUntypedArray, PyUntypedArrayMethods,
};
use pyo3::exceptions::{PyTypeError, PyValueError};
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
use crate::render::mesh::{Draw, Mesh, Textured};
use crate::render::options::{Provoking, RenderOptions, Shading};
use crate::render::placement::Placement;
use crate::render::raster::{Cull, Viewport};
use crate::render::texture::{Filter, Texels, Texture, Wrap};
use crate::render::transfer::Transfer;

/// A render's image and depth, of the vertices' dtype.
pub type Rendered<'py> = PyResult<(Bound<'py, PyAny>, Bound<'py, PyAny>)>;

/// A texture's values read in place, of the type the caller stores them in.
enum TexelArray<'py> {
    U8(PyReadonlyArray3<'py, u8>),
    U16(PyReadonlyArray3<'py, u16>),
    F32(PyReadonlyArray3<'py, f32>),
    F64(PyReadonlyArray3<'py, f64>),
}

impl<'py> TexelArray<'py> {
    /// `texture`, a (height, width, channels) array of uint8, uint16, float32 or float64.
    fn read(texture: &Bound<'py, PyUntypedArray>) -> PyResult<Self> {
        fn typed<'py, X: Element>(
            a: &Bound<'py, PyUntypedArray>,
        ) -> Option<PyReadonlyArray3<'py, X>> {
            a.cast::<numpy::PyArray3<X>>()
                .ok()
                .and_then(|a| a.try_readonly().ok())
        }
        typed::<u8>(texture)
            .map(Self::U8)
            .or_else(|| typed::<u16>(texture).map(Self::U16))
            .or_else(|| typed::<f32>(texture).map(Self::F32))
            .or_else(|| typed::<f64>(texture).map(Self::F64))
            .ok_or_else(|| {
                PyTypeError::new_err(format!(
                    "texture must be a (height, width, channels) array of uint8, uint16, \
                     float32 or float64, got {} of shape {}",
                    texture.dtype(),
                    shape_text(texture.shape())
                ))
            })
    }

    /// The shape, (height, width, channels).
    fn shape(&self) -> &[usize] {
        match self {
            Self::U8(a) => a.shape(),
            Self::U16(a) => a.shape(),
            Self::F32(a) => a.shape(),
            Self::F64(a) => a.shape(),
        }
    }

    /// The values in place; an error unless C-contiguous and aligned.
    fn texels(&self) -> PyResult<Texels<'_>> {
        let contiguous = || PyValueError::new_err("texture must be C-contiguous and aligned");
        Ok(match self {
            Self::U8(a) => Texels::U8(a.as_slice().map_err(|_| contiguous())?),
            Self::U16(a) => Texels::U16(a.as_slice().map_err(|_| contiguous())?),
            Self::F32(a) => Texels::F32(a.as_slice().map_err(|_| contiguous())?),
            Self::F64(a) => Texels::F64(a.as_slice().map_err(|_| contiguous())?),
        })
    }
}

/// A mesh's texture as the binding takes it: its texels as stored (height, width, channels),
/// the texture coordinates (n, 2) of the vertices' dtype, the filter and the wrap modes.
pub struct TextureArgs<'py> {
    texels: TexelArray<'py>,
    uv: Bound<'py, PyUntypedArray>,
    filter: Filter,
    wrap: [Wrap; 2],
}

impl<'py> TextureArgs<'py> {
    /// The texture of `texture` and `uv`, given together or not at all.
    fn parse(
        texture: Option<Bound<'py, PyUntypedArray>>,
        uv: Option<Bound<'py, PyUntypedArray>>,
        filter: &str,
        wrap: &(String, String),
    ) -> PyResult<Option<Self>> {
        match (texture, uv) {
            (Some(texels), Some(uv)) => Ok(Some(Self {
                texels: TexelArray::read(&texels)?,
                uv,
                filter: Filter::parse(filter).map_err(to_pyerr)?,
                wrap: [
                    Wrap::parse(&wrap.0).map_err(to_pyerr)?,
                    Wrap::parse(&wrap.1).map_err(to_pyerr)?,
                ],
            })),
            (None, None) => Ok(None),
            _ => Err(PyValueError::new_err(
                "texture and uv go together: give both or neither",
            )),
        }
    }
}

/// One mesh of a frame as the binding takes it: its arrays, its scene, its model matrix and
/// its culling.
pub struct DrawArgs<'py> {
    vertices: Bound<'py, PyUntypedArray>,
    faces: Bound<'py, PyUntypedArray>,
    scene: AnyScene<'py>,
    model: glam::DMat4,
    cull: Cull,
    placement: Placement,
    normals: Option<Bound<'py, PyUntypedArray>>,
    colors: Option<Bound<'py, PyUntypedArray>>,
    texture: Option<TextureArgs<'py>>,
}

/// A mesh's arrays read as `T`, owned while the render borrows them.
struct ReadDraw<'py, T: Element> {
    vertices: PyReadonlyArrayDyn<'py, T>,
    faces: Vec<[i64; 3]>,
    normals: Option<PyReadonlyArrayDyn<'py, T>>,
    colors: Option<PyReadonlyArrayDyn<'py, T>>,
    uv: Option<PyReadonlyArrayDyn<'py, T>>,
}

impl<'py, T: Element + Real> ReadDraw<'py, T> {
    /// Reads `draw`'s arrays; `at` names the draw in errors (empty for a lone mesh).
    fn new(draw: &DrawArgs<'py>, at: &str) -> PyResult<Self> {
        let named = |name: &str| format!("{at}{name}");
        let optional = |a: &Option<Bound<'py, PyUntypedArray>>, name: &str| {
            a.as_ref().map(|a| read::<T>(a, &named(name))).transpose()
        };
        Ok(Self {
            vertices: read::<T>(&draw.vertices, &named("vertices"))?,
            faces: faces::copy(&draw.faces)?,
            normals: optional(&draw.normals, "normals")?,
            colors: optional(&draw.colors, "colors")?,
            uv: draw
                .texture
                .as_ref()
                .map(|t| read::<T>(&t.uv, &named("uv")))
                .transpose()?,
        })
    }

    /// The mesh of these arrays and `texture`'s texels.
    fn mesh<'a>(
        &'a self,
        texture: Option<&'a TextureArgs<'py>>,
        at: &str,
    ) -> PyResult<Mesh<'a, T>> {
        let named = |name: &str| format!("{at}{name}");
        let textured = match (texture, &self.uv) {
            (Some(t), Some(uv)) => {
                let shape = t.texels.shape();
                Some(Textured {
                    uv: rows::<T, 2>(uv, &named("uv"))?,
                    texture: Texture {
                        width: shape[1],
                        height: shape[0],
                        channels: shape[2],
                        texels: t.texels.texels()?,
                        filter: t.filter,
                        wrap: t.wrap,
                    },
                })
            }
            _ => None,
        };
        Ok(Mesh {
            vertices: rows::<T, 3>(&self.vertices, &named("vertices"))?,
            faces: &self.faces,
            normals: self
                .normals
                .as_ref()
                .map(|n| rows::<T, 3>(n, &named("normals")))
                .transpose()?,
            colors: self.colors.as_ref().map(vertex_colors).transpose()?,
            textured,
        })
    }
}

/// Renders `draws`, of one model (`first` is the first one's state) and of vertices of `T`,
/// seen by each of `views`: one frame, or a stack of them (k, height, width, ...) for
/// `Views::Stack`.
fn render_typed<'py, T: Element + Real, M: BindingModel>(
    py: Python<'py>,
    draws: &[DrawArgs<'py>],
    first: &M,
    views: &Views,
    options: &RenderOptions,
) -> Rendered<'py> {
    let at = |d: usize| {
        if draws.len() > 1 {
            format!("draws[{d}].")
        } else {
            String::new()
        }
    };
    let mut scenes = Vec::with_capacity(draws.len());
    for (d, draw) in draws.iter().enumerate() {
        let scene = if d == 0 {
            Some(first)
        } else {
            draw.scene.state::<M>()
        };
        scenes.push(scene.ok_or_else(|| {
            PyTypeError::new_err(format!(
                "{}scene must be of the first draw's model, as every draw's",
                at(d)
            ))
        })?);
    }
    let read = draws
        .iter()
        .enumerate()
        .map(|(d, draw)| ReadDraw::<T>::new(draw, &at(d)))
        .collect::<PyResult<Vec<_>>>()?;
    let mut meshes = Vec::with_capacity(draws.len());
    for (d, (arrays, draw)) in read.iter().zip(draws).enumerate() {
        let mesh = arrays.mesh(draw.texture.as_ref(), &at(d))?;
        meshes.push(Draw {
            mesh,
            scene: scenes[d],
            model: draw.model,
            cull: draw.cull,
            placement: draw.placement,
        });
    }
    let Viewport { width, height } = options.viewport;
    options.viewport.validate().map_err(to_pyerr)?;
    let (image, depth) = if views.stacked {
        let k = views.cameras.len();
        (
            zeros::<T>(py, &[k, height, width, 4])?,
            zeros::<T>(py, &[k, height, width])?,
        )
    } else {
        (
            zeros::<T>(py, &[height, width, 4])?,
            zeros::<T>(py, &[height, width])?,
        )
    };
    {
        let (mut image, mut depth) = (image.readwrite(), depth.readwrite());
        let (image, depth) = (image.as_slice_mut()?, depth.as_slice_mut()?);
        let cameras = &views.cameras;
        run(py, true, |stop| {
            if views.stacked {
                crate::render::render_views(&meshes, cameras, options, image, depth, stop)
            } else {
                crate::render::render_draws(&meshes, &cameras[0], options, image, depth, stop)
            }
        })?;
    }
    Ok((image.into_any(), depth.into_any()))
}

/// The cameras of a render: one, for a frame, or a stack of frames, one a camera.
struct Views {
    cameras: Vec<Camera>,
    stacked: bool,
}

impl Views {
    /// The cameras of `view` and `projection`, (4, 4) each or (k, 4, 4) each.
    fn parse(
        view: &PyReadonlyArrayDyn<'_, f64>,
        projection: &PyReadonlyArrayDyn<'_, f64>,
    ) -> PyResult<Self> {
        let stack = |m: &PyReadonlyArrayDyn<'_, f64>, name: &str| -> PyResult<Vec<glam::DMat4>> {
            let values = m.as_slice().ok().filter(|_| m.is_c_contiguous());
            match (values, m.shape()) {
                (Some(v), [4, 4]) => Ok(vec![matrix_of(v)]),
                (Some(v), [_, 4, 4]) => Ok(v.chunks_exact(16).map(matrix_of).collect()),
                _ => Err(PyValueError::new_err(format!(
                    "{name} must be a C-contiguous (4, 4) or (k, 4, 4) array, got shape {}",
                    shape_text(m.shape())
                ))),
            }
        };
        let (views, projections) = (stack(view, "view")?, stack(projection, "projection")?);
        if views.len() != projections.len() || views.is_empty() {
            return Err(PyValueError::new_err(format!(
                "view and projection must hold as many matrices, at least one, got {} and {}",
                views.len(),
                projections.len()
            )));
        }
        let cameras = views
            .into_iter()
            .zip(projections)
            .map(|(view, projection)| Camera { view, projection })
            .collect();
        Ok(Self {
            cameras,
            stacked: view.ndim() == 3 || projection.ndim() == 3,
        })
    }
}

/// A (4, 4) matrix of 16 row-major values.
fn matrix_of(rows: &[f64]) -> glam::DMat4 {
    let mut values = [0.0; 16];
    values.copy_from_slice(rows);
    glam::DMat4::from_cols_array(&values).transpose()
}

/// The work of one render, done with whichever model the first draw's scene is.
struct RenderWork<'a, 'py> {
    py: Python<'py>,
    draws: &'a [DrawArgs<'py>],
    views: &'a Views,
    options: &'a RenderOptions,
}

impl<'py> OnModel for RenderWork<'_, 'py> {
    type Output = Rendered<'py>;
    fn call<M: BindingModel>(self, first: &M) -> Self::Output {
        let (py, draws, views, options) = (self.py, self.draws, self.views, self.options);
        match float_of(&draws[0].vertices, "vertices")? {
            Float::F32 => render_typed::<f32, M>(py, draws, first, views, options),
            Float::F64 => render_typed::<f64, M>(py, draws, first, views, options),
        }
    }
}

/// The camera of `view` and `projection`.
pub fn camera(
    view: &PyReadonlyArray2<'_, f64>,
    projection: &PyReadonlyArray2<'_, f64>,
) -> PyResult<Camera> {
    Ok(Camera {
        view: matrix(view, "view")?,
        projection: matrix(projection, "projection")?,
    })
}

/// The options of a frame that `render` and `render_points` share, as the binding takes them.
pub struct Frame<'a, 'py> {
    /// The image's width in pixels.
    pub width: usize,
    /// Its height.
    pub height: usize,
    /// The model matrix, (4, 4).
    pub model: &'a PyReadonlyArray2<'py, f64>,
    /// The clear colour, four values, encoded.
    pub background: &'a PyReadonlyArray1<'py, f64>,
    /// The transfer's name.
    pub transfer: &'a str,
    /// GL's clamp of the colours.
    pub clamp: bool,
    /// GL's colour-material mode, if any.
    pub color_material: Option<&'a str>,
    /// The faces it applies to.
    pub color_material_face: &'a str,
    /// `GL_NORMALIZE`.
    pub normalize: bool,
    /// `GL_RESCALE_NORMAL`.
    pub rescale_normal: bool,
}

impl Frame<'_, '_> {
    /// The render options of these, the others at their defaults.
    pub fn options(&self) -> PyResult<RenderOptions> {
        Ok(RenderOptions {
            viewport: Viewport {
                width: self.width,
                height: self.height,
            },
            model: matrix(self.model, "model")?,
            background: background(self.background)?,
            transfer: Transfer::parse(self.transfer).map_err(to_pyerr)?,
            normalize: self.normalize,
            rescale_normal: self.rescale_normal,
            color_material: self
                .color_material
                .map(|mode| ColorMaterial::parse(mode, self.color_material_face))
                .transpose()
                .map_err(to_pyerr)?,
            clamp: ColorClamp::from(self.clamp),
            ..RenderOptions::default()
        })
    }
}

/// The background colour, four values.
fn background(background: &PyReadonlyArray1<'_, f64>) -> PyResult<[f64; 4]> {
    background.as_slice()?.try_into().map_err(|_| {
        PyValueError::new_err(format!(
            "background must have 4 values, got shape {}",
            shape_text(background.shape())
        ))
    })
}

/// Renders a mesh lit by `scene`, a native scene of any model; see `glshade.render`, whose
/// intake prepared the arrays (float32 or float64 of one dtype, int64 faces, float64 matrices)
/// and passes GL's options (`color_material` to `rescale_normal`) for a `glshade.Scene` only.
/// `transfer` encodes the drawn pixels' RGB; `background` is written as it is (the caller
/// encodes it). Returns the (height, width, 4) image and the (height, width) depth, of the
/// vertices' dtype; with `view` and `projection` of shape (k, 4, 4), one view a pair, the
/// (k, height, width, 4) images and (k, height, width) depths, the normals computed once.
#[pyfunction]
#[pyo3(signature = (
    vertices, faces, scene, *, view, projection, model, width, height, shading, provoking_vertex,
    normals, colors, cull, background, transfer, clamp, texture, uv, texture_filter,
    texture_wrap, color_material=None, color_material_face="front_and_back", normalize=true,
    rescale_normal=false
))]
pub fn render<'py>(
    py: Python<'py>,
    vertices: Bound<'py, PyUntypedArray>,
    faces: Bound<'py, PyUntypedArray>,
    scene: AnyScene<'py>,
    view: PyReadonlyArrayDyn<'py, f64>,
    projection: PyReadonlyArrayDyn<'py, f64>,
    model: PyReadonlyArray2<'py, f64>,
    width: usize,
    height: usize,
    shading: &str,
    provoking_vertex: &str,
    normals: Option<Bound<'py, PyUntypedArray>>,
    colors: Option<Bound<'py, PyUntypedArray>>,
    cull: &str,
    background: PyReadonlyArray1<'py, f64>,
    transfer: &str,
    clamp: bool,
    texture: Option<Bound<'py, PyUntypedArray>>,
    uv: Option<Bound<'py, PyUntypedArray>>,
    texture_filter: &str,
    texture_wrap: (String, String),
    color_material: Option<&str>,
    color_material_face: &str,
    normalize: bool,
    rescale_normal: bool,
) -> Rendered<'py> {
    let texture = TextureArgs::parse(texture, uv, texture_filter, &texture_wrap)?;
    let frame = Frame {
        width,
        height,
        model: &model,
        background: &background,
        transfer,
        clamp,
        color_material,
        color_material_face,
        normalize,
        rescale_normal,
    };
    let options = RenderOptions {
        shading: Shading::parse(shading).map_err(to_pyerr)?,
        provoking: Provoking::parse(provoking_vertex).map_err(to_pyerr)?,
        cull: Cull::parse(cull).map_err(to_pyerr)?,
        ..frame.options()?
    };
    let draw = DrawArgs {
        vertices,
        faces,
        scene,
        model: options.model,
        cull: options.cull,
        placement: Placement::Model,
        normals,
        colors,
        texture,
    };
    let views = Views::parse(&view, &projection)?;
    let draws = [draw];
    draws[0].scene.with(RenderWork {
        py,
        draws: &draws,
        views: &views,
        options: &options,
    })
}

/// A mesh of `render_draws`: `(vertices, faces, scene, model, cull, normals, colors,
/// texture, uv, texture_filter, texture_wrap)`, as `render` takes them.
type DrawTuple<'py> = (
    Bound<'py, PyUntypedArray>,
    Bound<'py, PyUntypedArray>,
    AnyScene<'py>,
    PyReadonlyArray2<'py, f64>,
    String,
    Option<Bound<'py, PyUntypedArray>>,
    Option<Bound<'py, PyUntypedArray>>,
    Option<Bound<'py, PyUntypedArray>>,
    Option<Bound<'py, PyUntypedArray>>,
    String,
    (String, String),
);

/// Renders several meshes into one frame, depth-tested together in the order given, each with
/// its own scene (all of one model), model matrix and culling: `draws` is a non-empty list of
/// tuples `(vertices, faces, scene, model, cull, normals, colors, texture, uv,
/// texture_filter, texture_wrap)`, every vertex array of one dtype. `placement` says where
/// the model matrices apply: `"model"` as `render`'s `model`, or `"vertices"` per vertex
/// first, normals normalised there (a vertex shader's way). GL's own options take their
/// defaults. Returns the image and the depth as `render` does.
#[pyfunction]
#[pyo3(signature = (
    draws, *, view, projection, width, height, shading, provoking_vertex, background, transfer,
    clamp, placement="model"
))]
pub fn render_draws<'py>(
    py: Python<'py>,
    draws: Vec<DrawTuple<'py>>,
    view: PyReadonlyArray2<'py, f64>,
    projection: PyReadonlyArray2<'py, f64>,
    width: usize,
    height: usize,
    shading: &str,
    provoking_vertex: &str,
    background: PyReadonlyArray1<'py, f64>,
    transfer: &str,
    clamp: bool,
    placement: &str,
) -> Rendered<'py> {
    if draws.is_empty() {
        return Err(PyValueError::new_err(
            "draws must hold at least one mesh, got none",
        ));
    }
    let options = RenderOptions {
        viewport: Viewport { width, height },
        shading: Shading::parse(shading).map_err(to_pyerr)?,
        provoking: Provoking::parse(provoking_vertex).map_err(to_pyerr)?,
        background: self::background(&background)?,
        transfer: Transfer::parse(transfer).map_err(to_pyerr)?,
        clamp: ColorClamp::from(clamp),
        ..RenderOptions::default()
    };
    let placement = Placement::parse(placement).map_err(to_pyerr)?;
    let mut parsed = Vec::with_capacity(draws.len());
    for (d, draw) in draws.into_iter().enumerate() {
        let (vertices, faces, scene, model, cull, normals, colors, texture, uv, filter, wrap) =
            draw;
        parsed.push(DrawArgs {
            vertices,
            faces,
            scene,
            model: matrix(&model, &format!("draws[{d}].model"))?,
            cull: Cull::parse(&cull).map_err(to_pyerr)?,
            placement,
            normals,
            colors,
            texture: TextureArgs::parse(texture, uv, &filter, &wrap)?,
        });
    }
    let views = Views {
        cameras: vec![self::camera(&view, &projection)?],
        stacked: false,
    };
    parsed[0].scene.with(RenderWork {
        py,
        draws: &parsed,
        views: &views,
        options: &options,
    })
}
