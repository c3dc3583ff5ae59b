//! The binding of points (`glshade.render` of a point cloud): the arrays borrowed, the core's
//! [`crate::render::points::render_points`] called without the GIL.

use numpy::{Element, PyArrayMethods, PyReadonlyArray1, PyReadonlyArray2, PyUntypedArray};
use pyo3::prelude::*;

use super::arrays::{float_of, read, rows, vertex_colors, zeros, Float};
use super::model::{AnyScene, BindingModel, OnModel};
use super::render::{camera, Frame, Rendered};
use super::runtime::{run, to_pyerr};
use crate::numbers::real::Real;
use crate::render::mesh::Mesh;
use crate::render::options::RenderOptions;
use crate::render::points::{PointShape, PointStyle};
use crate::render::raster::Viewport;

/// The work of one points render, done with the scene's model.
struct PointsWork<'a, 'py> {
    py: Python<'py>,
    vertices: &'a Bound<'py, PyUntypedArray>,
    normals: Option<&'a Bound<'py, PyUntypedArray>>,
    colors: Option<&'a Bound<'py, PyUntypedArray>>,
    camera: crate::render::camera::Camera,
    options: RenderOptions,
    style: PointStyle,
}

impl<'py> OnModel for PointsWork<'_, 'py> {
    type Output = Rendered<'py>;
    fn call<M: BindingModel>(self, scene: &M) -> Self::Output {
        match float_of(self.vertices, "vertices")? {
            Float::F32 => points_typed::<f32, M>(&self, scene),
            Float::F64 => points_typed::<f64, M>(&self, scene),
        }
    }
}

fn points_typed<'py, T: Element + Real, M: BindingModel>(
    work: &PointsWork<'_, 'py>,
    scene: &M,
) -> Rendered<'py> {
    let vertices = read::<T>(work.vertices, "vertices")?;
    let normals = work.normals.map(|n| read::<T>(n, "normals")).transpose()?;
    let colors = work.colors.map(|c| read::<T>(c, "colors")).transpose()?;
    let points = Mesh {
        vertices: rows::<T, 3>(&vertices, "vertices")?,
        faces: &[],
        normals: normals
            .as_ref()
            .map(|n| rows::<T, 3>(n, "normals"))
            .transpose()?,
        colors: colors.as_ref().map(vertex_colors).transpose()?,
        textured: None,
    };
    let Viewport { width, height } = work.options.viewport;
    work.options.viewport.validate().map_err(to_pyerr)?;
    let image = zeros::<T>(work.py, &[height, width, 4])?;
    let depth = zeros::<T>(work.py, &[height, width])?;
    {
        let (mut image, mut depth) = (image.readwrite(), depth.readwrite());
        let (image, depth) = (image.as_slice_mut()?, depth.as_slice_mut()?);
        let (camera, options, style) = (&work.camera, &work.options, work.style);
        run(work.py, true, |stop| {
            crate::render::points::render_points(
                scene, &points, camera, options, style, image, depth, stop,
            )
        })?;
    }
    Ok((image.into_any(), depth.into_any()))
}

/// Draws `vertices` as GL points of `point_size` pixels, square or round (`point_shape`), lit
/// by `scene` where `normals` are given (one a point), else drawn in their `colors` (white
/// without); see `glshade.render`, whose intake prepared the arrays. Returns the (height,
/// width, 4) image and the (height, width) depth, of the vertices' dtype.
#[pyfunction]
#[pyo3(signature = (
    vertices, scene, *, view, projection, model, width, height, normals, colors, point_size,
    point_shape, background, transfer, clamp, color_material=None,
    color_material_face="front_and_back", normalize=true, rescale_normal=false
))]
pub fn render_points<'py>(
    py: Python<'py>,
    vertices: Bound<'py, PyUntypedArray>,
    scene: AnyScene<'py>,
    view: PyReadonlyArray2<'py, f64>,
    projection: PyReadonlyArray2<'py, f64>,
    model: PyReadonlyArray2<'py, f64>,
    width: usize,
    height: usize,
    normals: Option<Bound<'py, PyUntypedArray>>,
    colors: Option<Bound<'py, PyUntypedArray>>,
    point_size: f64,
    point_shape: &str,
    background: PyReadonlyArray1<'py, f64>,
    transfer: &str,
    clamp: bool,
    color_material: Option<&str>,
    color_material_face: &str,
    normalize: bool,
    rescale_normal: bool,
) -> Rendered<'py> {
    let options = Frame {
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
    }
    .options()?;
    let style = PointStyle {
        size: point_size,
        shape: PointShape::parse(point_shape).map_err(to_pyerr)?,
    };
    style.validate().map_err(to_pyerr)?;
    scene.with(PointsWork {
        py,
        vertices: &vertices,
        normals: normals.as_ref(),
        colors: colors.as_ref(),
        camera: camera(&view, &projection)?,
        options,
        style,
    })
}
