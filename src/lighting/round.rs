//! Per-call values rounded from `f64` to a kernel's type, saturated where they would overflow.

use glam::DVec3;

use crate::numbers::real::Real;

/// Each of the three RGB values of `c`, saturated at
/// ±[`Float::COLOR_SATURATION`](crate::simd::float::Float::COLOR_SATURATION) and rounded to `T`.
#[inline]
pub fn rgb<T: Real>(c: &[f64]) -> [T; 3] {
    let sat = T::COLOR_SATURATION.to_f64();
    [c[0], c[1], c[2]].map(|x| T::from_f64(x.clamp(-sat, sat)))
}

/// Rounds an `f64` vector to the kernel's type, saturating at ±`T::MAX` (instead of ±inf).
pub fn cast_saturating<T: Real>(v: DVec3) -> [T; 3] {
    let max = T::MAX.to_f64();
    v.to_array().map(|x| T::from_f64(x.clamp(-max, max)))
}
