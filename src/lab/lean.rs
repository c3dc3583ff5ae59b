//! How fast one directional light could be shaded if the fast mode kept none of its safeguards:
//! GL's equation for one directional light under an infinite viewer (Blinn, ĥ constant, the
//! exponent an integer known when compiled), as a compiler of the scene would write it, through
//! the same tasks, reads, transposes and stores as `shade` and the streaming floor. No |n|² − 1,
//! no power on the complement, no saturation, no clamp's NaN select, no test of the block's
//! normals: what `bench shade`'s "1 directional" costs at the least here, to say how much of its
//! distance from the floor is the equation and how much the exactness of the fast mode.

use std::mem::MaybeUninit;

use crate::errors::error::Error;
use crate::errors::stop::Stop;
use crate::gl::scene::ValidScene;
use crate::lighting::block::{emit, Block, SideColors};
use crate::lighting::driver::{run_shader, BlockShader, Inputs};
use crate::lighting::fixed_function::options::ShadeOptions;
use crate::lighting::fixed_function::power::{halfway_pow, squared_minus_one, Halfway, Scale};
use crate::lighting::fixed_function::prepare::{Prepared, Source, Viewer};
use crate::numbers::real::Real;
use crate::simd::dispatch::Isa;
use crate::simd::lanes::{Lanes, V3};

/// The exponent the bound is compiled for: the bench scenes' shininess.
pub const SHININESS: u32 = 32;

/// The fast mode's safeguards the bound can put back one by one, to say what each costs.
#[derive(Clone, Copy, Debug, Default)]
pub struct Safeguards {
    /// The output NaN where the input normal is not finite, and −0 made +0 ([`emit`]).
    pub nan: bool,
    /// The power of the fast mode: |n|² − 1 from exact squares and (n⊙ĥ)^s formed on the
    /// complement ([`halfway_pow`]; the bench's normals are all near unit length).
    pub power: bool,
    /// The light's weights saturated before they meet a colour.
    pub saturate: bool,
}

/// One directional light's equation with every per-call number folded: RGB = base + (n⊙VP)·d +
/// [n·VP > 0]·(n⊙ĥ)^32·s, clamped, alpha constant.
struct Lean<T: Real> {
    vp: [T; 3],
    halfway: Halfway<T>,
    /// Which of the fast mode's safeguards to put back.
    safeguards: Safeguards,
    /// e_cm + a_cm·(a_cs + a_cl), and d_cm's alpha.
    base: [T; 4],
    /// d_cm·d_cl.
    diffuse: [T; 3],
    /// s_cm·s_cl.
    specular: [T; 3],
}

impl<T: Real> Lean<T> {
    /// Channel `c` of the colour, before the clamp. A method, not a closure: a closure would be
    /// compiled without the kernel's target features and called (see `simd::lanes::each`).
    #[inline(always)]
    fn channel<V: Lanes<T = T>>(&self, c: usize, diffuse: V, power: V) -> V {
        let sum = V::splat(self.diffuse[c]).mul_add(diffuse, V::splat(self.base[c]));
        V::splat(self.specular[c]).mul_add(power, sum)
    }
}

impl<T: Real> BlockShader<T> for Lean<T> {
    #[inline(always)]
    fn reads_positions(&self) -> bool {
        false
    }
    #[inline(always)]
    fn sides(&self) -> usize {
        1
    }
    #[inline(always)]
    fn block<V: Lanes<T = T>>(&self, input: &Block<V>, _side: usize) -> SideColors<V> {
        let n = input.normals;
        let zero = V::splat(T::ZERO);
        let n_dot_vp = n.dot(V3::splat(self.vp));
        let lit = n_dot_vp.gt(zero);
        let guard = self.safeguards;
        let power = if guard.power {
            let (squared, _) = squared_minus_one(n);
            let scale = Scale::squared_only(squared);
            halfway_pow::<V>(
                n,
                n,
                &self.halfway,
                T::from_f64(f64::from(SHININESS)),
                &scale,
            )
        } else {
            let mut power = n.dot(V3::splat(self.halfway.direction)).max(zero);
            // 32 = 2^5: five squarings, as a scene compiler unrolls a constant exponent.
            for _ in 0..SHININESS.trailing_zeros() {
                power = power * power;
            }
            power
        };
        let (diffuse, power) = if guard.saturate {
            let most = V::splat(T::SATURATION);
            let diffuse = (n_dot_vp.min(V::splat(T::MAX))).min(most).or_zero(lit);
            (diffuse, power.min(V::splat(T::MAX)).min(most).or_zero(lit))
        } else {
            (n_dot_vp.max(zero), power.or_zero(lit))
        };
        let rgb = V3 {
            x: self.channel(0, diffuse, power),
            y: self.channel(1, diffuse, power),
            z: self.channel(2, diffuse, power),
        };
        let alpha = V::splat(self.base[3]);
        let colour = if guard.nan {
            emit(rgb, alpha, n.is_finite(), true)
        } else {
            [
                rgb.x.clamp(T::ZERO, T::ONE),
                rgb.y.clamp(T::ZERO, T::ONE),
                rgb.z.clamp(T::ZERO, T::ONE),
                alpha,
            ]
        };
        [colour, [zero; 4]]
    }
}

/// Writes the lean bound of `scene` on `normals` into `out` (n RGBA rows), with the tasks and
/// instruction set of [`crate::lighting::model::shade`] and the fast mode's `safeguards` put
/// back. Without `power` the colours err by up to 32 times the rounding of n⊙ĥ near the
/// highlight (a few 10⁻⁶ for unit normals); with it, as the fast mode's for unit normals.
///
/// # Errors
/// A value error unless the scene is one directional light under an infinite viewer with Blinn
/// specular, one side, no modelview, GL's specular gate and shininess [`SHININESS`]; a value
/// error for mismatched lengths; [`Error::interrupted`].
pub fn lean_directional<T: Real>(
    scene: &ValidScene,
    normals: &[[T; 3]],
    safeguards: Safeguards,
    out: &mut [MaybeUninit<T>],
    stop: &Stop,
) -> Result<(), Error> {
    let prepared = Prepared::<T>::new(scene, &ShadeOptions::default())?;
    let m = &prepared.materials[0];
    let fits = prepared.lights.len() == 1
        && matches!(prepared.viewer, Viewer::Infinite(_))
        && prepared.sides == 1
        && prepared.transform.is_none()
        && prepared.color_material.is_none()
        && !prepared.separate_specular
        && prepared.specular_gate
        && m.shininess == T::from_f64(f64::from(SHININESS));
    let (light, vp, halfway) = match prepared.lights.first().map(|l| (l, l.source)) {
        Some((
            light,
            Source::Directional {
                vp,
                halfway: Some(h),
                spot,
            },
        )) if fits && spot == T::ONE => (light, vp, h),
        _ => {
            return Err(Error::value(format!(
                "the lean bound takes one directional light under an infinite viewer, Blinn, \
                 one side, no modelview, GL's gate, shininess {SHININESS}"
            )))
        }
    };
    if out.len() != 4 * normals.len() {
        return Err(Error::value(format!(
            "lean_directional needs {} output values, got {}",
            4 * normals.len(),
            out.len()
        )));
    }
    let rgb = |f: &dyn Fn(usize) -> T| [f(0), f(1), f(2)];
    let ambient = rgb(&|c| m.ambient[c] * (prepared.global_ambient[c] + light.ambient[c]));
    let shader = Lean {
        vp,
        halfway,
        safeguards,
        base: [
            m.emission[0] + ambient[0],
            m.emission[1] + ambient[1],
            m.emission[2] + ambient[2],
            m.diffuse[3],
        ],
        diffuse: rgb(&|c| m.diffuse[c] * light.diffuse[c]),
        specular: rgb(&|c| m.specular[c] * light.specular[c]),
    };
    let inputs = Inputs {
        positions: &[],
        normals,
        colors: None,
    };
    run_shader(&shader, Isa::detect(), inputs, out, stop)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gl::light::Light;
    use crate::gl::material::Material;
    use crate::gl::scene::Scene;
    use crate::lighting::model::shade;
    use crate::memory::uninit::as_uninit;
    #[test]
    fn the_lean_bound_agrees_with_shade_on_the_bench_light() {
        let scene = Scene {
            lights: vec![Light {
                position: [0.3, 0.5, 1.0, 0.0],
                ..Light::default()
            }],
            material: Material {
                specular: [0.5, 0.5, 0.5, 1.0],
                shininess: 32.0,
                ..Material::default()
            },
            ..Scene::default()
        }
        .validated()
        .unwrap();
        let normals: Vec<[f32; 3]> = (0..1000)
            .map(|i| {
                let (a, b) = (i as f32 * 0.0137, i as f32 * 0.0291);
                [a.sin() * b.cos(), a.sin() * b.sin(), a.cos()]
            })
            .collect();
        let mut exact = vec![0.0f32; 4 * normals.len()];
        // Positions are not read for this light; `shade` still takes one row per vertex.
        let options = ShadeOptions::default();
        let stop = Stop::new();
        shade(
            &scene, &normals, &normals, None, &options, &mut exact, &stop,
        )
        .unwrap();
        let every = Safeguards {
            nan: true,
            power: true,
            saturate: true,
        };
        let mut lean = vec![0.0f32; 4 * normals.len()];
        for safeguards in [Safeguards::default(), every] {
            let out = as_uninit(&mut lean);
            lean_directional(&scene, &normals, safeguards, out, &Stop::new()).unwrap();
            let worst = lean
                .iter()
                .zip(&exact)
                .map(|(a, b)| (a - b).abs())
                .fold(0.0f32, f32::max);
            assert!(worst < 2e-6, "{safeguards:?}: {worst}");
        }
    }

    #[test]
    fn the_lean_bound_refuses_other_scenes() {
        let scene = Scene::default().validated().unwrap(); // no light
        let mut out = vec![0.0f32; 4];
        let got = lean_directional(
            &scene,
            &[[0.0f32, 0.0, 1.0]],
            Safeguards::default(),
            as_uninit(&mut out),
            &Stop::new(),
        );
        assert!(got.is_err());
    }
}
