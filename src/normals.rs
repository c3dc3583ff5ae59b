//! Face and vertex normals of triangle meshes, matching trimesh (angle weighting, its default),
//! Open3D (area weighting) and trimesh's `mean_vertex_normals` (uniform weighting).
//!
//! Vertex normals are a *gather*: every vertex sums the contributions of its faces in face order
//! through a vertex-to-face adjacency, so results are identical for any number of threads.
//!
//! All geometry runs in `f64`, also for `f32` vertices (widening is exact), as trimesh computes;
//! only the degeneracy and cancellation thresholds depend on the dtype, and results are rounded
//! to it once, at the end.
//!
//! The normals layer: [`adjacency`] (the vertex-to-face gather, which the renderer reuses) and
//! [`triangle`] (one triangle's geometry) below this module's entry points. Uses
//! [`crate::numbers`], [`crate::simd`], [`crate::memory`] and [`crate::errors`].

pub mod adjacency;
pub mod crease;
pub mod triangle;

use glam::DVec3;
use rayon::prelude::*;

use crate::errors::error::Error;
use crate::errors::stop::Stop;
use crate::memory::pages::Zeroed;
use crate::normals::adjacency::{index, Adjacency};
use crate::normals::triangle::{corner_weights, cross, face_normal, normal_and_cosines};
use crate::numbers::real::{normalize_and_length, Real};

/// Rows per parallel task for the per-face and per-vertex loops.
const ROWS_PER_TASK: usize = 4096;

/// Faces per block of the angle pass, which computes a block's cosines first and their arccos
/// next: the arccos calls of neighbouring faces then overlap instead of each waiting on its
/// face's square roots and divisions.
const FACES_PER_BLOCK: usize = 256;

/// A vertex's contributions cancel when their sum is at most this many ulp of the sum of their
/// magnitudes: what is left is rounding noise, with no direction.
const CANCELLED_ULPS: f64 = 8.0;

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
    let bad = |v: &i64| *v < 0 || *v >= bound;
    let Some(f) = faces
        .par_chunks(ROWS_PER_TASK)
        .enumerate()
        .find_map_first(|(t, chunk)| {
            let first = chunk.iter().position(|face| face.iter().any(bad))?;
            Some(t * ROWS_PER_TASK + first)
        })
    else {
        return Ok(());
    };
    let v = faces[f].into_iter().find(bad).unwrap_or_default();
    let why = if v < 0 {
        "negative indices are not allowed"
    } else {
        "out of range"
    };
    Err(Error::index(format!(
        "face {f} refers to vertex {v} ({why}), but there are only {vertex_count} vertices"
    )))
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

/// The corners of a checked face, widened to `f64`.
#[inline]
fn corners<T: Real>(vertices: &[[T; 3]], face: [i64; 3]) -> [DVec3; 3] {
    face.map(|i| DVec3::from_array(vertices[index(i)].map(T::to_f64)))
}

/// Writes the unit normal of every face into `out` (one row per face); degenerate faces get
/// (0, 0, 0). `stop` is polled before every task of `ROWS_PER_TASK` (4096) faces.
///
/// # Errors
/// An index error for an index outside the vertices, a value error when `out` does not have
/// one row per face, or [`Error::interrupted`] when `stop` was requested before the call finished.
pub fn face_normals<T: Real>(
    vertices: &[[T; 3]],
    faces: &[[i64; 3]],
    out: &mut [[T; 3]],
    stop: &Stop,
) -> Result<(), Error> {
    check_faces(faces, vertices.len())?;
    check_rows(out, faces.len())?;
    let epsilon = T::EPSILON.to_f64();
    out.par_chunks_mut(ROWS_PER_TASK)
        .zip(faces.par_chunks(ROWS_PER_TASK))
        .for_each(|(dst, src)| {
            if stop.is_requested() {
                return;
            }
            for (d, &face) in dst.iter_mut().zip(src) {
                let normal = face_normal(corners(vertices, face), epsilon);
                *d = normal.to_array().map(T::from_f64);
            }
        });
    stop.check()
}

/// What the faces add to their vertices, one entry per face. The buffers are fresh on every
/// call, so their size is paid in page faults: 24 to 48 bytes a face.
pub(crate) enum FaceTerms {
    /// Area weighting: the raw cross product and its length.
    Area(Zeroed<[f64; 4]>),
    /// Uniform weighting: the unit normals (zero if degenerate).
    Uniform(Zeroed<[f64; 3]>),
    /// Angle weighting: the unit normals (zero if degenerate) and the weights of the three
    /// corners, in two buffers (each under the heap's 32 MiB up to 1.4·10^6 faces).
    Angle(Zeroed<[f64; 3]>, Zeroed<[f64; 3]>),
}

impl FaceTerms {
    /// The terms of every face, polling `stop` per task.
    ///
    /// # Errors
    /// A memory error for the buffers, or [`Error::interrupted`].
    pub(crate) fn new<T: Real>(
        vertices: &[[T; 3]],
        faces: &[[i64; 3]],
        weighting: Weighting,
        stop: &Stop,
    ) -> Result<Self, Error> {
        let epsilon = T::EPSILON.to_f64();
        Ok(match weighting {
            Weighting::Area => Self::Area(per_face(faces, stop, |face| {
                let [a, b, c] = corners(vertices, face);
                let v = cross(b - a, c - b);
                [v.x, v.y, v.z, v.length()]
            })?),
            Weighting::Uniform => Self::Uniform(per_face(faces, stop, |face| {
                face_normal(corners(vertices, face), epsilon).to_array()
            })?),
            Weighting::Angle => angle_terms(vertices, faces, epsilon, stop)?,
        })
    }
}

/// `term(face)` for every face, in parallel, into a fresh buffer; tasks that start after `stop`
/// is requested are skipped.
///
/// # Errors
/// A memory error for the buffer, or [`Error::interrupted`].
fn per_face<R, F>(faces: &[[i64; 3]], stop: &Stop, term: F) -> Result<Zeroed<R>, Error>
where
    R: bytemuck::Pod + Send,
    F: Fn([i64; 3]) -> R + Sync,
{
    let mut terms = Zeroed::new(faces.len(), "the face terms")?;
    terms
        .par_chunks_mut(ROWS_PER_TASK)
        .zip(faces.par_chunks(ROWS_PER_TASK))
        .for_each(|(dst, src)| {
            if stop.is_requested() {
                return;
            }
            for (d, &face) in dst.iter_mut().zip(src) {
                *d = term(face);
            }
        });
    stop.check()?;
    Ok(terms)
}

/// Per face, the unit normal and the angle weights of its corners (see [`corner_weights`]), as
/// [`FaceTerms::Angle`].
///
/// # Errors
/// A memory error for the buffers, or [`Error::interrupted`].
fn angle_terms<T: Real>(
    vertices: &[[T; 3]],
    faces: &[[i64; 3]],
    epsilon: f64,
    stop: &Stop,
) -> Result<FaceTerms, Error> {
    let mut normals = Zeroed::<[f64; 3]>::new(faces.len(), "the face normals")?;
    let mut weights = Zeroed::<[f64; 3]>::new(faces.len(), "the corner weights")?;
    normals
        .par_chunks_mut(ROWS_PER_TASK)
        .zip(weights.par_chunks_mut(ROWS_PER_TASK))
        .zip(faces.par_chunks(ROWS_PER_TASK))
        .for_each(|((dn, dw), src)| {
            if stop.is_requested() {
                return;
            }
            for ((dn, dw), src) in dn
                .chunks_mut(FACES_PER_BLOCK)
                .zip(dw.chunks_mut(FACES_PER_BLOCK))
                .zip(src.chunks(FACES_PER_BLOCK))
            {
                for ((n, w), &face) in dn.iter_mut().zip(dw.iter_mut()).zip(src) {
                    let (normal, [c0, c1]) = normal_and_cosines(corners(vertices, face), epsilon);
                    *n = normal.to_array();
                    *w = [c0, c1, 0.0];
                }
                for (n, w) in dn.iter().zip(dw.iter_mut()) {
                    *w = corner_weights(*n == [0.0; 3], [w[0], w[1]]);
                }
            }
        });
    stop.check()?;
    Ok(FaceTerms::Angle(normals, weights))
}

/// Writes the normal of every vertex into `out` (one row per vertex): the normalised sum of its
/// faces' contributions under `weighting`, or (0, 0, 0) for a vertex that no face uses, whose
/// faces are all degenerate, or whose contributions cancel (`CANCELLED_ULPS`, 8 ulp). Sums run in
/// `f64` in face order. `stop` is polled before every task of `ROWS_PER_TASK` (4096) faces or
/// vertices, and in the sequential adjacency build.
///
/// # Errors
/// An index error for an index outside the vertices, a value error when `out` does not have
/// one row per vertex or there are more faces than the adjacency can hold (`u32::MAX / 3`), a
/// memory error when the scratch buffers (24 to 60 bytes a face) cannot be allocated, or
/// [`Error::interrupted`] when `stop` was requested before the call finished.
pub fn vertex_normals<T: Real>(
    vertices: &[[T; 3]],
    faces: &[[i64; 3]],
    weighting: Weighting,
    out: &mut [[T; 3]],
    stop: &Stop,
) -> Result<(), Error> {
    check_rows(out, vertices.len())?;
    let (adjacency, terms) = adjacency_and_terms(vertices, faces, weighting, stop)?;
    let cancel = CANCELLED_ULPS * T::EPSILON.to_f64();
    // Corner `k` (`3·face + corner`) adds a vector and its length to its vertex.
    match &terms {
        FaceTerms::Area(cross) => {
            let cross: &[[f64; 4]] = cross;
            gather(&adjacency, cancel, out, stop, |k| {
                let [x, y, z, length] = cross[k / 3];
                (DVec3::new(x, y, z), length)
            });
        }
        FaceTerms::Uniform(normals) => {
            let normals: &[[f64; 3]] = normals;
            gather(&adjacency, cancel, out, stop, |k| {
                let v = DVec3::from_array(normals[k / 3]);
                (v, if v == DVec3::ZERO { 0.0 } else { 1.0 })
            });
        }
        FaceTerms::Angle(normals, weights) => {
            let (normals, weights): (&[[f64; 3]], &[[f64; 3]]) = (normals, weights);
            gather(&adjacency, cancel, out, stop, |k| {
                let (normal, weight) = (normals[k / 3], weights[k / 3][k % 3]);
                (DVec3::from_array(normal) * weight, weight)
            });
        }
    }
    stop.check()
}

/// The vertex-to-face adjacency of checked `faces` and their terms under `weighting`, built
/// side by side (the adjacency's counting sort is sequential).
///
/// # Errors
/// An index error for an index outside the vertices, a value error for more faces than the
/// adjacency holds, a memory error, or [`Error::interrupted`].
fn adjacency_and_terms<T: Real>(
    vertices: &[[T; 3]],
    faces: &[[i64; 3]],
    weighting: Weighting,
    stop: &Stop,
) -> Result<(Adjacency, FaceTerms), Error> {
    check_faces(faces, vertices.len())?;
    if faces.len() > Adjacency::MAX_FACES {
        return Err(Error::value(format!(
            "faces must have at most {} rows, got {}",
            Adjacency::MAX_FACES,
            faces.len()
        )));
    }
    let (adjacency, terms) = rayon::join(
        || Adjacency::new(faces, vertices.len(), stop),
        || FaceTerms::new(vertices, faces, weighting, stop),
    );
    Ok((adjacency?, terms?))
}

/// Writes the normalised sum of every vertex's corner terms into `out` (one row per vertex), or
/// zero where the sum is at most `cancel` times the sum of the terms' lengths; tasks that start
/// after `stop` is requested are skipped.
fn gather<T, F>(adjacency: &Adjacency, cancel: f64, out: &mut [[T; 3]], stop: &Stop, corner: F)
where
    T: Real,
    F: Fn(usize) -> (DVec3, f64) + Sync,
{
    out.par_chunks_mut(ROWS_PER_TASK)
        .enumerate()
        .for_each(|(t, dst)| {
            if stop.is_requested() {
                return;
            }
            for (j, d) in dst.iter_mut().enumerate() {
                let (mut sum, mut magnitude) = (DVec3::ZERO, 0.0);
                for &k in adjacency.corners_of(t * ROWS_PER_TASK + j) {
                    let (term, length) = corner(k as usize);
                    sum += term;
                    magnitude += length;
                }
                *d = unit_or_zero(sum, magnitude, cancel);
            }
        });
}

/// `sum` normalised and rounded to `T`, or zero where its length is at most `cancel` times
/// `magnitude` (the sum of its terms' lengths): what is left is rounding noise, with no
/// direction.
#[inline]
fn unit_or_zero<T: Real>(sum: DVec3, magnitude: f64, cancel: f64) -> [T; 3] {
    let (unit, length) = normalize_and_length::<f64>(sum);
    if length <= cancel * magnitude {
        [T::ZERO; 3]
    } else {
        unit.to_array().map(T::from_f64)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A unit cube of 12 faces, counter-clockwise seen from outside.
    pub(crate) fn cube() -> (Vec<[f64; 3]>, Vec<[i64; 3]>) {
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
        face_normals(&v, &[[0, 1, 2]], &mut out, &Stop::new()).unwrap();
        assert_eq!(out, [[0.0, 0.0, 1.0]]);
        let mut vn = [[0.0; 3]; 3];
        vertex_normals(&v, &[[0, 1, 2]], Weighting::Angle, &mut vn, &Stop::new()).unwrap();
        assert_eq!(vn, [[0.0, 0.0, 1.0]; 3]);
    }

    #[test]
    fn cube_corners_point_along_the_diagonal_with_angle_weighting() {
        let (v, f) = cube();
        let mut vn = vec![[0.0; 3]; 8];
        vertex_normals(&v, &f, Weighting::Angle, &mut vn, &Stop::new()).unwrap();
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
        face_normals(&v, &[[0, 1, 2]], &mut fnorm, &Stop::new()).unwrap();
        assert_eq!(fnorm, [[0.0; 3]]);
        for w in [Weighting::Angle, Weighting::Area, Weighting::Uniform] {
            let mut vn = [[9.0; 3]; 4];
            vertex_normals(&v, &[[0, 1, 2]], w, &mut vn, &Stop::new()).unwrap();
            assert_eq!(vn, [[0.0; 3]; 4], "{w:?}");
        }
    }

    #[test]
    fn opposite_faces_cancel_to_zero() {
        let v = [[0.0_f64, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
        for w in [Weighting::Angle, Weighting::Area, Weighting::Uniform] {
            let mut vn = [[9.0; 3]; 3];
            vertex_normals(&v, &[[0, 1, 2], [0, 2, 1]], w, &mut vn, &Stop::new()).unwrap();
            assert_eq!(vn, [[0.0; 3]; 3], "{w:?}");
        }
    }

    #[test]
    fn the_degenerate_test_is_scale_invariant() {
        for scale in [1e-150, 1e-7, 1.0, 1e150] {
            let v = [[0.0, 0.0, 0.0], [scale, 0.0, 0.0], [0.0, scale, 0.0]];
            let mut out = [[0.0; 3]];
            face_normals(&v, &[[0, 1, 2]], &mut out, &Stop::new()).unwrap();
            assert_eq!(out, [[0.0, 0.0, 1.0]], "scale {scale}");
        }
    }

    #[test]
    fn bad_indices_name_the_face() {
        let v = [[0.0_f64; 3]; 3];
        let mut out = [[0.0; 3]; 3];
        let err = vertex_normals(
            &v,
            &[[0, 1, 2], [0, 3, 1]],
            Weighting::Angle,
            &mut out,
            &Stop::new(),
        )
        .unwrap_err();
        assert_eq!(err.kind, crate::errors::error::ErrorKind::Index);
        assert!(
            err.message.contains("face 1 refers to vertex 3")
                && err.message.contains("only 3 vertices"),
            "{}",
            err.message
        );
        let err = check_faces(&[[0, -1, 2]], 3).unwrap_err();
        assert!(err.message.contains("negative"));
    }

    /// Every normal of a scrambled mesh, as bits, computed on a pool of `threads` threads.
    fn normals_on<T: Real>(
        threads: usize,
        v: &[[T; 3]],
        f: &[[i64; 3]],
        weighting: Option<Weighting>,
    ) -> Vec<u64> {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        let rows = if weighting.is_some() {
            v.len()
        } else {
            f.len()
        };
        let mut out = vec![[T::ZERO; 3]; rows];
        pool.install(|| match weighting {
            Some(w) => vertex_normals(v, f, w, &mut out, &Stop::new()),
            None => face_normals(v, f, &mut out, &Stop::new()),
        })
        .unwrap();
        out.as_flattened()
            .iter()
            .map(|x| x.to_f64().to_bits())
            .collect()
    }

    fn thread_count_does_not_matter<T: Real>() {
        // 100,000 faces: several tasks per thread.
        let n = 40_000_u32;
        let v: Vec<[T; 3]> = (0..n)
            .map(|i| {
                let t = f64::from(i);
                [t.sin(), (t * 0.7).cos(), (t * 0.13).sin()].map(T::from_f64)
            })
            .collect();
        let m = i64::from(n);
        let f: Vec<[i64; 3]> = (0..100_000)
            .map(|i| [i % m, (i * 7 + 1) % m, (i * 13 + 2) % m])
            .collect();
        for weighting in [
            None,
            Some(Weighting::Angle),
            Some(Weighting::Area),
            Some(Weighting::Uniform),
        ] {
            let one = normals_on(1, &v, &f, weighting);
            for threads in [2, 3] {
                assert!(
                    one == normals_on(threads, &v, &f, weighting),
                    "{weighting:?} on {threads} threads"
                );
            }
        }
    }

    #[test]
    fn results_do_not_depend_on_the_thread_count() {
        thread_count_does_not_matter::<f32>();
        thread_count_does_not_matter::<f64>();
    }
}
