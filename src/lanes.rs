//! Lane arrays: `N` values of `f32` or `f64` processed together, one vertex per lane.
//!
//! Every operation is an element-wise loop over a fixed-size array, marked `#[inline(always)]`,
//! so inside a function compiled with `#[target_feature]` (see [`crate::dispatch`]) LLVM emits
//! one AVX-512, AVX2 or SSE2 instruction per operation. Only IEEE basic operations (+, −, ×, ÷,
//! √, comparisons, selects, bit moves) appear: no fused multiply-add, no approximate reciprocal,
//! so every instruction set gives the same bits.

use std::ops::{Add, BitAnd, BitOr, Div, Mul, Neg, Not, Sub};

use crate::real::Real;

/// `[f(0), …, f(N − 1)]`, built by a plain loop. `array::from_fn` and `array::map` may stay
/// out of line, and then run without the caller's target features, one lane at a time.
#[inline(always)]
pub fn build<U: Copy, const N: usize>(fill: U, f: impl Fn(usize) -> U) -> [U; N] {
    let mut out = [fill; N];
    for (i, o) in out.iter_mut().enumerate() {
        *o = f(i);
    }
    out
}

/// `N` values of `T`, one per vertex.
#[must_use]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pack<T, const N: usize>(pub [T; N]);

/// `N` booleans, the result of a lane-wise comparison.
#[must_use]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Mask<const N: usize>(pub [bool; N]);

impl<const N: usize> Mask<N> {
    /// Every lane set to `b`.
    #[inline(always)]
    pub fn splat(b: bool) -> Self {
        Self([b; N])
    }

    /// True when every lane is set.
    #[inline(always)]
    pub fn all(self) -> bool {
        self.0.iter().fold(true, |a, &b| a & b)
    }

    /// True when some lane is set.
    #[inline(always)]
    pub fn any(self) -> bool {
        self.0.iter().fold(false, |a, &b| a | b)
    }
}

impl<const N: usize> BitAnd for Mask<N> {
    type Output = Self;
    #[inline(always)]
    fn bitand(self, o: Self) -> Self {
        Self(build(false, |i| self.0[i] & o.0[i]))
    }
}

impl<const N: usize> BitOr for Mask<N> {
    type Output = Self;
    #[inline(always)]
    fn bitor(self, o: Self) -> Self {
        Self(build(false, |i| self.0[i] | o.0[i]))
    }
}

impl<const N: usize> Not for Mask<N> {
    type Output = Self;
    #[inline(always)]
    fn not(self) -> Self {
        Self(build(false, |i| !self.0[i]))
    }
}

impl<T: Real, const N: usize> Pack<T, N> {
    /// Every lane set to `x`.
    #[inline(always)]
    pub fn splat(x: T) -> Self {
        Self([x; N])
    }

    /// `f` applied to every lane.
    #[inline(always)]
    pub fn map(self, f: impl Fn(T) -> T) -> Self {
        Self(build(T::ZERO, |i| f(self.0[i])))
    }

    /// `f` applied lane by lane to `self` and `other`.
    #[inline(always)]
    pub fn zip(self, other: Self, f: impl Fn(T, T) -> T) -> Self {
        Self(build(T::ZERO, |i| f(self.0[i], other.0[i])))
    }

    /// `a` where `mask` is set, else `b`.
    #[inline(always)]
    pub fn select(mask: Mask<N>, a: Self, b: Self) -> Self {
        Self(build(T::ZERO, |i| if mask.0[i] { a.0[i] } else { b.0[i] }))
    }

    /// `self` where `mask` is set, else 0: a select, never a multiplication by a 0/1 mask
    /// (0 · inf would be NaN).
    #[inline(always)]
    pub fn or_zero(self, mask: Mask<N>) -> Self {
        Self::select(mask, self, Self::splat(T::ZERO))
    }

    /// Lane-wise `self < o`.
    #[inline(always)]
    pub fn lt(self, o: Self) -> Mask<N> {
        Mask(build(false, |i| self.0[i] < o.0[i]))
    }

    /// Lane-wise `self <= o`.
    #[inline(always)]
    pub fn le(self, o: Self) -> Mask<N> {
        Mask(build(false, |i| self.0[i] <= o.0[i]))
    }

    /// Lane-wise `self > o`.
    #[inline(always)]
    pub fn gt(self, o: Self) -> Mask<N> {
        o.lt(self)
    }

    /// Lane-wise `self >= o`.
    #[inline(always)]
    pub fn ge(self, o: Self) -> Mask<N> {
        o.le(self)
    }

    /// Lane-wise `self == o`.
    #[inline(always)]
    pub fn eq(self, o: Self) -> Mask<N> {
        Mask(build(false, |i| self.0[i] == o.0[i]))
    }

    /// The lanes that are neither NaN nor infinite (x − x is 0 exactly for finite x).
    #[inline(always)]
    #[allow(clippy::eq_op)]
    pub fn is_finite(self) -> Mask<N> {
        (self - self).eq(Self::splat(T::ZERO))
    }

    /// Lane-wise minimum; a NaN lane of `self` stays NaN.
    #[inline(always)]
    pub fn min(self, o: Self) -> Self {
        Self::select(o.lt(self), o, self)
    }

    /// Lane-wise maximum; a NaN lane of `self` stays NaN.
    #[inline(always)]
    pub fn max(self, o: Self) -> Self {
        Self::select(self.lt(o), o, self)
    }

    /// `self` clamped to [`lo`, `hi`] lane by lane; NaN stays NaN.
    #[inline(always)]
    pub fn clamp(self, lo: T, hi: T) -> Self {
        self.max(Self::splat(lo)).min(Self::splat(hi))
    }

    /// Lane-wise square root.
    #[inline(always)]
    pub fn sqrt(self) -> Self {
        self.map(T::sqrt)
    }

    /// Lane-wise `e^x` (see [`Real::exp_lanes`]).
    #[inline(always)]
    pub fn exp(self) -> Self {
        Self(T::exp_lanes(self.0))
    }

    /// Lane-wise `ln(1 + x)` (see [`Real::ln_1p_lanes`]).
    #[inline(always)]
    pub fn ln_1p(self) -> Self {
        Self(T::ln_1p_lanes(self.0))
    }
}

macro_rules! lane_op {
    ($trait:ident, $method:ident, $op:tt) => {
        impl<T: Real, const N: usize> $trait for Pack<T, N> {
            type Output = Self;
            #[inline(always)]
            fn $method(self, o: Self) -> Self {
                Self(build(T::ZERO, |i| self.0[i] $op o.0[i]))
            }
        }
    };
}
lane_op!(Add, add, +);
lane_op!(Sub, sub, -);
lane_op!(Mul, mul, *);
lane_op!(Div, div, /);

impl<T: Real, const N: usize> Neg for Pack<T, N> {
    type Output = Self;
    #[inline(always)]
    fn neg(self) -> Self {
        self.map(|x| -x)
    }
}

/// A 3-vector of packs: `N` vectors, stored as x, y and z lanes.
#[must_use]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct V3<T, const N: usize> {
    /// The x components.
    pub x: Pack<T, N>,
    /// The y components.
    pub y: Pack<T, N>,
    /// The z components.
    pub z: Pack<T, N>,
}

impl<T: Real, const N: usize> V3<T, N> {
    /// The zero vector in every lane.
    #[inline(always)]
    pub fn zero() -> Self {
        Self::splat([T::ZERO; 3])
    }

    /// The vector `v` in every lane.
    #[inline(always)]
    pub fn splat(v: [T; 3]) -> Self {
        Self {
            x: Pack::splat(v[0]),
            y: Pack::splat(v[1]),
            z: Pack::splat(v[2]),
        }
    }

    /// `N` rows `[x, y, z]`, one per lane.
    #[inline(always)]
    pub fn load(rows: &[[T; 3]; N]) -> Self {
        Self {
            x: Pack(build(T::ZERO, |i| rows[i][0])),
            y: Pack(build(T::ZERO, |i| rows[i][1])),
            z: Pack(build(T::ZERO, |i| rows[i][2])),
        }
    }

    /// The vector of lane `i`.
    #[inline(always)]
    pub fn lane(&self, i: usize) -> [T; 3] {
        [self.x.0[i], self.y.0[i], self.z.0[i]]
    }

    /// The dot product `(x·x' + y·y') + z·z'`, in glam's order.
    #[inline(always)]
    pub fn dot(self, o: Self) -> Pack<T, N> {
        self.x * o.x + self.y * o.y + self.z * o.z
    }

    /// Every component times `s`.
    #[inline(always)]
    pub fn scale(self, s: Pack<T, N>) -> Self {
        Self {
            x: self.x * s,
            y: self.y * s,
            z: self.z * s,
        }
    }

    /// Every component divided by `s`.
    #[inline(always)]
    pub fn div_by(self, s: Pack<T, N>) -> Self {
        Self {
            x: self.x / s,
            y: self.y / s,
            z: self.z / s,
        }
    }

    /// `a` where `mask` is set, else `b`.
    #[inline(always)]
    pub fn select(mask: Mask<N>, a: Self, b: Self) -> Self {
        Self {
            x: Pack::select(mask, a.x, b.x),
            y: Pack::select(mask, a.y, b.y),
            z: Pack::select(mask, a.z, b.z),
        }
    }

    /// The lanes whose three components are finite.
    #[inline(always)]
    pub fn is_finite(self) -> Mask<N> {
        self.x.is_finite() & self.y.is_finite() & self.z.is_finite()
    }

    /// The lanes holding the zero vector.
    #[inline(always)]
    pub fn is_zero(self) -> Mask<N> {
        let z = Pack::splat(T::ZERO);
        self.x.eq(z) & self.y.eq(z) & self.z.eq(z)
    }
}

impl<T: Real, const N: usize> Add for V3<T, N> {
    type Output = Self;
    #[inline(always)]
    fn add(self, o: Self) -> Self {
        Self {
            x: self.x + o.x,
            y: self.y + o.y,
            z: self.z + o.z,
        }
    }
}

impl<T: Real, const N: usize> Sub for V3<T, N> {
    type Output = Self;
    #[inline(always)]
    fn sub(self, o: Self) -> Self {
        Self {
            x: self.x - o.x,
            y: self.y - o.y,
            z: self.z - o.z,
        }
    }
}

impl<T: Real, const N: usize> Neg for V3<T, N> {
    type Output = Self;
    #[inline(always)]
    fn neg(self) -> Self {
        Self {
            x: -self.x,
            y: -self.y,
            z: -self.z,
        }
    }
}

/// The unit vector in the direction of `v` and the length of `v`, lane by lane; `(0, 0)` for
/// the zero vector.
///
/// Exact for every finite `v`: when |v|² is subnormal or overflows, `v` is first scaled by an
/// exact power of two ([`Real::UPSCALE`] or [`Real::DOWNSCALE`]), which changes no direction bit.
/// Such lanes are rare, so they leave the vector path for a scalar one. The length itself may
/// round to infinity for |v| beyond the type's range. Each component is divided by the length,
/// so an axis-aligned vector gives an exact unit vector.
#[inline(always)]
pub fn normalize_and_length<T: Real, const N: usize>(v: V3<T, N>) -> (V3<T, N>, Pack<T, N>) {
    normalize_by::<T, N, true>(v)
}

/// [`normalize_and_length`] with one division and three products instead of three divisions
/// (within 1 ulp of it): for the per-light vectors of the kernel, where the vector divider is
/// the scarcest unit.
#[inline(always)]
pub fn normalize_and_length_fast<T: Real, const N: usize>(v: V3<T, N>) -> (V3<T, N>, Pack<T, N>) {
    normalize_by::<T, N, false>(v)
}

#[inline(always)]
fn normalize_by<T: Real, const N: usize, const DIVIDE: bool>(
    v: V3<T, N>,
) -> (V3<T, N>, Pack<T, N>) {
    let len2 = v.dot(v);
    let ok = len2.ge(Pack::splat(T::MIN_POSITIVE)) & len2.le(Pack::splat(T::MAX));
    let len = len2.sqrt();
    let unit = if DIVIDE {
        v.div_by(len)
    } else {
        v.scale(Pack::splat(T::ONE) / len)
    };
    if ok.all() {
        return (unit, len);
    }
    rescaled::<T, N, DIVIDE>(v, len2, ok, unit, len)
}

/// The lanes of [`normalize_and_length`] whose squared length is zero, subnormal, infinite or
/// NaN, one at a time.
#[cold]
#[inline(never)]
fn rescaled<T: Real, const N: usize, const DIVIDE: bool>(
    v: V3<T, N>,
    len2: Pack<T, N>,
    ok: Mask<N>,
    mut unit: V3<T, N>,
    mut len: Pack<T, N>,
) -> (V3<T, N>, Pack<T, N>) {
    for i in (0..N).filter(|&i| !ok.0[i]) {
        let [x, y, z] = v.lane(i);
        let (u, l) = if x == T::ZERO && y == T::ZERO && z == T::ZERO {
            ([T::ZERO; 3], T::ZERO)
        } else if !v.is_finite().0[i] {
            ([T::NAN; 3], T::NAN)
        } else {
            let scale = if len2.0[i] < T::MIN_POSITIVE {
                T::UPSCALE
            } else {
                T::DOWNSCALE
            };
            let (x, y, z) = (x * scale, y * scale, z * scale);
            let l = (x * x + y * y + z * z).sqrt();
            let u = if DIVIDE {
                [x / l, y / l, z / l]
            } else {
                let r = T::ONE / l;
                [x * r, y * r, z * r]
            };
            (u, l / scale)
        };
        (unit.x.0[i], unit.y.0[i], unit.z.0[i], len.0[i]) = (u[0], u[1], u[2], l);
    }
    (unit, len)
}

/// The unit vector in the direction of `v`, or zero (see [`normalize_and_length_fast`]).
#[inline(always)]
pub fn normalize_or_zero_fast<T: Real, const N: usize>(v: V3<T, N>) -> V3<T, N> {
    normalize_and_length_fast(v).0
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn selects_never_multiply() {
        let a = Pack::<f32, 4>([f32::INFINITY, 1.0, f32::NAN, -2.0]);
        let m = a.gt(Pack::splat(0.0));
        assert_eq!(m, Mask([true, true, false, false]));
        let z = a.or_zero(m);
        assert_eq!(z.0[..2], [f32::INFINITY, 1.0]);
        assert_eq!(z.0[2..], [0.0, 0.0]);
        assert_eq!(a.is_finite(), Mask([false, true, false, true]));
        assert!(a.clamp(0.0, 1.0).0[2].is_nan(), "clamp keeps NaN");
    }

    #[test]
    fn normalisation_is_exact_at_any_scale_and_zero_for_zero() {
        let v = V3::<f32, 4> {
            x: Pack([3e-30, 0.0, 3e30, 3.0]),
            y: Pack([4e-30, 0.0, 4e30, 4.0]),
            z: Pack([0.0; 4]),
        };
        let (u, l) = normalize_and_length(v);
        for i in [0, 2, 3] {
            assert!((u.x.0[i] - 0.6).abs() < 1e-7 && (u.y.0[i] - 0.8).abs() < 1e-7);
        }
        assert_eq!((u.lane(1), l.0[1]), ([0.0; 3], 0.0));
        assert!((l.0[0] / 5e-30 - 1.0).abs() < 1e-6 && (l.0[2] / 5e30 - 1.0).abs() < 1e-6);
    }
}
