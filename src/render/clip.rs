//! Clipping of triangles in homogeneous clip coordinates (GL 2.1 §2.12).
//!
//! GL clips against the six planes −w ≤ x, y, z ≤ w. Against the near and far planes this
//! changes which fragments exist (depth clipping), so it is done exactly as GL does. Against the
//! side planes it only bounds window coordinates, since fragments outside the viewport are
//! discarded anyway; here the side planes are pushed out to a guard band |x|, |y| ≤
//! [`GUARD_BAND`]·w, as hardware and llvmpipe do, so that only triangles reaching far outside
//! the viewport are cut and every triangle stays inside the rasteriser's fixed-point range.
//!
//! Every vertex of a clipped polygon carries its barycentric coordinates in the original
//! triangle, so attributes are always interpolated from the original three vertices.

use glam::{DVec3, DVec4};

use crate::simd::float::{exponent, ldexp};

/// The guard band, in units of w (normalised device coordinates): side planes at ±4 keep
/// window coordinates within 2.5 viewports of the origin.
pub const GUARD_BAND: f64 = 4.0;

/// Most vertices a triangle clipped by six planes can have (each plane adds at most one).
pub const MAX_VERTICES: usize = 9;

/// The planes p with p · (x, y, z, w) ≥ 0 inside: near, far, then the guard band.
const PLANES: [DVec4; 6] = [
    DVec4::new(0.0, 0.0, 1.0, 1.0),
    DVec4::new(0.0, 0.0, -1.0, 1.0),
    DVec4::new(1.0, 0.0, 0.0, GUARD_BAND),
    DVec4::new(-1.0, 0.0, 0.0, GUARD_BAND),
    DVec4::new(0.0, 1.0, 0.0, GUARD_BAND),
    DVec4::new(0.0, -1.0, 0.0, GUARD_BAND),
];

/// A vertex of a clipped polygon.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ClipVertex {
    /// Clip coordinates (x, y, z, w).
    pub clip: DVec4,
    /// Barycentric coordinates in the original triangle (they sum to 1).
    pub weights: DVec3,
}

/// A convex polygon of up to [`MAX_VERTICES`] vertices, in the original triangle's order.
#[derive(Clone, Copy, Debug)]
struct Polygon {
    vertices: [ClipVertex; MAX_VERTICES],
    len: usize,
}

impl Polygon {
    fn vertices(&self) -> &[ClipVertex] {
        &self.vertices[..self.len]
    }
}

/// Bit k set when `clip` is outside plane k.
fn outcode(clip: DVec4) -> u8 {
    PLANES
        .iter()
        .enumerate()
        .fold(0, |code, (k, p)| code | (u8::from(p.dot(clip) < 0.0) << k))
}

/// (s, e) with s + e = a + b exactly (Knuth's TwoSum).
#[inline]
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// Σ `terms`, computed exactly as a nonoverlapping expansion (Shewchuk's Grow-Expansion) and
/// rounded from its smallest component up: within an ulp or two of the exact sum, however
/// much the terms cancel.
fn exact_sum<const N: usize>(terms: [f64; N]) -> f64 {
    let mut expansion = [0.0; N];
    for (n, &term) in terms.iter().enumerate() {
        let mut q = term;
        for e in &mut expansion[..n] {
            let (sum, error) = two_sum(q, *e);
            (q, *e) = (sum, error);
        }
        expansion[n] = q;
    }
    expansion.iter().fold(0.0, |sum, &e| sum + e)
}

/// The signed distance `plane · v` as an exact pair (hi, lo): the planes' coefficients are 0,
/// ±1 and 4, so it is the sum of two exact products.
fn distance(plane: DVec4, v: DVec4) -> (f64, f64) {
    let (axis, w) = if plane.x != 0.0 {
        (plane.x * v.x, plane.w * v.w)
    } else if plane.y != 0.0 {
        (plane.y * v.y, plane.w * v.w)
    } else {
        (plane.z * v.z, plane.w * v.w)
    };
    two_sum(axis, w)
}

/// The point where the edge from `inside` to `outside` crosses `plane`; always computed from
/// the inside end, so the two triangles sharing an edge cut it at the same point.
///
/// Each coordinate is (d_in·out − d_out·in)/(d_in − d_out), with the distances, the products
/// and their sums exact before the one division: of a huge triangle (coordinates up to 2^60
/// times the guard band, say), the cut points near the view would otherwise be lost to
/// cancellation (in + (out − in)·t has an error of an ulp of the huge coordinates).
fn crossing(plane: DVec4, inside: ClipVertex, outside: ClipVertex) -> ClipVertex {
    let (in_hi, in_lo) = distance(plane, inside.clip);
    let (out_hi, out_lo) = distance(plane, outside.clip);
    let denominator = exact_sum([in_hi, in_lo, -out_hi, -out_lo]);
    let product = |a: f64, b: f64| {
        let p = a * b;
        [p, a.mul_add(b, -p)]
    };
    let coordinate = |a: f64, b: f64| {
        let [p0, p1] = product(in_hi, b);
        let [p2, p3] = product(in_lo, b);
        let [p4, p5] = product(-out_hi, a);
        let [p6, p7] = product(-out_lo, a);
        exact_sum([p0, p1, p2, p3, p4, p5, p6, p7]) / denominator
    };
    let (a, b) = (inside.clip, outside.clip);
    let t = (in_hi + in_lo) / denominator;
    ClipVertex {
        clip: DVec4::new(
            coordinate(a.x, b.x),
            coordinate(a.y, b.y),
            coordinate(a.z, b.z),
            coordinate(a.w, b.w),
        ),
        weights: inside.weights + (outside.weights - inside.weights) * t,
    }
}

/// `vertices` scaled by one power of two so that the largest |component| of their clip
/// coordinates is in [1, 2): the projected polygon, its depths and its perspective-correct
/// weights (ratios of clip coordinates) are unchanged, and no later product over- or
/// underflows, whatever the triangle's size.
fn rescale(vertices: &mut [ClipVertex]) {
    let top = vertices
        .iter()
        .fold(0.0_f64, |m, v| m.max(v.clip.abs().max_element()));
    if !(top > 0.0 && top.is_finite()) {
        return;
    }
    let k = -exponent(top);
    for v in vertices {
        v.clip = v.clip.map(|x| ldexp(x, k));
    }
}

/// Clips the triangle with clip coordinates `corners` and calls `emit` with each triangle of
/// what is left inside, a fan around the first vertex of the clipped polygon (the triangle
/// itself when wholly inside; nothing when wholly outside or when a coordinate is not finite).
/// The clip coordinates it passes are the triangle's times a power of two (see `rescale`).
pub fn clip_triangle(corners: [DVec4; 3], mut emit: impl FnMut([ClipVertex; 3])) {
    if !corners.iter().all(|c| c.is_finite()) {
        return;
    }
    let weights = [DVec3::X, DVec3::Y, DVec3::Z];
    let mut corners: [ClipVertex; 3] = std::array::from_fn(|i| ClipVertex {
        clip: corners[i],
        weights: weights[i],
    });
    rescale(&mut corners);
    let codes = corners.map(|c| outcode(c.clip));
    if codes == [0; 3] {
        return emit(corners);
    }
    if codes[0] & codes[1] & codes[2] != 0 {
        return;
    }
    let mut polygon = Polygon {
        vertices: [corners[0]; MAX_VERTICES],
        len: 3,
    };
    polygon.vertices[..3].copy_from_slice(&corners);
    let crossed = codes[0] | codes[1] | codes[2];
    for (k, &plane) in PLANES.iter().enumerate() {
        if crossed & (1 << k) == 0 {
            continue;
        }
        let mut next = Polygon {
            vertices: polygon.vertices,
            len: 0,
        };
        let vertices = polygon.vertices();
        for (i, &a) in vertices.iter().enumerate() {
            let b = vertices[(i + 1) % vertices.len()];
            let (a_in, b_in) = (plane.dot(a.clip) >= 0.0, plane.dot(b.clip) >= 0.0);
            if a_in {
                next.vertices[next.len] = a;
                next.len += 1;
            }
            if a_in != b_in {
                next.vertices[next.len] = if a_in {
                    crossing(plane, a, b)
                } else {
                    crossing(plane, b, a)
                };
                next.len += 1;
            }
        }
        if next.len < 3 {
            return;
        }
        polygon = next;
    }
    let len = polygon.len;
    rescale(&mut polygon.vertices[..len]);
    let v = polygon.vertices();
    for i in 1..v.len() - 1 {
        emit([v[0], v[i], v[i + 1]]);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The clipped polygon: the fan's first vertex, then the far vertex of each triangle.
    fn clipped(corners: [DVec4; 3]) -> Vec<ClipVertex> {
        let mut out = Vec::new();
        clip_triangle(corners, |[a, b, c]| {
            if out.is_empty() {
                out.extend([a, b]);
            }
            out.push(c);
        });
        out
    }

    #[test]
    fn a_triangle_inside_is_kept_as_is() {
        let corners = [
            DVec4::new(0.0, 0.0, 0.0, 1.0),
            DVec4::new(1.0, 0.0, 0.5, 1.0),
            DVec4::new(0.0, 1.0, -0.5, 1.0),
        ];
        let v = clipped(corners);
        assert_eq!(v.len(), 3);
        assert_eq!(v[1].clip, corners[1]);
        assert_eq!(v[2].weights, DVec3::Z);
    }

    #[test]
    fn the_near_plane_cuts_one_corner_into_a_quad() {
        // Corner 2 is behind the near plane z = −w; the cut points are where z = −w.
        let corners = [
            DVec4::new(0.0, 0.0, 0.0, 1.0),
            DVec4::new(1.0, 0.0, 0.0, 1.0),
            DVec4::new(0.0, 0.0, -3.0, 1.0),
        ];
        let v = clipped(corners);
        assert_eq!(v.len(), 4);
        for p in &v {
            assert!(p.clip.z >= -p.clip.w - 1e-15);
            assert!((p.weights.element_sum() - 1.0).abs() < 1e-15);
            let from_weights =
                corners[0] * p.weights.x + corners[1] * p.weights.y + corners[2] * p.weights.z;
            assert!((from_weights - p.clip).abs().max_element() < 1e-15);
        }
        assert!(v.iter().any(|p| (p.weights.z - 1.0 / 3.0).abs() < 1e-15));
    }

    #[test]
    fn triangles_outside_one_plane_or_not_finite_are_dropped() {
        let behind = [
            DVec4::new(0.0, 0.0, -2.0, 1.0),
            DVec4::new(1.0, 0.0, -2.0, 1.0),
            DVec4::new(0.0, 1.0, -3.0, 1.0),
        ];
        assert!(clipped(behind).is_empty());
        let nan = [DVec4::new(f64::NAN, 0.0, 0.0, 1.0), DVec4::W, DVec4::W];
        assert!(clipped(nan).is_empty());
    }

    #[test]
    fn every_plane_can_cut() {
        // A huge triangle around the guard band leaves the band's square; one whose depth
        // also crosses the near and far planes is cut by all six.
        let corners = [
            DVec4::new(-100.0, -100.0, 0.0, 1.0),
            DVec4::new(100.0, -100.0, 0.0, 1.0),
            DVec4::new(0.0, 100.0, 0.0, 1.0),
        ];
        let v = clipped(corners);
        assert_eq!(v.len(), 4);
        for p in &v {
            assert_eq!((p.clip / p.clip.w).x.abs(), GUARD_BAND);
            assert_eq!((p.clip / p.clip.w).y.abs(), GUARD_BAND);
        }
        let corners = [
            DVec4::new(-100.0, -100.0, -2.0, 1.0),
            DVec4::new(100.0, -100.0, 2.0, 1.0),
            DVec4::new(0.0, 100.0, 0.0, 1.0),
        ];
        let v = clipped(corners);
        assert_eq!(v.len(), 4);
        for p in &v {
            let c = p.clip;
            assert!(c.x.abs().max(c.y.abs()) <= GUARD_BAND * c.w + 1e-12);
            assert!(c.z.abs() <= c.w + 1e-12);
        }
    }

    #[test]
    fn huge_triangles_are_cut_where_the_small_ones_are() {
        // Enclosing the guard band at any scale: cut to exactly its square, w kept near 1.
        for k in [1, 17, 18, 100, 200, 300] {
            let s = 10f64.powi(k);
            let corners = [
                DVec4::new(-3.0 * s, -3.0 * s, 0.0, 1.0),
                DVec4::new(3.0 * s, -3.0 * s, 0.0, 1.0),
                DVec4::new(0.0, 3.0 * s, 0.0, 1.0),
            ];
            let v = clipped(corners);
            assert_eq!(v.len(), 4, "1e{k}");
            for p in &v {
                let ndc = p.clip / p.clip.w;
                assert_eq!(
                    (ndc.x.abs(), ndc.y.abs()),
                    (GUARD_BAND, GUARD_BAND),
                    "1e{k}"
                );
                assert!(p.clip.abs().max_element() >= 1.0 && p.clip.abs().max_element() < 2.0);
            }
            // An edge along y = x/2 through the view stays there.
            let corners = [
                DVec4::new(-s, -0.5 * s, 0.0, 1.0),
                DVec4::new(s, 0.5 * s, 0.0, 1.0),
                DVec4::new(s, -s, 0.0, 1.0),
            ];
            for p in clipped(corners) {
                let ndc = p.clip / p.clip.w;
                let on_edge = (ndc.y - 0.5 * ndc.x).abs() <= 1e-15;
                let on_band = ndc.x.abs().max(ndc.y.abs()) == GUARD_BAND;
                assert!(on_edge || on_band, "1e{k}: {ndc}");
            }
        }
    }
}
