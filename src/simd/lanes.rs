//! Lanes: one value per vertex of a block, in one vector register where the CPU has one.
//!
//! [`Lanes`] is the vector of `f32` or `f64` the kernel computes with; its implementations are
//! the registers of each instruction set ([`x86`]: SSE2, AVX2, AVX-512) and plain arrays
//! ([`Pack`], for other CPUs and for one-lane evaluation); an [`InstructionSet`] names the
//! register type of `f32` and of `f64` in each (`crate::simd::dispatch` picks one at run time). The
//! kernel and the elementary functions are written once against the trait. Only IEEE basic
//! operations (+, −, ×, ÷, √, the fused multiply-add, comparisons, selects, integer operations
//! on the bits) are offered, so every implementation gives the same bits: the fused
//! multiply-add ([`Lanes::mul_add`], and [`Lanes::square_error`], an exact quantity) is one
//! instruction with AVX2 and AVX-512, and computed exactly another way elsewhere.

mod pair;
mod portable;
#[cfg(target_arch = "x86_64")]
mod sse2_fma;
#[cfg(target_arch = "x86_64")]
pub(crate) mod x86;

use std::mem::MaybeUninit;
use std::ops::{Add, BitAnd, BitOr, Div, Mul, Neg, Not, Sub};

pub use pair::Pair;
pub use portable::Pack;

use crate::simd::float::Float;

/// The most lanes any implementation has: the size of the buffers that hold one block.
pub const MAX_LANES: usize = 64;

/// Four registers as one block: four chains for the CPU to overlap where a register is
/// narrow and a block's values spill anyway.
pub(crate) type Quad<V> = Pair<Pair<V>>;

/// The register types of one instruction set.
pub trait InstructionSet {
    /// Lanes of `f32`.
    type F32: Lanes<T = f32>;
    /// Lanes of `f64`.
    type F64: Lanes<T = f64>;
    /// The lanes of one block of the kernel made of registers `V`: as many registers as give
    /// the polynomials of `exp` and `ln` independent chains to overlap without holding more
    /// values than the registers.
    type Block<V: Lanes>: Lanes<T = V::T>;
}

/// SSE2, the x86-64 baseline.
#[cfg(target_arch = "x86_64")]
pub(crate) struct Sse2;

#[cfg(target_arch = "x86_64")]
impl InstructionSet for Sse2 {
    type F32 = x86::F32x4;
    type F64 = x86::F64x2;
    type Block<V: Lanes> = Quad<V>;
}

/// AVX2 with FMA.
#[cfg(target_arch = "x86_64")]
pub(crate) struct Avx2;

#[cfg(target_arch = "x86_64")]
impl InstructionSet for Avx2 {
    type F32 = x86::F32x8;
    type F64 = x86::F64x4;
    type Block<V: Lanes> = Pair<V>;
}

/// AVX-512 F, BW, DQ and VL.
#[cfg(target_arch = "x86_64")]
pub(crate) struct Avx512;

#[cfg(target_arch = "x86_64")]
impl InstructionSet for Avx512 {
    type F32 = x86::F32x16;
    type F64 = x86::F64x8;
    type Block<V: Lanes> = Pair<V>;
}

/// Arrays for other CPUs, which LLVM vectorises as it can.
#[cfg_attr(all(target_arch = "x86_64", not(test)), allow(dead_code))]
pub(crate) struct Portable;

impl InstructionSet for Portable {
    type F32 = Pack<f32, 8>;
    type F64 = Pack<f64, 4>;
    type Block<V: Lanes> = Pair<V>;
}

/// One lane: the kernel's formulas applied to single values (the per-call constants).
pub(crate) struct Scalar;

impl InstructionSet for Scalar {
    type F32 = Pack<f32, 1>;
    type F64 = Pack<f64, 1>;
    type Block<V: Lanes> = V;
}

/// The result of a lane-wise comparison.
pub trait LaneMask:
    Copy + BitAnd<Output = Self> + BitOr<Output = Self> + Not<Output = Self>
{
    /// The number of lanes.
    const N: usize;
    /// Every lane set to `b`.
    fn splat(b: bool) -> Self;
    /// Bit `i` set when lane `i` is.
    fn bitmask(self) -> u64;
    /// True when every lane is set.
    fn all(self) -> bool;
}

/// The bits of a [`Lanes`] as unsigned integers of the same width (u32 for `f32`, u64 for
/// `f64`), with wrapping arithmetic and logical shifts.
pub trait LaneBits:
    Copy + Add<Output = Self> + Sub<Output = Self> + BitAnd<Output = Self> + BitOr<Output = Self>
{
    /// Every lane set to `x` (truncated to the lane width).
    fn splat(x: u64) -> Self;
    /// Each lane shifted left by `k` bits.
    #[must_use]
    fn shl(self, k: u32) -> Self;
    /// Each lane shifted right by `k` bits, filling with zeros.
    #[must_use]
    fn shr(self, k: u32) -> Self;
}

/// `N` values of `T`, one per vertex of a block.
///
/// `min` and `max` keep a NaN of `self` (`self.min(o)` is `o` where `o < self`, else `self`),
/// which is what x86's `minps o, self` computes.
pub trait Lanes:
    Copy
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
{
    /// The element type.
    type T: Float;
    /// A comparison's result.
    type Mask: LaneMask;
    /// The bits of the lanes.
    type Bits: LaneBits;
    /// The number of lanes (at most [`MAX_LANES`]).
    const N: usize;

    /// Every lane set to `x`.
    fn splat(x: Self::T) -> Self;
    /// The first `N` values of `src`.
    fn load(src: &[Self::T]) -> Self;
    /// Writes the lanes to the first `N` values of `dst`.
    fn store(self, dst: &mut [Self::T]);
    /// Lane-wise square root.
    #[must_use]
    fn sqrt(self) -> Self;
    /// Lane-wise minimum; a NaN lane of `self` stays NaN.
    #[must_use]
    fn min(self, o: Self) -> Self;
    /// Lane-wise maximum; a NaN lane of `self` stays NaN.
    #[must_use]
    fn max(self, o: Self) -> Self;
    /// Lane-wise `self < o`.
    fn lt(self, o: Self) -> Self::Mask;
    /// Lane-wise `self <= o`.
    fn le(self, o: Self) -> Self::Mask;
    /// Lane-wise `self == o`.
    fn eq(self, o: Self) -> Self::Mask;
    /// `a` where `mask` is set, else `b`.
    fn select(mask: Self::Mask, a: Self, b: Self) -> Self;
    /// The bits of every lane.
    fn to_bits(self) -> Self::Bits;
    /// The lanes with bits `b`.
    fn from_bits(b: Self::Bits) -> Self;

    /// `self · a + b` lane by lane, rounded once (a fused multiply-add): one instruction with
    /// AVX2 and AVX-512, the same value computed exactly elsewhere, so every instruction set
    /// gives the same bits. This default goes lane by lane through [`Float::mul_add`].
    #[inline(always)]
    #[must_use]
    fn mul_add(self, a: Self, b: Self) -> Self {
        let mut v = [[Self::T::ZERO; MAX_LANES]; 3];
        for (values, lanes) in v.iter_mut().zip([self, a, b]) {
            lanes.store(values);
        }
        let [x, y, z] = v;
        let mut out = [Self::T::ZERO; MAX_LANES];
        for (i, o) in out.iter_mut().enumerate().take(Self::N) {
            *o = x[i].mul_add(y[i], z[i]);
        }
        Self::load(&out)
    }

    /// `x·x − square` for `square` = x·x rounded: the rounding error of the square, exact
    /// wherever x·x neither over- nor underflows. Veltkamp's split and Dekker's product here;
    /// a fused multiply-add where the CPU has one (the same exact value).
    #[inline(always)]
    #[must_use]
    fn square_error(self, square: Self) -> Self {
        let c = self * Self::splat(Self::T::SPLIT);
        let high = c - (c - self);
        let low = self - high;
        ((high * high - square) + (high + high) * low) + low * low
    }

    /// `N` rows `[x, y, z]` (`rows` holds exactly `N`) as three lanes.
    #[inline(always)]
    fn load_rows3(rows: &[[Self::T; 3]]) -> V3<Self> {
        let mut planes = [[Self::T::ZERO; MAX_LANES]; 3];
        for (i, row) in rows.iter().enumerate().take(Self::N) {
            for (plane, &value) in planes.iter_mut().zip(row) {
                plane[i] = value;
            }
        }
        V3 {
            x: Self::load(&planes[0]),
            y: Self::load(&planes[1]),
            z: Self::load(&planes[2]),
        }
    }

    /// Writes four lanes as `N` rows `[r, g, b, a]` (`rows` holds exactly `N`; it need not be
    /// initialised, and is written, never read).
    #[inline(always)]
    fn store_rows4(rgba: [Self; 4], rows: &mut [[MaybeUninit<Self::T>; 4]]) {
        let mut planes = [[Self::T::ZERO; MAX_LANES]; 4];
        for (plane, lanes) in planes.iter_mut().zip(rgba) {
            lanes.store(plane);
        }
        for (i, row) in rows.iter_mut().enumerate().take(Self::N) {
            for (k, value) in row.iter_mut().enumerate() {
                value.write(planes[k][i]);
            }
        }
    }

    /// Lane-wise `self > o`.
    #[inline(always)]
    fn gt(self, o: Self) -> Self::Mask {
        o.lt(self)
    }

    /// Lane-wise `self >= o`.
    #[inline(always)]
    fn ge(self, o: Self) -> Self::Mask {
        o.le(self)
    }

    /// `self` where `mask` is set, else 0: a select, never a multiplication by a 0/1 mask
    /// (0 · inf would be NaN).
    #[inline(always)]
    #[must_use]
    fn or_zero(self, mask: Self::Mask) -> Self {
        Self::select(mask, self, Self::splat(Self::T::ZERO))
    }

    /// The lanes that are neither NaN nor infinite (x − x is 0 exactly for finite x).
    #[inline(always)]
    #[allow(clippy::eq_op)]
    fn is_finite(self) -> Self::Mask {
        (self - self).eq(Self::splat(Self::T::ZERO))
    }

    /// `self` clamped to [`lo`, `hi`] lane by lane; NaN stays NaN.
    #[inline(always)]
    #[must_use]
    fn clamp(self, lo: Self::T, hi: Self::T) -> Self {
        self.max(Self::splat(lo)).min(Self::splat(hi))
    }

    /// Lane `i`.
    #[inline(always)]
    fn lane(self, i: usize) -> Self::T {
        let mut values = [Self::T::ZERO; MAX_LANES];
        self.store(&mut values);
        values[i]
    }
}

/// A 3-vector of lanes: `N` vectors, stored as x, y and z lanes.
#[must_use]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct V3<V> {
    /// The x components.
    pub x: V,
    /// The y components.
    pub y: V,
    /// The z components.
    pub z: V,
}

impl<V: Lanes> V3<V> {
    /// The zero vector in every lane.
    #[inline(always)]
    pub fn zero() -> Self {
        Self::splat([V::T::ZERO; 3])
    }

    /// The vector `v` in every lane.
    #[inline(always)]
    pub fn splat(v: [V::T; 3]) -> Self {
        Self {
            x: V::splat(v[0]),
            y: V::splat(v[1]),
            z: V::splat(v[2]),
        }
    }

    /// The vector of lane `i`.
    #[inline(always)]
    pub fn lane(&self, i: usize) -> [V::T; 3] {
        [self.x.lane(i), self.y.lane(i), self.z.lane(i)]
    }

    /// The dot product `(x·x' + y·y') + z·z'`, in glam's order, unfused: `glshade.glsl` forms
    /// it the same way on GPUs, which need not fuse (llvmpipe does not).
    #[inline(always)]
    pub fn dot(self, o: Self) -> V {
        self.x * o.x + self.y * o.y + self.z * o.z
    }

    /// The cross product `self × o`, each component `a·b − c·d` as one product and one fused
    /// multiply-add (two roundings, none lost to the difference's cancellation beyond them).
    #[inline(always)]
    pub fn cross(self, o: Self) -> Self {
        Self {
            x: self.y.mul_add(o.z, -(self.z * o.y)),
            y: self.z.mul_add(o.x, -(self.x * o.z)),
            z: self.x.mul_add(o.y, -(self.y * o.x)),
        }
    }

    /// `self ⊙ o + c`, each component rounded once.
    #[inline(always)]
    pub fn mul_add(self, o: Self, c: Self) -> Self {
        Self {
            x: self.x.mul_add(o.x, c.x),
            y: self.y.mul_add(o.y, c.y),
            z: self.z.mul_add(o.z, c.z),
        }
    }

    /// Every component times `s`.
    #[inline(always)]
    pub fn scale(self, s: V) -> Self {
        Self {
            x: self.x * s,
            y: self.y * s,
            z: self.z * s,
        }
    }

    /// Every component divided by `s`.
    #[inline(always)]
    pub fn div_by(self, s: V) -> Self {
        Self {
            x: self.x / s,
            y: self.y / s,
            z: self.z / s,
        }
    }

    /// Component-wise product.
    #[inline(always)]
    pub fn mul_elements(self, o: Self) -> Self {
        Self {
            x: self.x * o.x,
            y: self.y * o.y,
            z: self.z * o.z,
        }
    }

    /// The lanes whose three components are finite.
    #[inline(always)]
    pub fn is_finite(self) -> V::Mask {
        self.x.is_finite() & self.y.is_finite() & self.z.is_finite()
    }

    /// The lanes holding the zero vector.
    #[inline(always)]
    pub fn is_zero(self) -> V::Mask {
        let z = V::splat(V::T::ZERO);
        self.x.eq(z) & self.y.eq(z) & self.z.eq(z)
    }
}

impl<V: Lanes> Add for V3<V> {
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

impl<V: Lanes> Sub for V3<V> {
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

impl<V: Lanes> Neg for V3<V> {
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

/// `[f(0), …, f(N − 1)]` for the kernels' per-channel lanes. `std::array::from_fn` and `map`
/// run the closure inside functions of the standard library that are compiled without the
/// kernel's target features, where each vector operation became a call (a call that spilled
/// the block: 16 and 32 lights ran 1.21 and 1.14 times as fast without one on a Zen 2).
#[inline(always)]
pub fn each<V: Lanes, const N: usize>(mut f: impl FnMut(usize) -> V) -> [V; N] {
    let mut out = [V::splat(V::T::ZERO); N];
    for (i, lane) in out.iter_mut().enumerate() {
        *lane = f(i);
    }
    out
}

/// The unit vector in the direction of `v` and the length of `v`, lane by lane; `(0, 0)` for
/// the zero vector.
///
/// Exact for every finite `v`: when |v|² is subnormal or overflows, `v` is first scaled by an
/// exact power of two ([`Float::UPSCALE`] or [`Float::DOWNSCALE`]), which changes no direction bit.
/// Such lanes are rare, so they leave the vector path for a scalar one. The length itself may
/// round to infinity for |v| beyond the type's range. Each component is divided by the length,
/// so an axis-aligned vector gives an exact unit vector.
#[inline(always)]
pub fn normalize_and_length<V: Lanes>(v: V3<V>) -> (V3<V>, V) {
    normalize_by::<V, true>(v)
}

/// [`normalize_and_length`] with one division and three products instead of three divisions
/// (within 1 ulp of it): for the per-light vectors of the kernel, where the vector divider is
/// the scarcest unit.
#[inline(always)]
pub fn normalize_and_length_fast<V: Lanes>(v: V3<V>) -> (V3<V>, V) {
    normalize_by::<V, false>(v)
}

/// [`normalize_and_length_fast`] with the reciprocal of the length too: the unit vector, |v|
/// and 1/|v| (∞ for a zero `v`, NaN for a non-finite one), from the one division the unit
/// vector takes, for a light's falloff in 1/d.
#[inline(always)]
pub fn normalize_and_lengths_fast<V: Lanes>(v: V3<V>) -> (V3<V>, V, V) {
    let len2 = v.dot(v);
    let ok = len2.ge(V::splat(V::T::MIN_POSITIVE)) & len2.le(V::splat(V::T::MAX));
    if !ok.all() {
        let (unit, length) = rescaled::<V, false>(&v);
        return (unit, length, V::splat(V::T::ONE) / length);
    }
    let length = len2.sqrt();
    let inverse = V::splat(V::T::ONE) / length;
    (v.scale(inverse), length, inverse)
}

#[inline(always)]
fn normalize_by<V: Lanes, const DIVIDE: bool>(v: V3<V>) -> (V3<V>, V) {
    let len2 = v.dot(v);
    let ok = len2.ge(V::splat(V::T::MIN_POSITIVE)) & len2.le(V::splat(V::T::MAX));
    if !ok.all() {
        return rescaled::<V, DIVIDE>(&v);
    }
    let len = len2.sqrt();
    let unit = if DIVIDE {
        v.div_by(len)
    } else {
        v.scale(V::splat(V::T::ONE) / len)
    };
    (unit, len)
}

/// [`normalize_and_length`] for a block with a lane whose squared length is zero, subnormal,
/// infinite or NaN: those lanes one at a time. It takes `v` by reference and recomputes the
/// rest, so the common path passes nothing through memory to it.
#[cold]
#[inline(never)]
fn rescaled<V: Lanes, const DIVIDE: bool>(v: &V3<V>) -> (V3<V>, V) {
    let buffer = |lanes: V| {
        let mut values = [V::T::ZERO; MAX_LANES];
        lanes.store(&mut values);
        values
    };
    let (vx, vy, vz) = (buffer(v.x), buffer(v.y), buffer(v.z));
    let (mut ux, mut uy, mut uz, mut l) = (
        [V::T::ZERO; MAX_LANES],
        [V::T::ZERO; MAX_LANES],
        [V::T::ZERO; MAX_LANES],
        [V::T::ZERO; MAX_LANES],
    );
    for i in 0..V::N {
        let [x, y, z] = [vx[i], vy[i], vz[i]];
        // The same operations as the vector path, lane by lane.
        let len2 = x * x + y * y + z * z;
        let scale = if len2 >= V::T::MIN_POSITIVE && len2 <= V::T::MAX {
            V::T::ONE
        } else if x == V::T::ZERO && y == V::T::ZERO && z == V::T::ZERO {
            (ux[i], uy[i], uz[i], l[i]) = (V::T::ZERO, V::T::ZERO, V::T::ZERO, V::T::ZERO);
            continue;
        } else if !(x.is_finite() && y.is_finite() && z.is_finite()) {
            (ux[i], uy[i], uz[i], l[i]) = (V::T::NAN, V::T::NAN, V::T::NAN, V::T::NAN);
            continue;
        } else if len2 < V::T::MIN_POSITIVE {
            V::T::UPSCALE
        } else {
            V::T::DOWNSCALE
        };
        let (x, y, z) = (x * scale, y * scale, z * scale);
        let length = (x * x + y * y + z * z).sqrt();
        let u = if DIVIDE {
            [x / length, y / length, z / length]
        } else {
            let r = V::T::ONE / length;
            [x * r, y * r, z * r]
        };
        (ux[i], uy[i], uz[i], l[i]) = (u[0], u[1], u[2], length / scale);
    }
    (
        V3 {
            x: V::load(&ux),
            y: V::load(&uy),
            z: V::load(&uz),
        },
        V::load(&l),
    )
}

/// The unit vector in the direction of `v`, or zero (see [`normalize_and_length_fast`]).
#[inline(always)]
pub fn normalize_or_zero_fast<V: Lanes>(v: V3<V>) -> V3<V> {
    normalize_and_length_fast(v).0
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn selects_never_multiply() {
        let a = Pack::<f32, 4>([f32::INFINITY, 1.0, f32::NAN, -2.0]);
        let m = a.gt(Pack::splat(0.0));
        assert_eq!(m.bitmask(), 0b0011);
        let z = a.or_zero(m);
        assert_eq!(z.0[..2], [f32::INFINITY, 1.0]);
        assert_eq!(z.0[2..], [0.0, 0.0]);
        assert_eq!(a.is_finite().bitmask(), 0b1010);
        assert!(a.clamp(0.0, 1.0).0[2].is_nan(), "clamp keeps NaN");
    }

    #[test]
    fn normalisation_is_exact_at_any_scale_and_zero_for_zero() {
        let v = V3::<Pack<f32, 4>> {
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
