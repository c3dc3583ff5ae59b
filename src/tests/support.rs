//! What the crate's tests share: a deterministic stream of numbers and the vertices the
//! kernels are compared on.

use crate::numbers::real::Real;

/// Vertices per subset: five full blocks of the widest kind (32 lanes) and a short one.
pub(crate) const VERTICES: usize = 165;

/// A deterministic stream of numbers in [-1, 1) (a 64-bit LCG; no dependency).
pub(crate) struct Numbers(pub(crate) u64);

impl Numbers {
    /// The next number.
    pub(crate) fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (self.0 >> 11) as f64 / (1u64 << 52) as f64 - 1.0
    }

    /// Three numbers, each times `scale`.
    pub(crate) fn vec3(&mut self, scale: f64) -> [f64; 3] {
        [
            self.next() * scale,
            self.next() * scale,
            self.next() * scale,
        ]
    }
}

/// Vertices around the lights: random rows, and the awkward ones (a zero normal, a non-unit
/// normal, a vertex at a light, NaN rows), 165 in all: five full blocks of the widest kind (32
/// lanes) and a short one.
pub(crate) fn vertices<T: Real>() -> (Vec<[T; 3]>, Vec<[T; 3]>, Vec<T>) {
    let mut numbers = Numbers(7);
    let mut positions: Vec<[f64; 3]> = (0..VERTICES).map(|_| numbers.vec3(2.0)).collect();
    let mut normals: Vec<[f64; 3]> = (0..VERTICES).map(|_| numbers.vec3(1.0)).collect();
    let colors: Vec<f64> = (0..VERTICES * 4).map(|_| numbers.next().abs()).collect();
    normals[3] = [0.0; 3];
    normals[4] = [0.0, 0.0, 3.0];
    positions[5] = [1.0, 2.0, 1.0];
    positions[6] = [f64::NAN, 0.0, 0.0];
    normals[7] = [0.0, f64::INFINITY, 0.0];
    // Halfway between the tests' point light (1, 2, 1) and local viewer (0.5, 0, 2): VP and
    // VP_e opposite, a zero halfway vector.
    positions[8] = [0.75, 1.0, 1.5];
    let cast = |rows: Vec<[f64; 3]>| rows.into_iter().map(|r| r.map(T::from_f64)).collect();
    (
        cast(positions),
        cast(normals),
        colors.into_iter().map(T::from_f64).collect(),
    )
}
