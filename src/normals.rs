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

/// Checks that an output has `rows` rows.
fn check_rows<R>(out: &[R], rows: usize) -> Result<(), Error> {
    if out.len() == rows {
        Ok(())
    } else {
        Err(Error::value(format!(
            "out must have {rows} rows, got {}",
            out.len()
        )))
    }
}

/// A vertex index that [`check_faces`] has proven to be in `0..vertex_count`.
#[inline]
#[allow(clippy::cast_sign_loss)]
pub(crate) fn index(v: i64) -> usize {
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

/// A triangle's unit normal (zero when degenerate, see [`DEGENERATE_ULPS`]) and the unit
/// directions of its first two edges, b − a and c − b, which the corner angles reuse.
#[inline]
fn normal_and_edges<T: Real>(tri: [T::Vec3; 3]) -> (T::Vec3, T::Vec3, T::Vec3) {
    let (unit, length) = normalize_and_length::<T>(cross::<T>(tri));
    let (u, l0) = normalize_and_length::<T>(tri[1] - tri[0]);
    let (w, l1) = normalize_and_length::<T>(tri[2] - tri[1]);
    // |e0 × e1| = |e0||e1| sin θ; compared in f64 so the product of two lengths cannot overflow.
    let degenerate =
        length.to_f64() <= DEGENERATE_ULPS * T::EPSILON.to_f64() * l0.to_f64() * l1.to_f64();
    (if degenerate { T::Vec3::ZERO } else { unit }, u, w)
}

/// trimesh's first two corner angles: the arccos of the unit edges' dot products. `u` and `w`
/// are the unit edges b − a and c − b.
#[inline]
fn corner_angles<T: Real>([a, _, c]: [T::Vec3; 3], u: T::Vec3, w: T::Vec3) -> [f64; 2] {
    let v = normalize_or_zero::<T>(c - a);
    let a0 = u.dot(v).to_f64().clamp(-1.0, 1.0).acos();
    let a1 = (-u).dot(w).to_f64().clamp(-1.0, 1.0).acos();
    [a0, a1]
}

/// trimesh's angle weights from the first two corner angles: the third is π minus both, and all
/// three are zero when any is below [`MIN_CORNER_ANGLE`].
#[inline]
fn corner_weights([a0, a1]: [f64; 2]) -> [f64; 3] {
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
    check_rows(out, faces.len())?;
    out.par_chunks_mut(ROWS_PER_TASK)
        .zip(faces.par_chunks(ROWS_PER_TASK))
        .for_each(|(dst, src)| {
            for (d, &face) in dst.iter_mut().zip(src) {
                *d = normal_and_edges::<T>(corners::<T>(vertices, face))
                    .0
                    .to_array();
            }
        });
    Ok(())
}

/// What the faces add to their vertices: per face the vector that is summed (the unit normal,
/// zero if degenerate, or the raw cross product for area weighting) and, for angle weighting,
/// its first two corner angles. 24 or 40 bytes a face: the buffer is written fresh on every
/// call, so its size is paid in page faults.
enum FaceTerms {
    /// Area or uniform weighting: `(vector, unit)`, where `unit` says the vectors are unit normals.
    Vectors(Vec<glam::DVec3>, bool),
    /// Angle weighting: the unit normal and the first two corner angles.
    WithAngles(Vec<(glam::DVec3, [f64; 2])>),
}

impl FaceTerms {
    fn new<T: Real>(vertices: &[[T; 3]], faces: &[[i64; 3]], weighting: Weighting) -> Self {
        let to_f64 = |v: T::Vec3| glam::DVec3::from_array(v.to_array().map(T::to_f64));
        // One exact-length collect per case (rayon's `unzip` would go through linked chunks).
        let each = faces
            .par_iter()
            .with_min_len(ROWS_PER_TASK)
            .map(|&face| corners::<T>(vertices, face));
        match weighting {
            Weighting::Area => {
                Self::Vectors(each.map(|tri| to_f64(cross::<T>(tri))).collect(), false)
            }
            Weighting::Uniform => Self::Vectors(
                each.map(|tri| to_f64(normal_and_edges::<T>(tri).0))
                    .collect(),
                true,
            ),
            Weighting::Angle => Self::WithAngles(
                each.map(|tri| {
                    let (normal, u, w) = normal_and_edges::<T>(tri);
                    (to_f64(normal), corner_angles::<T>(tri, u, w))
                })
                .collect(),
            ),
        }
    }

    /// The term corner `k` (`3·face + corner`) adds to its vertex, and the term's length.
    #[inline]
    fn corner(&self, k: usize) -> (glam::DVec3, f64) {
        match self {
            Self::Vectors(vectors, false) => (vectors[k / 3], vectors[k / 3].length()),
            Self::Vectors(vectors, true) => {
                let v = vectors[k / 3];
                (v, if v == glam::DVec3::ZERO { 0.0 } else { 1.0 })
            }
            Self::WithAngles(terms) => {
                let (normal, angles) = terms[k / 3];
                let weight = corner_weights(angles)[k % 3];
                (normal * weight, weight)
            }
        }
    }
}

/// The vertex-to-face adjacency in compressed-sparse-row form: the face corners of vertex `v`
/// are `corners[offsets[v]..offsets[v + 1]]`, each `3·face + corner`, in increasing face order.
/// `u32` halves the memory traffic of the gather; meshes are limited to 2^32 corners.
struct Adjacency {
    offsets: Vec<u32>,
    corners: Vec<u32>,
}

impl Adjacency {
    /// A counting sort of the corners by vertex: stable, so each vertex lists its faces in order.
    /// `corner_count` is `3 · faces.len()`, which the caller has checked fits in `u32`.
    fn new(faces: &[[i64; 3]], vertex_count: usize, corner_count: u32) -> Self {
        let mut offsets = vec![0u32; vertex_count + 1];
        for &v in faces.as_flattened() {
            offsets[index(v) + 1] += 1;
        }
        for i in 0..vertex_count {
            offsets[i + 1] += offsets[i];
        }
        let mut next = offsets[..vertex_count].to_vec();
        let mut corners = vec![0u32; corner_count as usize];
        for (k, &v) in (0..corner_count).zip(faces.as_flattened()) {
            let slot = &mut next[index(v)];
            corners[*slot as usize] = k;
            *slot += 1;
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
    check_rows(out, vertices.len())?;
    let corner_count = u32::try_from(faces.len() * 3).map_err(|_| {
        Error::value(format!(
            "faces must have at most {} rows, got {}",
            u32::MAX / 3,
            faces.len()
        ))
    })?;
    // The adjacency's counting sort is sequential: build it while the faces are computed.
    let (adjacency, terms) = rayon::join(
        || Adjacency::new(faces, vertices.len(), corner_count),
        || FaceTerms::new(vertices, faces, weighting),
    );
    out.par_chunks_mut(ROWS_PER_TASK)
        .enumerate()
        .for_each(|(t, dst)| {
            for (j, d) in dst.iter_mut().enumerate() {
                let v = t * ROWS_PER_TASK + j;
                let (start, end) = (
                    adjacency.offsets[v] as usize,
                    adjacency.offsets[v + 1] as usize,
                );
                let (mut sum, mut magnitude) = (glam::DVec3::ZERO, 0.0);
                for &k in &adjacency.corners[start..end] {
                    let (term, length) = terms.corner(k as usize);
                    sum += term;
                    magnitude += length;
                }
                let (unit, length) = normalize_and_length::<f64>(sum);
                let cancelled = length <= CANCELLED_ULPS * T::EPSILON.to_f64() * magnitude;
                *d = if cancelled {
                    [T::ZERO; 3]
                } else {
                    unit.to_array().map(T::from_f64)
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
