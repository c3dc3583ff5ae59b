//! The BRDF of one light at a block of vertices, pyrender's `compute_brdf` term by term:
//!
//! ```text
//! F = f0 + (1 − f0)·(1 − v·h)^5                        Schlick's Fresnel (RGB)
//! G = nv/(nv(1 − k) + k) · nl/(nl(1 − k) + k)          Smith-Schlick, k = (r + 1)²/8
//! D = a²/(π·((n·h)²(a² − 1) + 1)²)                     GGX, a = r²
//! f = (1 − F)·c_diff/π + F·G·D/(4·nl·nv + 0.001)
//! ```
//!
//! with nl = clamp(n·l, 0.001, 1), nv = clamp(|n·v|, 0.001, 1), n·h and v·h clamped to [0, 1],
//! and r the perceptual roughness raised to 0.04. D's denominator is formed as
//! a² + (1 − a²)·|n × ĥ|² (the same value, since 1 − (n·ĥ)² = |n × ĥ|² for unit vectors):
//! near the highlight of a smooth surface 1 − (n·ĥ)² cancels, and rounding n·ĥ alone would cost
//! up to 2/a² ≈ 8·10⁵ ulp of D at the least roughness.

use crate::numbers::real::Real;
use crate::simd::lanes::{each, normalize_or_zero_fast, Lanes, V3};

/// pyrender's `min_roughness`: the least perceptual roughness, and the dielectric f0.
pub const MIN_ROUGHNESS: f64 = 0.04;

/// The least n·l and |n·v| (pyrender's clamps), so a light behind the surface still adds its
/// 0.001 share and the specular denominator never vanishes.
pub const LEAST_COSINE: f64 = 0.001;

/// What the BRDF needs of the material, in `T`, per call.
#[derive(Clone, Copy, Debug)]
pub struct Surface<T: Real> {
    /// a² = r⁴, the GGX parameter squared.
    pub a2: T,
    /// k = (r + 1)²/8.
    pub k: T,
    /// The albedo of the material's base colour factor, the same at every vertex.
    pub albedo: Albedo<T>,
    /// 0.04·(1 − metallic) and metallic: f0 = this + base·metallic, per texel.
    f0_of_base: [T; 2],
    /// 0.96·(1 − metallic)/π: c_diff/π = base·this, per texel.
    diffuse_of_base: T,
}

/// The colours of a surface point, RGB: f0 and the diffuse factor.
#[derive(Clone, Copy, Debug)]
pub struct Albedo<X> {
    /// f0 = mix(0.04, base colour, metallic).
    pub f0: [X; 3],
    /// (1 − f0)·c_diff/π with c_diff = base colour·0.96·(1 − metallic): the diffuse term is
    /// this times (1 − (1 − v·h)^5), since 1 − F = (1 − f0)(1 − (1 − v·h)^5).
    pub diffuse: [X; 3],
}

impl<T: Real> Surface<T> {
    /// The surface of a material's linear base colour (RGB), metallic and roughness factors.
    pub fn new(base: [f64; 3], metallic: f64, roughness: f64) -> Self {
        let m = metallic.clamp(0.0, 1.0);
        let r = roughness.clamp(MIN_ROUGHNESS, 1.0);
        let f0 = base.map(|c| MIN_ROUGHNESS * (1.0 - m) + c * m);
        let diffuse: [f64; 3] = std::array::from_fn(|i| {
            let c_diff = base[i] * (1.0 - MIN_ROUGHNESS) * (1.0 - m);
            (1.0 - f0[i]) * c_diff / std::f64::consts::PI
        });
        Self {
            a2: T::from_f64((r * r) * (r * r)),
            k: T::from_f64((r + 1.0) * (r + 1.0) / 8.0),
            albedo: Albedo {
                f0: f0.map(T::from_f64),
                diffuse: diffuse.map(T::from_f64),
            },
            f0_of_base: [T::from_f64(MIN_ROUGHNESS * (1.0 - m)), T::from_f64(m)],
            diffuse_of_base: T::from_f64((1.0 - MIN_ROUGHNESS) * (1.0 - m) / std::f64::consts::PI),
        }
    }

    /// Some channel has a diffuse term (c_diff ≠ 0).
    pub fn has_diffuse(&self) -> bool {
        self.albedo.diffuse.iter().any(|&c| c != T::ZERO)
    }

    /// The material's albedo in every lane.
    #[inline(always)]
    pub fn splat<V: Lanes<T = T>>(&self) -> Albedo<V> {
        let (f0, diffuse) = (self.albedo.f0, self.albedo.diffuse);
        Albedo {
            f0: each(|i| V::splat(f0[i])),
            diffuse: each(|i| V::splat(diffuse[i])),
        }
    }

    /// The albedo of a base colour per lane (the factor times a texel, RGB).
    #[inline(always)]
    pub fn albedo_of<V: Lanes<T = T>>(&self, base: [V; 3]) -> Albedo<V> {
        let [offset, metallic] = self.f0_of_base;
        let (offset, metallic) = (V::splat(offset), V::splat(metallic));
        let f0 = each(|i| base[i].mul_add(metallic, offset));
        let one = V::splat(T::ONE);
        let per = V::splat(self.diffuse_of_base);
        Albedo {
            f0,
            diffuse: each(|i| (one - f0[i]) * (base[i] * per)),
        }
    }
}

/// The cosines of one light at a block: n·l and |n·v| after pyrender's clamps.
#[derive(Clone, Copy)]
pub struct Cosines<V> {
    /// nl = clamp(n·l, 0.001, 1).
    pub nl: V,
    /// nv = clamp(|n·v|, 0.001, 1).
    pub nv: V,
}

/// f (RGB) for unit (or zero) `n`, `v` and `l` at points of `albedo`; the diffuse part only
/// when `diffuse` (a uniform branch: without it c_diff is 0).
#[inline(always)]
pub fn brdf<T: Real, V: Lanes<T = T>>(
    surface: &Surface<T>,
    albedo: &Albedo<V>,
    n: V3<V>,
    v: V3<V>,
    l: V3<V>,
    c: Cosines<V>,
    diffuse: bool,
) -> V3<V> {
    let zero = V::splat(T::ZERO);
    let one = V::splat(T::ONE);
    let h = normalize_or_zero_fast(l + v);
    let vh = v.dot(h).clamp(T::ZERO, T::ONE);
    // Fresnel: q = (1 − v·h)^5 by multiplication (GLSL's pow(x, 5.0)).
    let t = one - vh;
    let t2 = t * t;
    let q = t2 * t2 * t;
    // Occlusion's denominators: G = nv·nl / that.
    let (k, one_k) = (V::splat(surface.k), V::splat(T::ONE - surface.k));
    let occlusion = c.nv.mul_add(one_k, k) * c.nl.mul_add(one_k, k);
    // Distribution: 1 − (n·h)² as |n × h|², and n·h ≤ 0 clamped to 0 (denominator 1).
    let cross = V3 {
        x: n.y * h.z - n.z * h.y,
        y: n.z * h.x - n.x * h.z,
        z: n.x * h.y - n.y * h.x,
    };
    let a2 = V::splat(surface.a2);
    let sin2 = cross.dot(cross).min(one);
    let den = V::select(
        n.dot(h).gt(zero),
        sin2.mul_add(V::splat(T::ONE - surface.a2), a2),
        one,
    );
    let pi = V::splat(T::from_f64(std::f64::consts::PI));
    // G·D/(4·nl·nv + 0.001) as one quotient: one division for four (the divider is the
    // kernel's scarcest unit), and each factor at least 10⁻³ or α⁴, so nothing underflows.
    let nl_nv = c.nl * c.nv;
    let four_nl_nv = V::splat(T::from_f64(4.0)) * nl_nv;
    let specular = (a2 * nl_nv)
        / (occlusion * (pi * den * den) * (four_nl_nv + V::splat(T::from_f64(LEAST_COSINE))));
    V3 {
        x: channel(albedo.f0[0], albedo.diffuse[0], q, specular, diffuse),
        y: channel(albedo.f0[1], albedo.diffuse[1], q, specular, diffuse),
        z: channel(albedo.f0[2], albedo.diffuse[2], q, specular, diffuse),
    }
}

/// One channel of f: Schlick's Fresnel of `f0` with `q` = (1 − v·h)^5 times the `specular`
/// term, plus `diffuse_part`·(1 − q) when `diffuse`. A function rather than a closure, so that
/// it is inlined wherever the kernel is (a closure called three times was not, at opt-level 2).
#[inline(always)]
fn channel<T: Real, V: Lanes<T = T>>(
    f0: V,
    diffuse_part: V,
    q: V,
    specular: V,
    diffuse: bool,
) -> V {
    let one = V::splat(T::ONE);
    let fresnel = (one - f0).mul_add(q, f0);
    let spec = fresnel * specular;
    if diffuse {
        diffuse_part.mul_add(one - q, spec)
    } else {
        spec
    }
}
