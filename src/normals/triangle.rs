//! The geometry of one triangle, in `f64`: trimesh's face normal, with a relative test for
//! degenerate faces, and trimesh's corner angles.

use glam::DVec3;

use crate::numbers::real::{normalize_and_length, normalize_or_zero};
use crate::simd::float::{exponent, ldexp};

/// A face is degenerate when the sine of the angle between its first two edges is at most this
/// many ulp of the dtype: at its precision the cross product is rounding noise. The test is
/// relative, so it does not depend on the mesh's scale (trimesh's |cross| <= 1e-13 does).
const DEGENERATE_ULPS: f64 = 8.0;

/// trimesh's `tol.merge`: a face with a corner angle below 1e-8 rad gets angle weight 0.
const MIN_CORNER_ANGLE: f64 = 1e-8;

/// True when `x = e·e` is a normal, finite number: then `sqrt(x)` is the length of `e` to half an
/// ulp, and the product of two such lengths neither overflows nor underflows.
#[inline]
fn in_range(x: f64) -> bool {
    (f64::MIN_POSITIVE..=f64::MAX).contains(&x)
}

/// trimesh's cross product, (v1 − v0) × (v2 − v1), from those two edges: the same bits as
/// `triangles.cross`.
#[inline]
pub(crate) fn cross(e0: DVec3, e1: DVec3) -> DVec3 {
    DVec3::new(
        e0.y * e1.z - e0.z * e1.y,
        e0.z * e1.x - e0.x * e1.z,
        e0.x * e1.y - e0.y * e1.x,
    )
}

/// Whether a face is degenerate for a dtype of machine epsilon `epsilon` (see
/// [`DEGENERATE_ULPS`]), from the lengths of its cross product and of its first two edges.
#[inline]
fn degenerate(cross_length: f64, l0: f64, l1: f64, epsilon: f64) -> bool {
    // |e0 × e1| = |e0||e1| sin θ; the small factor first, so the product overflows only for
    // edges beyond 1e161.
    cross_length <= DEGENERATE_ULPS * epsilon * l0 * l1
}

/// `e` times the power of two that brings its largest |component| into [1, 2) (exact; `e`
/// itself when zero).
fn prescaled(e: DVec3) -> DVec3 {
    let top = e.abs().max_element();
    if top > 0.0 && top.is_finite() {
        e.map(|x| ldexp(x, -exponent(top)))
    } else {
        e
    }
}

/// The normal of a face some of whose squared lengths leave the normal range: the edges
/// scaled by exact powers of two first, so their cross product neither over- nor underflows
/// (edges beyond 1e154 made it infinite, the normal NaN), and each length rescaled likewise
/// (see [`normalize_and_length`]). Both scalings leave the direction's bits and the
/// degeneracy test as they were wherever the unscaled products were in range.
#[cold]
fn normal_rescaled(e0: DVec3, e1: DVec3, epsilon: f64) -> DVec3 {
    let (e0, e1) = (prescaled(e0), prescaled(e1));
    let (unit, length) = normalize_and_length::<f64>(cross(e0, e1));
    let (l0, l1) = (
        normalize_and_length::<f64>(e0).1,
        normalize_and_length::<f64>(e1).1,
    );
    if degenerate(length, l0, l1, epsilon) {
        DVec3::ZERO
    } else {
        unit
    }
}

/// trimesh's unit normal of a triangle, or zero when it is degenerate.
#[inline]
pub(crate) fn face_normal([a, b, c]: [DVec3; 3], epsilon: f64) -> DVec3 {
    let (e0, e1) = (b - a, c - b);
    let n = cross(e0, e1);
    let squares = [e0.dot(e0), e1.dot(e1), n.dot(n)];
    if !squares.into_iter().all(in_range) {
        return normal_rescaled(e0, e1, epsilon);
    }
    // Independent square roots, which the compiler pairs.
    let [l0, l1, length] = squares.map(f64::sqrt);
    if degenerate(length, l0, l1, epsilon) {
        DVec3::ZERO
    } else {
        n / length
    }
}

/// A triangle's unit normal (that of [`face_normal`], to the bit) and the cosines of its first
/// two corner angles, clipped to [−1, 1] as trimesh does before its arccos.
///
/// Each cosine is the edges' dot product over the product of their lengths: trimesh's dot
/// product of unit edges to a few ulp, for two divisions instead of nine. Squared lengths out of
/// range take the rescaling path and trimesh's unit edges.
// Measured: called out of line, its edges are spilled to the stack and reloaded across store
// boundaries, and the angle pass takes a third longer.
#[allow(clippy::inline_always)]
#[inline(always)]
pub(crate) fn normal_and_cosines([a, b, c]: [DVec3; 3], epsilon: f64) -> (DVec3, [f64; 2]) {
    let (e0, e1, e2) = (b - a, c - b, c - a);
    let n = cross(e0, e1);
    let squares = [e0.dot(e0), e1.dot(e1), e2.dot(e2), n.dot(n)];
    let (normal, cosines) = if squares.into_iter().all(in_range) {
        // Four independent square roots, which the compiler pairs into two instructions.
        let [l0, l1, l2, length] = squares.map(f64::sqrt);
        let normal = if degenerate(length, l0, l1, epsilon) {
            DVec3::ZERO
        } else {
            n / length
        };
        (normal, [e0.dot(e2) / (l0 * l2), -e0.dot(e1) / (l0 * l1)])
    } else {
        let u = normalize_or_zero::<f64>(e0);
        let (v, w) = (normalize_or_zero::<f64>(e2), normalize_or_zero::<f64>(e1));
        (normal_rescaled(e0, e1, epsilon), [u.dot(v), (-u).dot(w)])
    };
    (normal, cosines.map(|x| x.clamp(-1.0, 1.0)))
}

/// trimesh's angle weights of a face from the cosines of its first two corner angles: the
/// angles, the third being π minus both; all three zero when any is below [`MIN_CORNER_ANGLE`],
/// or when the face is degenerate (its contributions have no direction and no length).
#[inline]
pub(crate) fn corner_weights(degenerate: bool, [c0, c1]: [f64; 2]) -> [f64; 3] {
    if degenerate {
        return [0.0; 3];
    }
    let (a0, a1) = (c0.acos(), c1.acos());
    let angles = [a0, a1, std::f64::consts::PI - a0 - a1];
    if angles.iter().any(|&x| x < MIN_CORNER_ANGLE) {
        [0.0; 3]
    } else {
        angles
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const TRIANGLES: [[[f64; 3]; 3]; 4] = [
        [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]],
        [[0.3, -1.2, 2.0], [1.7, 0.4, -0.5], [-0.8, 2.2, 0.9]],
        [
            [1.0, 1.0, 1.0],
            [1.0 + 1e-6, 1.0, 1.0],
            [1.0, 1.0 + 3e-7, 1.0 + 2e-7],
        ],
        [[5.0, 0.0, 0.0], [0.0, 5.0, 0.0], [0.0, 0.0, 5.0]],
    ];

    fn triangle(corners: [[f64; 3]; 3], scale: f64) -> [DVec3; 3] {
        corners.map(|c| DVec3::from_array(c) * scale)
    }

    /// trimesh's cosines: dot products of unit edges.
    fn unit_edge_cosines([a, b, c]: [DVec3; 3]) -> [f64; 2] {
        let (u, v, w) = (
            (b - a).normalize(),
            (c - a).normalize(),
            (c - b).normalize(),
        );
        [u.dot(v), (-u).dot(w)]
    }

    #[test]
    fn cosines_match_the_unit_edge_formula() {
        for corners in TRIANGLES {
            let tri = triangle(corners, 1.0);
            let (_, got) = normal_and_cosines(tri, f64::EPSILON);
            let want = unit_edge_cosines(tri);
            for k in 0..2 {
                assert!(
                    (got[k] - want[k]).abs() <= 4.0 * f64::EPSILON,
                    "{got:?} {want:?}"
                );
            }
        }
    }

    #[test]
    fn cosines_of_tiny_and_huge_triangles_take_the_rescaled_path_and_agree() {
        // Squared edges of about 2^-1080 underflow, of 2^1040 overflow: both leave the fast
        // path; the cross product is formed from prescaled edges there.
        for scale in [2f64.powi(-540), 2f64.powi(520)] {
            for corners in TRIANGLES {
                let (_, c1) = normal_and_cosines(triangle(corners, 1.0), f64::EPSILON);
                let (_, c2) = normal_and_cosines(triangle(corners, scale), f64::EPSILON);
                for k in 0..2 {
                    assert!((c1[k] - c2[k]).abs() <= 4.0 * f64::EPSILON, "{c1:?} {c2:?}");
                }
            }
        }
    }

    #[test]
    fn the_angle_path_has_face_normals_normal_to_the_bit() {
        // Including slivers around the degeneracy threshold (sin θ = 8ε ≈ 1.8e-15).
        let slivers = (0..40).map(|i| {
            [
                [0.0, 0.0, 0.0],
                [1.0, 0.0, 0.0],
                [2.0, 1e-16 * f64::from(i), 0.0],
            ]
        });
        for corners in TRIANGLES.into_iter().chain(slivers) {
            for scale in [1.0, 2f64.powi(-540), 3.0] {
                for epsilon in [f64::EPSILON, f64::from(f32::EPSILON)] {
                    let tri = triangle(corners, scale);
                    let (normal, _) = normal_and_cosines(tri, epsilon);
                    assert_eq!(normal, face_normal(tri, epsilon), "{corners:?} x {scale}");
                }
            }
        }
    }

    #[test]
    fn corner_weights_are_the_angles_or_all_zero() {
        let (_, cosines) = normal_and_cosines(triangle(TRIANGLES[0], 1.0), f64::EPSILON);
        let w = corner_weights(false, cosines);
        let quarter = std::f64::consts::FRAC_PI_4;
        for (got, want) in w.iter().zip([2.0 * quarter, quarter, quarter]) {
            assert!((got - want).abs() <= 4.0 * f64::EPSILON, "{w:?}");
        }
        assert_eq!(corner_weights(true, cosines), [0.0; 3]);
        // A corner angle of 0 (cosine 1) zeroes the whole face, as in trimesh.
        assert_eq!(corner_weights(false, [1.0, 0.0]), [0.0; 3]);
    }

    #[test]
    fn the_degenerate_test_is_relative_to_the_dtype() {
        // sin θ ≈ 1e-9 between the first two edges: rounding noise for f32, a direction for f64.
        let tri = triangle([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [2.0, 1e-9, 0.0]], 1.0);
        assert_eq!(face_normal(tri, f64::from(f32::EPSILON)), DVec3::ZERO);
        assert_eq!(face_normal(tri, f64::EPSILON), DVec3::Z);
    }
}
