//! Two [`Lanes`] side by side as one: twice the lanes, and two independent chains of
//! instructions for the CPU to overlap where one alone would wait on the latency of the
//! polynomials of `exp` and `ln`. Every operation applies to both halves, so the bits are
//! those of the halves.

use std::mem::MaybeUninit;
use std::ops::{Add, BitAnd, BitOr, Div, Mul, Neg, Not, Sub};

use super::{LaneBits, LaneMask, Lanes, V3};

/// The lanes of `V` twice: lanes `0..V::N` in `.0`, the rest in `.1`.
#[must_use]
#[derive(Clone, Copy, Debug)]
pub struct Pair<V>(pub V, pub V);

macro_rules! both {
    ($($trait:ident, $method:ident;)*) => {$(
        impl<V: $trait<Output = V>> $trait for Pair<V> {
            type Output = Self;
            #[inline(always)]
            fn $method(self, o: Self) -> Self {
                Pair(self.0.$method(o.0), self.1.$method(o.1))
            }
        }
    )*};
}

both!(Add, add; Sub, sub; Mul, mul; Div, div; BitAnd, bitand; BitOr, bitor;);

impl<V: Neg<Output = V>> Neg for Pair<V> {
    type Output = Self;
    #[inline(always)]
    fn neg(self) -> Self {
        Pair(-self.0, -self.1)
    }
}

impl<V: Not<Output = V>> Not for Pair<V> {
    type Output = Self;
    #[inline(always)]
    fn not(self) -> Self {
        Pair(!self.0, !self.1)
    }
}

impl<M: LaneMask> LaneMask for Pair<M> {
    const N: usize = 2 * M::N;

    #[inline(always)]
    fn splat(b: bool) -> Self {
        Pair(M::splat(b), M::splat(b))
    }
    #[inline(always)]
    fn bitmask(self) -> u64 {
        self.0.bitmask() | self.1.bitmask() << M::N
    }
    #[inline(always)]
    fn all(self) -> bool {
        (self.0 & self.1).all()
    }
}

impl<B: LaneBits> LaneBits for Pair<B> {
    #[inline(always)]
    fn splat(x: u64) -> Self {
        Pair(B::splat(x), B::splat(x))
    }
    #[inline(always)]
    fn shl(self, k: u32) -> Self {
        Pair(self.0.shl(k), self.1.shl(k))
    }
    #[inline(always)]
    fn shr(self, k: u32) -> Self {
        Pair(self.0.shr(k), self.1.shr(k))
    }
}

impl<V: Lanes> Lanes for Pair<V> {
    type T = V::T;
    type Mask = Pair<V::Mask>;
    type Bits = Pair<V::Bits>;
    const N: usize = 2 * V::N;

    #[inline(always)]
    fn splat(x: V::T) -> Self {
        Pair(V::splat(x), V::splat(x))
    }
    #[inline(always)]
    fn load(src: &[V::T]) -> Self {
        Pair(V::load(src), V::load(&src[V::N..]))
    }
    #[inline(always)]
    fn store(self, dst: &mut [V::T]) {
        self.0.store(dst);
        self.1.store(&mut dst[V::N..]);
    }
    #[inline(always)]
    fn mul_add(self, a: Self, b: Self) -> Self {
        Pair(self.0.mul_add(a.0, b.0), self.1.mul_add(a.1, b.1))
    }
    #[inline(always)]
    fn sqrt(self) -> Self {
        Pair(self.0.sqrt(), self.1.sqrt())
    }
    #[inline(always)]
    fn min(self, o: Self) -> Self {
        Pair(self.0.min(o.0), self.1.min(o.1))
    }
    #[inline(always)]
    fn max(self, o: Self) -> Self {
        Pair(self.0.max(o.0), self.1.max(o.1))
    }
    #[inline(always)]
    fn lt(self, o: Self) -> Self::Mask {
        Pair(self.0.lt(o.0), self.1.lt(o.1))
    }
    #[inline(always)]
    fn le(self, o: Self) -> Self::Mask {
        Pair(self.0.le(o.0), self.1.le(o.1))
    }
    #[inline(always)]
    fn eq(self, o: Self) -> Self::Mask {
        Pair(self.0.eq(o.0), self.1.eq(o.1))
    }
    #[inline(always)]
    fn select(mask: Self::Mask, a: Self, b: Self) -> Self {
        Pair(V::select(mask.0, a.0, b.0), V::select(mask.1, a.1, b.1))
    }
    #[inline(always)]
    fn to_bits(self) -> Self::Bits {
        Pair(self.0.to_bits(), self.1.to_bits())
    }
    #[inline(always)]
    fn from_bits(b: Self::Bits) -> Self {
        Pair(V::from_bits(b.0), V::from_bits(b.1))
    }
    #[inline(always)]
    fn square_error(self, square: Self) -> Self {
        Pair(self.0.square_error(square.0), self.1.square_error(square.1))
    }
    #[inline(always)]
    fn load_rows3(rows: &[[V::T; 3]]) -> V3<Self> {
        let (a, b) = (V::load_rows3(rows), V::load_rows3(&rows[V::N..]));
        V3 {
            x: Pair(a.x, b.x),
            y: Pair(a.y, b.y),
            z: Pair(a.z, b.z),
        }
    }
    #[inline(always)]
    fn store_rows4(rgba: [Self; 4], rows: &mut [[MaybeUninit<V::T>; 4]]) {
        let [r, g, b, a] = rgba;
        V::store_rows4([r.0, g.0, b.0, a.0], rows);
        V::store_rows4([r.1, g.1, b.1, a.1], &mut rows[V::N..]);
    }
}
