//! Face and vertex normals of triangle meshes, matching trimesh (angle weighting, its default),
//! Open3D (area weighting) and trimesh's `mean_vertex_normals` (uniform weighting).
//!
//! Vertex normals are a *gather*: every vertex sums the contributions of its faces in face order
//! through a vertex-to-face adjacency, so results are identical for any number of threads.

use rayon::prelude::*;

use crate::error::Error;
use crate::real::{normalize_and_length, normalize_or_zero, Real, Vector3};

/// Rows per parallel task for the per-face and per-vertex loops.
const ROWS_PER_TASK: usize = 4096;

/// A face is degenerate when the sine of the angle between its first two edges is at most this
/// many ulp of the dtype: its cross product is rounding noise, with no direction. The test is
/// relative, so it does not depend on the mesh's scale (trimesh's |cross| <= 1e-13 does).
const DEGENERATE_ULPS: f64 = 8.0;

/// A vertex's contributions cancel when their sum is at most this many ulp of the sum of their
/// magnitudes: what is left is rounding noise, with no direction.
const CANCELLED_ULPS: f64 = 8.0;

/// trimesh's `tol.merge`: a face with a corner angle below 1e-8 rad gets angle weight 0.
const MIN_CORNER_ANGLE: f64 = 1e-8;

/// How the face normals around a vertex are weighted.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Weighting {
    /// The unit face normals weighted by the corner angle at the vertex (trimesh's default).
    #[default]
    Angle,
    /// The unnormalised face cross products, i.e. weighted by twice the area (Open3D).
    Area,
    /// The unit face normals, unweighted (trimesh's `mean_vertex_normals`).
    Uniform,
}

impl Weighting {
    /// Parses `"angle"`, `"area"` or `"uniform"`.
    ///
    /// # Errors
    /// A value error naming `weighting` for any other string.
    pub fn parse(name: &str) -> Result<Self, Error> {
        match name {
            "angle" => Ok(Self::Angle),
            "area" => Ok(Self::Area),
            "uniform" => Ok(Self::Uniform),
            _ => Err(Error::value(format!(
                "weighting must be 'angle', 'area' or 'uniform', got '{name}'"
            ))),
        }
    }
}

/// Checks that every index of `faces` names one of `vertex_count` vertices.
///
/// # Errors
/// An index error naming the first bad face, the index and the vertex count.
pub fn check_faces(faces: &[[i64; 3]], vertex_count: usize) -> Result<(), Error> {
    let bound = i64::try_from(vertex_count).unwrap_or(i64::MAX);
    if let Some((f, &v)) = faces
        .iter()
        .enumerate()
        .find_map(|(f, face)| face.iter().find(|&&v| v < 0 || v >= bound).map(|v| (f, v)))
    {
        let why = if v < 0 {
            "negative indices are not allowed"
        } else {
            "out of range"
        };
        return Err(Error::index(format!(
            "face {f} refers to vertex {v} ({why}), but there are only {vertex_count} vertices"
        )));
    }
    Ok(())
}

/// A vertex index that [`check_faces`] has proven to be in `0..vertex_count`.
#[inline]
#[allow(clippy::cast_sign_loss)]
fn index(v: i64) -> usize {
    v as usize
}

/// The corners of a checked face as vectors.
#[inline]
fn corners<T: Real>(vertices: &[[T; 3]], face: [i64; 3]) -> [T::Vec3; 3] {
    face.map(|i| T::Vec3::from_array(vertices[index(i)]))
}

/// trimesh's cross product, (v1 − v0) × (v2 − v1): the same bits as `triangles.cross`.
#[inline]
fn cross<T: Real>([a, b, c]: [T::Vec3; 3]) -> T::Vec3 {
    let (e0, e1) = (b - a, c - b);
    let [x0, y0, z0] = e0.to_array();
    let [x1, y1, z1] = e1.to_array();
    T::Vec3::from_array([y0 * z1 - z0 * y1, z0 * x1 - x0 * z1, x0 * y1 - y0 * x1])
}

/// The unit normal of a triangle, or zero when it is degenerate (see [`DEGENERATE_ULPS`]).
#[inline]
fn unit_normal<T: Real>(tri: [T::Vec3; 3]) -> T::Vec3 {
    let (unit, length) = normalize_and_length::<T>(cross::<T>(tri));
    let (_, e0) = normalize_and_length::<T>(tri[1] - tri[0]);
    let (_, e1) = normalize_and_length::<T>(tri[2] - tri[1]);
    // |e0 × e1| = |e0||e1| sin θ; compared in f64 so the product of two lengths cannot overflow.
    if length.to_f64() <= DEGENERATE_ULPS * T::EPSILON.to_f64() * e0.to_f64() * e1.to_f64() {
        return T::Vec3::ZERO;
    }
    unit
}

/// trimesh's corner angles: arccos of the unit edges' dot products for corners 0 and 1, π minus
/// both for corner 2, and all three zero when any is below [`MIN_CORNER_ANGLE`].
#[inline]
fn corner_angles<T: Real>([a, b, c]: [T::Vec3; 3]) -> [f64; 3] {
    let u = normalize_or_zero::<T>(b - a);
    let v = normalize_or_zero::<T>(c - a);
    let w = normalize_or_zero::<T>(c - b);
    let a0 = u.dot(v).to_f64().clamp(-1.0, 1.0).acos();
    let a1 = (-u).dot(w).to_f64().clamp(-1.0, 1.0).acos();
    let angles = [a0, a1, std::f64::consts::PI - a0 - a1];
    if angles.iter().any(|&x| x < MIN_CORNER_ANGLE) {
        [0.0; 3]
    } else {
        angles
    }
}

/// Writes the unit normal of every face into `out` (one row per face); degenerate faces get
/// (0, 0, 0).
///
/// # Errors
/// An index error from [`check_faces`], or a value error when `out` does not have one row per
/// face.
pub fn face_normals<T: Real>(
    vertices: &[[T; 3]],
    faces: &[[i64; 3]],
    out: &mut [[T; 3]],
) -> Result<(), Error> {
    check_faces(faces, vertices.len())?;
    if out.len() != faces.len() {
        return Err(Error::value(format!(
            "out must have {} rows, got {}",
            faces.len(),
            out.len()
        )));
    }
    out.par_chunks_mut(ROWS_PER_TASK)
        .zip(faces.par_chunks(ROWS_PER_TASK))
        .for_each(|(dst, src)| {
            for (d, &face) in dst.iter_mut().zip(src) {
                *d = unit_normal::<T>(corners::<T>(vertices, face)).to_array();
            }
        });
    Ok(())
}

/// The vertex-to-face adjacency in compressed-sparse-row form: the face corners of vertex `v`
/// are `corners[offsets[v]..offsets[v + 1]]`, each `3·face + corner`, in increasing face order.
struct Adjacency {
    offsets: Vec<usize>,
    corners: Vec<usize>,
}

impl Adjacency {
    /// A counting sort of the corners by vertex: stable, so each vertex lists its faces in order.
    fn new(faces: &[[i64; 3]], vertex_count: usize) -> Self {
        let mut offsets = vec![0usize; vertex_count + 1];
        for &v in faces.as_flattened() {
            offsets[index(v) + 1] += 1;
        }
        for i in 0..vertex_count {
            offsets[i + 1] += offsets[i];
        }
        let mut next = offsets[..vertex_count].to_vec();
        let mut corners = vec![0usize; offsets[vertex_count]];
        for (k, &v) in faces.as_flattened().iter().enumerate() {
            corners[next[index(v)]] = k;
            next[index(v)] += 1;
        }
        Self { offsets, corners }
    }
}

/// Writes the normal of every vertex into `out` (one row per vertex): the normalised sum of its
/// faces' contributions under `weighting`, or (0, 0, 0) for a vertex that no face uses, whose
/// faces are all degenerate, or whose contributions cancel (see [`CANCELLED_ULPS`]). Sums run in
/// `f64` in face order.
///
/// # Errors
/// An index error from [`check_faces`], or a value error when `out` does not have one row per
/// vertex.
pub fn vertex_normals<T: Real>(
    vertices: &[[T; 3]],
    faces: &[[i64; 3]],
    weighting: Weighting,
    out: &mut [[T; 3]],
) -> Result<(), Error> {
    check_faces(faces, vertices.len())?;
    if out.len() != vertices.len() {
        return Err(Error::value(format!(
            "out must have {} rows, got {}",
            vertices.len(),
            out.len()
        )));
    }
    // Per face: the vector that is summed, and per corner its weight.
    let mut vectors = vec![[0.0f64; 3]; faces.len()];
    let mut weights = vec![[1.0f64; 3]; faces.len()];
    vectors
        .par_chunks_mut(ROWS_PER_TASK)
        .zip(weights.par_chunks_mut(ROWS_PER_TASK))
        .zip(faces.par_chunks(ROWS_PER_TASK))
        .for_each(|((vs, ws), fs)| {
            for ((v, w), &face) in vs.iter_mut().zip(ws.iter_mut()).zip(fs) {
                let tri = corners::<T>(vertices, face);
                let vector = match weighting {
                    Weighting::Area => cross::<T>(tri),
                    Weighting::Angle | Weighting::Uniform => unit_normal::<T>(tri),
                };
                *v = vector.to_array().map(T::to_f64);
                if weighting == Weighting::Angle {
                    *w = corner_angles::<T>(tri);
                }
            }
        });
    let adjacency = Adjacency::new(faces, vertices.len());
    let weights = weights.as_flattened();
    out.par_chunks_mut(ROWS_PER_TASK)
        .enumerate()
        .for_each(|(t, dst)| {
            for (j, d) in dst.iter_mut().enumerate() {
                let v = t * ROWS_PER_TASK + j;
                let (mut sum, mut magnitude) = (glam::DVec3::ZERO, 0.0);
                for &k in &adjacency.corners[adjacency.offsets[v]..adjacency.offsets[v + 1]] {
                    let term = glam::DVec3::from_array(vectors[k / 3]) * weights[k];
                    sum += term;
                    magnitude += term.length();
                }
                let cancelled = sum.length() <= CANCELLED_ULPS * T::EPSILON.to_f64() * magnitude;
                *d = if cancelled {
                    [T::ZERO; 3]
                } else {
                    normalize_or_zero::<f64>(sum).to_array().map(T::from_f64)
                };
            }
        });
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cube() -> (Vec<[f64; 3]>, Vec<[i64; 3]>) {
        let v = (0..8)
            .map(|i| {
                [
                    f64::from(i & 1),
                    f64::from((i >> 1) & 1),
                    f64::from((i >> 2) & 1),
                ]
            })
            .collect();
        let f = vec![
            [0, 2, 1],
            [1, 2, 3],
            [4, 5, 6],
            [5, 7, 6],
            [0, 1, 4],
            [1, 5, 4],
            [2, 6, 3],
            [3, 6, 7],
            [0, 4, 2],
            [2, 4, 6],
            [1, 3, 5],
            [3, 7, 5],
        ];
        (v, f)
    }

    #[test]
    fn one_triangle() {
        let v = [[0.0_f32, 0.0, 0.0], [2.0, 0.0, 0.0], [0.0, 3.0, 0.0]];
        let mut out = [[0.0; 3]];
        face_normals(&v, &[[0, 1, 2]], &mut out).unwrap();
        assert_eq!(out, [[0.0, 0.0, 1.0]]);
        let mut vn = [[0.0; 3]; 3];
        vertex_normals(&v, &[[0, 1, 2]], Weighting::Angle, &mut vn).unwrap();
        assert_eq!(vn, [[0.0, 0.0, 1.0]; 3]);
    }

    #[test]
    fn cube_corners_point_along_the_diagonal_with_angle_weighting() {
        let (v, f) = cube();
        let mut vn = vec![[0.0; 3]; 8];
        vertex_normals(&v, &f, Weighting::Angle, &mut vn).unwrap();
        let s = 1.0 / 3f64.sqrt();
        for (i, n) in vn.iter().enumerate() {
            let expected = [(i & 1) as f64, ((i >> 1) & 1) as f64, ((i >> 2) & 1) as f64]
                .map(|x| (2.0 * x - 1.0) * s);
            for k in 0..3 {
                assert!((n[k] - expected[k]).abs() < 1e-15, "vertex {i}: {n:?}");
            }
        }
    }

    #[test]
    fn degenerate_faces_and_unreferenced_vertices_give_zero() {
        let v = [
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [2.0, 0.0, 0.0],
            [5.0, 5.0, 5.0],
        ];
        let mut fnorm = [[9.0; 3]];
        face_normals(&v, &[[0, 1, 2]], &mut fnorm).unwrap();
        assert_eq!(fnorm, [[0.0; 3]]);
        for w in [Weighting::Angle, Weighting::Area, Weighting::Uniform] {
            let mut vn = [[9.0; 3]; 4];
            vertex_normals(&v, &[[0, 1, 2]], w, &mut vn).unwrap();
            assert_eq!(vn, [[0.0; 3]; 4], "{w:?}");
        }
    }

    #[test]
    fn opposite_faces_cancel_to_zero() {
        let v = [[0.0_f64, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
        for w in [Weighting::Angle, Weighting::Area, Weighting::Uniform] {
            let mut vn = [[9.0; 3]; 3];
            vertex_normals(&v, &[[0, 1, 2], [0, 2, 1]], w, &mut vn).unwrap();
            assert_eq!(vn, [[0.0; 3]; 3], "{w:?}");
        }
    }

    #[test]
    fn the_degenerate_test_is_scale_invariant() {
        for scale in [1e-150, 1e-7, 1.0, 1e150] {
            let v = [[0.0, 0.0, 0.0], [scale, 0.0, 0.0], [0.0, scale, 0.0]];
            let mut out = [[0.0; 3]];
            face_normals(&v, &[[0, 1, 2]], &mut out).unwrap();
            assert_eq!(out, [[0.0, 0.0, 1.0]], "scale {scale}");
        }
    }

    #[test]
    fn bad_indices_name_the_face() {
        let v = [[0.0_f64; 3]; 3];
        let mut out = [[0.0; 3]; 3];
        let err =
            vertex_normals(&v, &[[0, 1, 2], [0, 3, 1]], Weighting::Angle, &mut out).unwrap_err();
        assert_eq!(err.kind, crate::ErrorKind::Index);
        assert!(
            err.message.contains("face 1 refers to vertex 3")
                && err.message.contains("only 3 vertices"),
            "{}",
            err.message
        );
        let err = check_faces(&[[0, -1, 2]], 3).unwrap_err();
        assert!(err.message.contains("negative"));
    }

    #[test]
    fn results_do_not_depend_on_the_thread_count() {
        let n = 30_000;
        let v: Vec<[f32; 3]> = (0..n)
            .map(|i| {
                let t = i as f32;
                [t.sin(), (t * 0.7).cos(), (t * 0.13).sin()]
            })
            .collect();
        let m = i64::try_from(n).unwrap();
        let f: Vec<[i64; 3]> = (0..m - 2)
            .map(|i| [i, (i * 7 + 1) % m, (i * 13 + 2) % m])
            .collect();
        let run = |threads| {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap();
            let mut out = vec![[0.0_f32; 3]; n];
            pool.install(|| vertex_normals(&v, &f, Weighting::Angle, &mut out).unwrap());
            out.as_flattened()
                .iter()
                .map(|x| x.to_bits())
                .collect::<Vec<_>>()
        };
        assert_eq!(run(1), run(4));
    }
}
