//! The binding of `face_normals`, `vertex_normals` and `crease_normals`.

use numpy::{Element, PyArrayMethods, PyUntypedArray};
use pyo3::prelude::*;

use super::arrays::{float_of, read, rows, zeros, Float};
use super::faces;
use super::runtime::{run, to_pyerr};
use crate::normals::Weighting;
use crate::numbers::real::Real;

/// Faces above which a call answers Ctrl-C while it runs (see `shading::LONG_CALL`).
const LONG_CALL: usize = 1 << 15;

/// Which normals a call computes.
#[derive(Clone, Copy)]
enum Kind {
    /// One per face.
    Faces,
    /// One per vertex, weighted.
    Vertices(Weighting),
    /// One per face corner, weighted, with creases sharper than an angle (degrees).
    Corners(Weighting, f64),
}

fn normals_typed<'py, T: Element + Real>(
    py: Python<'py>,
    vertices: &Bound<'py, PyUntypedArray>,
    faces: &Bound<'py, PyUntypedArray>,
    kind: Kind,
) -> PyResult<Bound<'py, PyAny>> {
    let vertices = read::<T>(vertices, "vertices")?;
    let v = rows::<T, 3>(&vertices, "vertices")?;
    let f = faces::copy(faces)?;
    let shape = match kind {
        Kind::Faces => vec![f.len(), 3],
        Kind::Vertices(_) => vec![v.len(), 3],
        Kind::Corners(..) => vec![f.len(), 3, 3],
    };
    let array = zeros::<T>(py, &shape)?;
    let mut rw = array.readwrite();
    let out = rw.as_slice_mut()?.as_chunks_mut::<3>().0;
    let f = &f[..];
    run(py, f.len() > LONG_CALL, |stop| match kind {
        Kind::Faces => crate::normals::face_normals(v, f, out, stop),
        Kind::Vertices(w) => crate::normals::vertex_normals(v, f, w, out, stop),
        Kind::Corners(w, angle) => {
            crate::normals::crease::crease_normals(v, f, w, angle, out, stop)
        }
    })?;
    drop(rw);
    Ok(array.into_any())
}

/// The unit normal of every face, (m, 3) of the vertices' dtype; see `glshade.face_normals`.
#[pyfunction]
pub fn face_normals<'py>(
    py: Python<'py>,
    vertices: &Bound<'py, PyUntypedArray>,
    faces: &Bound<'py, PyUntypedArray>,
) -> PyResult<Bound<'py, PyAny>> {
    match float_of(vertices, "vertices")? {
        Float::F32 => normals_typed::<f32>(py, vertices, faces, Kind::Faces),
        Float::F64 => normals_typed::<f64>(py, vertices, faces, Kind::Faces),
    }
}

/// The normal of every vertex, (n, 3) of the vertices' dtype; see `glshade.vertex_normals`.
#[pyfunction]
pub fn vertex_normals<'py>(
    py: Python<'py>,
    vertices: &Bound<'py, PyUntypedArray>,
    faces: &Bound<'py, PyUntypedArray>,
    weighting: &str,
) -> PyResult<Bound<'py, PyAny>> {
    let kind = Kind::Vertices(Weighting::parse(weighting).map_err(to_pyerr)?);
    match float_of(vertices, "vertices")? {
        Float::F32 => normals_typed::<f32>(py, vertices, faces, kind),
        Float::F64 => normals_typed::<f64>(py, vertices, faces, kind),
    }
}

/// One normal per face corner, (m, 3, 3) of the vertices' dtype; see `glshade.crease_normals`.
#[pyfunction]
pub fn crease_normals<'py>(
    py: Python<'py>,
    vertices: &Bound<'py, PyUntypedArray>,
    faces: &Bound<'py, PyUntypedArray>,
    weighting: &str,
    angle: f64,
) -> PyResult<Bound<'py, PyAny>> {
    let kind = Kind::Corners(Weighting::parse(weighting).map_err(to_pyerr)?, angle);
    match float_of(vertices, "vertices")? {
        Float::F32 => normals_typed::<f32>(py, vertices, faces, kind),
        Float::F64 => normals_typed::<f64>(py, vertices, faces, kind),
    }
}
