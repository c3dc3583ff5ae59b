//! The fused multiply-add of four `f32` lanes with SSE2 only, which has none: the same bits as
//! AVX2's `vfmadd`, from `f64` arithmetic rounded to odd.
#![allow(unsafe_code)]

use std::arch::x86_64::{
    __m128, __m128d, _mm_add_pd, _mm_and_pd, _mm_and_si128, _mm_andnot_si128, _mm_castpd_si128,
    _mm_castsi128_pd, _mm_cmpneq_pd, _mm_cmpord_pd, _mm_cvtpd_ps, _mm_cvtps_pd, _mm_movehl_ps,
    _mm_movelh_ps, _mm_mul_pd, _mm_or_si128, _mm_set1_epi64x, _mm_setzero_pd, _mm_srli_epi64,
    _mm_sub_epi64, _mm_sub_pd, _mm_xor_si128,
};

/// `a·b + c` rounded once to `f32`, lane by lane, in SSE2's `f64` arithmetic: a·b is exact in
/// `f64` (24 + 24 bits), the sum is rounded to odd (Boldo and Melquiond: truncated, with its
/// last bit set where inexact), and rounding that to `f32` is the correctly rounded fused
/// multiply-add, since 53 bits exceed 24 by two or more. The same bits as AVX2's `vfmadd`.
#[inline(always)]
pub(crate) fn fma_f32x4(a: __m128, b: __m128, c: __m128) -> __m128 {
    // SAFETY: SSE2 is the x86-64 baseline.
    unsafe {
        let upper = |x: __m128| _mm_cvtps_pd(_mm_movehl_ps(x, x));
        let low = fma_to_odd(_mm_cvtps_pd(a), _mm_cvtps_pd(b), _mm_cvtps_pd(c));
        let high = fma_to_odd(upper(a), upper(b), upper(c));
        _mm_movelh_ps(_mm_cvtpd_ps(low), _mm_cvtpd_ps(high))
    }
}

/// `a·b + c` rounded to odd in `f64`, for `a`, `b` and `c` that are `f32` values.
#[inline(always)]
fn fma_to_odd(a: __m128d, b: __m128d, c: __m128d) -> __m128d {
    // SAFETY: SSE2 is the x86-64 baseline.
    unsafe {
        let p = _mm_mul_pd(a, b);
        let s = _mm_add_pd(p, c);
        // Knuth's TwoSum: s + e = p + c exactly (e is NaN only where s is not finite).
        let pp = _mm_sub_pd(s, c);
        let e = _mm_add_pd(_mm_sub_pd(p, pp), _mm_sub_pd(c, _mm_sub_pd(s, pp)));
        let inexact = _mm_castpd_si128(_mm_and_pd(
            _mm_cmpneq_pd(e, _mm_setzero_pd()),
            _mm_cmpord_pd(e, e),
        ));
        // Truncated: one step toward zero where s was rounded away from it (e and s of
        // opposite signs), then the last bit set.
        let bits = _mm_castpd_si128(s);
        let away = _mm_srli_epi64::<63>(_mm_xor_si128(_mm_castpd_si128(e), bits));
        let odd = _mm_or_si128(_mm_sub_epi64(bits, away), _mm_set1_epi64x(1));
        let bits = _mm_or_si128(_mm_and_si128(inexact, odd), _mm_andnot_si128(inexact, bits));
        _mm_castsi128_pd(bits)
    }
}

#[cfg(test)]
mod tests {
    use super::fma_f32x4;
    use std::arch::x86_64::{_mm_loadu_ps, _mm_storeu_ps};

    /// `fma_f32x4` of four triples, lane by lane.
    fn fma4(a: [f32; 4], b: [f32; 4], c: [f32; 4]) -> [f32; 4] {
        let mut out = [0.0; 4];
        // SAFETY: SSE2 is the x86-64 baseline; the arrays hold four values each.
        unsafe {
            let r = fma_f32x4(
                _mm_loadu_ps(a.as_ptr()),
                _mm_loadu_ps(b.as_ptr()),
                _mm_loadu_ps(c.as_ptr()),
            );
            _mm_storeu_ps(out.as_mut_ptr(), r);
        }
        out
    }

    /// Triples whose exact a·b + c lies at or next to a midpoint of `f32` (where rounding twice
    /// goes wrong), near zero, at the subnormals and at the overflow, and the special values.
    fn triples() -> Vec<[f32; 3]> {
        let mut t = Vec::new();
        for k in 0..64_u16 {
            for j in 0..64_u16 {
                // With the steps 2^-12, a·b = 1 + (k + j)·2^-12 + kj·2^-24: a midpoint of f32
                // for odd kj, which a tiny c moves off.
                let step = [f32::EPSILON, 2f32.powi(-12)][usize::from(k % 2 == 1 && j % 2 == 1)];
                let a = 1.0 + f32::from(k) * step;
                let b = 1.0 + f32::from(j) * step;
                for e in [24, 25, 26, 47, 48, 49, 50, 70] {
                    let tiny = 2f32.powi(-e);
                    for c in [tiny, -tiny, tiny * 1.5, -tiny * 0.75, -(a * b), 0.0, -0.0] {
                        t.push([a, b, c]);
                    }
                }
            }
        }
        let mut x: u32 = 0x1234_5678;
        for _ in 0..200_000 {
            let mut next = || {
                x ^= x << 13;
                x ^= x >> 17;
                x ^= x << 5;
                f32::from_bits(x)
            };
            t.push([next(), next(), next()]);
        }
        let special = [
            0.0,
            -0.0,
            1.0,
            f32::MAX,
            f32::MIN_POSITIVE,
            1e-45,
            f32::INFINITY,
        ];
        for &a in &special {
            for &b in &special {
                for &c in &[0.0, -0.0, -1.0, f32::NEG_INFINITY, f32::NAN, -f32::MAX] {
                    t.push([a, b, c]);
                    t.push([-a, b, c]);
                }
            }
        }
        t
    }

    #[test]
    fn sse2_gives_the_bits_of_a_fused_multiply_add() {
        let t = triples();
        let mut twice = 0;
        for chunk in t.chunks_exact(4) {
            let col = |k: usize| std::array::from_fn(|i| chunk[i][k]);
            let got = fma4(col(0), col(1), col(2));
            for (g, [a, b, c]) in got.iter().zip(chunk) {
                let exact = a.mul_add(*b, *c);
                let same = g.to_bits() == exact.to_bits() || (g.is_nan() && exact.is_nan());
                assert!(same, "{a:e}·{b:e} + {c:e}: {g:e}, not {exact:e}");
                let rounded_twice = (f64::from(*a) * f64::from(*b) + f64::from(*c)) as f32;
                twice += usize::from(rounded_twice.to_bits() != exact.to_bits() && !exact.is_nan());
            }
        }
        // The cases include some where rounding to f64 and then to f32 is wrong.
        assert!(twice > 0);
    }
}
