//! The elementary functions of `accuracy="display"`: `exp` and `ln(1 + x)` with the lowest
//! polynomial degrees whose error keeps every output within 2^-10 of the exact value (a quarter
//! of an 8-bit step), one definition for `f32` and `f64` over [`Lanes`], from IEEE basic
//! operations only, so the display tier also gives the same bits on every CPU.
//!
//! Errors (relative, measured by the tests below over the domains the kernel uses):
//! `exp` ≤ 4e-6 (degree 4 in 2^r, r in [−½, ½]; in `f32` up to 7e-6 for |x| near 88, from
//! the rounding of x·log2 e), `ln_1p` ≤ 2e-6 (degree 4 in the tail of ln(1 + f), f in
//! [√½ − 1, √2 − 1]). A power exp(s·ln(1 − x)) of a unit cosine then errs by at
//! most 2e-6/e + 4e-6 absolutely; `tests/core/accuracy/test_stiff.py` holds the tier to 2^-10.

// Coefficients are fitted to the minimax relative error (reweighted least squares).
#![allow(clippy::excessive_precision, clippy::unreadable_literal)]

use crate::numbers::elementary::{ElementaryLanes, Tier};
use crate::simd::float::Float;
use crate::simd::lanes::{LaneBits, Lanes};

/// The display tier's functions; see the module.
pub struct Display;

/// `c` in the lanes' type.
#[inline(always)]
fn c<V: Lanes>(x: f64) -> V {
    V::splat(V::T::from_f64(x))
}

/// 2^k exactly, for k below 1024.
fn two_to(k: u32) -> f64 {
    f64::from_bits(u64::from(1023 + k) << 52)
}

/// 2^k for the two's complement bits of an integer k in the normal exponent range.
#[inline(always)]
fn pow2<V: Lanes>(k: V::Bits) -> V {
    V::from_bits((k + V::Bits::splat(V::T::EXPONENT_BIAS)).shl(V::T::MANTISSA_BITS))
}

/// `e^x` within 4e-6 relative for results from the smallest normal 2^(1 − bias) to
/// 2^(bias + 0.49); below, that smallest normal (an absolute error under 1.2e-38 in `f32`);
/// above, 2^(bias + 0.49), finite (the kernel saturates powers at `MAX` anyway); NaN for NaN.
#[inline(always)]
pub fn exp<V: Lanes>(x: V) -> V {
    const Q: [f64; 4] = [0.69312419, 0.24024097, 0.05590646, 0.00958296];
    let bias = V::T::EXPONENT_BIAS as f64;
    let t = (x * c(std::f64::consts::LOG2_E))
        .clamp(V::T::from_f64(1.0 - bias), V::T::from_f64(bias + 0.49));
    let magic: V = c(1.5 * two_to(V::T::MANTISSA_BITS));
    let biased = t + magic;
    let kf = biased - magic;
    let k = biased.to_bits() - magic.to_bits();
    // Exact (Sterbenz): r in [−½, ½].
    let r = t - kf;
    let r2 = r * r;
    let q = r2.mul_add(
        c::<V>(Q[3]).mul_add(r, c(Q[2])),
        c::<V>(Q[1]).mul_add(r, c(Q[0])),
    );
    r.mul_add(q, c(1.0)) * pow2::<V>(k)
}

/// `ln(1 + x)` for x in (−1, ½] within 2e-6 relative (and to the rounding of 1 + x, which is
/// added back, so tiny x keep their value): u = 1 + x = 2^k·m with m in [√½, √2), and
/// ln m = f − f²/2 + f³·q(f) for f = m − 1.
#[inline(always)]
pub fn ln_1p<V: Lanes>(x: V) -> V {
    const Q: [f64; 5] = [0.33320854, -0.24943786, 0.20442295, -0.18407721, 0.11782057];
    let one = c::<V>(1.0);
    let u = one + x;
    // The rounding error of 1 + x over u, as in `elementary::ln_1p_le_half_f32`.
    let correction = (x - (u - one)) * (c::<V>(2.0) - u);
    let bits = V::Bits::splat;
    let mantissa = V::T::MANTISSA_BITS;
    let sqrt_half = c::<V>(std::f64::consts::FRAC_1_SQRT_2).to_bits();
    let ix = u.to_bits() + (one.to_bits() - sqrt_half);
    // The exponent k exactly: 2^p + (ix >> p) − 2^p − bias, p the significand bits.
    let two_p: V = c(two_to(mantissa));
    let k = V::from_bits(two_p.to_bits() | ix.shr(mantissa))
        - c(two_to(mantissa) + V::T::EXPONENT_BIAS as f64);
    let m = V::from_bits((ix & bits((1u64 << mantissa) - 1)) + sqrt_half);
    let f = m - one;
    let f2 = f * f;
    let q = f2.mul_add(
        f2.mul_add(c(Q[4]), c::<V>(Q[3]).mul_add(f, c(Q[2]))),
        c::<V>(Q[1]).mul_add(f, c(Q[0])),
    );
    let tail = f2 * f * q - c::<V>(0.5) * f2 + correction;
    (f + tail) + k * c(std::f64::consts::LN_2)
}

impl Tier for Display {
    const NAME: &'static str = "display";
    #[inline(always)]
    fn exp<V: ElementaryLanes>(x: V) -> V {
        exp(x)
    }
    #[inline(always)]
    fn ln_1p<V: ElementaryLanes>(x: V) -> V {
        ln_1p(x)
    }
}

#[cfg(test)]
mod tests {
    use crate::simd::lanes::{Lanes, Pack};

    fn exp1<T: crate::simd::float::Float>(x: T) -> T
    where
        Pack<T, 1>: Lanes<T = T>,
    {
        super::exp(Pack([x])).0[0]
    }

    fn ln1<T: crate::simd::float::Float>(x: T) -> T
    where
        Pack<T, 1>: Lanes<T = T>,
    {
        super::ln_1p(Pack([x])).0[0]
    }

    fn sweep(lo: f64, hi: f64, count: usize) -> impl Iterator<Item = f64> {
        (0..count).map(move |i| lo + (hi - lo) * (i as f64 + 0.5) / count as f64)
    }

    #[test]
    fn exp_is_within_4e_6_in_both_types() {
        // In f32, the rounding of x·log2(e) adds up to |x|·2^-24 relative: 3.7e-6 at |x| = 88.
        let (mut worst, mut wide): (f64, f64) = (0.0, 0.0);
        for x in sweep(-87.0, 88.0, 1_000_000) {
            let x32 = x as f32;
            let exact = f64::from(x32).exp();
            let e32 = (f64::from(exp1(x32)) / exact - 1.0).abs();
            wide = wide.max(e32);
            if x.abs() <= 16.0 {
                worst = worst.max(e32);
            }
            worst = worst.max((exp1(x) / x.exp() - 1.0).abs());
        }
        assert!(worst <= 4e-6 && wide <= 7e-6, "{worst}, {wide}");
        assert_eq!(exp1(0.0_f32), 1.0);
        assert!(exp1(-1000.0_f32) <= f32::MIN_POSITIVE && exp1(-1000.0_f64) > 0.0);
        assert!(exp1(1000.0_f32).is_finite() && exp1(f32::NAN).is_nan());
    }

    #[test]
    fn ln_1p_is_within_2e_6_near_zero_and_far() {
        let tiny = sweep(-30.0, -0.31, 300_000).flat_map(|e| [10f64.powf(e), -(10f64.powf(e))]);
        let mut worst: f64 = 0.0;
        for x in tiny.chain(sweep(-0.999_999, 0.5, 1_000_000)) {
            let x32 = x as f32;
            let exact = f64::from(x32).ln_1p();
            worst = worst.max((f64::from(ln1(x32)) - exact).abs() / exact.abs());
            worst = worst.max((ln1(x) - x.ln_1p()).abs() / x.ln_1p().abs());
        }
        assert!(worst <= 2e-6, "{worst}");
        assert_eq!(ln1(0.0_f32), 0.0);
    }

    #[test]
    fn a_power_of_a_unit_cosine_errs_by_under_2_to_the_minus_17() {
        // |exp(s·ln(1 − x)) − (1 − x)^s| for s from 1 to 10^6 and every base.
        let mut worst: f64 = 0.0;
        for s in [1.0, 2.0, 8.0, 32.0, 128.0, 1e4, 1e6] {
            for x in sweep(1e-9, 0.999, 20_000) {
                let y = -(x as f32);
                let got = f64::from(exp1(s as f32 * ln1(y)));
                let exact = (s * f64::from(y).ln_1p()).exp();
                worst = worst.max((got - exact).abs());
            }
        }
        assert!(worst <= 2f64.powi(-17), "{worst}");
    }
}
