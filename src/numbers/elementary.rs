//! `exp` and `ln_1p` for `f32` and `f64` from IEEE basic operations and integer operations on
//! the bits only, without branches, over [`Lanes`]: one definition runs in every register width
//! and gives the same bits on every CPU (libm calls do neither).
//!
//! The algorithms are the classic ones: Cephes `expf` (degree-6 polynomial after reduction by
//! ln 2, ≤ 2 ulp), fdlibm `exp` (rational form, ≤ 1 ulp), fdlibm `log` (atanh series in
//! s = f/(2 + f), ≤ 1 ulp), with the log1p correction term for `ln_1p`. The measured maximum errors are
//! checked by the tests below.

// Coefficients are quoted as published (Cephes, fdlibm); the bit manipulation is on purpose.
#![allow(clippy::excessive_precision, clippy::unreadable_literal)]

use crate::simd::float::Float;
use crate::simd::lanes::{LaneBits, Lanes};

/// 1.5 · 2^23: `x + MAGIC − MAGIC` rounds an `f32` to the nearest integer (|x| < 2^22), and the
/// low bits of `x + MAGIC` hold that integer.
const MAGIC_F32: f32 = 12_582_912.0;
/// 1.5 · 2^52, the same for `f64`.
const MAGIC_F64: f64 = 6_755_399_441_055_744.0;

/// 2^k for an integer `k` in the normal exponent range, given as the two's complement bits of
/// `k`: the biased exponent shifted into place.
#[inline(always)]
fn pow2<V: Lanes>(k: V::Bits) -> V {
    let bias = V::Bits::splat(V::T::EXPONENT_BIAS);
    V::from_bits((k + bias).shl(V::T::MANTISSA_BITS))
}

/// `p · 2^k` for the bits of an integer `k`, in two exact steps of ⌊k/2⌋ and the rest, so k
/// from below the normal range (−150 in `f32`, −1075 in `f64`) to one past it needs no special
/// case. ⌊k/2⌋ is a logical shift of k biased by twice the exponent range (no instruction set
/// here has a 64-bit arithmetic shift).
#[inline(always)]
fn scale<V: Lanes>(p: V, k: V::Bits) -> V {
    let bias = 2 * (V::T::EXPONENT_BIAS + 1);
    let half = (k + V::Bits::splat(bias)).shr(1) - V::Bits::splat(bias / 2);
    p * pow2::<V>(half) * pow2::<V>(k - half)
}

/// `e^x` in `f32`, within 2 ulp for results in the normal range; 0 below −103.97 (the result
/// would be below the smallest subnormal), +inf above 88.73, NaN for NaN.
#[inline(always)]
pub fn exp_f32<V: Lanes<T = f32>>(x: V) -> V {
    const LOG2E: f32 = std::f32::consts::LOG2_E;
    const C1: f32 = 0.693_359_375; // ln 2 split so that k·C1 is exact
    const C2: f32 = -2.121_944_4e-4;
    const P: [f32; 6] = [
        1.987_569_15e-4,
        1.398_199_95e-3,
        8.333_451_9e-3,
        4.166_579_59e-2,
        1.666_666_55e-1,
        5.000_000_1e-1,
    ];
    const LO: f32 = -103.972_08;
    const HI: f32 = 88.722_84;
    let c = V::splat;
    let t = x.clamp(LO, HI);
    let biased = t * c(LOG2E) + c(MAGIC_F32);
    let kf = biased - c(MAGIC_F32);
    let k = biased.to_bits() - V::Bits::splat(MAGIC_F32.to_bits().into());
    let r = (t - kf * c(C1)) - kf * c(C2);
    // Estrin's scheme: three independent pairs, so the chain is three steps deep, not six.
    let r2 = r * r;
    let (a0, a1, a2) = (
        c(P[4]).mul_add(r, c(P[5])),
        c(P[2]).mul_add(r, c(P[3])),
        c(P[0]).mul_add(r, c(P[1])),
    );
    let p = r2.mul_add(r2.mul_add(a2, a1), a0).mul_add(r2, r) + c(1.0);
    let y = scale(p, k);
    V::select(
        x.lt(c(LO)),
        c(0.0),
        V::select(x.gt(c(HI)), c(f32::INFINITY), y),
    )
}

/// `e^x` in `f64`, within 1 ulp for results in the normal range; 0 below −745.14, +inf above
/// 709.79, NaN for NaN.
#[inline(always)]
pub fn exp_f64<V: Lanes<T = f64>>(x: V) -> V {
    const INV_LN2: f64 = std::f64::consts::LOG2_E;
    const LN2_HI: f64 = 6.931_471_803_691_238_164_90e-1;
    const LN2_LO: f64 = 1.908_214_929_270_587_700_02e-10;
    const P: [f64; 5] = [
        1.666_666_666_666_660_190_37e-1,
        -2.777_777_777_701_559_338_42e-3,
        6.613_756_321_437_934_361_17e-5,
        -1.653_390_220_546_525_153_90e-6,
        4.138_136_797_057_238_460_39e-8,
    ];
    const LO: f64 = -745.133_219_101_941_2;
    const HI: f64 = 709.782_712_893_384;
    let c = V::splat;
    let t = x.clamp(LO, HI);
    let biased = t * c(INV_LN2) + c(MAGIC_F64);
    let kf = biased - c(MAGIC_F64);
    let k = biased.to_bits() - V::Bits::splat(MAGIC_F64.to_bits());
    let hi = t - kf * c(LN2_HI);
    let lo = kf * c(LN2_LO);
    let r = hi - lo;
    let r2 = r * r;
    let poly = c(P[0]) + r2 * (c(P[1]) + r2 * (c(P[2]) + r2 * (c(P[3]) + r2 * c(P[4]))));
    let cr = r - r2 * poly;
    let p = c(1.0) - ((lo - (r * cr) / (c(2.0) - cr)) - hi);
    let y = scale(p, k);
    V::select(
        x.lt(c(LO)),
        c(0.0),
        V::select(x.gt(c(HI)), c(f64::INFINITY), y),
    )
}

/// ln(u) + c for a positive normal `u` (Cephes' `logf`): u = 2^k · m with m in [√½, √2),
/// ln m = f − f²/2 + f³·P(f) for f = m − 1. No division, so it costs no more than a few
/// multiplications in a vector. `c` is a small correction added with the low-order terms.
#[inline(always)]
fn ln_core_f32<V: Lanes<T = f32>>(u: V, c: V) -> V {
    const LN2_HI: f32 = 0.693_359_375; // ln 2 split so that k·LN2_HI is exact
    const LN2_LO: f32 = -2.121_944_4e-4;
    const P: [f32; 9] = [
        7.037_683_6e-2,
        -1.151_461_03e-1,
        1.167_699_87e-1,
        -1.242_014_08e-1,
        1.424_932_28e-1,
        -1.666_805_77e-1,
        2.000_071_48e-1,
        -2.499_999_4e-1,
        3.333_333_1e-1,
    ];
    let b = V::Bits::splat;
    let s = V::splat;
    let ix = u.to_bits() + b(0x3f80_0000 - 0x3f35_04f3);
    // The exponent k, exactly, through 2^23 + (ix >> 23) − 2^23 − 127 (at most 9 bits).
    let dk = V::from_bits(b(0x4b00_0000) | ix.shr(23)) - s(8_388_608.0 + 127.0);
    let m = V::from_bits((ix & b(0x007f_ffff)) + b(0x3f35_04f3));
    let f = m - s(1.0);
    let z = f * f;
    // Estrin's scheme (P[8 − k] multiplies f^k): four independent pairs, then powers of f²,
    // so the chain is four steps deep instead of nine.
    let z2 = z * z;
    let (a0, a1) = (s(P[7]).mul_add(f, s(P[8])), s(P[5]).mul_add(f, s(P[6])));
    let (a2, a3) = (s(P[3]).mul_add(f, s(P[4])), s(P[1]).mul_add(f, s(P[2])));
    let p = z2.mul_add(z2.mul_add(s(P[0]), z.mul_add(a3, a2)), z.mul_add(a1, a0));
    let y = p * f * z + (dk * s(LN2_LO) + c) - s(0.5) * z;
    (f + y) + dk * s(LN2_HI)
}

/// ln(u) + c for a positive normal `u` (fdlibm's `log`, on the high word).
#[inline(always)]
fn ln_core_f64<V: Lanes<T = f64>>(u: V, c: V) -> V {
    const LN2_HI: f64 = 6.931_471_803_691_238_164_90e-1;
    const LN2_LO: f64 = 1.908_214_929_270_587_700_02e-10;
    const LG: [f64; 7] = [
        6.666_666_666_666_735_130e-1,
        3.999_999_999_940_941_908e-1,
        2.857_142_874_366_239_149e-1,
        2.222_219_843_214_978_396e-1,
        1.818_357_216_161_805_012e-1,
        1.531_383_769_920_937_332e-1,
        1.479_819_860_511_658_591e-1,
    ];
    let b = V::Bits::splat;
    let s = V::splat;
    let bits = u.to_bits();
    let hx = bits.shr(32) + b(0x3ff0_0000 - 0x3fe6_a09e);
    // The exponent as an exact f64, through 2^52 + e − 2^52 (no integer-to-float instruction).
    let dk =
        V::from_bits(b(0x4330_0000_0000_0000) | hx.shr(20)) - s(4_503_599_627_370_496.0 + 1023.0);
    let m =
        V::from_bits(((hx & b(0x000f_ffff)) + b(0x3fe6_a09e)).shl(32) | (bits & b(0xffff_ffff)));
    let f = m - s(1.0);
    let hfsq = s(0.5) * f * f;
    let q = f / (s(2.0) + f);
    let z = q * q;
    let w = z * z;
    let t1 = w * (s(LG[1]) + w * (s(LG[3]) + w * s(LG[5])));
    let t2 = z * (s(LG[0]) + w * (s(LG[2]) + w * (s(LG[4]) + w * s(LG[6]))));
    q * (hfsq + (t2 + t1)) + (dk * s(LN2_LO) + c) - hfsq + f + dk * s(LN2_HI)
}

/// `ln(1 + x)` in `f32` for x in (−1, f32::MAX], within 2 ulp (also for tiny x).
#[cfg(test)]
#[inline(always)]
pub fn ln_1p_f32<V: Lanes<T = f32>>(x: V) -> V {
    let u = V::splat(1.0) + x;
    // ln(1 + x) = ln u + ln(1 + e/u) with e = x − (u − 1), the rounding error of 1 + x, exact
    // (u − 1 is exact by Sterbenz where it matters).
    ln_core_f32(u, (x - (u - V::splat(1.0))) / u)
}

/// `ln(1 + x)` in `f32` for x in (−1, ½], within 2 ulp, without a division: the kernel's
/// ln(1 − x) near a highlight.
///
/// The correction e/u of `ln_1p_f32` (the whole domain, kept for the tests) becomes e·(2 − u), which is within (1 − u)²/u of it: a
/// quarter of a term below 2^-25 at worst (u = ½; for u ≤ ½ the sum 1 + x is exact and e = 0).
#[inline(always)]
pub fn ln_1p_le_half_f32<V: Lanes<T = f32>>(x: V) -> V {
    let u = V::splat(1.0) + x;
    ln_core_f32(u, (x - (u - V::splat(1.0))) * (V::splat(2.0) - u))
}

/// `ln(1 + x)` in `f64` for x in (−1, f64::MAX], within 1 ulp (also for tiny x).
#[inline(always)]
pub fn ln_1p_f64<V: Lanes<T = f64>>(x: V) -> V {
    let u = V::splat(1.0) + x;
    ln_core_f64(u, (x - (u - V::splat(1.0))) / u)
}

/// The argument of the core logarithm for `ln x`: subnormal x lifted by `lift` = 2^k into the
/// range of its bit manipulation, and the lanes lifted.
#[inline(always)]
fn lifted<V: Lanes>(x: V, lift: V::T) -> (V, V::Mask) {
    let subnormal = x.lt(V::splat(V::T::MIN_POSITIVE));
    (V::select(subnormal, x * V::splat(lift), x), subnormal)
}

/// `ln x` from `y`, the core logarithm of the lifted x: k ln 2 (`ln_lift`) taken off in the
/// lifted lanes; −inf at 0, +inf at +inf, NaN for NaN and negative x.
#[inline(always)]
fn ln_special<V: Lanes>(x: V, y: V, subnormal: V::Mask, ln_lift: V::T) -> V {
    let s = V::splat;
    let zero = s(V::T::ZERO);
    let y = V::select(subnormal, y - s(ln_lift), y);
    let y = V::select(x.eq(s(V::T::INFINITY)), x, y);
    let y = V::select(!x.eq(x) | x.lt(zero), s(V::T::NAN), y);
    V::select(x.eq(zero), -s(V::T::INFINITY), y)
}

/// `ln x` in `f32` for every x ≥ 0: within 2 ulp, −inf at 0, +inf at +inf, NaN for NaN and
/// negative x.
#[inline(always)]
pub fn ln_f32<V: Lanes<T = f32>>(x: V) -> V {
    let (u, subnormal) = lifted(x, 16_777_216.0); // 2^24
    ln_special(x, ln_core_f32(u, V::splat(0.0)), subnormal, 16.635_532) // 24 ln 2
}

/// `ln x` in `f64` for every x ≥ 0: within 1 ulp, −inf at 0, +inf at +inf, NaN for NaN and
/// negative x.
#[inline(always)]
pub fn ln_f64<V: Lanes<T = f64>>(x: V) -> V {
    let (u, subnormal) = lifted(x, 18_014_398_509_481_984.0); // 2^54
    ln_special(
        x,
        ln_core_f64(u, V::splat(0.0)),
        subnormal,
        37.429_947_750_237_04,
    ) // 54 ln 2
}

/// A float type with its lane-wise elementary functions: which of the functions above its
/// lanes run.
pub trait Elementary: Float {
    /// `ln(1 + x)` lane by lane for x in (−1, ½], accurate near 0 (within 2 ulp in f32, 1 ulp
    /// in f64, the same bits on every CPU).
    fn ln_1p_lanes<V: Lanes<T = Self>>(x: V) -> V;
    /// `e^x` lane by lane (within 2 ulp in f32, 1 ulp in f64).
    fn exp_lanes<V: Lanes<T = Self>>(x: V) -> V;
    /// `ln x` lane by lane for x ≥ 0.
    fn ln_lanes<V: Lanes<T = Self>>(x: V) -> V;
}

impl Elementary for f32 {
    #[inline(always)]
    fn ln_1p_lanes<V: Lanes<T = Self>>(x: V) -> V {
        ln_1p_le_half_f32(x)
    }
    #[inline(always)]
    fn exp_lanes<V: Lanes<T = Self>>(x: V) -> V {
        exp_f32(x)
    }
    #[inline(always)]
    fn ln_lanes<V: Lanes<T = Self>>(x: V) -> V {
        ln_f32(x)
    }
}

impl Elementary for f64 {
    #[inline(always)]
    fn ln_1p_lanes<V: Lanes<T = Self>>(x: V) -> V {
        ln_1p_f64(x)
    }
    #[inline(always)]
    fn exp_lanes<V: Lanes<T = Self>>(x: V) -> V {
        exp_f64(x)
    }
    #[inline(always)]
    fn ln_lanes<V: Lanes<T = Self>>(x: V) -> V {
        ln_f64(x)
    }
}

/// The elementary functions as methods of [`Lanes`] whose element type has them.
pub trait ElementaryLanes: Lanes {
    /// Lane-wise `e^x` (see [`Elementary::exp_lanes`]).
    #[must_use]
    fn exp(self) -> Self;
    /// Lane-wise `ln(1 + x)` for x in (−1, ½] (see [`Elementary::ln_1p_lanes`]).
    #[must_use]
    fn ln_1p(self) -> Self;
    /// Lane-wise `ln x` (see [`Elementary::ln_lanes`]).
    #[must_use]
    fn ln(self) -> Self;
}

impl<V: Lanes> ElementaryLanes for V
where
    V::T: Elementary,
{
    #[inline(always)]
    fn exp(self) -> Self {
        V::T::exp_lanes(self)
    }
    #[inline(always)]
    fn ln_1p(self) -> Self {
        V::T::ln_1p_lanes(self)
    }
    #[inline(always)]
    fn ln(self) -> Self {
        V::T::ln_lanes(self)
    }
}

#[cfg(test)]
mod tests {
    use super::ElementaryLanes;
    use crate::numbers::real::Real;
    use crate::simd::dispatch::{Isa, LaneWork};
    use crate::simd::lanes::{InstructionSet, Lanes, Portable, MAX_LANES};
    use scalar::{exp_f32, exp_f64, ln_1p_f32, ln_1p_f64, ln_1p_le_half_f32, ln_f32, ln_f64};

    /// The functions on one value.
    mod scalar {
        use crate::simd::lanes::Pack;

        macro_rules! one {
            ($($name:ident: $t:ty;)*) => {$(
                pub fn $name(x: $t) -> $t {
                    super::super::$name(Pack([x])).0[0]
                }
            )*};
        }

        one!(
            exp_f32: f32; exp_f64: f64; ln_1p_f32: f32; ln_1p_le_half_f32: f32;
            ln_1p_f64: f64; ln_f32: f32; ln_f64: f64;
        );
    }

    /// `exp`, `ln_1p` (on its domain) and `ln` of `x` with the registers of `S`, as bits.
    struct Sweep<'a, T> {
        x: &'a [T],
        bits: &'a mut [Vec<u64>; 3],
    }

    impl<T: Real> LaneWork for Sweep<'_, T> {
        #[inline(always)]
        fn run<S: InstructionSet>(self) {
            type V<T, S> = <T as Real>::Vector<S>;
            let n = V::<T, S>::N;
            let mut out = [T::ZERO; MAX_LANES];
            for chunk in self.x.chunks_exact(n) {
                let x = V::<T, S>::load(chunk);
                let small = x.min(V::<T, S>::splat(T::HALF));
                for (bits, y) in self.bits.iter_mut().zip([x.exp(), small.ln_1p(), x.ln()]) {
                    y.store(&mut out);
                    bits.extend(out[..n].iter().map(|v| v.to_f64().to_bits()));
                }
            }
        }
    }

    fn sweep_bits<T: Real>(isa: Option<Isa>) -> [Vec<u64>; 3] {
        let specials = [
            0.0,
            -0.0,
            1.0,
            -1.0,
            0.5,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NAN,
        ];
        let x: Vec<T> = (0..4096)
            .map(|i| {
                let e = f64::from(i % 700) - 350.0;
                (1.0 + f64::from(i) / 4096.0)
                    * 2f64.powf(e / 2.0)
                    * if i % 3 == 0 { -1.0 } else { 1.0 }
            })
            .chain(specials)
            .chain(
                [1e-310, -0.999_999, 1e-40, 3e-45]
                    .into_iter()
                    .cycle()
                    .take(MAX_LANES - specials.len()),
            )
            .map(T::from_f64)
            .collect();
        let mut bits = [Vec::new(), Vec::new(), Vec::new()];
        let sweep = Sweep {
            x: &x,
            bits: &mut bits,
        };
        match isa {
            Some(isa) => isa.run(sweep),
            None => sweep.run::<Portable>(),
        }
        bits
    }

    #[test]
    fn every_instruction_set_gives_the_same_bits() {
        for isa in Isa::ALL.into_iter().filter(|i| i.supported()) {
            assert!(
                sweep_bits::<f32>(Some(isa)) == sweep_bits::<f32>(None),
                "{isa:?}, f32"
            );
            assert!(
                sweep_bits::<f64>(Some(isa)) == sweep_bits::<f64>(None),
                "{isa:?}, f64"
            );
        }
    }

    /// The distance in units in the last place of `exact` between `got` and `exact`.
    fn ulps_f32(got: f32, exact: f64) -> f64 {
        let e = exact as f32;
        let ulp = f64::from(f32::from_bits(e.abs().to_bits() + 1) - e.abs());
        (f64::from(got) - exact).abs() / ulp
    }

    fn ulps_f64(got: f64, exact: f64) -> f64 {
        let ulp = f64::from_bits(exact.abs().to_bits() + 1) - exact.abs();
        (got - exact).abs() / ulp
    }

    /// A deterministic sweep: `count` points spread log-uniformly and linearly over the range.
    fn sweep(lo: f64, hi: f64, count: usize) -> impl Iterator<Item = f64> {
        (0..count).map(move |i| lo + (hi - lo) * (i as f64 + 0.5) / count as f64)
    }

    #[test]
    fn exp_f32_is_within_2_ulp() {
        let worst = sweep(-87.0, 88.7, 2_000_000)
            .map(|x| {
                let x = x as f32;
                ulps_f32(exp_f32(x), f64::from(x).exp())
            })
            .fold(0.0, f64::max);
        assert!(worst <= 2.0, "{worst} ulp");
        assert_eq!(exp_f32(0.0), 1.0);
        assert_eq!(exp_f32(-200.0), 0.0);
        assert_eq!(exp_f32(100.0), f32::INFINITY);
        assert!(exp_f32(f32::NAN).is_nan());
        assert!(exp_f32(-100.0) > 0.0, "subnormal results are kept");
    }

    #[test]
    fn exp_f64_is_within_1_ulp() {
        let worst = sweep(-708.0, 709.0, 2_000_000)
            .map(|x| ulps_f64(exp_f64(x), x.exp()))
            .fold(0.0, f64::max);
        assert!(worst <= 1.0, "{worst} ulp");
        assert_eq!(exp_f64(0.0), 1.0);
        assert_eq!(exp_f64(-800.0), 0.0);
        assert_eq!(exp_f64(710.0), f64::INFINITY);
    }

    #[test]
    fn ln_1p_f32_is_within_2_ulp_near_zero_and_far() {
        let tiny = sweep(-30.0, -1.0, 500_000).flat_map(|e| [10f64.powf(e), -(10f64.powf(e))]);
        let wide = sweep(-0.999_999, 1e6, 1_000_000);
        let worst = tiny
            .chain(wide)
            .map(|x| {
                let x = x as f32;
                ulps_f32(ln_1p_f32(x), f64::from(x).ln_1p())
            })
            .fold(0.0, f64::max);
        assert!(worst <= 2.0, "{worst} ulp");
        assert_eq!(ln_1p_f32(0.0), 0.0);
    }

    #[test]
    fn ln_1p_le_half_f32_is_within_2_ulp_on_its_domain() {
        let tiny = sweep(-30.0, -0.31, 500_000).flat_map(|e| [10f64.powf(e), -(10f64.powf(e))]);
        let wide = sweep(-0.999_999, 0.5, 1_000_000);
        let worst = tiny
            .chain(wide)
            .map(|x| {
                let x = x as f32;
                ulps_f32(ln_1p_le_half_f32(x), f64::from(x).ln_1p())
            })
            .fold(0.0, f64::max);
        assert!(worst <= 2.0, "{worst} ulp");
    }

    #[test]
    fn ln_1p_f64_is_within_1_ulp_near_zero_and_far() {
        let tiny = sweep(-300.0, -1.0, 500_000).flat_map(|e| [10f64.powf(e), -(10f64.powf(e))]);
        let wide = sweep(-0.999_999_999, 1e12, 1_000_000);
        let worst = tiny
            .chain(wide)
            .map(|x| ulps_f64(ln_1p_f64(x), x.ln_1p()))
            .fold(0.0, f64::max);
        assert!(worst <= 1.0, "{worst} ulp");
        assert_eq!(ln_1p_f64(0.0), 0.0);
    }

    #[test]
    fn ln_f32_is_within_2_ulp_everywhere() {
        let worst = sweep(-45.0, 38.0, 1_000_000)
            .map(|e| 10f64.powf(e) as f32)
            .chain(sweep(0.5, 2.0, 500_000).map(|x| x as f32))
            .filter(|x| *x > 0.0 && x.is_finite())
            .map(|x| ulps_f32(ln_f32(x), f64::from(x).ln()))
            .fold(0.0, f64::max);
        assert!(worst <= 2.0, "{worst} ulp");
        assert_eq!(ln_f32(0.0), f32::NEG_INFINITY);
        assert_eq!(ln_f32(f32::INFINITY), f32::INFINITY);
        assert!(ln_f32(-1.0).is_nan());
    }

    #[test]
    fn ln_f64_is_within_1_ulp_everywhere() {
        let worst = sweep(-1070.0, 308.0, 1_000_000)
            .map(|e| 10f64.powf(e / 3.3))
            .chain(sweep(0.5, 2.0, 500_000))
            .map(|x| ulps_f64(ln_f64(x), x.ln()))
            .fold(0.0, f64::max);
        assert!(worst <= 1.0, "{worst} ulp");
        assert_eq!(ln_f64(1.0), 0.0);
        assert_eq!(ln_f64(0.0), f64::NEG_INFINITY);
        assert_eq!(ln_f64(f64::INFINITY), f64::INFINITY);
        assert!(ln_f64(-1.0).is_nan() && ln_f64(f64::NAN).is_nan());
        assert!((ln_f64(5e-324) - 5e-324f64.ln()).abs() < 1e-12);
    }
}
