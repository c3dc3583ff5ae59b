//! [`Lanes`] as plain arrays: the kernel on CPUs without a register implementation, and the
//! one-lane evaluation of the per-call constants and of the unit tests.

use std::ops::{Add, BitAnd, BitOr, Div, Mul, Neg, Not, Sub};

use super::{LaneBits, LaneMask, Lanes};

/// `N` values of `T`, one per vertex.
#[must_use]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pack<T, const N: usize>(pub [T; N]);

/// `N` booleans.
#[must_use]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PackMask<const N: usize>(pub [bool; N]);

/// `N` unsigned integers.
#[must_use]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PackBits<U, const N: usize>(pub [U; N]);

/// `[f(0), …, f(N − 1)]`.
#[inline(always)]
fn build<U: Copy + Default, const N: usize>(f: impl Fn(usize) -> U) -> [U; N] {
    let mut out = [U::default(); N];
    for (i, o) in out.iter_mut().enumerate() {
        *o = f(i);
    }
    out
}

impl<const N: usize> LaneMask for PackMask<N> {
    const N: usize = N;

    #[inline(always)]
    fn splat(b: bool) -> Self {
        Self([b; N])
    }
    #[inline(always)]
    fn bitmask(self) -> u64 {
        self.0
            .iter()
            .enumerate()
            .fold(0, |bits, (i, &b)| bits | u64::from(b) << i)
    }
    #[inline(always)]
    fn all(self) -> bool {
        self.0.iter().all(|&b| b)
    }
}

impl<const N: usize> BitAnd for PackMask<N> {
    type Output = Self;
    #[inline(always)]
    fn bitand(self, o: Self) -> Self {
        Self(build(|i| self.0[i] & o.0[i]))
    }
}

impl<const N: usize> BitOr for PackMask<N> {
    type Output = Self;
    #[inline(always)]
    fn bitor(self, o: Self) -> Self {
        Self(build(|i| self.0[i] | o.0[i]))
    }
}

impl<const N: usize> Not for PackMask<N> {
    type Output = Self;
    #[inline(always)]
    fn not(self) -> Self {
        Self(build(|i| !self.0[i]))
    }
}

macro_rules! lane_ops {
    ($type:ident, $t:ty, $($trait:ident, $method:ident, $op:expr;)*) => {$(
        impl<const N: usize> $trait for $type<$t, N> {
            type Output = Self;
            #[inline(always)]
            fn $method(self, o: Self) -> Self {
                Self(build(|i| $op(self.0[i], o.0[i])))
            }
        }
    )*};
}

macro_rules! portable {
    ($t:ty, $u:ty) => {
        lane_ops!(
            PackBits, $u,
            Add, add, <$u>::wrapping_add;
            Sub, sub, <$u>::wrapping_sub;
            BitAnd, bitand, |a: $u, b: $u| a & b;
            BitOr, bitor, |a: $u, b: $u| a | b;
        );

        impl<const N: usize> LaneBits for PackBits<$u, N> {
            #[inline(always)]
            fn splat(x: u64) -> Self {
                Self([x as $u; N])
            }
            #[inline(always)]
            fn shl(self, k: u32) -> Self {
                Self(build(|i| self.0[i] << k))
            }
            #[inline(always)]
            fn shr(self, k: u32) -> Self {
                Self(build(|i| self.0[i] >> k))
            }
        }

        impl<const N: usize> Lanes for Pack<$t, N> {
            type T = $t;
            type Mask = PackMask<N>;
            type Bits = PackBits<$u, N>;
            const N: usize = N;

            #[inline(always)]
            fn splat(x: $t) -> Self {
                Self([x; N])
            }
            #[inline(always)]
            fn load(src: &[$t]) -> Self {
                Self(build(|i| src[i]))
            }
            #[inline(always)]
            fn store(self, dst: &mut [$t]) {
                dst[..N].copy_from_slice(&self.0);
            }
            #[inline(always)]
            fn sqrt(self) -> Self {
                Self(build(|i| self.0[i].sqrt()))
            }
            #[inline(always)]
            fn mul_add(self, a: Self, b: Self) -> Self {
                Self(build(|i| self.0[i].mul_add(a.0[i], b.0[i])))
            }
            #[inline(always)]
            fn min(self, o: Self) -> Self {
                Self::select(o.lt(self), o, self)
            }
            #[inline(always)]
            fn max(self, o: Self) -> Self {
                Self::select(self.lt(o), o, self)
            }
            #[inline(always)]
            fn lt(self, o: Self) -> PackMask<N> {
                PackMask(build(|i| self.0[i] < o.0[i]))
            }
            #[inline(always)]
            fn le(self, o: Self) -> PackMask<N> {
                PackMask(build(|i| self.0[i] <= o.0[i]))
            }
            #[inline(always)]
            fn eq(self, o: Self) -> PackMask<N> {
                PackMask(build(|i| self.0[i] == o.0[i]))
            }
            #[inline(always)]
            fn select(mask: PackMask<N>, a: Self, b: Self) -> Self {
                Self(build(|i| if mask.0[i] { a.0[i] } else { b.0[i] }))
            }
            #[inline(always)]
            fn to_bits(self) -> PackBits<$u, N> {
                PackBits(build(|i| self.0[i].to_bits()))
            }
            #[inline(always)]
            fn from_bits(b: PackBits<$u, N>) -> Self {
                Self(build(|i| <$t>::from_bits(b.0[i])))
            }
        }

        lane_ops!(
            Pack, $t,
            Add, add, |a: $t, b: $t| a + b;
            Sub, sub, |a: $t, b: $t| a - b;
            Mul, mul, |a: $t, b: $t| a * b;
            Div, div, |a: $t, b: $t| a / b;
        );
    };
}

portable!(f32, u32);
portable!(f64, u64);

impl<T: Copy + Neg<Output = T> + Default, const N: usize> Neg for Pack<T, N> {
    type Output = Self;
    #[inline(always)]
    fn neg(self) -> Self {
        Self(build(|i| -self.0[i]))
    }
}
