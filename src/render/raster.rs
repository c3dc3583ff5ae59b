//! Triangle setup and rasterisation (GL 2.1 §2.11.1, §3.5.1), with llvmpipe's choices where GL
//! leaves one: vertices snapped to 1/256 pixel, pixel centres at half-integers, and a pixel
//! centre exactly on an edge covered by the triangle on its left or below it (Mesa's rule for
//! framebuffer objects; D3D's top-left rule in GL's bottom-up row order), so a pixel on an edge
//! shared by two triangles is covered exactly once.
//!
//! Window coordinates follow GL: x to the right, y up, pixel (0, 0) at the bottom left;
//! `x_w = (x_ndc + 1)·width/2`, `y_w = (y_ndc + 1)·height/2`, `z_w = (z_ndc + 1)/2`
//! (`glViewport(0, 0, width, height)`, `glDepthRange(0, 1)`). A triangle is front-facing when
//! its window-space area is positive (counter-clockwise, `glFrontFace(GL_CCW)`).
//!
//! Coverage is decided in exact integer arithmetic on the snapped vertices; attributes are
//! interpolated from the unsnapped ones, perspective-correctly (§3.5.1): the
//! barycentric coordinates in the original triangle divided by w are affine in window space.

use glam::{DVec2, DVec3, DVec4};

use crate::errors::error::Error;
use crate::render::clip::ClipVertex;

/// Sub-pixel precision of the snapped vertices, in bits (llvmpipe's `FIXED_ORDER`).
pub const SUBPIXEL_BITS: u32 = 8;

const FIXED_ONE: i64 = 1 << SUBPIXEL_BITS;

/// A pixel coordinate as a signed number; pixel coordinates are below the viewport size, which
/// the renderer keeps below 2^14.
#[inline]
#[allow(clippy::cast_possible_wrap)]
fn signed(x: usize) -> i64 {
    x as i64
}

/// `x` rounded to the nearest integer, ties to even (as llvmpipe's `lrintf`), for |x| < 2^51:
/// adding and subtracting 1.5·2^52 rounds in the FPU's default mode, where a libm call would
/// not be inlined.
#[inline]
fn round_ties_even(x: f64) -> i64 {
    const SHIFT: f64 = 6_755_399_441_055_744.0; // 1.5 · 2^52
    ((x + SHIFT) - SHIFT) as i64
}

/// A coordinate already clamped into the viewport as a pixel coordinate.
#[inline]
#[allow(clippy::cast_sign_loss)]
fn unsigned(x: i64) -> usize {
    x.max(0) as usize
}

/// Which facing triangles are discarded (`glCullFace`; `None` is `glDisable(GL_CULL_FACE)`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Cull {
    /// Draw every triangle (GL's default).
    #[default]
    None,
    /// Discard back-facing (clockwise) triangles.
    Back,
    /// Discard front-facing (counter-clockwise) triangles.
    Front,
    /// Discard every triangle.
    FrontAndBack,
}

impl Cull {
    /// Parses `"none"`, `"back"`, `"front"` or `"front_and_back"`.
    ///
    /// # Errors
    /// A value error naming `cull` for any other string.
    pub fn parse(name: &str) -> Result<Self, Error> {
        match name {
            "none" => Ok(Self::None),
            "back" => Ok(Self::Back),
            "front" => Ok(Self::Front),
            "front_and_back" => Ok(Self::FrontAndBack),
            _ => Err(Error::value(format!(
                "cull must be None, 'back', 'front' or 'front_and_back', got '{name}'"
            ))),
        }
    }

    fn discards(self, front: bool) -> bool {
        match self {
            Self::None => false,
            Self::Back => !front,
            Self::Front => front,
            Self::FrontAndBack => true,
        }
    }
}

/// The largest width or height (llvmpipe's `GL_MAX_VIEWPORT_DIMS`).
pub const MAX_SIZE: usize = 16384;

/// The size of the viewport (and of the image) in pixels.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Viewport {
    /// Width in pixels.
    pub width: usize,
    /// Height in pixels.
    pub height: usize,
}

impl Viewport {
    /// Checks that the width and height are in [1, `MAX_SIZE`] (16384).
    ///
    /// # Errors
    /// A value error naming `width` or `height`.
    pub fn validate(self) -> Result<(), Error> {
        for (name, size) in [("width", self.width), ("height", self.height)] {
            if size == 0 || size > MAX_SIZE {
                return Err(Error::value(format!(
                    "{name} must be in [1, {MAX_SIZE}], got {size}"
                )));
            }
        }
        Ok(())
    }

    /// Window coordinates (x, y, z) and 1/w of a clip-space point with w > 0.
    fn window(self, clip: DVec4) -> (DVec3, f64) {
        let inv_w = 1.0 / clip.w;
        let ndc = clip.truncate() * inv_w;
        let window = DVec3::new(
            (ndc.x + 1.0) * 0.5 * self.width as f64,
            (ndc.y + 1.0) * 0.5 * self.height as f64,
            (ndc.z + 1.0) * 0.5,
        );
        (window, inv_w)
    }
}

/// An affine function of window coordinates: `value + dx·(x − x₀) + dy·(y − y₀)`.
#[derive(Clone, Copy, Debug, Default)]
struct Plane {
    value: f64,
    dx: f64,
    dy: f64,
}

/// An edge function `a·X + b·Y + c` of snapped pixel centres (X = x·256 for pixel x), ≥ 0 on
/// the covered side; the tie-breaking rule is folded into `c`. `a` and `b` are differences of
/// snapped coordinates inside the guard band, below 2^25.
#[derive(Clone, Copy, Debug)]
struct Edge {
    a: i32,
    b: i32,
    c: i64,
}

/// A triangle ready to rasterise: one triangle of a face's clipped polygon.
///
/// What the visibility pass reads comes first, in 96 bytes (`repr(C)` keeps the order): it visits
/// triangles scattered in memory, one or two cache lines each.
#[derive(Clone, Copy, Debug)]
#[repr(C)]
pub struct Triangle {
    edges: [Edge; 3],
    /// Pixel bounds, inclusive, inside the viewport: x0, y0, x1, y1 (window coordinates).
    bounds: [u16; 4],
    origin: DVec2,
    depth: Plane,
    /// The barycentric coordinates in the face, divided by w.
    weights: [Plane; 3],
    /// The index of the face it comes from.
    pub face: u32,
    /// Counter-clockwise in window coordinates.
    pub front: bool,
}

/// The planes through three values at three window points; `None` for a zero area.
fn planes<const K: usize>(xy: [DVec2; 3], values: [[f64; K]; 3]) -> Option<[Plane; K]> {
    let (e1, e2) = (xy[1] - xy[0], xy[2] - xy[0]);
    let area = e1.perp_dot(e2);
    if area == 0.0 || !area.is_finite() {
        return None;
    }
    Some(std::array::from_fn(|k| {
        let (d1, d2) = (values[1][k] - values[0][k], values[2][k] - values[0][k]);
        Plane {
            value: values[0][k],
            dx: (d1 * e2.y - d2 * e1.y) / area,
            dy: (d2 * e1.x - d1 * e2.x) / area,
        }
    }))
}

impl Triangle {
    /// Sets up the triangle `corners` of face `face` (a fan triangle of its clipped polygon, so
    /// inside the guard band) in a viewport of at most [`MAX_SIZE`] pixels a side; `None` when
    /// it is culled, has no area after snapping, or misses the viewport.
    pub fn new(
        face: u32,
        corners: [ClipVertex; 3],
        viewport: Viewport,
        cull: Cull,
    ) -> Option<Self> {
        if corners.iter().any(|v| v.clip.w <= 0.0) {
            return None; // only a polygon through the eye point has w ≤ 0 after clipping
        }
        let mut window = corners.map(|v| viewport.window(v.clip));
        let mut weights = corners.map(|v| v.weights);
        let snap = |p: DVec3| {
            let s = |x: f64| round_ties_even((x - 0.5) * FIXED_ONE as f64);
            [s(p.x), s(p.y)]
        };
        let mut fixed = window.map(|(p, _)| snap(p));
        let area = (fixed[1][0] - fixed[0][0]) * (fixed[2][1] - fixed[0][1])
            - (fixed[2][0] - fixed[0][0]) * (fixed[1][1] - fixed[0][1]);
        let front = area > 0;
        if area == 0 || cull.discards(front) {
            return None;
        }
        if !front {
            // Counter-clockwise order from here on: the edge functions are positive inside.
            window.swap(1, 2);
            weights.swap(1, 2);
            fixed.swap(1, 2);
        }
        let edges = [(0, 1), (1, 2), (2, 0)].map(|(i, j)| {
            let (dx, dy) = (fixed[j][0] - fixed[i][0], fixed[j][1] - fixed[i][1]);
            // Left edges (going down) and bottom edges (going right) own their pixels.
            let owns = dy < 0 || (dy == 0 && dx > 0);
            let (a, b) = (-dy, dx);
            Edge {
                a: a as i32,
                b: b as i32,
                c: -(a * fixed[i][0] + b * fixed[i][1]) - i64::from(!owns),
            }
        });
        let lo = |k: usize| fixed.iter().map(|p| p[k]).min().unwrap_or(0);
        let hi = |k: usize| fixed.iter().map(|p| p[k]).max().unwrap_or(0);
        let bounds = [
            -((-lo(0)).div_euclid(FIXED_ONE)),
            -((-lo(1)).div_euclid(FIXED_ONE)),
            hi(0).div_euclid(FIXED_ONE).min(signed(viewport.width) - 1),
            hi(1).div_euclid(FIXED_ONE).min(signed(viewport.height) - 1),
        ];
        if bounds[0] > bounds[2] || bounds[1] > bounds[3] || bounds[2] < 0 || bounds[3] < 0 {
            return None;
        }
        let bounds = bounds.map(|b| unsigned(b) as u16);
        let xy = window.map(|(p, _)| p.truncate());
        let values: [[f64; 4]; 3] = std::array::from_fn(|i| {
            let (p, inv_w) = window[i];
            let q = weights[i] * inv_w;
            [p.z, q.x, q.y, q.z]
        });
        // Interpolate from the unsnapped vertices, unless snapping made the difference between
        // a sliver and nothing; then the snapped ones, which have an area by construction.
        let snapped = fixed
            .map(|[x, y]| DVec2::new(x as f64, y as f64) / FIXED_ONE as f64 + DVec2::splat(0.5));
        let (origin, [depth, q0, q1, q2]) = match planes(xy, values) {
            Some(p) if (xy[1] - xy[0]).perp_dot(xy[2] - xy[0]) > 0.0 => (xy[0], p),
            _ => (snapped[0], planes(snapped, values)?),
        };
        Some(Self {
            face,
            front,
            edges,
            bounds,
            origin,
            depth,
            weights: [q0, q1, q2],
        })
    }

    /// The window depth at the centre of pixel (x, y), clamped to [0, 1].
    #[inline]
    pub fn depth_at(&self, x: usize, y: usize) -> f64 {
        self.eval(&self.depth, x, y).clamp(0.0, 1.0)
    }

    /// The barycentric coordinates in the face at the centre of pixel (x, y), perspective
    /// corrected (they sum to 1).
    #[inline]
    pub fn weights_at(&self, x: usize, y: usize) -> DVec3 {
        let q = DVec3::from_array(self.weights.map(|p| self.eval(&p, x, y)));
        q / q.element_sum()
    }

    #[inline]
    fn eval(&self, plane: &Plane, x: usize, y: usize) -> f64 {
        // Through u32: converting a usize to f64 takes a slow sequence on x86-64.
        let d = DVec2::new(f64::from(x as u32) + 0.5, f64::from(y as u32) + 0.5) - self.origin;
        plane.value + plane.dx * d.x + plane.dy * d.y
    }

    /// Inclusive pixel rows (window coordinates) the triangle may cover.
    pub fn rows(&self) -> (usize, usize) {
        (usize::from(self.bounds[1]), usize::from(self.bounds[3]))
    }

    /// Calls `covered(x)` for every pixel of row `y` whose centre the triangle covers, left to
    /// right.
    #[inline]
    pub fn for_each_in_row(&self, y: usize, mut covered: impl FnMut(usize)) {
        let (x0, x1) = (usize::from(self.bounds[0]), usize::from(self.bounds[2]));
        let (fixed_x, fixed_y) = (signed(x0) * FIXED_ONE, signed(y) * FIXED_ONE);
        let mut e = self
            .edges
            .map(|edge| i64::from(edge.a) * fixed_x + i64::from(edge.b) * fixed_y + edge.c);
        let step = self.edges.map(|edge| i64::from(edge.a) * FIXED_ONE);
        for x in x0..=x1 {
            if e[0] >= 0 && e[1] >= 0 && e[2] >= 0 {
                covered(x);
            }
            for k in 0..3 {
                e[k] += step[k];
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const VIEW: Viewport = Viewport {
        width: 8,
        height: 8,
    };

    /// A triangle given in window coordinates (z = 0.5, w = 1).
    fn window_triangle(p: [[f64; 2]; 3], cull: Cull) -> Option<Triangle> {
        let corners = [0, 1, 2].map(|i| ClipVertex {
            clip: DVec4::new(p[i][0] / 4.0 - 1.0, p[i][1] / 4.0 - 1.0, 0.0, 1.0),
            weights: [DVec3::X, DVec3::Y, DVec3::Z][i],
        });
        Triangle::new(0, corners, VIEW, cull)
    }

    fn coverage(t: &Triangle) -> Vec<(usize, usize)> {
        let mut out = Vec::new();
        let (y0, y1) = t.rows();
        for y in y0..=y1 {
            t.for_each_in_row(y, |x| out.push((x, y)));
        }
        out
    }

    #[test]
    fn rounding_is_to_nearest_even() {
        let cases = [
            (0.5, 0),
            (1.5, 2),
            (2.5, 2),
            (-0.5, 0),
            (-1.5, -2),
            (2.4, 2),
            (-2.6, -3),
        ];
        for (x, rounded) in cases {
            assert_eq!(round_ties_even(x), rounded, "{x}");
        }
    }

    #[test]
    fn pixel_centres_decide_coverage() {
        // The lower-left half of the 4x4 square [0, 4]²: centres with x + y < 4 are inside,
        // and the diagonal x + y = 4 is a right/top edge, so its centres are not.
        let t = window_triangle([[0.0, 0.0], [4.0, 0.0], [0.0, 4.0]], Cull::None).unwrap();
        let covered = coverage(&t);
        assert_eq!(covered.len(), 6, "{covered:?}");
        assert!(covered.iter().all(|&(x, y)| x + y < 3));
    }

    #[test]
    fn a_shared_edge_covers_each_pixel_once() {
        let a = [[0.0, 0.0], [4.0, 0.0], [0.0, 4.0]];
        let b = [[4.0, 0.0], [4.0, 4.0], [0.0, 4.0]];
        let mut all: Vec<_> = [a, b]
            .iter()
            .flat_map(|p| coverage(&window_triangle(*p, Cull::None).unwrap()))
            .collect();
        all.sort_unstable();
        let n = all.len();
        all.dedup();
        assert_eq!((n, all.len()), (16, 16));
    }

    #[test]
    fn left_and_bottom_edges_own_their_pixels() {
        // Vertical edge x = 1.5 and horizontal edge y = 1.5 through pixel centres.
        let right_of = window_triangle([[1.5, 0.0], [4.0, 0.0], [1.5, 4.0]], Cull::None).unwrap();
        assert!(coverage(&right_of).contains(&(1, 0)));
        let left_of = window_triangle([[0.0, 0.0], [1.5, 0.0], [1.5, 4.0]], Cull::None).unwrap();
        assert!(!coverage(&left_of).contains(&(1, 0)));
        let above = window_triangle([[0.0, 1.5], [4.0, 1.5], [0.0, 4.0]], Cull::None).unwrap();
        assert!(coverage(&above).contains(&(0, 1)));
        let below = window_triangle([[0.0, 0.0], [4.0, 1.5], [0.0, 1.5]], Cull::None).unwrap();
        assert!(!coverage(&below).contains(&(0, 1)));
    }

    #[test]
    fn winding_decides_facing_and_culling() {
        let ccw = [[0.0, 0.0], [4.0, 0.0], [0.0, 4.0]];
        let cw = [ccw[0], ccw[2], ccw[1]];
        assert!(window_triangle(ccw, Cull::None).unwrap().front);
        let back = window_triangle(cw, Cull::None).unwrap();
        assert!(!back.front);
        assert_eq!(
            coverage(&back),
            coverage(&window_triangle(ccw, Cull::None).unwrap())
        );
        assert!(window_triangle(cw, Cull::Back).is_none());
        assert!(window_triangle(ccw, Cull::Front).is_none());
        assert!(window_triangle(ccw, Cull::FrontAndBack).is_none());
        assert!(window_triangle([[0.0, 0.0], [1.0, 1.0], [2.0, 2.0]], Cull::None).is_none());
    }

    #[test]
    fn weights_are_barycentric_at_pixel_centres() {
        let t = window_triangle([[0.0, 0.0], [8.0, 0.0], [0.0, 8.0]], Cull::None).unwrap();
        let w = t.weights_at(1, 2);
        let expected = DVec3::new(1.0 - 1.5 / 8.0 - 2.5 / 8.0, 1.5 / 8.0, 2.5 / 8.0);
        assert!((w - expected).abs().max_element() < 1e-15, "{w}");
        assert!((t.depth_at(3, 3) - 0.5).abs() < 1e-15);
        // Swapped into counter-clockwise order, the weights still follow the face's corners.
        let t = window_triangle([[0.0, 0.0], [0.0, 8.0], [8.0, 0.0]], Cull::None).unwrap();
        let w = t.weights_at(1, 2);
        assert!(
            (w - DVec3::new(expected.x, expected.z, expected.y))
                .abs()
                .max_element()
                < 1e-15
        );
    }

    #[test]
    fn perspective_correct_weights_follow_one_over_w() {
        // Corner 1 at w = 3: halfway across the screen is a quarter of the way in the triangle.
        let corners = [
            (DVec4::new(-1.0, -1.0, 0.0, 1.0), DVec3::X),
            (DVec4::new(3.0, -3.0, 0.0, 3.0), DVec3::Y),
            (DVec4::new(-1.0, 1.0, 0.0, 1.0), DVec3::Z),
        ]
        .map(|(clip, weights)| ClipVertex { clip, weights });
        let t = Triangle::new(0, corners, VIEW, Cull::None).unwrap();
        // Pixel (3, 0) has centre (3.5, 0.5): screen weights λ = (1 − 3.5/8 − 0.5/8, 3.5/8, 0.5/8).
        let lambda = DVec3::new(0.5, 3.5 / 8.0, 0.5 / 8.0);
        let q = lambda * DVec3::new(1.0, 1.0 / 3.0, 1.0);
        let w = t.weights_at(3, 0);
        assert!((w - q / q.element_sum()).abs().max_element() < 1e-15, "{w}");
    }
}
