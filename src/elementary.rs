//! `exp` and `ln_1p` for `f32` and `f64` from IEEE basic operations only, without branches, so
//! that a loop over lanes vectorises on every instruction set and gives the same bits on all of
//! them (libm calls do neither).
//!
//! The algorithms are the classic ones: Cephes `expf` (degree-6 polynomial after reduction by
//! ln 2, ≤ 2 ulp), fdlibm `exp` (rational form, ≤ 1 ulp), fdlibm `log` (atanh series in
//! s = f/(2 + f), ≤ 1 ulp), with the log1p correction term for `ln_1p`. The measured maximum errors are
//! checked by the tests below.

// Coefficients are quoted as published (Cephes, fdlibm); the bit manipulation is on purpose.
#![allow(
    clippy::excessive_precision,
    clippy::unreadable_literal,
    clippy::cast_sign_loss,
    clippy::cast_possible_wrap
)]

/// 1.5 · 2^23: `x + MAGIC − MAGIC` rounds an `f32` to the nearest integer (|x| < 2^22), and the
/// low bits of `x + MAGIC` hold that integer.
const MAGIC_F32: f32 = 12_582_912.0;
/// 1.5 · 2^52, the same for `f64`.
const MAGIC_F64: f64 = 6_755_399_441_055_744.0;

/// 2^k for an integer `k` in [−126, 127].
#[inline(always)]
fn pow2_f32(k: i32) -> f32 {
    f32::from_bits(((k + 127) as u32) << 23)
}

/// 2^k for an integer `k` in [−1022, 1023].
#[inline(always)]
fn pow2_f64(k: i64) -> f64 {
    f64::from_bits(((k + 1023) as u64) << 52)
}

/// `e^x` in `f32`, within 2 ulp for results in the normal range; 0 below −103.97 (the result
/// would be below the smallest subnormal), +inf above 88.73, NaN for NaN.
#[inline(always)]
pub fn exp_f32(x: f32) -> f32 {
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
    let t = x.clamp(LO, HI);
    let biased = t * LOG2E + MAGIC_F32;
    let kf = biased - MAGIC_F32;
    let k = biased.to_bits().wrapping_sub(MAGIC_F32.to_bits()) as i32;
    let r = (t - kf * C1) - kf * C2;
    let p =
        (((((P[0] * r + P[1]) * r + P[2]) * r + P[3]) * r + P[4]) * r + P[5]) * (r * r) + r + 1.0;
    // 2^k in two exact steps, so k from −150 to 128 needs no special case.
    let half = k >> 1;
    let y = p * pow2_f32(half) * pow2_f32(k - half);
    if x < LO {
        0.0
    } else if x > HI {
        f32::INFINITY
    } else {
        y
    }
}

/// `e^x` in `f64`, within 1 ulp for results in the normal range; 0 below −745.14, +inf above
/// 709.79, NaN for NaN.
#[inline(always)]
pub fn exp_f64(x: f64) -> f64 {
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
    let t = x.clamp(LO, HI);
    let biased = t * INV_LN2 + MAGIC_F64;
    let kf = biased - MAGIC_F64;
    let k = biased.to_bits().wrapping_sub(MAGIC_F64.to_bits()) as i64;
    let hi = t - kf * LN2_HI;
    let lo = kf * LN2_LO;
    let r = hi - lo;
    let r2 = r * r;
    let c = r - r2 * (P[0] + r2 * (P[1] + r2 * (P[2] + r2 * (P[3] + r2 * P[4]))));
    let p = 1.0 - ((lo - (r * c) / (2.0 - c)) - hi);
    let half = k >> 1;
    let y = p * pow2_f64(half) * pow2_f64(k - half);
    if x < LO {
        0.0
    } else if x > HI {
        f64::INFINITY
    } else {
        y
    }
}

/// ln(u) + c for a positive normal `u` (Cephes' `logf`): u = 2^k · m with m in [√½, √2),
/// ln m = f − f²/2 + f³·P(f) for f = m − 1. No division, so it costs no more than a few
/// multiplications in a vector. `c` is a small correction added with the low-order terms.
#[inline(always)]
fn ln_core_f32(u: f32, c: f32) -> f32 {
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
    let ix = u.to_bits().wrapping_add(0x3f80_0000 - 0x3f35_04f3);
    let dk = ((ix >> 23) as i32 - 0x7f) as f32;
    let m = f32::from_bits((ix & 0x007f_ffff) + 0x3f35_04f3);
    let f = m - 1.0;
    let z = f * f;
    let p = P[1..].iter().fold(P[0], |acc, &k| acc * f + k);
    let y = p * f * z + (dk * LN2_LO + c) - 0.5 * z;
    (f + y) + dk * LN2_HI
}

/// ln(u) + c for a positive normal `u` (fdlibm's `log`, on the high word).
#[inline(always)]
fn ln_core_f64(u: f64, c: f64) -> f64 {
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
    let bits = u.to_bits();
    let hx = (bits >> 32).wrapping_add(0x3ff0_0000 - 0x3fe6_a09e);
    // The exponent as an exact f64, through 2^52 + e − 2^52 (no integer-to-float instruction).
    let dk =
        f64::from_bits(0x4330_0000_0000_0000 | (hx >> 20)) - (4_503_599_627_370_496.0 + 1023.0);
    let m = f64::from_bits((((hx & 0x000f_ffff) + 0x3fe6_a09e) << 32) | (bits & 0xffff_ffff));
    let f = m - 1.0;
    let hfsq = 0.5 * f * f;
    let s = f / (2.0 + f);
    let z = s * s;
    let w = z * z;
    let t1 = w * (LG[1] + w * (LG[3] + w * LG[5]));
    let t2 = z * (LG[0] + w * (LG[2] + w * (LG[4] + w * LG[6])));
    s * (hfsq + (t2 + t1)) + (dk * LN2_LO + c) - hfsq + f + dk * LN2_HI
}

/// `ln(1 + x)` in `f32` for x in (−1, f32::MAX], within 2 ulp (also for tiny x).
#[inline(always)]
pub fn ln_1p_f32(x: f32) -> f32 {
    let u = 1.0 + x;
    // ln(1 + x) = ln u + ln(1 + e/u) with e = x − (u − 1), the rounding error of 1 + x, exact
    // (u − 1 is exact by Sterbenz where it matters).
    ln_core_f32(u, (x - (u - 1.0)) / u)
}

/// `ln(1 + x)` in `f32` for x in (−1, ½], within 2 ulp, without a division: the kernel's
/// ln(1 − x) near a highlight.
///
/// The correction e/u of [`ln_1p_f32`] becomes e·(2 − u), which is within (1 − u)²/u of it: a
/// quarter of a term below 2^-25 at worst (u = ½; for u ≤ ½ the sum 1 + x is exact and e = 0).
#[inline(always)]
pub fn ln_1p_le_half_f32(x: f32) -> f32 {
    let u = 1.0 + x;
    ln_core_f32(u, (x - (u - 1.0)) * (2.0 - u))
}

/// `ln(1 + x)` in `f64` for x in (−1, f64::MAX], within 1 ulp (also for tiny x).
#[inline(always)]
pub fn ln_1p_f64(x: f64) -> f64 {
    let u = 1.0 + x;
    ln_core_f64(u, (x - (u - 1.0)) / u)
}

/// `ln x` in `f32` for every x ≥ 0: within 2 ulp, −inf at 0, +inf at +inf, NaN for NaN and
/// negative x.
#[inline(always)]
pub fn ln_f32(x: f32) -> f32 {
    // Subnormals are lifted by 2^24 into the range of the bit manipulation.
    const LIFT: f32 = 16_777_216.0;
    const LN_LIFT: f32 = 16.635_532; // 24 ln 2
    let subnormal = x < f32::MIN_POSITIVE;
    let y = ln_core_f32(if subnormal { x * LIFT } else { x }, 0.0);
    if x == 0.0 {
        f32::NEG_INFINITY
    } else if x.is_nan() || x < 0.0 {
        f32::NAN
    } else if x == f32::INFINITY {
        x
    } else if subnormal {
        y - LN_LIFT
    } else {
        y
    }
}

/// `ln x` in `f64` for every x ≥ 0: within 1 ulp, −inf at 0, +inf at +inf, NaN for NaN and
/// negative x.
#[inline(always)]
pub fn ln_f64(x: f64) -> f64 {
    // Subnormals are lifted by 2^54 into the range of the bit manipulation.
    const LIFT: f64 = 18_014_398_509_481_984.0;
    const LN_LIFT: f64 = 37.429_947_750_237_04; // 54 ln 2
    let subnormal = x < f64::MIN_POSITIVE;
    let y = ln_core_f64(if subnormal { x * LIFT } else { x }, 0.0);
    if x == 0.0 {
        f64::NEG_INFINITY
    } else if x.is_nan() || x < 0.0 {
        f64::NAN
    } else if x == f64::INFINITY {
        x
    } else if subnormal {
        y - LN_LIFT
    } else {
        y
    }
}

#[cfg(test)]
mod tests {
    use super::*;

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
