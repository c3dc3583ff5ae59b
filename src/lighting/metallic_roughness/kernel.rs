//! The metallic-roughness model over a block of vertices: pyrender's `main()` for a
//! `USE_METALLIC_MATERIAL` shader with at most a base colour texture,
//!
//! ```text
//! c = Σ_i nl·radiance_i·f_i + base·ambient + emissive,   then c·colour, alpha = base.a·colour.a
//! ```
//!
//! radiance_i is colour × intensity, over d² for point lights and times the cone factor
//! clamp(cos θ·scale + offset, 0, 1)² for spots. Per-vertex colours either multiply the result
//! (pyrender's `COLOR_0`) or the base colour (a texture's texels: [`ColorRole`]). Each light's
//! weight nl·radiance·f is saturated like the GL kernel's (at [`Float::SATURATION`] and the sum
//! at `MAX`), so a light at the vertex itself (d = 0, whose direction is taken as zero: nl at
//! its floor 0.001) gives a large finite colour, never inf or NaN.

use std::fmt;

use crate::errors::error::Error;
use crate::gltf::light::Punctual;
use crate::gltf::scene::ValidScene;
use crate::lighting::block::{Block, SideColors};
use crate::lighting::metallic_roughness::brdf::{brdf, Albedo, Cosines, Surface, LEAST_COSINE};
use crate::lighting::metallic_roughness::options::{ColorRole, Options};
use crate::lighting::metallic_roughness::plan::Plan;
use crate::lighting::round::{cast_saturating, rgb};
use crate::lighting::world::{kept, placed, rgb_of, unit, Frame, WorldKernel};
use crate::numbers::real::Real;
use crate::simd::float::Float;
use crate::simd::lanes::{each, normalize_and_length_fast, normalize_and_lengths_fast, Lanes, V3};

/// Where one light's rays come from, in `T`.
#[derive(Clone, Copy, Debug)]
enum Source<T: Real> {
    /// The unit direction towards the light.
    Directional { l: [T; 3] },
    /// The light's position.
    Point { position: [T; 3] },
    /// The light's position, the cone's unit axis and the cone factor's scale and offset.
    Spot {
        position: [T; 3],
        axis: [T; 3],
        scale: T,
        offset: T,
    },
}

/// One light, prepared.
#[derive(Clone, Copy, Debug)]
struct Light<T: Real> {
    source: Source<T>,
    /// colour × intensity, saturated at `COLOR_SATURATION`.
    radiance: [T; 3],
}

/// The model for one call: the material, lights and options in `T`, and the plan.
pub struct Kernel<T: Real> {
    lights: Vec<Light<T>>,
    surface: Surface<T>,
    /// base·ambient + emissive (RGB).
    constant: [T; 3],
    /// The base colour factor (RGBA), for per-vertex base colours.
    base: [T; 4],
    /// The ambient light and the emission, for per-vertex base colours.
    ambient: [T; 3],
    emissive: [T; 3],
    /// What the per-vertex colours are.
    role: ColorRole,
    camera: [T; 3],
    /// The model matrix, the finite test and the clamp.
    frame: Frame<T>,
    plan: Plan,
}

impl<T: Real> Kernel<T> {
    /// Σ nl·radiance·f over the lights that shine, at unit normals `n`, view vectors `v` and
    /// points of `albedo`.
    #[inline(always)]
    fn lit<V: Lanes<T = T>>(&self, p: V3<V>, n: V3<V>, v: V3<V>, albedo: &Albedo<V>) -> V3<V> {
        let least = V::T::from_f64(LEAST_COSINE);
        let nv = n.dot(v);
        let nv = nv.max(-nv).clamp(least, T::ONE);
        let mut sum = V3::<V>::zero();
        for light in &self.lights {
            let (l, attenuation) = match light.source {
                Source::Directional { l } => (V3::splat(l), None),
                Source::Point { position } => {
                    let (l, _, inverse) = normalize_and_lengths_fast(V3::splat(position) - p);
                    (l, Some(inverse_square(inverse)))
                }
                Source::Spot {
                    position,
                    axis,
                    scale,
                    offset,
                } => {
                    let (l, _, inverse) = normalize_and_lengths_fast(V3::splat(position) - p);
                    let cd = (-V3::<V>::splat(axis).dot(l)).clamp(T::ZERO, T::ONE);
                    let s = cd
                        .mul_add(V::splat(scale), V::splat(offset))
                        .clamp(T::ZERO, T::ONE);
                    (l, Some(s * s * inverse_square(inverse)))
                }
            };
            let nl = n.dot(l).clamp(least, T::ONE);
            let f = brdf(
                &self.surface,
                albedo,
                n,
                v,
                l,
                Cosines { nl, nv },
                self.plan.diffuse,
            );
            // `match`, not `Option::map_or` (see `simd::lanes::each`).
            let w = match attenuation {
                Some(a) => (nl * a).min(V::splat(T::SATURATION)),
                None => nl,
            };
            let saturation = V::splat(T::SATURATION);
            let max = V::splat(T::MAX);
            let c = light.radiance;
            sum = V3 {
                x: V::splat(c[0])
                    .mul_add((f.x * w).min(saturation), sum.x)
                    .min(max),
                y: V::splat(c[1])
                    .mul_add((f.y * w).min(saturation), sum.y)
                    .min(max),
                z: V::splat(c[2])
                    .mul_add((f.z * w).min(saturation), sum.z)
                    .min(max),
            };
        }
        sum
    }
}

/// 1/d² from 1/d, with no division: finite at d = 0 (1/`MIN_POSITIVE`) and 0 at d = ∞.
#[inline(always)]
fn inverse_square<V: Lanes>(inverse: V) -> V {
    (inverse * inverse).min(V::splat(V::T::ONE / V::T::MIN_POSITIVE))
}

impl<T: Real> WorldKernel<T> for Kernel<T> {
    type Scene = ValidScene;
    type Options = Options;

    fn new(scene: &ValidScene, options: &Options) -> Result<Self, Error> {
        let m = &scene.material;
        let base = [m.base_color[0], m.base_color[1], m.base_color[2]];
        let surface = Surface::<T>::new(base, m.metallic, m.roughness);
        let plan = Plan::new(scene, surface.has_diffuse());
        let lights = kept(&plan.lights, &scene.lights)
            .map(|light| {
                let source = match light.punctual {
                    Punctual::Directional { direction } => Source::Directional {
                        l: unit(direction.map(|x| -x)),
                    },
                    Punctual::Point { position } => Source::Point {
                        position: cast_saturating(position.into()),
                    },
                    Punctual::Spot {
                        position,
                        direction,
                        ..
                    } => {
                        let (position, axis) = placed(position, direction);
                        let (scale, offset) = light.cone().unwrap_or((0.0, 0.0));
                        let (scale, offset) = (T::from_f64(scale), T::from_f64(offset));
                        Source::Spot {
                            position,
                            axis,
                            scale,
                            offset,
                        }
                    }
                };
                Light {
                    source,
                    radiance: rgb(&light.color.map(|c| c * light.intensity)),
                }
            })
            .collect();
        let constant: [f64; 3] =
            std::array::from_fn(|i| base[i] * scene.ambient_light[i] + m.emissive[i]);
        let frame = Frame::new(options.model.as_ref(), options.clamp, plan.positions)?;
        Ok(Self {
            lights,
            surface,
            constant: rgb(&constant),
            base: m.base_color.map(T::from_f64),
            ambient: rgb(&scene.ambient_light),
            emissive: rgb(&m.emissive),
            role: options.colors,
            camera: cast_saturating(scene.camera_position.into()),
            frame,
            plan,
        })
    }

    fn parts(&self) -> (&Frame<T>, &dyn fmt::Display) {
        (&self.frame, &self.plan)
    }

    #[inline(always)]
    fn block<V: Lanes<T = T>>(&self, input: &Block<V>, _side: usize) -> SideColors<V> {
        let (p, n, finite) = self.frame.inputs(input);
        // Per-vertex base colours (a texture's) change the albedo and the constant term.
        let base = match (&input.colors, self.role) {
            (Some(c), ColorRole::BaseColor) => {
                Some(each::<V, 4>(|k| V::splat(self.base[k]) * c[k]))
            }
            _ => None,
        };
        let albedo = match &base {
            Some(b) => self.surface.albedo_of([b[0], b[1], b[2]]),
            None => self.surface.splat(),
        };
        let mut rgb = if self.plan.positions {
            let n = normalize_and_length_fast(n).0;
            let v = normalize_and_length_fast(V3::splat(self.camera) - p).0;
            self.lit(p, n, v, &albedo)
        } else {
            V3::zero()
        };
        let mut alpha = V::splat(self.base[3]);
        if let Some(b) = &base {
            rgb = rgb_of(b).mul_add(V3::splat(self.ambient), rgb + V3::splat(self.emissive));
            alpha = b[3];
        } else if self.plan.constant {
            rgb = rgb + V3::splat(self.constant);
        }
        if let (Some(c), ColorRole::Multiply) = (&input.colors, self.role) {
            rgb = rgb.mul_elements(rgb_of(c));
            alpha = alpha * c[3];
        }
        self.frame.emit(rgb, alpha, finite)
    }
}
