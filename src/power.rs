//! The powers of the lighting equation (OpenGL 2.1 §2.14.1): the specular power
//! (n̂⊙ĥ)^s_rm of eq. 2.2 and the spot factor (P_pli→V ⊙ ŝ_dli)^s_rli of eq. 2.5, as
//! `exp(s·ln(1 − x))` over lanes, shared by the per-call constants and the kernel.

use std::ops::{Add, Sub};

use crate::elementary::{ElementaryLanes, Tier};
use crate::float::Float;
use crate::lanes::{LaneMask, Lanes, V3};

/// A spot light's cone, in the kernel's type.
#[derive(Clone, Copy, Debug)]
pub struct Spot<T: Float> {
    /// ŝ_dli, the unit spot direction.
    pub direction: [T; 3],
    /// cos(c_rli); exactly 0 for a 90° cutoff (f32 `cos(π/2)` is −4.4e-8, f64 +6.1e-17).
    pub cos_cutoff: T,
    /// s_rli.
    pub exponent: T,
}

/// The length of a vector that stands for a unit direction times that length: the cosine of
/// the direction becomes `length · cos` in a power.
///
/// Near 1 (|v|² in [0.5, 2], `near`) the length enters as |v| − 1, computed without
/// cancellation ([`length_minus_one`]); elsewhere as ln |v|. So (|v| cos)^s needs one `ln_1p`
/// per power: ln_1p((|v| − 1) − |v|·x) near 1, ln_1p(−x) + ln |v| elsewhere, x = 1 − cos.
#[derive(Clone, Copy)]
pub struct Scale<V: Lanes> {
    /// The lanes whose length is near 1.
    pub near: V::Mask,
    /// |v| (at most `T::MAX`).
    pub length: V,
    /// |v| − 1 in the `near` lanes.
    pub minus_one: V,
    /// ln |v| in the other lanes.
    pub ln: V,
}

impl<V: ElementaryLanes> Scale<V> {
    /// Length 1: a unit vector.
    #[inline(always)]
    pub fn unit() -> Self {
        Self {
            near: V::Mask::splat(true),
            length: V::splat(V::T::ONE),
            minus_one: V::splat(V::T::ZERO),
            ln: V::splat(V::T::ZERO),
        }
    }

    /// The scale of `v`, whose length (from [`normalize_and_length`]) is `length`.
    #[inline(always)]
    pub fn of(v: V3<V>, length: V) -> Self {
        let (minus_one, near) = length_minus_one(v, length);
        let length = length.min(V::splat(V::T::MAX));
        // ln |v| is read in the far lanes only, and unit normals have none: skip it then.
        let ln = if near.all() {
            V::splat(V::T::ZERO)
        } else {
            V::select(near, V::splat(V::T::ONE), length).ln()
        };
        Self {
            near,
            length,
            minus_one,
            ln,
        }
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

/// |v| − 1 to a few ulp of the result, and the lanes where that holds (|v|² in [0.5, 2]): the
/// squares and their sum are formed exactly, so |v|² − 1 keeps every bit when |v| ≈ 1 (f32 unit
/// normals differ from 1 by a few ulp, and (n·ĥ)^s multiplies that by s).
#[inline(always)]
pub fn length_minus_one<V: Lanes>(v: V3<V>, length: V) -> (V, V::Mask) {
    let one = V::splat(V::T::ONE);
    let (a, ae) = square_exact(v.x);
    let (b, be) = square_exact(v.y);
    let (c, ce) = square_exact(v.z);
    let (ab, e1) = sum_exact(a, b);
    let (abc, e2) = sum_exact(ab, c);
    let near = abc.ge(V::splat(V::T::HALF)) & abc.le(one + one);
    // abc − 1 is exact by Sterbenz in the near lanes.
    let squared_minus_one = (abc - one) + ((e1 + e2) + ((ae + be) + ce));
    let m1 = squared_minus_one / (length + one);
    (m1, near)
}

/// `(scale.length · max(â·b̂, 0))^s` for unit `a`, `b` whose dot product is `cos`, with 0^0 = 1,
/// with the elementary functions of tier `F`.
///
/// 1 − â·b̂ is taken as x = |â − b̂|²/2, which has no cancellation near the highlight, and the
/// power as `exp(s·ln(1 − x))`: the error stays a few ulp at any exponent instead of growing as
/// s·ulp. The length of the vector `a` stands for enters through `scale` (see [`Scale`]).
#[inline(always)]
pub fn cos_pow<V: ElementaryLanes, F: Tier>(
    cos: V,
    a: V3<V>,
    b: V3<V>,
    s: V::T,
    scale: &Scale<V>,
) -> V {
    if s == V::T::ZERO {
        return V::splat(V::T::ONE);
    }
    let d = a - b;
    let x = V::splat(V::T::HALF) * d.dot(d);
    let near = scale.minus_one - scale.length * x;
    let y = V::select(scale.near, near, -x);
    // y > −1: the base is positive (not rounded to 0, where ln would be −inf).
    let zero = V::splat(V::T::ZERO);
    let valid = cos.gt(zero) & x.lt(V::splat(V::T::ONE)) & y.gt(V::splat(-V::T::ONE));
    let ln = F::ln_1p(y) + V::select(scale.near, zero, scale.ln);
    let power = F::exp(V::splat(s) * ln);
    power.min(V::splat(V::T::MAX)).or_zero(valid)
}

/// spot_i of eq. 2.5 for the unit light-to-vertex vectors `to_vertex` (P_pli→V): 0 outside the
/// cone, `(to_vertex ⊙ ŝ)^exponent` inside, with the edge inside (`≥`) and 0^0 = 1.
#[inline(always)]
pub fn spot_factor<V: ElementaryLanes, F: Tier>(spot: &Spot<V::T>, to_vertex: V3<V>) -> V {
    let axis = V3::splat(spot.direction);
    let c = to_vertex.dot(axis).max(V::splat(V::T::ZERO));
    let inside = c.ge(V::splat(spot.cos_cutoff));
    cos_pow::<V, F>(c, to_vertex, axis, spot.exponent, &Scale::unit()).or_zero(inside)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::elementary::Full;
    use crate::lanes::{normalize_and_length, Pack};

    type One = Pack<f32, 1>;

    fn one(v: [f32; 3]) -> V3<One> {
        V3::splat(v)
    }

    fn pow1(cos: f32, a: [f32; 3], b: [f32; 3], s: f32) -> f32 {
        cos_pow::<_, Full>(Pack([cos]), one(a), one(b), s, &Scale::unit()).0[0]
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

    #[test]
    fn length_minus_one_keeps_every_bit_near_one() {
        // f32 unit normals: |n| − 1 is a few ulp, and (n·h)^s multiplies it by s.
        let mut worst: f64 = 0.0;
        for i in 0..20_000 {
            let t = f64::from(i) * 0.013;
            let v = [t.sin() * t.cos(), t.sin() * t.sin(), t.cos()].map(|c| c as f32);
            let (_, len) = normalize_and_length(V3::<One>::splat(v));
            let (m1, near) = length_minus_one(V3::<One>::splat(v), len);
            assert!(near.0[0]);
            let exact = v.map(f64::from).iter().map(|c| c * c).sum::<f64>().sqrt() - 1.0;
            worst = worst.max((f64::from(m1.0[0]) - exact).abs());
        }
        assert!(worst < 1e-14, "{worst}");
    }

    #[test]
    fn the_scale_of_long_and_short_vectors_enters_as_a_logarithm() {
        for &(v, s) in &[([3.0_f32, 0.0, 4.0], 3.0_f32), ([0.06, 0.0, 0.08], 2.0)] {
            let v1 = V3::<One>::splat(v);
            let (unit, len) = normalize_and_length(v1);
            let scale = Scale::of(v1, len);
            assert!(!scale.near.0[0]);
            let h = V3::splat([0.0, 0.0, 1.0]);
            let got = f64::from(cos_pow::<_, Full>(unit.dot(h), unit, h, s, &scale).0[0]);
            let exact = f64::from(v[2]).powf(f64::from(s));
            assert!((got / exact - 1.0).abs() < 1e-6, "{got} vs {exact}");
        }
    }
}
