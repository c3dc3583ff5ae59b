//! The binding of `render`.

use numpy::{
    Element, PyArray1, PyArrayMethods, PyReadonlyArray1, PyReadonlyArray2, PyUntypedArray,
};
use pyo3::prelude::*;

use super::{float_of, matrix, rows, scene_from, to_pyerr, typed, vec4, vertex_colors, Float};
use crate::camera::Camera;
use crate::material::ColorMaterial;
use crate::raster::{Cull, Viewport};
use crate::real::Real;
use crate::render::{Mesh, RenderOptions, Shading};
use crate::scene::Scene;

/// Every argument of `render` that does not depend on the dtype.
struct Call {
    scene: Scene,
    camera: Camera,
    options: RenderOptions,
}

fn render_typed<'py, T: Element + Real>(
    py: Python<'py>,
    call: &Call,
    vertices: &Bound<'py, PyUntypedArray>,
    faces: &PyReadonlyArray2<'py, i64>,
    normals: Option<&Bound<'py, PyUntypedArray>>,
    colors: Option<&Bound<'py, PyUntypedArray>>,
) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyAny>)> {
    let vertices = typed::<T>(vertices, "vertices", "vertices")?;
    let normals = normals
        .map(|a| typed::<T>(a, "normals", "vertices"))
        .transpose()?;
    let colors = colors
        .map(|a| typed::<T>(a, "colors", "vertices"))
        .transpose()?;
    let v = rows::<T, 3>(&vertices, "vertices")?;
    let mesh = Mesh {
        vertices: v,
        faces: rows::<i64, 3>(faces, "faces")?,
        normals: normals
            .as_ref()
            .map(|n| rows::<T, 3>(n, "normals"))
            .transpose()?,
        colors: colors
            .as_ref()
            .map(|c| vertex_colors(c, v.len()))
            .transpose()?,
    };
    let viewport = call.options.viewport;
    viewport.validate().map_err(to_pyerr)?;
    let Viewport { width, height } = viewport;
    let mut image = vec![T::ZERO; width * height * 4];
    let mut depth = vec![T::ZERO; width * height];
    py.detach(|| {
        crate::render::render(
            &call.scene,
            &mesh,
            &call.camera,
            &call.options,
            &mut image,
            &mut depth,
        )
    })
    .map_err(to_pyerr)?;
    Ok((
        PyArray1::from_vec(py, image)
            .reshape([height, width, 4])?
            .into_any(),
        PyArray1::from_vec(py, depth)
            .reshape([height, width])?
            .into_any(),
    ))
}

/// Renders a mesh; see `glshade.render` for the arguments, which arrive here already coerced
/// (C-contiguous float32 or float64 arrays, int64 faces, float64 matrices and scene tables).
/// Returns the (height, width, 4) image and the (height, width) depth, of the vertices' dtype.
#[pyfunction]
#[pyo3(signature = (
    vertices, faces, lights, material, back_material, global_ambient, viewer, two_side,
    separate_specular, specular, specular_gate, view, projection, model, width, height, shading,
    normals,
    colors, color_material, color_material_face, normalize, rescale_normal, cull, background
))]
pub fn render<'py>(
    py: Python<'py>,
    vertices: &Bound<'py, PyUntypedArray>,
    faces: PyReadonlyArray2<'py, i64>,
    lights: PyReadonlyArray2<'py, f64>,
    material: PyReadonlyArray1<'py, f64>,
    back_material: PyReadonlyArray1<'py, f64>,
    global_ambient: PyReadonlyArray1<'py, f64>,
    viewer: PyReadonlyArray1<'py, f64>,
    two_side: bool,
    separate_specular: bool,
    specular: &str,
    specular_gate: bool,
    view: PyReadonlyArray2<'py, f64>,
    projection: PyReadonlyArray2<'py, f64>,
    model: PyReadonlyArray2<'py, f64>,
    width: usize,
    height: usize,
    shading: &str,
    normals: Option<&Bound<'py, PyUntypedArray>>,
    colors: Option<&Bound<'py, PyUntypedArray>>,
    color_material: Option<&str>,
    color_material_face: &str,
    normalize: bool,
    rescale_normal: bool,
    cull: &str,
    background: PyReadonlyArray1<'py, f64>,
) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyAny>)> {
    let call = Call {
        scene: scene_from(
            &lights,
            &material,
            &back_material,
            &global_ambient,
            &viewer,
            two_side,
            separate_specular,
            specular,
            specular_gate,
        )?,
        camera: Camera {
            view: matrix(&view, "view")?,
            projection: matrix(&projection, "projection")?,
        },
        options: RenderOptions {
            viewport: Viewport { width, height },
            shading: Shading::parse(shading).map_err(to_pyerr)?,
            cull: Cull::parse(cull).map_err(to_pyerr)?,
            model: matrix(&model, "model")?,
            background: vec4(&background, "background")?,
            normalize,
            rescale_normal,
            color_material: color_material
                .map(|mode| ColorMaterial::parse(mode, color_material_face))
                .transpose()
                .map_err(to_pyerr)?,
        },
    };
    match float_of(py, vertices, "vertices")? {
        Float::F32 => render_typed::<f32>(py, &call, vertices, &faces, normals, colors),
        Float::F64 => render_typed::<f64>(py, &call, vertices, &faces, normals, colors),
    }
}
