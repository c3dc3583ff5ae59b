//! The OpenGL 2.1 fixed-function lighting equation (§2.14.1, eqs. 2.2–2.5) over blocks of `N`
//! vertices at once, one vertex per lane:
//!
//! ```text
//! c_pri = e_cm + a_cm·a_cs + Σ_i att_i·spot_i·[a_cm·a_cli + (n⊙VP)·d_cm·d_cli + f_i·(n⊙ĥ)^s·s_cm·s_cli]
//! ```
//!
//! The sum is regrouped by material factor (a_cm·Σ w_i a_cli + d_cm·Σ w_i (n⊙VP) d_cli + …), so a
//! per-vertex colour material costs nothing per light. This is the only copy of the equation:
//! `shade`, the plan's general reference and the renderer all run it. Every conditional term is
//! a select, never a multiplication by a 0/1 mask. A light's weight (att·spot times n⊙VP or the
//! power) is formed first and then saturated at [`Real::SATURATION`], so a huge |n|^s times a
//! tiny spot factor keeps its value, and colours are saturated at [`Real::COLOR_SATURATION`]:
//! finite input never meets `inf · 0` or `inf − inf`.

use crate::lanes::{
    build, normalize_and_length, normalize_and_length_fast, normalize_or_zero_fast, Mask, Pack, V3,
};
use crate::material::ColorMaterialMode;
use crate::plan::Plan;
use crate::prepare::{Prepared, PreparedLight, Source, Spot, Viewer};
use crate::real::Real;
use crate::scene::Specular;

/// Per-vertex colours for `GL_COLOR_MATERIAL`: `data` holds `width` (3 or 4) values per vertex,
/// row after row; a missing alpha is 1.
#[derive(Clone, Copy, Debug)]
pub struct VertexColors<'a, T> {
    /// The colours, C order.
    pub data: &'a [T],
    /// Values per vertex: 3 (RGB) or 4 (RGBA).
    pub width: usize,
}

/// The length of a vector that stands for a unit direction times that length: the cosine of
/// the direction becomes `length · cos` in a power.
///
/// Near 1 (|v|² in [0.5, 2], `near`) the length enters as |v| − 1, computed without
/// cancellation ([`length_minus_one`]); elsewhere as ln |v|. So (|v| cos)^s needs one `ln_1p`
/// per power: ln_1p((|v| − 1) − |v|·x) near 1, ln_1p(−x) + ln |v| elsewhere, x = 1 − cos.
#[derive(Clone, Copy)]
pub struct Scale<T, const N: usize> {
    /// The lanes whose length is near 1.
    pub near: Mask<N>,
    /// |v| (at most `T::MAX`).
    pub length: Pack<T, N>,
    /// |v| − 1 in the `near` lanes.
    pub minus_one: Pack<T, N>,
    /// ln |v| in the other lanes.
    pub ln: Pack<T, N>,
}

impl<T: Real, const N: usize> Scale<T, N> {
    /// Length 1: a unit vector.
    #[inline(always)]
    pub fn unit() -> Self {
        Self {
            near: Mask::splat(true),
            length: Pack::splat(T::ONE),
            minus_one: Pack::splat(T::ZERO),
            ln: Pack::splat(T::ZERO),
        }
    }

    /// The scale of `v`, whose length (from [`normalize_and_length`]) is `length`.
    #[inline(always)]
    pub fn of(v: V3<T, N>, length: Pack<T, N>) -> Self {
        let (minus_one, near) = length_minus_one(v, length);
        let length = length.min(Pack::splat(T::MAX));
        let far = Pack::select(near, Pack::splat(T::ONE), length);
        Self {
            near,
            length,
            minus_one,
            ln: Pack(T::ln_lanes(far.0)),
        }
    }
}

/// (a, e) with a + e = x · x exactly (Dekker's product from Veltkamp's split; no fused
/// multiply-add, so the same bits on every CPU), for |x| well inside the type's range.
#[inline(always)]
fn square_exact<T: Real, const N: usize>(x: Pack<T, N>) -> (Pack<T, N>, Pack<T, N>) {
    let c = x * Pack::splat(T::SPLIT);
    let high = c - (c - x);
    let low = x - high;
    let square = x * x;
    let error = ((high * high - square) + (high + high) * low) + low * low;
    (square, error)
}

/// (s, e) with s + e = a + b exactly (Knuth's TwoSum).
#[inline(always)]
fn sum_exact<T: Real, const N: usize>(a: Pack<T, N>, b: Pack<T, N>) -> (Pack<T, N>, Pack<T, N>) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// |v| − 1 to a few ulp of the result, and the lanes where that holds (|v|² in [0.5, 2]): the
/// squares and their sum are formed exactly, so |v|² − 1 keeps every bit when |v| ≈ 1 (f32 unit
/// normals differ from 1 by a few ulp, and (n·ĥ)^s multiplies that by s).
#[inline(always)]
pub fn length_minus_one<T: Real, const N: usize>(
    v: V3<T, N>,
    length: Pack<T, N>,
) -> (Pack<T, N>, Mask<N>) {
    let (a, ae) = square_exact(v.x);
    let (b, be) = square_exact(v.y);
    let (c, ce) = square_exact(v.z);
    let (ab, e1) = sum_exact(a, b);
    let (abc, e2) = sum_exact(ab, c);
    let near = abc.ge(Pack::splat(T::HALF)) & abc.le(Pack::splat(T::ONE + T::ONE));
    // abc − 1 is exact by Sterbenz in the near lanes.
    let squared_minus_one = (abc - Pack::splat(T::ONE)) + ((e1 + e2) + ((ae + be) + ce));
    let m1 = squared_minus_one / (length + Pack::splat(T::ONE));
    (m1, near)
}

/// `(scale.length · max(â·b̂, 0))^s` for unit `a`, `b` whose dot product is `cos`, with 0^0 = 1.
///
/// 1 − â·b̂ is taken as x = |â − b̂|²/2, which has no cancellation near the highlight, and the
/// power as `exp(s·ln(1 − x))`: the error stays a few ulp at any exponent instead of growing as
/// s·ulp. The length of the vector `a` stands for enters through `scale` (see [`Scale`]).
#[inline(always)]
pub fn cos_pow<T: Real, const N: usize>(
    cos: Pack<T, N>,
    a: V3<T, N>,
    b: V3<T, N>,
    s: T,
    scale: &Scale<T, N>,
) -> Pack<T, N> {
    if s == T::ZERO {
        return Pack::splat(T::ONE);
    }
    let d = a - b;
    let x = Pack::splat(T::HALF) * d.dot(d);
    let near = scale.minus_one - scale.length * x;
    let y = Pack::select(scale.near, near, -x);
    // y > −1: the base is positive (not rounded to 0, where ln would be −inf).
    let valid =
        cos.gt(Pack::splat(T::ZERO)) & x.lt(Pack::splat(T::ONE)) & y.gt(Pack::splat(-T::ONE));
    let ln = y.ln_1p() + Pack::select(scale.near, Pack::splat(T::ZERO), scale.ln);
    let power = (Pack::splat(s) * ln).exp();
    power.min(Pack::splat(T::MAX)).or_zero(valid)
}

/// spot_i of eq. 2.5 for the unit light-to-vertex vectors `to_vertex` (P_pli→V): 0 outside the
/// cone, `(to_vertex ⊙ ŝ)^exponent` inside, with the edge inside (`≥`) and 0^0 = 1.
#[inline(always)]
pub fn spot_factor<T: Real, const N: usize>(spot: &Spot<T>, to_vertex: V3<T, N>) -> Pack<T, N> {
    let axis = V3::splat(spot.direction);
    let c = to_vertex.dot(axis).max(Pack::splat(T::ZERO));
    let inside = c.ge(Pack::splat(spot.cos_cutoff));
    cos_pow(c, to_vertex, axis, spot.exponent, &Scale::unit()).or_zero(inside)
}

/// att_i of eq. 2.4; zero coefficients are skipped so an infinite distance gives 0, not NaN, and
/// a zero denominator (the light at the vertex with k0 = 0) gives a large finite weight.
#[inline(always)]
fn attenuation<T: Real, const N: usize>(k: [T; 3], d: Pack<T, N>) -> Pack<T, N> {
    let mut den = Pack::splat(k[0]);
    if k[1] != T::ZERO {
        den = den + Pack::splat(k[1]) * d;
    }
    if k[2] != T::ZERO {
        den = den + Pack::splat(k[2]) * d * d;
    }
    Pack::splat(T::ONE) / den.max(Pack::splat(T::MIN_POSITIVE))
}

/// `x` clamped to ±[`Real::SATURATION`].
#[inline(always)]
fn sat<T: Real, const N: usize>(x: Pack<T, N>) -> Pack<T, N> {
    x.clamp(-T::SATURATION, T::SATURATION)
}

/// `w · factor` for w ≥ 0 and factor > 0 (in the lanes that use it), saturated: a product of
/// two finite values, so at worst +inf before the clamp, never NaN.
#[inline(always)]
fn weight<T: Real, const N: usize>(w: Pack<T, N>, factor: Pack<T, N>) -> Pack<T, N> {
    (w * factor.min(Pack::splat(T::MAX))).min(Pack::splat(T::SATURATION))
}

/// `rgb` saturated lane by lane.
#[inline(always)]
fn sat3<T: Real, const N: usize>(v: V3<T, N>) -> V3<T, N> {
    V3 {
        x: sat(v.x),
        y: sat(v.y),
        z: sat(v.z),
    }
}

/// `a += b` component by component with TwoSum, the rounding errors added to `error`.
#[inline(always)]
fn two_sum3<T: Real, const N: usize>(a: &mut V3<T, N>, b: V3<T, N>, error: &mut V3<T, N>) {
    let (x, ex) = sum_exact(a.x, b.x);
    let (y, ey) = sum_exact(a.y, b.y);
    let (z, ez) = sum_exact(a.z, b.z);
    *a = V3 { x, y, z };
    *error = *error
        + V3 {
            x: ex,
            y: ey,
            z: ez,
        };
}

/// The normal of one side as the equation needs it.
#[derive(Clone, Copy)]
struct SideNormal<T, const N: usize> {
    /// n as GL uses it (unit only with `normalize`), negated for the back side.
    n: V3<T, N>,
    /// n̂, its direction (when the plan computes it).
    unit: V3<T, N>,
    /// |n| (1 with `normalize`): (n·ĥ)^s = (|n| n̂·ĥ)^s.
    scale: Scale<T, N>,
}

/// The light-weighted sums of one side: Σ w·a_cli, Σ w(n⊙VP)d_cli and Σ w·f·pow·s_cli.
#[derive(Clone, Copy)]
struct Sums<T, const N: usize> {
    ambient: V3<T, N>,
    diffuse: V3<T, N>,
    specular: V3<T, N>,
}

impl<T: Real, const N: usize> Sums<T, N> {
    #[inline(always)]
    fn zero() -> Self {
        Self {
            ambient: V3::zero(),
            diffuse: V3::zero(),
            specular: V3::zero(),
        }
    }

    /// Every sum, lane by lane, through `f`.
    #[inline(always)]
    fn map<U: Real>(&self, f: impl Fn(V3<T, N>) -> V3<U, N>) -> Sums<U, N> {
        Sums {
            ambient: f(self.ambient),
            diffuse: f(self.diffuse),
            specular: f(self.specular),
        }
    }

    /// `self += o` with TwoSum, the rounding errors added to `error`.
    #[inline(always)]
    fn add_exact(&mut self, o: &Self, error: &mut Self) {
        two_sum3(&mut self.ambient, o.ambient, &mut error.ambient);
        two_sum3(&mut self.diffuse, o.diffuse, &mut error.diffuse);
        two_sum3(&mut self.specular, o.specular, &mut error.specular);
    }

    #[inline(always)]
    fn add(&mut self, o: &Self) {
        self.ambient = self.ambient + o.ambient;
        self.diffuse = self.diffuse + o.diffuse;
        self.specular = self.specular + o.specular;
    }
}

/// `v` converted lane by lane.
#[inline(always)]
fn convert<T: Real, U: Real, const N: usize>(v: V3<T, N>) -> V3<U, N> {
    let c = |p: Pack<T, N>| Pack(build(U::ZERO, |i| U::from_f64(p.0[i].to_f64())));
    V3 {
        x: c(v.x),
        y: c(v.y),
        z: c(v.z),
    }
}

/// One block's inputs, already loaded into lanes.
#[derive(Clone, Copy)]
pub struct Block<T, const N: usize> {
    /// Positions (model coordinates), or zeros when the plan does not read them.
    pub positions: V3<T, N>,
    /// Normals (model coordinates).
    pub normals: V3<T, N>,
    /// RGBA vertex colours for `GL_COLOR_MATERIAL`.
    pub colors: Option<[Pack<T, N>; 4]>,
}

/// The primary and secondary RGBA colours of one side of a block, after the clamp (the
/// secondary is unused without separate specular).
pub type SideColors<T, const N: usize> = [[Pack<T, N>; 4]; 2];

/// A prepared scene and its plan: the kernel of one `shade` call.
pub struct Kernel<'a, T: Real> {
    /// The per-call constants.
    pub prepared: &'a Prepared<T>,
    /// Which terms to compute.
    pub plan: &'a Plan,
}

impl<T: Real> Kernel<'_, T> {
    /// VP_pli (unit, or zero for a light at the vertex) and att_i·spot_i (finite: at most
    /// 1/`MIN_POSITIVE`).
    #[inline(always)]
    fn light_at<const N: usize>(
        light: &PreparedLight<T>,
        attenuated: bool,
        p: V3<T, N>,
    ) -> (V3<T, N>, Pack<T, N>) {
        match light.source {
            Source::Directional { vp, spot, .. } => (V3::splat(vp), Pack::splat(spot)),
            Source::Positional {
                position,
                attenuation: k,
                spot,
            } => {
                let (vp, d) = normalize_and_length_fast(V3::splat(position) - p);
                let att = if attenuated {
                    attenuation(k, d)
                } else {
                    Pack::splat(T::ONE)
                };
                let w = match spot {
                    Some(s) => att * spot_factor(&s, -vp),
                    None => att,
                };
                (vp, w)
            }
        }
    }

    /// (n⊙ĥ)^s (Blinn) or (R⊙VP_e)^s (Phong); 0^0 = 1 whatever ĥ, and for s > 0 no specular
    /// from a zero ĥ or a viewer at the vertex.
    #[inline(always)]
    fn specular_power<const N: usize>(
        &self,
        light: &PreparedLight<T>,
        side: &SideNormal<T, N>,
        vp: V3<T, N>,
        view: V3<T, N>,
        n_dot_vp: Pack<T, N>,
        s: T,
    ) -> Pack<T, N> {
        if s == T::ZERO {
            return Pack::splat(T::ONE);
        }
        match self.prepared.specular {
            Specular::Blinn => {
                let h = match light.source {
                    Source::Directional {
                        halfway: Some(h), ..
                    } => V3::splat(h),
                    _ => normalize_or_zero_fast(vp + view),
                };
                let power = cos_pow(side.unit.dot(h), side.unit, h, s, &side.scale);
                power.or_zero(!h.is_zero())
            }
            Specular::Phong => {
                let r = side.n.scale(n_dot_vp + n_dot_vp) - vp;
                let (r_unit, r_length) = normalize_and_length_fast(r);
                let zero = r_length.eq(Pack::splat(T::ZERO));
                let scale = if self.prepared.normalize {
                    Scale::unit()
                } else {
                    Scale::of(r, r_length)
                };
                let power = cos_pow(r_unit.dot(view), r_unit, view, s, &scale);
                power.or_zero(!(zero | view.is_zero()))
            }
        }
    }

    /// The material of `side` (0 front, 1 back), with the vertex colours where
    /// `GL_COLOR_MATERIAL` tracks them: ambient, diffuse, specular, emission, as RGBA lanes.
    #[inline(always)]
    fn material<const N: usize>(
        &self,
        side: usize,
        colors: Option<[Pack<T, N>; 4]>,
    ) -> [[Pack<T, N>; 4]; 4] {
        let m = &self.prepared.materials[side];
        let splat = |c: [T; 4]| [0, 1, 2, 3].map(|k| Pack::splat(c[k]));
        let mut out = [
            splat(m.ambient),
            splat(m.diffuse),
            splat(m.specular),
            splat(m.emission),
        ];
        if let (Some(cm), Some(c)) = (self.prepared.color_material, colors) {
            if cm.applies_to(side == 1) {
                let slots: &[usize] = match cm.mode {
                    ColorMaterialMode::Ambient => &[0],
                    ColorMaterialMode::Diffuse => &[1],
                    ColorMaterialMode::Specular => &[2],
                    ColorMaterialMode::Emission => &[3],
                    ColorMaterialMode::AmbientAndDiffuse => &[0, 1],
                };
                for &k in slots {
                    out[k] = c;
                }
            }
        }
        out
    }

    /// The light sums of `lights` (the lights `first..` of the scene) at one block, for
    /// `side` (0 front, 1 back, whose normal `normal` is already negated).
    #[inline(always)]
    fn sums<const N: usize>(
        &self,
        lights: &[PreparedLight<T>],
        first: usize,
        p: V3<T, N>,
        normal: &SideNormal<T, N>,
        side: usize,
        view: V3<T, N>,
    ) -> Sums<T, N> {
        let (prepared, plan) = (self.prepared, self.plan);
        let zero = Pack::splat(T::ZERO);
        let side_plan = &plan.sides[side];
        let s = prepared.materials[side].shininess;
        let mut acc = Sums::<T, N>::zero();
        for (light, lp) in lights.iter().zip(&plan.lights[first..]) {
            let (vp, w) = Self::light_at(light, lp.attenuated, p);
            if lp.ambient {
                let weight = w.min(Pack::splat(T::SATURATION));
                acc.ambient = acc.ambient + V3::splat(light.ambient).scale(weight);
            }
            let n_dot_vp = normal.n.dot(vp);
            // f_i: no diffuse and no specular unless n·VP > 0 (a select, never a 0· mask).
            let lit = n_dot_vp.gt(zero);
            if lp.diffuse {
                let weight = weight(w, n_dot_vp).or_zero(lit);
                acc.diffuse = acc.diffuse + V3::splat(light.diffuse).scale(weight);
            }
            if lp.specular && side_plan.specular {
                let power = if side_plan.power {
                    self.specular_power(light, normal, vp, view, n_dot_vp, s)
                } else {
                    Pack::splat(T::ONE)
                };
                // Without the gate (learnopengl) a zero normal or a light at the vertex still
                // has no direction, so no specular.
                let gate = if prepared.specular_gate {
                    lit
                } else {
                    !(normal.n.is_zero() | vp.is_zero())
                };
                let weight = weight(w, power).or_zero(gate);
                acc.specular = acc.specular + V3::splat(light.specular).scale(weight);
            }
        }
        acc
    }

    /// The colours of one side of a block of `N` vertices (0 front, 1 back: the back of
    /// two-sided lighting is lit with −n and the back material): the primary and, with separate
    /// specular, the secondary colour, clamped, NaN in the lanes whose inputs are not finite.
    /// The equation for `N` vertices at once.
    #[inline(always)]
    pub fn block<const N: usize>(&self, input: &Block<T, N>, side: usize) -> SideColors<T, N> {
        let (prepared, plan) = (self.prepared, self.plan);
        let zero = Pack::splat(T::ZERO);
        let (mut p, mut n) = (input.positions, input.normals);
        if let Some(t) = &prepared.transform {
            n = t.normal(n);
            if plan.positions {
                p = t.point(p);
            }
        }
        let mut finite = n.is_finite();
        if plan.positions {
            finite = finite & p.is_finite();
        }
        if let Some(c) = &input.colors {
            finite = finite & c.iter().fold(Mask::splat(true), |m, x| m & x.is_finite());
        }

        let front = if plan.unit_normal {
            let (unit, length) = normalize_and_length(n);
            if prepared.normalize {
                SideNormal {
                    n: unit,
                    unit,
                    scale: Scale::unit(),
                }
            } else {
                let scale = if plan.normal_length {
                    Scale::of(n, length)
                } else {
                    Scale::unit()
                };
                SideNormal { n, unit, scale }
            }
        } else {
            SideNormal {
                n,
                unit: n,
                scale: Scale::unit(),
            }
        };
        let normal = if side == 0 {
            front
        } else {
            SideNormal {
                n: -front.n,
                unit: -front.unit,
                ..front
            }
        };
        let view = match prepared.viewer {
            Viewer::Infinite(v) => V3::splat(v),
            Viewer::Local(e) if plan.view => normalize_or_zero_fast(V3::splat(e) - p),
            Viewer::Local(_) => V3::zero(),
        };

        let lights = &prepared.lights;
        let sums = if lights.len() <= T::SUM_BLOCK {
            self.sums(lights, 0, p, &normal, side, view)
        } else {
            // Blocks of SUM_BLOCK lights, added in f64 with their rounding errors kept apart:
            // the error is SUM_BLOCK ulp of Σ|terms| whatever the light count.
            let (mut total, mut error) = (Sums::<f64, N>::zero(), Sums::<f64, N>::zero());
            for (b, chunk) in lights.chunks(T::SUM_BLOCK).enumerate() {
                let part = self.sums(chunk, b * T::SUM_BLOCK, p, &normal, side, view);
                total.add_exact(&part.map(convert::<T, f64, N>), &mut error);
            }
            total.add(&error);
            total.map(convert::<f64, T, N>)
        };
        let sums = sums.map(sat3);

        let nan = Pack::splat(T::NAN);
        // + 0 turns −0 into +0; the clamp keeps NaN, which `finite` then decides.
        let clamp = |x: Pack<T, N>| Pack::select(finite, (x + zero).clamp(T::ZERO, T::ONE), nan);
        let emit = |rgb: V3<T, N>, alpha: Pack<T, N>| {
            [clamp(rgb.x), clamp(rgb.y), clamp(rgb.z), clamp(alpha)]
        };
        let [a, d, s, e] = self.material(side, input.colors);
        let alpha = d[3];
        let rgb = |c: [Pack<T, N>; 4]| V3 {
            x: c[0],
            y: c[1],
            z: c[2],
        };
        let (a, d, s, e) = (rgb(a), rgb(d), rgb(s), rgb(e));
        let mul = |m: V3<T, N>, v: V3<T, N>| V3 {
            x: m.x * v.x,
            y: m.y * v.y,
            z: m.z * v.z,
        };
        let global = V3::splat(prepared.global_ambient);
        let lit = e + mul(a, global) + mul(a, sums.ambient) + mul(d, sums.diffuse);
        let specular = mul(s, sums.specular);
        if prepared.separate_specular {
            [emit(lit, alpha), emit(specular, Pack::splat(T::ONE))]
        } else {
            [emit(lit + specular, alpha), [zero; 4]]
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn one(v: [f32; 3]) -> V3<f32, 1> {
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

    #[test]
    fn length_minus_one_keeps_every_bit_near_one() {
        // f32 unit normals: |n| − 1 is a few ulp, and (n·h)^s multiplies it by s.
        let mut worst: f64 = 0.0;
        for i in 0..20_000 {
            let t = f64::from(i) * 0.013;
            let v = [t.sin() * t.cos(), t.sin() * t.sin(), t.cos()].map(|c| c as f32);
            let (_, len) = normalize_and_length(V3::<f32, 1>::splat(v));
            let (m1, near) = length_minus_one(V3::<f32, 1>::splat(v), len);
            assert!(near.0[0]);
            let exact = v.map(f64::from).iter().map(|c| c * c).sum::<f64>().sqrt() - 1.0;
            worst = worst.max((f64::from(m1.0[0]) - exact).abs());
        }
        assert!(worst < 1e-14, "{worst}");
    }

    #[test]
    fn the_scale_of_long_and_short_vectors_enters_as_a_logarithm() {
        for &(v, s) in &[([3.0_f32, 0.0, 4.0], 3.0_f32), ([0.06, 0.0, 0.08], 2.0)] {
            let v1 = V3::<f32, 1>::splat(v);
            let (unit, len) = normalize_and_length(v1);
            let scale = Scale::of(v1, len);
            assert!(!scale.near.0[0]);
            let h = V3::splat([0.0, 0.0, 1.0]);
            let got = f64::from(cos_pow(unit.dot(h), unit, h, s, &scale).0[0]);
            let exact = f64::from(v[2]).powf(f64::from(s));
            assert!((got / exact - 1.0).abs() < 1e-6, "{got} vs {exact}");
        }
    }

    #[test]
    fn attenuation_skips_zero_coefficients() {
        let d = Pack([0.0_f32, 2.0, f32::INFINITY]);
        assert_eq!(attenuation([1.0, 0.0, 0.0], d).0, [1.0; 3]);
        let quadratic = attenuation([0.0, 0.0, 1.0], d).0;
        assert_eq!(quadratic[1], 0.25);
        assert!(
            quadratic[0].is_finite() && quadratic[0] > 1e37,
            "k0 = 0 at d = 0 stays finite"
        );
        assert_eq!(quadratic[2], 0.0, "an infinite distance gives 0, not NaN");
    }
}
