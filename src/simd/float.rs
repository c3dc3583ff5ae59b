//! The two arithmetic types of the kernels, `f32` (glam `Vec3`) and `f64` (glam `DVec3`), as
//! single values behind one trait, so every formula is written once and compiled for both.
//!
//! The bottom of the numeric layers: it knows nothing of lanes ([`crate::simd::lanes`] builds on
//! it, and [`crate::numbers::real`] ties each type to its lanes).

use glam::{DVec3, Vec3};

use std::fmt::Debug;
use std::ops::{Add, AddAssign, Div, Mul, Neg, Sub};

/// A 3-vector of `T`: the operations of glam's `Vec3`/`DVec3` that the kernels use.
pub trait Vector3<T>:
    Copy
    + Send
    + Sync
    + Debug
    + PartialEq
    + Add<Output = Self>
    + Sub<Output = Self>
    + Neg<Output = Self>
    + Mul<T, Output = Self>
    + Div<T, Output = Self>
{
    /// (0, 0, 0).
    const ZERO: Self;
    /// The vector `(a[0], a[1], a[2])`.
    fn from_array(a: [T; 3]) -> Self;
    /// The components as an array.
    fn to_array(self) -> [T; 3];
    /// The dot product `x·x' + y·y' + z·z'`.
    fn dot(self, other: Self) -> T;
    /// True when no component is NaN or infinite.
    fn is_finite(self) -> bool;
}

macro_rules! impl_vector3 {
    ($vec:ty, $t:ty) => {
        impl Vector3<$t> for $vec {
            const ZERO: Self = <$vec>::ZERO;
            #[inline]
            fn from_array(a: [$t; 3]) -> Self {
                <$vec>::from_array(a)
            }
            #[inline]
            fn to_array(self) -> [$t; 3] {
                <$vec>::to_array(&self)
            }
            #[inline]
            fn dot(self, other: Self) -> $t {
                <$vec>::dot(self, other)
            }
            #[inline]
            fn is_finite(self) -> bool {
                <$vec>::is_finite(self)
            }
        }
    };
}
impl_vector3!(Vec3, f32);
impl_vector3!(DVec3, f64);

/// A floating-point type the kernels compute in: `f32` or `f64`, as single values.
// Pod: scratch buffers of `T` come zeroed from `pages::Zeroed`, mapped (not written) when large.
pub trait Float:
    Copy
    + bytemuck::Pod
    + Send
    + Sync
    + Debug
    + PartialOrd
    + Add<Output = Self>
    + AddAssign
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
    + 'static
{
    /// The glam 3-vector of this precision.
    type Vec3: Vector3<Self>;
    /// 0.
    const ZERO: Self;
    /// 1.
    const ONE: Self;
    /// 0.5.
    const HALF: Self;
    /// The largest finite value.
    const MAX: Self;
    /// The machine epsilon, 2^-23 or 2^-52.
    const EPSILON: Self;
    /// The smallest positive normal value.
    const MIN_POSITIVE: Self;
    /// Not a number.
    const NAN: Self;
    /// The exponent bias of the IEEE format, 127 or 1023.
    const EXPONENT_BIAS: u64;
    /// The explicit significand bits of the IEEE format, 23 or 52.
    const MANTISSA_BITS: u32;
    /// +∞.
    const INFINITY: Self;
    /// An exact power of two that lifts any nonzero subnormal-length vector into the normal range
    /// without overflowing its squared length.
    const UPSCALE: Self;
    /// The reciprocal of [`Float::UPSCALE`], for vectors whose squared length overflows.
    const DOWNSCALE: Self;
    /// The magnitude at which the kernels saturate a light's weight (att·spot times n⊙VP or the
    /// specular power) and the light sums: 2^64 in f32, 2^240 in f64. A weight times a colour
    /// (below [`Float::COLOR_SATURATION`]) stays below 2^124 (f32) or 2^480 (f64), so sums of
    /// them stay finite and no `inf · 0` or `inf − inf` can arise from finite input.
    const SATURATION: Self;
    /// The magnitude at which light and material colours saturate: 2^60 in f32, 2^240 in f64.
    const COLOR_SATURATION: Self;
    /// How many lights are summed in this type before the partial sum is added to a
    /// compensated `f64` total: 8, so the sum's error stays 8 ulp of Σ|terms| whatever the
    /// light count.
    const SUM_BLOCK: usize;
    /// Rounds an `f64` to this type.
    #[must_use]
    fn from_f64(x: f64) -> Self;
    /// Widens (exactly) to `f64`.
    #[must_use]
    fn to_f64(self) -> f64;
    /// Square root.
    #[must_use]
    fn sqrt(self) -> Self;
    /// `self · a + b` rounded once (IEEE fusedMultiplyAdd; in software where the CPU has none).
    #[must_use]
    fn mul_add(self, a: Self, b: Self) -> Self;
    /// Veltkamp's splitter 2^⌈p/2⌉ + 1 (4097 in f32, 2^27 + 1 in f64): `c = x·SPLIT`,
    /// `hi = c − (c − x)` leaves half the significand in `hi`, so products of halves are exact.
    const SPLIT: Self;
    /// The smaller of two numbers (the non-NaN one if one is NaN).
    #[must_use]
    fn min(self, other: Self) -> Self;
    /// The larger of two numbers (the non-NaN one if one is NaN).
    #[must_use]
    fn max(self, other: Self) -> Self;
    /// True unless NaN or infinite.
    fn is_finite(self) -> bool;
    /// The magnitude.
    #[must_use]
    fn abs(self) -> Self;
    /// The magnitude of `self` with the sign of `sign`.
    #[must_use]
    fn copysign(self, sign: Self) -> Self;
    /// `self` to the power `e`, as the C library's `pow` (not for the kernels: their powers are
    /// [`crate::numbers::elementary`]'s).
    #[must_use]
    fn powf(self, e: Self) -> Self;
}

macro_rules! impl_float_common {
    () => {
        #[inline]
        fn sqrt(self) -> Self {
            self.sqrt()
        }
        #[inline]
        fn mul_add(self, a: Self, b: Self) -> Self {
            self.mul_add(a, b)
        }
        #[inline]
        fn min(self, other: Self) -> Self {
            self.min(other)
        }
        #[inline]
        fn max(self, other: Self) -> Self {
            self.max(other)
        }
        #[inline]
        fn is_finite(self) -> bool {
            self.is_finite()
        }
        #[inline]
        fn abs(self) -> Self {
            self.abs()
        }
        #[inline]
        fn copysign(self, sign: Self) -> Self {
            self.copysign(sign)
        }
        #[inline]
        fn powf(self, e: Self) -> Self {
            self.powf(e)
        }
    };
}

impl Float for f32 {
    type Vec3 = Vec3;
    const ZERO: Self = 0.0;
    const ONE: Self = 1.0;
    const HALF: Self = 0.5;
    const MAX: Self = f32::MAX;
    const EPSILON: Self = f32::EPSILON;
    const MIN_POSITIVE: Self = f32::MIN_POSITIVE;
    const NAN: Self = f32::NAN;
    const EXPONENT_BIAS: u64 = 127;
    const MANTISSA_BITS: u32 = f32::MANTISSA_DIGITS - 1;
    const INFINITY: Self = f32::INFINITY;
    // 2^-149 · 2^100 = 2^-49 (its square is normal); 2^128 · 2^-100 = 2^28 (its square is finite).
    const UPSCALE: Self = f32::from_bits((127 + 100) << 23);
    const DOWNSCALE: Self = f32::from_bits((127 - 100) << 23);
    const SATURATION: Self = f32::from_bits((127 + 64) << 23);
    const COLOR_SATURATION: Self = f32::from_bits((127 + 60) << 23);
    const SUM_BLOCK: usize = 8;
    #[inline]
    fn from_f64(x: f64) -> Self {
        x as f32
    }
    #[inline]
    fn to_f64(self) -> f64 {
        f64::from(self)
    }
    impl_float_common!();
    const SPLIT: f32 = 4097.0;
}

impl Float for f64 {
    type Vec3 = DVec3;
    const ZERO: Self = 0.0;
    const ONE: Self = 1.0;
    const HALF: Self = 0.5;
    const MAX: Self = f64::MAX;
    const EPSILON: Self = f64::EPSILON;
    const MIN_POSITIVE: Self = f64::MIN_POSITIVE;
    const NAN: Self = f64::NAN;
    const EXPONENT_BIAS: u64 = 1023;
    const MANTISSA_BITS: u32 = f64::MANTISSA_DIGITS - 1;
    const INFINITY: Self = f64::INFINITY;
    // 2^-1074 · 2^600 = 2^-474 (its square is normal); 2^1024 · 2^-600 = 2^424 (its square is
    // finite).
    const UPSCALE: Self = f64::from_bits((1023 + 600) << 52);
    const DOWNSCALE: Self = f64::from_bits((1023 - 600) << 52);
    const SATURATION: Self = f64::from_bits((1023 + 240) << 52);
    const COLOR_SATURATION: Self = f64::from_bits((1023 + 240) << 52);
    const SUM_BLOCK: usize = 8;
    #[inline]
    fn from_f64(x: f64) -> Self {
        x
    }
    #[inline]
    fn to_f64(self) -> f64 {
        self
    }
    impl_float_common!();
    const SPLIT: f64 = 134_217_729.0;
}

/// ⌊log2 |x|⌋ for finite nonzero `x` (subnormals included), from the bits; 0 for 0.
pub(crate) fn exponent(x: f64) -> i32 {
    if x == 0.0 {
        return 0;
    }
    let biased = ((x.to_bits() >> 52) & 0x7ff) as i32;
    if biased == 0 {
        // Subnormal: lift by 2^64 (exact) and read the exponent there.
        return exponent(x * 2f64.powi(64)) - 64;
    }
    biased - 1023
}

/// `x · 2^k`, in steps that stay within `f64`'s exponent range (2^k itself may not be one:
/// k up to ±2044); exact unless the result is subnormal (then rounded) or beyond the range (±inf).
/// Always inlined: the kernel calls it inside its `#[target_feature]` functions.
#[inline(always)]
pub(crate) fn ldexp(x: f64, k: i32) -> f64 {
    // k in [−1022, 1023]: a biased exponent in [1, 2046], so 2^k is a normal f64.
    let step = |x: f64, k: i32| x * f64::from_bits(u64::from((1023 + k).unsigned_abs()) << 52);
    let half = k / 2;
    step(
        step(x, half.clamp(-1022, 1023)),
        (k - half).clamp(-1022, 1023),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn scale_constants_are_exact_powers_of_two() {
        assert_eq!(f32::UPSCALE, 2f32.powi(100));
        assert_eq!(f32::DOWNSCALE, 2f32.powi(-100));
        assert_eq!(f64::UPSCALE, 2f64.powi(600));
        assert_eq!(f64::DOWNSCALE, 2f64.powi(-600));
    }
}
