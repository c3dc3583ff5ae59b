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
//! power) is formed first and then saturated at [`Float::SATURATION`], so a huge |n|^s times a
//! tiny spot factor keeps its value, and colours are saturated at [`Float::COLOR_SATURATION`]:
//! finite input never meets `inf · 0` or `inf − inf`. Eye-space normals are saturated at
//! 2^[`normal_exponent`] with their direction kept ([`Kernel::block`]), so a finite normal of
//! any magnitude, under any normal matrix, lights finitely.
//!
//! That is the careful path. A float32 kernel first runs each block on the lean path, the same
//! equation in plain float32 arithmetic (`LEAN`: plain powers, no saturation, 1/d and the
//! attenuation from one division), and keeps the colours of each group of [`LEAN_GROUP`] lanes
//! whose every lane passed the lean path's checks (`Kernel::lean_block`); the other groups take
//! the careful path's colours. Groups, not blocks, so every block width gives the same bits.

use std::marker::PhantomData;

use crate::gl::material::ColorMaterialMode;
use crate::gl::scene::Specular;
use crate::lighting::block::{emit, Block, SideColors};
use crate::lighting::clamp::ColorClamp;
use crate::lighting::driver::BlockShader;
use crate::lighting::fixed_function::plan::{LightKind, LightPlan, Plan};
use crate::lighting::fixed_function::power::{
    cos_pow, half_even_exponent, halfway_even_pow, halfway_pow, normal_scale, plain_pow,
    spot_factor, squared_minus_one, sum_exact, Scale,
};
use crate::lighting::fixed_function::prepare::{Prepared, PreparedLight, Source, Viewer};
use crate::lighting::fixed_function::shape::{flag, General, Shape};
use crate::numbers::elementary::ElementaryLanes;
use crate::numbers::real::{Real, LEAN_GROUP};
use crate::simd::dispatch::{Isa, LaneWork};
use crate::simd::float::{ldexp, Float};
use crate::simd::lanes::{
    normalize_and_length, normalize_and_length_fast, normalize_or_zero_fast, LaneMask, Lanes,
    MAX_LANES, V3,
};

/// The exponent of the largest eye-space normal the kernel lights as it is, 2^63 in f32 and
/// 2^511 in f64 (|n|² ≤ 1/`MIN_POSITIVE`): Phong's R = 2(n·VP)n − VP then stays below
/// 2^127 or 2^1023, and |n|² below `MAX`. Longer normals are saturated ([`Kernel::block`]).
pub fn normal_exponent<T: Real>() -> i32 {
    ((T::EXPONENT_BIAS - 1) / 2) as i32
}

/// ⌊log2 x⌋ for finite x > 0, subnormals included (inlined, unlike `real::exponent`: the
/// kernel's rare path must make no call).
#[inline(always)]
fn log2_floor(x: f64) -> i32 {
    let (x, lift) = if x < f64::MIN_POSITIVE {
        (x * f64::from_bits((1023 + 64) << 52), 64)
    } else {
        (x, 0)
    };
    ((x.to_bits() >> 52) & 0x7ff) as i32 - 1023 - lift
}

/// att_i of eq. 2.4; zero coefficients are skipped so an infinite distance gives 0, not NaN, and
/// a zero denominator (the light at the vertex with k0 = 0) gives a large finite weight.
#[inline(always)]
fn attenuation<V: Lanes>(k: [V::T; 3], d: V) -> V {
    let mut den = V::splat(k[0]);
    if k[1] != V::T::ZERO {
        den = V::splat(k[1]).mul_add(d, den);
    }
    if k[2] != V::T::ZERO {
        den = (V::splat(k[2]) * d).mul_add(d, den);
    }
    V::splat(V::T::ONE) / den.max(V::splat(V::T::MIN_POSITIVE))
}

/// `w · factor` for w ≥ 0 and factor > 0 (in the lanes that use it), saturated: a product of
/// two finite values, so at worst +inf before the clamp, never NaN. `LEAN`: the product alone
/// (the lean path's checks keep both factors far inside the range).
#[inline(always)]
fn weight<V: Lanes, const LEAN: bool>(w: V, factor: V) -> V {
    if LEAN {
        return w * factor;
    }
    (w * factor.min(V::splat(V::T::MAX))).min(V::splat(V::T::SATURATION))
}

/// The lanes where `x` lies in [`lo`, `hi`] (not NaN).
#[inline(always)]
fn within<V: Lanes>(x: V, lo: f64, hi: f64) -> V::Mask {
    x.ge(V::splat(V::T::from_f64(lo))) & x.le(V::splat(V::T::from_f64(hi)))
}

/// The lanes of `held` whose whole [`LEAN_GROUP`] is set: the lean path's colours of a group
/// do not depend on the block around it. Off the common path (a block with a lane on the
/// careful one), so by way of memory.
#[inline(always)]
fn whole_groups<V: Lanes>(held: V::Mask) -> V::Mask {
    let bits = held.bitmask();
    let width = LEAN_GROUP.min(V::N);
    let mut whole = [V::T::ZERO; MAX_LANES];
    for start in (0..V::N).step_by(width) {
        let group = (u64::MAX >> (64 - width)) << start;
        if bits & group == group {
            whole[start..start + width].fill(V::T::ONE);
        }
    }
    V::load(&whole).gt(V::splat(V::T::ZERO))
}

/// The squared distances and distance–attenuation products the lean path takes, 2^-40 to
/// 2^40: 1/d, att and att·spot then stay below 2^60, and with a power of at most 2^64
/// ([`crate::lighting::fixed_function::plan::LEAN_EXPONENT_MAX`]) every weight below 2^124,
/// finite in float32.
const LEAN_RANGE: (f64, f64) = (9.094_947_017_729_282e-13, 1_099_511_627_776.0);

/// `x` saturated at ±[`Float::SATURATION`] lane by lane.
#[inline(always)]
fn sat<V: Lanes>(x: V) -> V {
    x.clamp(-V::T::SATURATION, V::T::SATURATION)
}

/// `rgb` saturated lane by lane.
#[inline(always)]
fn sat3<V: Lanes>(v: V3<V>) -> V3<V> {
    V3 {
        x: sat(v.x),
        y: sat(v.y),
        z: sat(v.z),
    }
}

/// The normal of one side as the equation needs it.
#[derive(Clone, Copy)]
struct SideNormal<V: Lanes> {
    /// n as GL uses it (unit only with `normalize`), negated for the back side.
    n: V3<V>,
    /// n̂, its direction (when the plan computes it, and in a block with a normal far from unit
    /// length whenever the plan computes |n|).
    unit: V3<V>,
    /// |n| (1 with `normalize`): (n·ĥ)^s = (|n| n̂·ĥ)^s.
    scale: Scale<V>,
}

/// (n̂⊙ĥ)^s of [`Kernel::specular_power`] from ĥ itself: 0 for a zero `g` (VP + VP_e) and
/// s > 0, for the exponents [`halfway_even_pow`] does not take and the lanes it does not hold.
#[inline(always)]
fn halfway_power<V: ElementaryLanes>(side: &SideNormal<V>, g: V3<V>, s: V::T) -> V {
    let h = normalize_or_zero_fast(g);
    let power = cos_pow::<V>(side.unit.dot(h), side.unit, h, s, &side.scale);
    power.or_zero(!h.is_zero())
}

/// `sum + color · weight`, channel by channel (one fused multiply-add each).
#[inline(always)]
fn add_scaled<V: Lanes>(sum: V3<V>, color: [V::T; 3], weight: V) -> V3<V> {
    let c = V3::<V>::splat(color);
    V3 {
        x: c.x.mul_add(weight, sum.x),
        y: c.y.mul_add(weight, sum.y),
        z: c.z.mul_add(weight, sum.z),
    }
}

/// [`add_scaled`], or for `GREY` (r, g and b of `color` and of `sum` the same bits) its red
/// channel alone, copied to the other two: the same bits, one fused multiply-add.
#[inline(always)]
fn add_scaled_as<V: Lanes, const GREY: bool>(sum: V3<V>, color: [V::T; 3], weight: V) -> V3<V> {
    if GREY {
        let x = V::splat(color[0]).mul_add(weight, sum.x);
        V3 { x, y: x, z: x }
    } else {
        add_scaled(sum, color, weight)
    }
}

/// A sum of blocks kept as `total + error` (Knuth's TwoSum per block), so the blocks' own
/// rounding is all that remains: [`Float::SUM_BLOCK`] ulp of Σ|terms| at most, whatever the
/// light count.
#[derive(Clone, Copy)]
struct Compensated<V: Lanes> {
    total: V3<V>,
    error: V3<V>,
}

impl<V: Lanes> Compensated<V> {
    /// The sum with the block sum `part` added.
    #[inline(always)]
    fn add(self, part: V3<V>) -> Self {
        let (x, ex) = sum_exact(self.total.x, part.x);
        let (y, ey) = sum_exact(self.total.y, part.y);
        let (z, ez) = sum_exact(self.total.z, part.z);
        Self {
            total: V3 { x, y, z },
            error: V3 {
                x: self.error.x + ex,
                y: self.error.y + ey,
                z: self.error.z + ez,
            },
        }
    }

    /// The compensated sum, rounded once.
    #[inline(always)]
    fn rounded(self) -> V3<V> {
        self.total + self.error
    }
}

/// The RGBA lanes of a material colour.
#[inline(always)]
fn splat4<V: Lanes>(c: [V::T; 4]) -> [V; 4] {
    [
        V::splat(c[0]),
        V::splat(c[1]),
        V::splat(c[2]),
        V::splat(c[3]),
    ]
}

/// The RGB of RGBA lanes.
#[inline(always)]
fn v3<V: Lanes>(c: [V; 4]) -> V3<V> {
    V3 {
        x: c[0],
        y: c[1],
        z: c[2],
    }
}

/// A prepared scene and its plan: the kernel of one `shade` call, compiled for scenes of shape
/// `S` (whose flags the plan must have: see [`crate::lighting::fixed_function::shape::fits`]).
pub struct Kernel<'a, T: Real, S: Shape = General> {
    /// The per-call constants.
    pub prepared: &'a Prepared<T>,
    /// Which terms to compute.
    pub plan: &'a Plan,
    /// The shape.
    pub compiled: PhantomData<S>,
    /// Positions are read by a local viewer alone, with no positional light whose distance
    /// check would catch a non-finite one: the lean path checks them itself (once per call,
    /// not per block).
    viewer_reads_alone: bool,
}

impl<'a, T: Real, S: Shape> Kernel<'a, T, S> {
    /// The kernel of `prepared` and `plan` for shape `S`.
    pub fn new(prepared: &'a Prepared<T>, plan: &'a Plan) -> Self {
        let positional = plan.lights.iter().copied().any(LightPlan::positional);
        Self {
            prepared,
            plan,
            compiled: PhantomData,
            viewer_reads_alone: plan.positions && !positional,
        }
    }

    /// Positions are read.
    #[inline(always)]
    pub fn reads_positions(&self) -> bool {
        flag(S::KNOWN.positions, self.plan.positions)
    }

    /// Sides lit: 1, or 2 with two-sided lighting.
    #[inline(always)]
    pub fn sides(&self) -> usize {
        flag(S::KNOWN.sides, self.prepared.sides)
    }
}

impl<T: Real, S: Shape> Kernel<'_, T, S> {
    /// The kernel computes in float32: the only type its extra copies (grey sums, near-unit
    /// normals) are compiled for, to spare the build.
    const FLOAT32: bool = std::mem::size_of::<T>() == std::mem::size_of::<f32>();

    /// This kernel sums `plan`'s light sums in one channel: its lights are grey and its shape
    /// and type have the copy that does ([`Shape::GREY_SUMS`], float32 only).
    #[inline(always)]
    pub(crate) fn sums_grey(plan: &Plan) -> bool {
        S::GREY_SUMS && Self::FLOAT32 && plan.grey
    }

    /// Some light has an ambient term.
    #[inline(always)]
    fn any_ambient(&self) -> bool {
        flag(S::KNOWN.light_ambient, self.plan.ambient())
    }

    /// VP_pli (unit, or zero for a light at the vertex) and att_i·spot_i (finite: at most
    /// 1/`MIN_POSITIVE`).
    ///
    /// `LEAN`: 1/d and the attenuation from one division ([`Kernel::lean_distance`], which
    /// clears in `held` the lanes out of its range).
    #[inline(always)]
    fn light_at<V: Lanes<T = T>, const LEAN: bool>(
        light: &PreparedLight<T>,
        attenuated: bool,
        p: V3<V>,
        held: &mut V::Mask,
    ) -> (V3<V>, V) {
        let kind = S::KNOWN.light_kind;
        match light.source {
            Source::Directional { vp, spot, .. } => (V3::splat(vp), V::splat(spot)),
            // A shape of directional lights never meets this arm (`shape::fits`).
            Source::Positional { .. } if matches!(kind, Some(LightKind::Directional { .. })) => {
                (V3::zero(), V::splat(T::ZERO))
            }
            Source::Positional {
                position,
                attenuation: k,
                spot,
                range,
            } => {
                let attenuated = flag(S::KNOWN.attenuated, attenuated);
                let (vp, d, att) = if LEAN {
                    Self::lean_distance(position, k, attenuated, p, held)
                } else {
                    let (vp, d) = normalize_and_length_fast(V3::splat(position) - p);
                    let att = if attenuated {
                        attenuation(k, d)
                    } else {
                        V::splat(T::ONE)
                    };
                    (vp, d, att)
                };
                let cone = kind != Some(LightKind::Positional { spot: false });
                let edges = S::KNOWN.edges != Some(false);
                let w = match spot {
                    Some(s) if cone => att * spot_factor::<V>(&s, -vp, edges),
                    _ => att,
                };
                match range {
                    // Luna's `if (d > L.Range) return;`: nothing at all beyond the range.
                    Some(r) if edges => (vp, w.or_zero(d.le(V::splat(r)))),
                    _ => (vp, w),
                }
            }
        }
    }

    /// The lean path's VP, d and att_i of a positional light at `position` (attenuation `k`)
    /// from the vertex `p`: one square root and one division. The lanes where d² leaves the
    /// normal range, or with k1 or k2, where d² or d·(k0 + k1·d + k2·d²) leaves [`LEAN_RANGE`]
    /// (a light at the vertex or far beyond the scene, a NaN position) are cleared in `held`.
    #[inline(always)]
    fn lean_distance<V: Lanes<T = T>>(
        position: [T; 3],
        k: [T; 3],
        attenuated: bool,
        p: V3<V>,
        held: &mut V::Mask,
    ) -> (V3<V>, V, V) {
        let (lo, hi) = LEAN_RANGE;
        let one = V::splat(T::ONE);
        let l = V3::splat(position) - p;
        let d2 = l.dot(l);
        let d = d2.sqrt();
        // Without a quotient only VP depends on d: the careful path's own range for it, so a
        // scene scaled by a power of two keeps its path and its bits.
        let mut inside = within(d2, T::MIN_POSITIVE.to_f64(), T::MAX.to_f64());
        let (inverse, att) = if attenuated && (k[1] != T::ZERO || k[2] != T::ZERO) {
            inside = inside & within(d2, lo, hi);
            let mut den = V::splat(k[0]);
            if k[1] != T::ZERO {
                den = V::splat(k[1]).mul_add(d, den);
            }
            if k[2] != T::ZERO {
                den = V::splat(k[2]).mul_add(d2, den);
            }
            let product = d * den;
            inside = inside & within(product, lo, hi);
            let r = one / product;
            (r * den, r * d)
        } else if attenuated {
            // The careful path's 1/max(k0, MIN_POSITIVE), once per call (at most 2^60: the
            // plan's condition for the lean path).
            (one / d, V::splat(T::ONE / k[0].max(T::MIN_POSITIVE)))
        } else {
            (one / d, one)
        };
        *held = *held & inside;
        (l.scale(inverse), d, att)
    }

    /// (n⊙ĥ)^s (Blinn) or (R⊙VP_e)^s (Phong); 0^0 = 1 whatever ĥ, and for s > 0 no specular
    /// from a zero ĥ or a viewer at the vertex. `LEAN`: the plain power of the plain cosine
    /// ([`Kernel::lean_power`]).
    #[inline(always)]
    fn specular_power<V: Lanes<T = T>, const LEAN: bool>(
        &self,
        light: &PreparedLight<T>,
        side: &SideNormal<V>,
        vp: V3<V>,
        view: V3<V>,
        n_dot_vp: V,
        s: T,
    ) -> V {
        if s == T::ZERO {
            return V::splat(T::ONE);
        }
        if LEAN {
            return self.lean_power(light, side.n, vp, view, n_dot_vp, s);
        }
        match flag(S::KNOWN.specular, self.prepared.specular) {
            Specular::Blinn => {
                if let Source::Directional {
                    halfway: Some(h), ..
                } = light.source
                {
                    // A constant ĥ is zero in every lane or in none.
                    if h.direction == [T::ZERO; 3] {
                        return V::splat(T::ZERO);
                    }
                    return halfway_pow::<V>(side.n, side.unit, &h, s, &side.scale);
                }
                // A shape whose every ĥ is constant never comes here (`shape::fits`).
                let constant = LightKind::Directional {
                    constant_halfway: true,
                };
                if S::KNOWN.light_kind == Some(constant) {
                    return V::splat(T::ZERO);
                }
                let g = vp + view;
                // An even exponent (most scenes': 32, 64, 128) needs no ĥ, so no √ and ÷
                // for it (8 mixed lights 1.11 times as fast on a Zen 2).
                let Some(half) = half_even_exponent(s) else {
                    return halfway_power(side, g, s);
                };
                let (power, held) = halfway_even_pow(side.n, side.unit, g, half, &side.scale);
                if held.all() {
                    power
                } else {
                    V::select(held, power, halfway_power(side, g, s))
                }
            }
            Specular::Phong => {
                let r = side.n.scale(n_dot_vp + n_dot_vp) - vp;
                let (r_unit, r_length) = normalize_and_length_fast(r);
                let zero = r_length.eq(V::splat(T::ZERO));
                let scale = if self.prepared.normalize {
                    Scale::unit()
                } else {
                    Scale::of(r, r_length)
                };
                let power = cos_pow::<V>(r_unit.dot(view), r_unit, view, s, &scale);
                power.or_zero(!(zero | view.is_zero()))
            }
        }
    }

    /// The lean path's specular power for s > 0: [`plain_pow`] of max(n·ĥ, 0) for a constant
    /// ĥ; of (n·g)²/|g|² to s/2 for an even s and g = VP + VP_e (no ĥ, as the careful
    /// path), else of max(n·g, 0)/|g|; Phong's of max(R·VP_e, 0), R = 2(n·VP)n − VP, divided
    /// by |R| with `normalize` (GL's R is unit then; without it GL takes R as it is).
    #[inline(always)]
    fn lean_power<V: Lanes<T = T>>(
        &self,
        light: &PreparedLight<T>,
        n: V3<V>,
        vp: V3<V>,
        view: V3<V>,
        n_dot_vp: V,
        s: T,
    ) -> V {
        let zero = V::splat(T::ZERO);
        if flag(S::KNOWN.specular, self.prepared.specular) == Specular::Phong {
            let r = n.scale(n_dot_vp + n_dot_vp) - vp;
            let cos = if self.prepared.normalize {
                // R is unit only to the rounding of n and VP, which s would multiply.
                r.dot(view) / r.dot(r).sqrt()
            } else {
                r.dot(view)
            };
            return plain_pow(cos.max(zero), s);
        }
        if let Source::Directional {
            halfway: Some(h), ..
        } = light.source
        {
            return plain_pow(n.dot(V3::splat(h.direction)).max(zero), s);
        }
        let constant = LightKind::Directional {
            constant_halfway: true,
        };
        if S::KNOWN.light_kind == Some(constant) {
            return zero;
        }
        let g = vp + view;
        let n_dot_g = n.dot(g);
        // A zero g (VP = −VP_e) has n·g = 0: no specular, as the careful path's.
        let g2 = g.dot(g).max(V::splat(T::MIN_POSITIVE));
        match half_even_exponent(s) {
            Some(half) => plain_pow(n_dot_g * n_dot_g / g2, half).or_zero(n_dot_g.gt(zero)),
            None => plain_pow((n_dot_g / g2.sqrt()).max(zero), s),
        }
    }

    /// One colour of the material of `side` (0 front, 1 back) as RGBA lanes: `slot` 0 is the
    /// ambient, 1 the diffuse, 2 the specular and 3 the emission colour; the vertex colour where
    /// `GL_COLOR_MATERIAL` tracks it. One colour at a time: an array of all four would be
    /// copied through memory.
    #[inline(always)]
    fn material<V: Lanes<T = T>>(
        &self,
        side: usize,
        slot: usize,
        colors: Option<[V; 4]>,
    ) -> [V; 4] {
        if let (Some(cm), Some(c)) = (self.prepared.color_material, colors) {
            let tracked = match cm.mode {
                ColorMaterialMode::Ambient => slot == 0,
                ColorMaterialMode::Diffuse => slot == 1,
                ColorMaterialMode::Specular => slot == 2,
                ColorMaterialMode::Emission => slot == 3,
                ColorMaterialMode::AmbientAndDiffuse => slot <= 1,
            };
            if tracked && cm.applies_to(side == 1) {
                return c;
            }
        }
        let m = &self.prepared.materials[side];
        splat4([m.ambient, m.diffuse, m.specular, m.emission][slot])
    }

    /// The light sums of `lights` (the lights `first..` of the scene) at one block, for
    /// `side` (0 front, 1 back, whose normal `normal` is already negated): ambient, diffuse
    /// and specular.
    #[inline(always)]
    #[allow(clippy::too_many_arguments)]
    fn sums<V: Lanes<T = T>, const GREY: bool, const LEAN: bool>(
        &self,
        lights: &[PreparedLight<T>],
        first: usize,
        p: V3<V>,
        normal: &SideNormal<V>,
        side: usize,
        view: V3<V>,
        held: &mut V::Mask,
    ) -> [V3<V>; 3] {
        let (prepared, plan) = (self.prepared, self.plan);
        let zero = V::splat(T::ZERO);
        let side_plan = &plan.sides[side];
        let s = prepared.materials[side].shininess;
        let [mut ambient, mut diffuse, mut specular] = [V3::zero(); 3];
        let lit_all = S::KNOWN.lit == Some(true) && side == 0;
        let light_plans = &plan.lights[first..first + lights.len()];
        // By index, not `zip`: at the tests' optimisation level `Zip::new` stayed a call (see
        // `simd::lanes::each`), and the slices' equal lengths drop the bounds checks.
        for i in 0..lights.len() {
            let (light, lp) = (&lights[i], &light_plans[i]);
            let (vp, w) = Self::light_at::<V, LEAN>(light, lp.attenuated, p, held);
            if flag(S::KNOWN.light_ambient, lp.ambient) {
                let weight = if LEAN {
                    w
                } else {
                    w.min(V::splat(T::SATURATION))
                };
                ambient = add_scaled_as::<V, GREY>(ambient, light.ambient, weight);
            }
            let n_dot_vp = normal.n.dot(vp);
            // f_i: no diffuse and no specular unless n·VP > 0 (a select, never a 0· mask).
            let lit = n_dot_vp.gt(zero);
            if lit_all || lp.diffuse {
                let weight = weight::<V, LEAN>(w, n_dot_vp).or_zero(lit);
                diffuse = add_scaled_as::<V, GREY>(diffuse, light.diffuse, weight);
            }
            if lit_all || (lp.specular && side_plan.specular) {
                let power = if lit_all || side_plan.power {
                    self.specular_power::<V, LEAN>(light, normal, vp, view, n_dot_vp, s)
                } else {
                    V::splat(T::ONE)
                };
                // Without the gate (learnopengl) a zero normal or a light at the vertex still
                // has no direction, so no specular.
                let gate = if flag(S::KNOWN.gate, prepared.specular_gate) {
                    lit
                } else {
                    !(normal.n.is_zero() | vp.is_zero())
                };
                let weight = weight::<V, LEAN>(w, power).or_zero(gate);
                specular = add_scaled_as::<V, GREY>(specular, light.specular, weight);
            }
        }
        [ambient, diffuse, specular]
    }

    /// The light sums of every light, saturated: in blocks of [`Float::SUM_BLOCK`] lights
    /// summed in `T` (within ½ ulp of Σ|terms| per light), the blocks' sums saturated and added
    /// with their rounding errors kept apart ([`Compensated`]), so the error is `SUM_BLOCK` ulp
    /// of Σ|terms| whatever the light count. `LEAN`: the same sums, unsaturated (the caller
    /// checks them).
    #[inline(always)]
    fn all_sums<V: Lanes<T = T>, const GREY: bool, const LEAN: bool>(
        &self,
        p: V3<V>,
        normal: &SideNormal<V>,
        side: usize,
        view: V3<V>,
        held: &mut V::Mask,
    ) -> [V3<V>; 3] {
        let lights = &self.prepared.lights;
        let sums = if flag(S::KNOWN.few_lights, lights.len() <= T::SUM_BLOCK) {
            // One or two lights of a shape's one kind as straight code: the sums stay in
            // registers, not memory (one directional light 1.2 times as fast on a Zen 2). One
            // call per length, so that each call's slice has a constant length to unroll.
            let one_kind = S::KNOWN.light_kind.is_some();
            let (p, n) = (p, normal);
            match lights.len() {
                1 if one_kind => {
                    self.sums::<V, GREY, LEAN>(&lights[..1], 0, p, n, side, view, held)
                }
                2 if one_kind => {
                    self.sums::<V, GREY, LEAN>(&lights[..2], 0, p, n, side, view, held)
                }
                _ => self.sums::<V, GREY, LEAN>(lights, 0, p, n, side, view, held),
            }
        } else {
            let empty = Compensated {
                total: V3::zero(),
                error: V3::zero(),
            };
            let mut sums = [empty; 3];
            for (b, chunk) in lights.chunks(T::SUM_BLOCK).enumerate() {
                let first = b * T::SUM_BLOCK;
                let part = self.sums::<V, GREY, LEAN>(chunk, first, p, normal, side, view, held);
                for (sum, part) in sums.iter_mut().zip(part) {
                    // Saturated, so no partial total overflows (inf − inf would be NaN; the
                    // lean path's check of the sums sends such a block to the careful path).
                    *sum = sum.add(if LEAN { part } else { sat3(part) });
                }
            }
            // Not `sums.map(..)`, whose additions became calls (see `simd::lanes::each`).
            let [a, d, s] = sums;
            [a.rounded(), d.rounded(), s.rounded()]
        };
        if LEAN {
            return sums;
        }
        let ambient = if self.any_ambient() {
            sat3(sums[0])
        } else {
            sums[0]
        };
        [ambient, sat3(sums[1]), sat3(sums[2])]
    }

    /// The colours of one side of a block whose front normal is `front`: the light sums, the
    /// material and the clamp ([`Kernel::block`] after the normal). `LEAN`: with the lean
    /// arithmetic, the lanes it does not hold cleared in `held`.
    #[inline(always)]
    fn side_colors<V: Lanes<T = T>, const LEAN: bool>(
        &self,
        p: V3<V>,
        front: SideNormal<V>,
        colors: Option<[V; 4]>,
        finite: V::Mask,
        side: usize,
        held: &mut V::Mask,
    ) -> SideColors<V> {
        // Grey lights sum one channel (8 mixed and 32 point lights 1.1 times as fast on a Zen 2).
        if Self::sums_grey(self.plan) {
            self.side_colors_as::<V, true, LEAN>(p, front, colors, finite, side, held)
        } else {
            self.side_colors_as::<V, false, LEAN>(p, front, colors, finite, side, held)
        }
    }

    /// [`Kernel::side_colors`], its light sums of one channel for `GREY` lights
    /// ([`add_scaled_as`]).
    #[inline(always)]
    fn side_colors_as<V: Lanes<T = T>, const GREY: bool, const LEAN: bool>(
        &self,
        p: V3<V>,
        front: SideNormal<V>,
        colors: Option<[V; 4]>,
        finite: V::Mask,
        side: usize,
        held: &mut V::Mask,
    ) -> SideColors<V> {
        let (prepared, plan) = (self.prepared, self.plan);
        let normal = if side == 0 {
            front
        } else {
            SideNormal {
                n: -front.n,
                unit: -front.unit,
                ..front
            }
        };
        let local = S::KNOWN.local_viewer != Some(false);
        let view = match prepared.viewer {
            Viewer::Infinite(v) => V3::splat(v),
            Viewer::Local(e) if local && plan.view => normalize_or_zero_fast(V3::splat(e) - p),
            Viewer::Local(_) => V3::zero(),
        };
        let sums = self.all_sums::<V, GREY, LEAN>(p, &normal, side, view, held);
        if LEAN {
            // Unsaturated sums must stay where the careful path's saturation would not act.
            let top = T::SATURATION.to_f64();
            let first = usize::from(!self.any_ambient());
            for sum in &sums[first..] {
                let mut inside = within(sum.x, -top, top);
                if !GREY {
                    inside = inside & within(sum.y, -top, top) & within(sum.z, -top, top);
                }
                *held = *held & inside;
            }
        }
        let [ambient, diffuse, specular] = sums;

        let d = self.material(side, 1, colors);
        let alpha = d[3];
        let (a, d) = (v3(self.material(side, 0, colors)), v3(d));
        let s = v3(self.material(side, 2, colors));
        let e = v3(self.material(side, 3, colors));
        let global = V3::splat(prepared.global_ambient);
        // Without an ambient term the sum is +0, and a·(+0) could only change the sign of a
        // zero, which the final clamp makes +0 anyway: the same bits without it.
        let base = a.mul_add(global, e);
        let base = if self.any_ambient() {
            a.mul_add(ambient, base)
        } else {
            base
        };
        let lit = d.mul_add(diffuse, base);
        let clamp = prepared.clamp == ColorClamp::On;
        if flag(S::KNOWN.separate_specular, prepared.separate_specular) {
            [
                emit(lit, alpha, finite, clamp),
                emit(s.mul_elements(specular), V::splat(T::ONE), finite, clamp),
            ]
        } else {
            let zero = V::splat(T::ZERO);
            [
                emit(s.mul_add(specular, lit), alpha, finite, clamp),
                [zero; 4],
            ]
        }
    }

    /// The colours of one side of a block from its eye-space normals `n` by the careful
    /// arithmetic, the front normal formed as the plan needs it.
    #[inline(always)]
    fn lit_block<V: Lanes<T = T>>(
        &self,
        p: V3<V>,
        n: V3<V>,
        colors: Option<[V; 4]>,
        finite: V::Mask,
        side: usize,
    ) -> SideColors<V> {
        let plan = self.plan;
        let front = if self.prepared.normalize {
            let (unit, _) = normalize_and_length(n);
            SideNormal {
                n: unit,
                unit,
                scale: Scale::unit(),
            }
        } else if !plan.normal_length {
            // n̂ only with `normalize`; no power needs |n|.
            SideNormal {
                n,
                unit: n,
                scale: Scale::unit(),
            }
        } else {
            let (squared, near) = squared_minus_one(n);
            let (unit, scale) = normal_scale(n, squared, near, plan.unit_normal);
            SideNormal { n, unit, scale }
        };
        let mut held = V::Mask::splat(true);
        self.side_colors::<V, false>(p, front, colors, finite, side, &mut held)
    }

    /// The colours of one side of a block by the lean arithmetic and the lanes they hold for:
    /// every normal (`n`, whose |n|² is `n2`) in the lean band, finite vertex colours, every
    /// light's distance in [`LEAN_RANGE`] and finite, unsaturated light sums; `None` where the
    /// normals and colours alone leave no [`LEAN_GROUP`] whole. No saturation, no exact squares,
    /// no compensated sum: plain float32 arithmetic, within the fast mode's bound (|n|² in
    /// [½, 2], or [½, 1.2] for Phong's R, keeps every power of an exponent up to
    /// [`crate::lighting::fixed_function::plan::LEAN_EXPONENT_MAX`] below 2^64).
    #[inline(always)]
    fn lean_block<V: Lanes<T = T>>(
        &self,
        p: V3<V>,
        n: V3<V>,
        n2: V,
        colors: Option<[V; 4]>,
        side: usize,
    ) -> Option<(SideColors<V>, V::Mask)> {
        let prepared = self.prepared;
        let phong = flag(S::KNOWN.specular, prepared.specular) == Specular::Phong;
        let band = match (prepared.normalize, phong) {
            (true, _) => LEAN_RANGE,
            (false, true) => (0.5, 1.2),
            (false, false) => (0.5, 2.0),
        };
        let mut held = within(n2, band.0, band.1);
        if let Some(c) = &colors {
            held = held & c[0].is_finite() & c[1].is_finite();
            held = held & c[2].is_finite() & c[3].is_finite();
        }
        // A position read only by a local viewer (a positional light's distance checks its own).
        if self.reads_positions() && self.viewer_reads_alone {
            held = held & p.is_finite();
        }
        if !held.all() && whole_groups::<V>(held).bitmask() == 0 {
            return None;
        }
        let n = if prepared.normalize {
            // As the careful path's: a unit normal to ½ ulp per component, which s multiplies.
            normalize_and_length(n).0
        } else {
            n
        };
        let front = SideNormal {
            n,
            unit: n,
            scale: Scale::unit(),
        };
        let finite = V::Mask::splat(true);
        let colours = self.side_colors::<V, true>(p, front, colors, finite, side, &mut held);
        Some((colours, held))
    }

    /// [`Kernel::block`]'s eye-space normals N·n for a block with a lane whose N·n is not
    /// finite or longer than 2^[`normal_exponent`], one lane at a time from the input
    /// `normals`.
    ///
    /// The lanes in range get the vector path's N·n (the same operations). A finite input
    /// whose N·n is not is scaled by an exact power of two (its largest component into
    /// [1/8, 1/4), so no partial sum of N·n can overflow), transformed, and scaled back by the
    /// same power of two or, where that would leave its largest component at or above
    /// 2^(`normal_exponent` − 1), by the largest power of two that does not: the direction of
    /// N·n exactly (to the rounding of N·n itself), the magnitude capped. A lane whose input
    /// is not finite keeps the vector path's NaN or inf (its output is NaN).
    // Inlined, with no call: a call here made every block keep its values across it (14%
    // slower with one directional light).
    #[inline(always)]
    fn saturated_normals<V: Lanes<T = T>>(&self, normals: &V3<V>) -> V3<V> {
        let buffer = |lanes: V| {
            let mut values = [T::ZERO; MAX_LANES];
            lanes.store(&mut values);
            values
        };
        let input = [buffer(normals.x), buffer(normals.y), buffer(normals.z)];
        let mut out = [[T::ZERO; MAX_LANES]; 3];
        let transform = |v: [T; 3]| match &self.prepared.transform {
            Some(t) => t.normal_of(v),
            None => v,
        };
        let top = |v: [T; 3]| v.iter().fold(0.0_f64, |m, c| m.max(c.to_f64().abs()));
        for i in 0..V::N {
            let v = [input[0][i], input[1][i], input[2][i]];
            let mut y = transform(v);
            // The vector path's test, in its operations.
            let in_range = y[0] * y[0] + y[1] * y[1] + y[2] * y[2] <= T::ONE / T::MIN_POSITIVE;
            if !in_range && v.iter().all(|c| c.is_finite()) && top(v) != 0.0 {
                let shift = log2_floor(top(v)) + 3;
                y = transform(v.map(|c| T::from_f64(ldexp(c.to_f64(), -shift))));
                let y_top = top(y);
                let back = if y_top == 0.0 {
                    0
                } else {
                    shift.min(normal_exponent::<T>() - 2 - log2_floor(y_top))
                };
                y = y.map(|c| T::from_f64(ldexp(c.to_f64(), back)));
            }
            for (plane, c) in out.iter_mut().zip(y) {
                plane[i] = c;
            }
        }
        V3 {
            x: V::load(&out[0]),
            y: V::load(&out[1]),
            z: V::load(&out[2]),
        }
    }

    /// The colours of one side of a block of vertices (0 front, 1 back: the back of two-sided
    /// lighting is lit with −n and the back material): the primary and, with separate
    /// specular, the secondary colour, clamped, NaN in the lanes whose inputs are not finite.
    /// The equation for a whole block at once.
    ///
    /// The eye-space normal N·n of a finite input normal is saturated at the magnitude
    /// 2^[`normal_exponent`] (2^63 in f32, 2^511 in f64; see `Kernel::saturated_normals`):
    /// beyond it, or where N·n overflows, the lane lights with the same direction and a
    /// magnitude in [2^61, 2^63) (f32) or [2^509, 2^511) (f64), so n·VP, Phong's
    /// R = 2(n·VP)n − VP and |n| stay finite. Only a block with such a lane (or a non-finite
    /// normal) leaves the vector path, after one comparison of |N·n|² per lane.
    #[inline(always)]
    pub fn block<V: Lanes<T = T>>(&self, input: &Block<V>, side: usize) -> SideColors<V> {
        let prepared = self.prepared;
        let (mut p, mut n) = (input.positions, input.normals);
        let colors = if S::KNOWN.colors == Some(false) {
            None
        } else {
            input.colors
        };
        if S::KNOWN.transform != Some(false) {
            if let Some(t) = &prepared.transform {
                n = t.normal(n);
                if self.reads_positions() {
                    p = t.point(p);
                }
            }
        }
        let n2 = n.dot(n);
        let lean = if Self::FLOAT32 && self.plan.lean {
            self.lean_block(p, n, n2, colors, side)
        } else {
            None
        };
        if let Some((colours, held)) = lean {
            if held.all() {
                return colours;
            }
        }
        // One call, so the careful path is inlined once.
        let careful = self.careful_block(input, p, n, n2, colors, side);
        let Some((colours, held)) = lean else {
            return careful;
        };
        // Each group of lanes whole on the lean path keeps its colours, as it would in a block
        // of its own.
        let groups = whole_groups::<V>(held);
        let mut out = careful;
        for (side, lean) in out.iter_mut().zip(colours) {
            for (channel, lean) in side.iter_mut().zip(lean) {
                *channel = V::select(groups, lean, *channel);
            }
        }
        out
    }

    /// [`Kernel::block`] on the careful path, from the eye-space `p` and `n` (|n|² `n2`).
    #[inline(always)]
    fn careful_block<V: Lanes<T = T>>(
        &self,
        input: &Block<V>,
        p: V3<V>,
        mut n: V3<V>,
        n2: V,
        colors: Option<[V; 4]>,
        side: usize,
    ) -> SideColors<V> {
        // Saturation: |N·n|² ≤ 1/MIN_POSITIVE (|N·n| ≤ 2^63 in f32, 2^511 in f64), else rescaled.
        let in_range = n2.le(V::splat(T::ONE / T::MIN_POSITIVE));
        let mut finite = if in_range.all() {
            in_range
        } else {
            // Finite exactly where the input normal is (a non-finite one keeps its NaN or inf).
            n = self.saturated_normals(&input.normals);
            n.is_finite()
        };
        if self.reads_positions() {
            finite = finite & p.is_finite();
        }
        if let Some(c) = &colors {
            finite = finite & c[0].is_finite() & c[1].is_finite();
            finite = finite & c[2].is_finite() & c[3].is_finite();
        }

        self.lit_block(p, n, colors, finite, side)
    }
}

impl<T: Real, S: Shape> BlockShader<T> for Kernel<'_, T, S> {
    #[inline(always)]
    fn reads_positions(&self) -> bool {
        Kernel::reads_positions(self)
    }
    #[inline(always)]
    fn sides(&self) -> usize {
        Kernel::sides(self)
    }
    #[inline(always)]
    fn block<V: Lanes<T = T>>(&self, input: &Block<V>, side: usize) -> SideColors<V> {
        Kernel::block(self, input, side)
    }
    fn dispatch<W: LaneWork>(isa: Isa, work: W) {
        S::run(isa, work);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::simd::lanes::Pack;

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
