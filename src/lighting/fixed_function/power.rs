//! The powers of the lighting equation (OpenGL 2.1 §2.14.1): the specular power
//! (n̂⊙ĥ)^s_rm of eq. 2.2 and the spot factor (P_pli→V ⊙ ŝ_dli)^s_rli of eq. 2.5, as
//! `(1 − x)^s`, by squaring for integer s and as `exp(s·ln(1 − x))` otherwise, over lanes,
//! shared by the per-call constants and the kernel.

use std::ops::{Add, Sub};

use crate::numbers::elementary::ElementaryLanes;
use crate::simd::float::Float;
use crate::simd::lanes::{normalize_and_length, LaneMask, Lanes, V3};

/// A spot light's cone, in the kernel's type.
#[derive(Clone, Copy, Debug)]
pub struct Spot<T: Float> {
    /// ŝ_dli, the unit spot direction.
    pub direction: [T; 3],
    /// cos(c_rli); exactly 0 for a 90° cutoff (f32 `cos(π/2)` is −4.4e-8, f64 +6.1e-17).
    pub cos_cutoff: T,
    /// s_rli.
    pub exponent: T,
    /// The soft edge, or `None` for GL's hard one.
    pub edge: Option<SoftEdge<T>>,
}

/// A spot light's soft edge (learnopengl's): the factor ramps linearly in cos θ from 0 at the
/// cutoff to 1 at the inner cone.
#[derive(Clone, Copy, Debug)]
pub struct SoftEdge<T: Float> {
    /// cos(inner) − cos(c_rli) > 0, learnopengl's ε.
    pub width: T,
}

/// The length of a vector that stands for a unit direction times that length: the cosine of
/// the direction becomes `length · cos` in a power.
///
/// Near 1 (|v|² in [0.5, 2], `near`) the length enters as |v| − 1, computed without
/// cancellation (the exact [`squared_minus_one`] over |v| + 1); elsewhere as ln |v|. So
/// (|v| cos)^s needs one `ln_1p` per power: ln_1p((|v| − 1) − |v|·x) near 1, ln_1p(−x) + ln |v|
/// elsewhere, x = 1 − cos.
#[derive(Clone, Copy)]
pub struct Scale<V: Lanes> {
    /// The lanes whose length is near 1.
    pub near: V::Mask,
    /// |v| (at most `T::MAX`).
    pub length: V,
    /// |v| − 1 in the `near` lanes.
    pub minus_one: V,
    /// |v|² − 1 in the `near` lanes, from exact squares ([`squared_minus_one`]).
    pub squared_minus_one: V,
    /// ln |v| in the other lanes.
    pub ln: V,
}

impl<V: ElementaryLanes> Scale<V> {
    /// Length 1: a unit vector.
    #[inline(always)]
    pub fn unit() -> Self {
        let zero = V::splat(V::T::ZERO);
        Self {
            near: V::Mask::splat(true),
            length: V::splat(V::T::ONE),
            minus_one: zero,
            squared_minus_one: zero,
            ln: zero,
        }
    }

    /// The scale of `v`, whose length (from [`normalize_and_length`]) is `length`.
    #[inline(always)]
    pub fn of(v: V3<V>, length: V) -> Self {
        let (squared, near) = squared_minus_one(v);
        Self::from_squared(squared, near, length)
    }

    /// The scale of a vector from its [`squared_minus_one`] and its `length`.
    #[inline(always)]
    pub fn from_squared(squared_minus_one: V, near: V::Mask, length: V) -> Self {
        let one = V::splat(V::T::ONE);
        let minus_one = squared_minus_one / (length + one);
        let length = length.min(V::splat(V::T::MAX));
        // ln |v| is read in the far lanes only, and unit normals have none: skip it then.
        let ln = if near.all() {
            V::splat(V::T::ZERO)
        } else {
            V::select(near, one, length).ln()
        };
        Self {
            near,
            length,
            minus_one,
            squared_minus_one,
            ln,
        }
    }

    /// The scale of a vector whose every lane is near 1, for [`halfway_pow`] alone, which reads
    /// only `squared_minus_one` there: no square root and no division. `length` and `minus_one`
    /// are not formed (1 and 0), so no other power may be given it.
    #[inline(always)]
    pub fn squared_only(squared_minus_one: V) -> Self {
        Self {
            squared_minus_one,
            ..Self::unit()
        }
    }
}

/// (n̂, the scale of n) for a normal `n` that is not normalised, from its
/// [`squared_minus_one`] (`squared`, `near`): n̂ and |n| in every block when `every_block`,
/// else (when the only powers are [`halfway_pow`]'s) only in a block with a lane far from unit
/// length, and `n` itself with [`Scale::squared_only`] in the others.
#[inline(always)]
pub fn normal_scale<V: ElementaryLanes>(
    n: V3<V>,
    squared: V,
    near: V::Mask,
    every_block: bool,
) -> (V3<V>, Scale<V>) {
    if every_block || !near.all() {
        let (unit, length) = normalize_and_length(n);
        (unit, Scale::from_squared(squared, near, length))
    } else {
        (n, Scale::squared_only(squared))
    }
}

/// (a, e) with a + e = x · x exactly (Dekker's product, or a fused multiply-add: the same exact
/// error on every CPU), for |x| well inside the type's range.
#[inline(always)]
fn square_exact<V: Lanes>(x: V) -> (V, V) {
    let square = x * x;
    (square, x.square_error(square))
}

/// (s, e) with s + e = a + b exactly (Knuth's TwoSum).
#[inline(always)]
pub fn sum_exact<W: Copy + Add<Output = W> + Sub<Output = W>>(a: W, b: W) -> (W, W) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// |v|² − 1 to a few ulp of the result, and the lanes where that holds (|v|² in [0.5, 2]): the
/// squares and their sum are formed exactly, so |v|² − 1 keeps every bit when |v| ≈ 1 (f32 unit
/// normals differ from 1 by a few ulp, and (n·ĥ)^s multiplies that by s).
#[inline(always)]
pub fn squared_minus_one<V: Lanes>(v: V3<V>) -> (V, V::Mask) {
    let one = V::splat(V::T::ONE);
    let (a, ae) = square_exact(v.x);
    let (b, be) = square_exact(v.y);
    let (c, ce) = square_exact(v.z);
    let (ab, e1) = sum_exact(a, b);
    let (abc, e2) = sum_exact(ab, c);
    let near = abc.ge(V::splat(V::T::HALF)) & abc.le(one + one);
    // abc − 1 is exact by Sterbenz in the near lanes.
    ((abc - one) + ((e1 + e2) + ((ae + be) + ce)), near)
}

/// `(scale.length · max(â·b̂, 0))^s` for unit `a`, `b` whose dot product is `cos`, with 0^0 = 1,
/// with the kernel's elementary functions.
///
/// 1 − â·b̂ is taken as x = |â − b̂|²/2, which has no cancellation near the highlight, and the
/// power as `(1 − x)^s` by squaring on the complement x for the integers s up to
/// [`SQUARED_EXPONENT_MAX`] ([`complement_pow`]: about a tenth of the operations), else as
/// `exp(s·ln(1 − x))`: either way the error stays a few ulp at any exponent instead of growing
/// as s·ulp. The length of the vector `a` stands for enters through `scale` (see [`Scale`]):
/// near 1 as the complement's |v| − 1, elsewhere (those lanes take exp and ln) as ln |v|.
#[inline(always)]
pub fn cos_pow<V: ElementaryLanes>(cos: V, a: V3<V>, b: V3<V>, s: V::T, scale: &Scale<V>) -> V {
    if s == V::T::ZERO {
        return V::splat(V::T::ONE);
    }
    let x = one_minus_cos(a, b);
    let near = scale.minus_one - scale.length * x;
    let y = V::select(scale.near, near, -x);
    // y > −1: the base is positive (not rounded to 0, where ln would be −inf).
    let zero = V::splat(V::T::ZERO);
    let valid = cos.gt(zero) & x.lt(V::splat(V::T::ONE)) & y.gt(V::splat(-V::T::ONE));
    power_of_base::<V>(y, scale, s, valid)
}

/// 1 − â·b̂ for unit `a` and `b`, as |â − b̂|²/2: no cancellation near â = b̂.
#[inline(always)]
fn one_minus_cos<V: Lanes>(a: V3<V>, b: V3<V>) -> V {
    let d = a - b;
    V::splat(V::T::HALF) * d.dot(d)
}

/// A constant unit direction ĥ (a directional light's halfway vector under an infinite
/// viewer) with the per-call constants [`halfway_pow`] needs, from its `f64` length.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Halfway<T: Float> {
    /// ĥ, rounded to the kernel's type.
    pub direction: [T; 3],
    /// (|ĥ| − 1)² of the rounded ĥ.
    pub offset: T,
    /// 1 / (2|ĥ|) of the rounded ĥ (0 for a zero ĥ).
    pub half_inverse_length: T,
}

impl<T: Float> Halfway<T> {
    /// The constants of the rounded direction `direction`.
    pub fn new(direction: [T; 3]) -> Self {
        let length = direction
            .iter()
            .map(|c| c.to_f64() * c.to_f64())
            .sum::<f64>()
            .sqrt();
        Self {
            direction,
            offset: T::from_f64((length - 1.0) * (length - 1.0)),
            half_inverse_length: T::from_f64(if length > 0.0 { 0.5 / length } else { 0.0 }),
        }
    }
}

/// `(max(n·ĥ/|ĥ|, 0))^s` for a constant ĥ (`halfway`, nonzero), with 0^0 = 1: [`cos_pow`] of
/// n̂ and ĥ with `scale` that of `n`, without n̂ where |n| is near 1.
///
/// There the base minus one is n·ĥ/|ĥ| − 1 = ((|n|² − 1) + (|ĥ| − 1)² − |n − ĥ|²) / (2|ĥ|):
/// |n|² − 1 is exact (`scale.squared_minus_one`) and |n − ĥ|² does not cancel near the
/// highlight, so the power keeps cos_pow's few ulp with no square root and no division per
/// vertex. The other lanes take cos_pow's 1 − n̂·ĥ = |n̂ − ĥ|²/2 and ln |n|, from `unit`
/// (n̂), which is read only in a block that has such a lane.
#[inline(always)]
pub fn halfway_pow<V: ElementaryLanes>(
    n: V3<V>,
    unit: V3<V>,
    halfway: &Halfway<V::T>,
    s: V::T,
    scale: &Scale<V>,
) -> V {
    if s == V::T::ZERO {
        return V::splat(V::T::ONE);
    }
    let h = V3::splat(halfway.direction);
    let (zero, one) = (V::splat(V::T::ZERO), V::splat(V::T::ONE));
    let d = n - h;
    let y_near = (scale.squared_minus_one + V::splat(halfway.offset) - d.dot(d))
        * V::splat(halfway.half_inverse_length);
    let lit = n.dot(h).gt(zero);
    let (y, valid) = if scale.near.all() {
        (y_near, lit & y_near.gt(-one))
    } else {
        let x = one_minus_cos(unit, h);
        let y = V::select(scale.near, y_near, -x);
        (y, lit & (scale.near | x.lt(one)) & y.gt(-one))
    };
    power_of_base::<V>(y, scale, s, valid)
}

/// The least |g|² [`halfway_even_pow`] takes, 2^-60: above it |n × g|² underflows only where
/// sin² θ < 2^-66, whose power differs from 1 by less than 2^-56 for exponents to 1024.
const HALFWAY_SQUARED_MIN: f64 = 8.673_617_379_884_035e-19;

/// `s / 2` for the even integers `s` from 2 to [`SQUARED_EXPONENT_MAX`], whose specular power
/// [`halfway_even_pow`] forms with no ĥ; `None` for the other exponents.
#[inline(always)]
pub fn half_even_exponent<T: Float>(s: T) -> Option<T> {
    match squared_exponent(s) {
        Some(k) if k % 2 == 0 => Some(T::HALF * s),
        _ => None,
    }
}

/// `(scale.length · max(n̂⊙ĝ, 0))^(2·half)` for a halfway vector `g` as it is (VP + VP_e, not
/// normalised), `half` from [`half_even_exponent`], with 0 where n·g ≤ 0: [`cos_pow`] of n̂ and
/// ĝ without forming ĝ, which takes a square root and a division per light and vertex.
///
/// By Lagrange's identity (n·g)²/|g|² = |n|² − |n × g|²/|g|², so the base (|n| cos θ)² less
/// one is (|n|² − 1) − |n × g|²/|g|²: |n|² − 1 exact (`scale.squared_minus_one`), and near the
/// highlight, where n × g is small, nothing cancels, so the power keeps cos_pow's few ulp. It
/// is squared on the complement as cos_pow's is. Lanes far from unit length take sin² θ from
/// n̂ (`unit`, read only in a block that has one) and 2 ln |n|, as exp and ln.
///
/// Returns the power and the lanes it holds in: those whose |g|² is at least 2^-60 (below,
/// VP and VP_e nearly opposite or not finite, the caller forms ĝ itself, exactly).
#[inline(always)]
pub fn halfway_even_pow<V: ElementaryLanes>(
    n: V3<V>,
    unit: V3<V>,
    g: V3<V>,
    half: V::T,
    scale: &Scale<V>,
) -> (V, V::Mask) {
    let (zero, one) = (V::splat(V::T::ZERO), V::splat(V::T::ONE));
    let g2 = g.dot(g);
    let held = g2.ge(V::splat(V::T::from_f64(HALFWAY_SQUARED_MIN)));
    let c = n.cross(g);
    let y_near = scale.squared_minus_one - c.dot(c) / g2;
    let y = if scale.near.all() {
        y_near
    } else {
        let c = unit.cross(g);
        V::select(scale.near, y_near, -(c.dot(c) / g2))
    };
    let valid = n.dot(g).gt(zero) & y.gt(-one);
    let squared = Scale {
        ln: scale.ln + scale.ln,
        ..*scale
    };
    (power_of_base::<V>(y, &squared, half, valid), held)
}

/// (1 + y)^s in the `valid` lanes (y > −1 there), 0 elsewhere, for s ≠ 0: by squaring on the
/// complement −y for the integer s up to [`SQUARED_EXPONENT_MAX`] where the length of `scale`
/// is near 1, else `exp(s·(ln_1p(y) + ln |v|))`, ln |v| in the lanes that are not near 1.
#[inline(always)]
fn power_of_base<V: ElementaryLanes>(y: V, scale: &Scale<V>, s: V::T, valid: V::Mask) -> V {
    let zero = V::splat(V::T::ZERO);
    // `match`, not `Option::map`: a closure the standard library calls may be compiled
    // without the kernel's target features (see `simd::lanes::each`).
    #[allow(clippy::manual_map)]
    let squared = match squared_exponent(s) {
        Some(k) => Some(complement_pow(-y, k)),
        None => None,
    };
    let power = match squared {
        Some(p) if scale.near.all() => p,
        _ => {
            let ln = y.ln_1p() + V::select(scale.near, zero, scale.ln);
            let general = (V::splat(s) * ln).exp();
            // Lane by lane, so a lane's value does not depend on the block it shares.
            match squared {
                Some(p) => V::select(scale.near, p, general),
                None => general,
            }
        }
    };
    power.min(V::splat(V::T::MAX)).or_zero(valid)
}

/// The exponents whose powers are formed by squaring ([`complement_pow`]) rather than as
/// exp(s·ln(1 − x)): the integers from 1 to this.
pub const SQUARED_EXPONENT_MAX: u32 = 1024;

/// `s` as an integer when its power is formed by squaring: a conversion and three comparisons
/// per block and light, with no call (`fract` is one on the SSE2 baseline).
#[inline(always)]
#[allow(clippy::cast_sign_loss, clippy::cast_possible_truncation)] // checked by the round trip
fn squared_exponent<T: Float>(s: T) -> Option<u32> {
    let k = s.to_f64();
    let whole = k as u32; // saturating; NaN gives 0
    (k >= 1.0 && k <= f64::from(SQUARED_EXPONENT_MAX) && f64::from(whole) == k).then_some(whole)
}

/// (1 − c)^k for c < 1 and k ≥ 1, formed on the complement: with 1 − c_{i+1} = (1 − c_i)²,
/// c_{i+1} = c_i·(2 − c_i), and a product (1 − a)(1 − b) = 1 − (a + b·(1 − a)). For c in
/// [0, 1) no step cancels and none amplifies the complement's relative error, however small it
/// is, so the power errs by a few roundoffs of 1 (3.2 in f32, 2.3 in f64, measured on a sample
/// of the k up to [`SQUARED_EXPONENT_MAX`]), not by k of them as a naive power does. For c < 0
/// (a base above 1: a normal longer than 1) the relative error grows with k·ln(1 − c), as that
/// of `exp(s·ln(1 − c))` does; past `MAX` the result is +inf.
#[inline(always)]
fn complement_pow<V: Lanes>(c: V, k: u32) -> V {
    let one = V::splat(V::T::ONE);
    let two = one + one;
    let (mut x, mut e) = (c, k);
    let mut total: Option<V> = None;
    loop {
        if e & 1 == 1 {
            total = Some(match total {
                None => x,
                Some(t) => x.mul_add(one - t, t),
            });
        }
        e >>= 1;
        if e == 0 {
            break;
        }
        x = x * (two - x);
    }
    one - total.unwrap_or(V::splat(V::T::ZERO))
}

/// x^s for x ≥ 0 and s > 0 in plain arithmetic, the lean kernel's power: by squaring for the
/// integers up to [`SQUARED_EXPONENT_MAX`], else `exp(s·ln x)` (0 at x = 0). It errs by about
/// s times the rounding of x, which the fast mode's bound allows ([`complement_pow`] does not).
#[inline(always)]
pub fn plain_pow<V: ElementaryLanes>(x: V, s: V::T) -> V {
    let Some(k) = squared_exponent(s) else {
        let zero = V::splat(V::T::ZERO);
        return (V::splat(s) * x.ln()).exp().or_zero(x.gt(zero));
    };
    let (mut base, mut e) = (x, k);
    let mut total: Option<V> = None;
    loop {
        if e & 1 == 1 {
            total = Some(match total {
                None => base,
                Some(t) => t * base,
            });
        }
        e >>= 1;
        if e == 0 {
            break;
        }
        base = base * base;
    }
    total.unwrap_or(V::splat(V::T::ONE))
}

/// spot_i of eq. 2.5 for the unit light-to-vertex vectors `to_vertex` (P_pli→V): 0 outside the
/// cone, `(to_vertex ⊙ ŝ)^exponent` inside, with the edge inside (`≥`) and 0^0 = 1; times
/// clamp((cos θ − cos c_rli)/ε, 0, 1) with a soft edge (`soft`, and the spot has one).
#[inline(always)]
pub fn spot_factor<V: ElementaryLanes>(spot: &Spot<V::T>, to_vertex: V3<V>, soft: bool) -> V {
    let axis = V3::splat(spot.direction);
    let c = to_vertex.dot(axis).max(V::splat(V::T::ZERO));
    let inside = c.ge(V::splat(spot.cos_cutoff));
    let factor = cos_pow::<V>(c, to_vertex, axis, spot.exponent, &Scale::unit()).or_zero(inside);
    match spot.edge {
        Some(edge) if soft => {
            // learnopengl's clamp((theta - outerCutOff) / epsilon, 0.0, 1.0), division included.
            let ramp = (c - V::splat(spot.cos_cutoff)) / V::splat(edge.width);
            factor * ramp.clamp(V::T::ZERO, V::T::ONE)
        }
        _ => factor,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::simd::lanes::Pack;

    type One = Pack<f32, 1>;

    fn one(v: [f32; 3]) -> V3<One> {
        V3::splat(v)
    }

    fn pow1(cos: f32, a: [f32; 3], b: [f32; 3], s: f32) -> f32 {
        cos_pow(Pack([cos]), one(a), one(b), s, &Scale::unit()).0[0]
    }

    #[test]
    fn cos_pow_matches_powf_and_pins_zero_to_the_zero() {
        let (a, b) = ([0.6, 0.8, 0.0], [1.0, 0.0, 0.0]);
        assert!((pow1(0.6, a, b, 3.0) - 0.216).abs() < 1e-6);
        assert_eq!(pow1(0.0, [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], 0.0), 1.0);
        assert_eq!(pow1(-0.6, [-0.6, -0.8, 0.0], b, 0.0), 1.0);
        assert_eq!(pow1(-0.6, [-0.6, -0.8, 0.0], b, 2.0), 0.0);
        assert_eq!(pow1(1.0, b, b, 1e6), 1.0);
    }

    #[test]
    fn cos_pow_is_stable_at_high_exponents() {
        // θ = 1e-3 rad: (cos θ)^1e6 = exp(1e6·ln cos θ) ≈ e^-0.5.
        let theta = 1e-3_f64;
        let exact = (1e6 * theta.cos().ln()).exp();
        let a = [theta.sin() as f32, 0.0, theta.cos() as f32];
        let got = f64::from(pow1(a[2], a, [0.0, 0.0, 1.0], 1e6));
        assert!((got - exact).abs() / exact < 2e-3, "{got} vs {exact}");
        let naive = f64::from(a[2].powf(1e6));
        assert!((naive - exact).abs() > (got - exact).abs());
    }

    /// The exponents a squaring test runs: every one up to 40, the powers of two and their
    /// neighbours, and a sample of the rest up to the cap.
    fn squared_exponents() -> impl Iterator<Item = u32> {
        (1..=SQUARED_EXPONENT_MAX)
            .filter(|&k| k <= 40 || k % 37 == 0 || k.is_power_of_two() || (k + 1).is_power_of_two())
    }

    /// (1 − c)^k in float64 for a float64 c.
    fn complement_pow_f64(c: f64, k: u32) -> f64 {
        complement_pow(Pack([c]), k).0[0]
    }

    #[test]
    fn integer_powers_by_squaring_err_by_a_few_ulp_of_one() {
        let (mut worst32, mut worst64): (f64, f64) = (0.0, 0.0);
        for k in squared_exponents() {
            for i in 0..400 {
                // Complements from 1e-12 to 1 − 1e-7: the base from next to 1 to next to 0.
                let c = 10f64
                    .powf(-12.0 + 12.0 * f64::from(i) / 400.0)
                    .min(1.0 - 1e-7);
                let c32 = c as f32;
                let exact = (1.0 - f64::from(c32)).powi(k.cast_signed());
                let got = f64::from(complement_pow(Pack([c32]), k).0[0]);
                worst32 = worst32.max((got - exact).abs());
                let exact64 = (-c).ln_1p() * f64::from(k);
                worst64 = worst64.max((complement_pow_f64(c, k) - exact64.exp()).abs());
            }
        }
        // In units of the roundoff of 1 (2^-24, 2^-53).
        let (ulp32, ulp64) = (worst32 / 2f64.powi(-24), worst64 / 2f64.powi(-53));
        // Measured: 3.2 and 2.3.
        assert!(ulp32 <= 8.0 && ulp64 <= 8.0, "{ulp32}, {ulp64}");
    }

    #[test]
    fn integer_powers_of_bases_above_one_err_as_exp_and_ln_do() {
        // A normal longer than 1 (up to √2, the near range) makes the base exceed 1.
        let mut worst: f64 = 0.0;
        for k in squared_exponents() {
            for i in 1..200 {
                let c = -0.414 * f64::from(i) / 200.0;
                let c32 = c as f32;
                let exact = (1.0 - f64::from(c32)).powi(k.cast_signed());
                let got = f64::from(complement_pow(Pack([c32]), k).0[0]);
                if exact < f64::from(f32::MAX) {
                    worst = worst.max((got / exact - 1.0).abs());
                } else {
                    assert_eq!(got, f64::INFINITY);
                }
            }
        }
        // Measured: 183 units of 2^-24, where exp(s·ln b) errs by 142 (both grow with s·ln b,
        // which the range of f32 caps at 88.7).
        assert!(worst <= 256.0 * 2f64.powi(-24), "{worst}");
    }

    #[test]
    fn a_lanes_power_does_not_depend_on_the_lanes_beside_it() {
        // Near-unit and long normals in one block: squaring in some lanes, exp and ln in others,
        // and for a constant ĥ, n̂ only in the far lanes.
        let rows = [
            [0.6_f32, 0.0, 0.8],
            [3.0, 0.0, 4.0],
            [0.0, 0.28, 0.96],
            [0.1, 0.0, 0.05],
        ];
        let (h, halfway) = ([0.0, 0.0, 1.0], Halfway::new([0.0, 0.6, 0.8]));
        let powers = |v: V3<Pack<f32, 4>>| {
            let (unit, len) = normalize_and_length(v);
            let scale = Scale::of(v, len);
            let h = V3::splat(h);
            let (even, _) = halfway_even_pow(v, unit, V3::splat([0.3, 0.0, 1.4]), 16.0, &scale);
            [
                cos_pow(unit.dot(h), unit, h, 32.0, &scale).0,
                halfway_pow(v, unit, &halfway, 32.0, &scale).0,
                even.0,
            ]
        };
        let block = powers(V3 {
            x: Pack(rows.map(|r| r[0])),
            y: Pack(rows.map(|r| r[1])),
            z: Pack(rows.map(|r| r[2])),
        });
        for (i, row) in rows.iter().enumerate() {
            let alone = powers(V3::splat(*row));
            for (b, a) in block.iter().zip(alone) {
                assert_eq!(b[i].to_bits(), a[0].to_bits(), "lane {i}");
            }
            // The kernel's lean form (no n̂ in a block of near lanes) gives the same bits.
            let lean = halfway1(*row, halfway.direction, 32.0);
            assert_eq!(block[1][i].to_bits(), lean.to_bits(), "lane {i}");
        }
    }

    /// a × b in `f64`, for the tests' orthonormal frames.
    fn cross64(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
        glam::DVec3::from(a).cross(glam::DVec3::from(b)).to_array()
    }

    /// (|n|·n̂⊙ĝ)^s by [`halfway_even_pow`] in `f32` for the normal `n` as the kernel forms its
    /// scale, and whether it holds.
    fn even1(n: [f32; 3], g: [f32; 3], s: f32) -> (f32, bool) {
        let v = V3::<One>::splat(n);
        let (squared, near) = squared_minus_one(v);
        let (unit, scale) = normal_scale(v, squared, near, false);
        let half = half_even_exponent(s).expect("an even exponent");
        let (power, held) = halfway_even_pow(v, unit, V3::splat(g), half, &scale);
        (power.0[0], held.0[0])
    }

    #[test]
    fn even_exponents_only_are_halved() {
        assert_eq!(half_even_exponent(32.0_f32), Some(16.0));
        assert_eq!(half_even_exponent(1024.0_f64), Some(512.0));
        for s in [
            0.0_f32,
            1.0,
            31.0,
            31.7,
            1026.0,
            -2.0,
            f32::NAN,
            f32::INFINITY,
        ] {
            assert_eq!(half_even_exponent(s), None, "{s}");
        }
    }

    #[test]
    fn even_powers_of_an_unnormalised_halfway_match_a_float64_transcription() {
        // Normals of unit length, within 30% of it and far from it (0.2, 4), halfway vectors
        // g of lengths from 2^-29 to 2 at angles to 1.2 rad, most near the highlight: the power
        // of the f32 inputs as given, (|n|·max(n̂·ĝ, 0))^s in f64 (at most `MAX`), within a
        // few roundoffs of 1 plus a few of the power times s·(||n|² − 1| + |cos − 1|), as for
        // a constant ĥ.
        let u = 2f64.powi(-24);
        let lengths = [1.0, 1.3, 0.8, 0.2, 4.0];
        let g_lengths = [2.0, 1.0, 0.3, 1e-4, 2f64.powi(-29)];
        for &s in &[2.0_f32, 32.0, 128.0, 1024.0] {
            let mut worst: f64 = 0.0;
            for i in 0..6000_u32 {
                let t = f64::from(i) * 0.37;
                let theta = (f64::from(i % 89) / 89.0).powi(3) * 1.2;
                let axis = [t.sin() * 0.6, t.cos() * 0.6, 0.8];
                // A unit vector at θ from `axis`, about it by t·1.3.
                let ex = [axis[2], 0.0, -axis[0]].map(|c| c / (axis[0].powi(2) + 0.64).sqrt());
                let ey = cross64(axis, ex);
                let (a, b) = ((t * 1.3).cos() * theta.sin(), (t * 1.3).sin() * theta.sin());
                let length = lengths[i as usize % lengths.len()];
                let n: [f32; 3] = std::array::from_fn(|k| {
                    (length * (a * ex[k] + b * ey[k] + theta.cos() * axis[k])) as f32
                });
                let g = axis.map(|c| (c * g_lengths[(i as usize / 5) % g_lengths.len()]) as f32);
                let (n64, g64) = (n.map(f64::from), g.map(f64::from));
                let dot: f64 = (0..3).map(|k| n64[k] * g64[k]).sum();
                let g_len = g64.iter().map(|c| c * c).sum::<f64>().sqrt();
                let n_len = n64.iter().map(|c| c * c).sum::<f64>().sqrt();
                let cos = dot / (g_len * n_len);
                let exact = (n_len * cos.max(0.0))
                    .powf(f64::from(s))
                    .min(f64::from(f32::MAX));
                let (got, held) = even1(n, g, s);
                assert!(held, "|g| = {g_len}");
                let amplified = f64::from(s) * ((n_len * n_len - 1.0).abs() + (cos - 1.0).abs());
                let allowed = 16.0 * u * (1.0 + amplified) * exact + 8.0 * u;
                worst = worst.max((f64::from(got) - exact).abs() / allowed);
            }
            assert!(worst <= 1.0, "s = {s}: {worst} of the allowed error");
        }
    }

    #[test]
    fn even_powers_leave_a_zero_or_tiny_halfway_to_the_caller() {
        let n = [0.0, 0.0, 1.0];
        assert!(!even1(n, [0.0; 3], 32.0).1);
        assert!(!even1(n, [0.0, 0.0, 2e-10], 32.0).1);
        assert!(!even1(n, [f32::NAN, 0.0, 1.0], 32.0).1);
        assert!(even1(n, [0.0, 0.0, 1e-9], 32.0).1);
        // Behind the normal, or at 90° to it: 0.
        assert_eq!(even1(n, [0.0, 0.6, -0.8], 2.0), (0.0, true));
        assert_eq!(even1(n, [0.0, 1.0, 0.0], 2.0), (0.0, true));
    }

    #[test]
    fn length_minus_one_keeps_every_bit_near_one() {
        // f32 unit normals: |n| − 1 is a few ulp, and (n·h)^s multiplies it by s.
        let mut worst: f64 = 0.0;
        for i in 0..20_000 {
            let t = f64::from(i) * 0.013;
            let v = [t.sin() * t.cos(), t.sin() * t.sin(), t.cos()].map(|c| c as f32);
            let (_, len) = normalize_and_length(V3::<One>::splat(v));
            let scale = Scale::of(V3::<One>::splat(v), len);
            let (m1, near) = (scale.minus_one, scale.near);
            assert!(near.0[0]);
            let exact = v.map(f64::from).iter().map(|c| c * c).sum::<f64>().sqrt() - 1.0;
            worst = worst.max((f64::from(m1.0[0]) - exact).abs());
        }
        assert!(worst < 1e-14, "{worst}");
    }

    /// (n·ĥ/|ĥ|)^s by [`halfway_pow`] in `f32` for the normal `n` (its scale as the kernel
    /// forms it: n̂ only where |n| is far from 1).
    fn halfway1(n: [f32; 3], h: [f32; 3], s: f32) -> f32 {
        let v = V3::<One>::splat(n);
        let (squared, near) = squared_minus_one(v);
        let (unit, scale) = normal_scale(v, squared, near, false);
        halfway_pow(v, unit, &Halfway::new(h), s, &scale).0[0]
    }

    #[test]
    fn constant_halfway_powers_match_a_float64_transcription() {
        // Normals within a few ulp of unit length and up to 30% off it, around a rounded ĥ: the
        // power of the f32 inputs as given, (max(n·ĥ, 0)/|ĥ|)^s in f64 (at most `MAX`), within
        // a few roundoffs of 1 (squaring on the complement errs absolutely) plus a few of the
        // power times s·(||n|² − 1| + |n·ĥ − 1|), the condition of the power in its base.
        // An orthonormal frame (ex, ey, hz) about ĥ, and ĥ rounded to f32.
        let hz = [0.3_f64, 0.5, 1.0].map(|c| c / 1.34_f64.sqrt());
        let ex = [hz[2], 0.0, -hz[0]].map(|c| c / (hz[0] * hz[0] + hz[2] * hz[2]).sqrt());
        let ey = cross64(hz, ex);
        let h = hz.map(|c| c as f32);
        let h_len = h.iter().map(|&c| f64::from(c).powi(2)).sum::<f64>().sqrt();
        let u = 2f64.powi(-24);
        for &s in &[1.0_f32, 7.0, 32.0, 31.7, 1000.0, 1e4] {
            let mut worst: f64 = 0.0;
            for i in 0..4000 {
                // Angles from ĥ up to 0.6 rad, most near the highlight, around the whole circle.
                let t = f64::from(i) * 0.37;
                let theta = (f64::from(i % 97) / 97.0).powi(3) * 0.6;
                let length = if i % 3 == 0 {
                    1.0
                } else {
                    1.0 + 0.3 * (t * 1.7).sin()
                };
                let d = [theta.sin() * t.cos(), theta.sin() * t.sin(), theta.cos()];
                let n: [f32; 3] = std::array::from_fn(|k| {
                    (length * (d[0] * ex[k] + d[1] * ey[k] + d[2] * hz[k])) as f32
                });
                let dot: f64 = (0..3).map(|k| f64::from(n[k]) * f64::from(h[k])).sum();
                let exact = (dot / h_len)
                    .max(0.0)
                    .powf(f64::from(s))
                    .min(f64::from(f32::MAX));
                let got = f64::from(halfway1(n, h, s));
                // The roundings of |n|² − 1 and of n·ĥ − 1, each a few u of its magnitude,
                // times s.
                let squared = n.iter().map(|&c| f64::from(c).powi(2)).sum::<f64>() - 1.0;
                let amplified = f64::from(s) * (squared.abs() + (dot / h_len - 1.0).abs());
                let allowed = 16.0 * u * (1.0 + amplified) * exact + 8.0 * u;
                worst = worst.max((got - exact).abs() / allowed);
            }
            assert!(worst <= 1.0, "s = {s}: {worst} of the allowed error");
        }
        // No power from behind the surface, 0^0 = 1, a zero ĥ's constants stay finite.
        assert_eq!(halfway1([0.0, 0.0, -1.0], [0.0, 0.0, 1.0], 3.0), 0.0);
        assert_eq!(halfway1([0.0, 0.0, -1.0], [0.0, 0.0, 1.0], 0.0), 1.0);
        assert_eq!(Halfway::<f32>::new([0.0; 3]).half_inverse_length, 0.0);
    }

    #[test]
    fn the_scale_of_long_and_short_vectors_enters_as_a_logarithm() {
        for &(v, s) in &[([3.0_f32, 0.0, 4.0], 3.0_f32), ([0.06, 0.0, 0.08], 2.0)] {
            let v1 = V3::<One>::splat(v);
            let (unit, len) = normalize_and_length(v1);
            let scale = Scale::of(v1, len);
            assert!(!scale.near.0[0]);
            let h = V3::splat([0.0, 0.0, 1.0]);
            let got = f64::from(cos_pow(unit.dot(h), unit, h, s, &scale).0[0]);
            let exact = f64::from(v[2]).powf(f64::from(s));
            assert!((got / exact - 1.0).abs() < 1e-6, "{got} vs {exact}");
        }
    }
}
