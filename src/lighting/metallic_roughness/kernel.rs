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

use glam::DMat4;

use crate::errors::error::Error;
use crate::gltf::light::Punctual;
use crate::gltf::scene::Scene;
use crate::lighting::kernel::{emit, world_inputs, Block, SideColors};
use crate::lighting::metallic_roughness::brdf::{brdf, Albedo, Cosines, Surface, LEAST_COSINE};
use crate::lighting::metallic_roughness::plan::Plan;
use crate::lighting::metallic_roughness::shade::{ColorRole, Options};
use crate::lighting::prepare::{cast_saturating, rgb, ColorClamp, Transform};
use crate::lighting::shade::BlockShader;
use crate::numbers::real::{normalize_or_zero, Real};
use crate::simd::float::{Float, Vector3};
use crate::simd::lanes::{each, normalize_and_length, normalize_and_length_fast, Lanes, V3};

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

/// A unit vector in `T` from a nonzero `f64` direction.
fn unit<T: Real>(d: [f64; 3]) -> [T; 3] {
    let u = normalize_or_zero::<f64>(glam::DVec3::from_array(d));
    u.to_array().map(T::from_f64)
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
    /// Model to world coordinates (`None`: the identity).
    transform: Option<Transform<T>>,
    clamp: bool,
    plan: Plan,
}

impl<T: Real> Kernel<T> {
    /// Prepares `scene` for arrays of `T` with `options`, whose model takes the arrays to world
    /// coordinates.
    ///
    /// # Errors
    /// A value error for a model that is not finite, affine and invertible, or whose entries
    /// exceed `T`'s range.
    pub fn new(scene: &Scene, options: &Options) -> Result<Self, Error> {
        let (model, clamp): (Option<&DMat4>, ColorClamp) = (options.model.as_ref(), options.clamp);
        let m = &scene.material;
        let base = [m.base_color[0], m.base_color[1], m.base_color[2]];
        let surface = Surface::<T>::new(base, m.metallic, m.roughness);
        let plan = Plan::new(scene, surface.has_diffuse());
        let lights = plan
            .lights
            .iter()
            .map(|&(i, _)| {
                let light = &scene.lights[i];
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
                        let (scale, offset) = light.cone().unwrap_or((0.0, 0.0));
                        Source::Spot {
                            position: cast_saturating(position.into()),
                            axis: unit(direction),
                            scale: T::from_f64(scale),
                            offset: T::from_f64(offset),
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
        let transform = model
            .map(|model| Transform::for_shading(model, false, true, plan.positions))
            .transpose()?;
        Ok(Self {
            lights,
            surface,
            constant: rgb(&constant),
            base: m.base_color.map(T::from_f64),
            ambient: rgb(&scene.ambient_light),
            emissive: rgb(&m.emissive),
            role: options.colors,
            camera: cast_saturating(scene.camera_position.into()),
            transform,
            clamp: clamp == ColorClamp::On,
            plan,
        })
    }

    /// What the call computes.
    pub fn plan(&self) -> &Plan {
        &self.plan
    }

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
                    let (l, d) = normalize_and_length_fast(V3::splat(position) - p);
                    (l, Some(inverse_square(d)))
                }
                Source::Spot {
                    position,
                    axis,
                    scale,
                    offset,
                } => {
                    let (l, d) = normalize_and_length_fast(V3::splat(position) - p);
                    let cd = (-V3::<V>::splat(axis).dot(l)).clamp(T::ZERO, T::ONE);
                    let s = cd
                        .mul_add(V::splat(scale), V::splat(offset))
                        .clamp(T::ZERO, T::ONE);
                    (l, Some(s * s * inverse_square(d)))
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

/// 1/d², finite at d = 0 (1/`MIN_POSITIVE`) and 0 at d = ∞.
#[inline(always)]
fn inverse_square<V: Lanes>(d: V) -> V {
    V::splat(V::T::ONE) / (d * d).max(V::splat(V::T::MIN_POSITIVE))
}

impl<T: Real> BlockShader<T> for Kernel<T> {
    #[inline(always)]
    fn reads_positions(&self) -> bool {
        self.plan.positions
    }
    #[inline(always)]
    fn sides(&self) -> usize {
        1
    }
    #[inline(always)]
    fn block<V: Lanes<T = T>>(&self, input: &Block<V>, _side: usize) -> SideColors<V> {
        let (p, n, finite) = world_inputs(input, self.transform.as_ref(), self.plan.positions);
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
            let n = normalize_and_length(n).0;
            let v = normalize_and_length_fast(V3::splat(self.camera) - p).0;
            self.lit(p, n, v, &albedo)
        } else {
            V3::zero()
        };
        let mut alpha = V::splat(self.base[3]);
        if let Some(b) = &base {
            let b3 = V3 {
                x: b[0],
                y: b[1],
                z: b[2],
            };
            rgb = b3.mul_add(V3::splat(self.ambient), rgb + V3::splat(self.emissive));
            alpha = b[3];
        } else if self.plan.constant {
            rgb = rgb + V3::splat(self.constant);
        }
        if let (Some(c), ColorRole::Multiply) = (&input.colors, self.role) {
            rgb = rgb.mul_elements(V3 {
                x: c[0],
                y: c[1],
                z: c[2],
            });
            alpha = alpha * c[3];
        }
        let zero = V::splat(T::ZERO);
        [emit(rgb, alpha, finite, self.clamp), [zero; 4]]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gltf::light::Light as GltfLight;
    use crate::gltf::material::Material;
    use crate::simd::lanes::Pack;

    fn scene(punctual: Punctual) -> Scene {
        Scene {
            lights: vec![GltfLight {
                punctual,
                color: [1.0, 0.5, 0.25],
                intensity: 3.0,
            }],
            material: Material {
                base_color: [0.8, 0.6, 0.4, 0.5],
                metallic: 0.3,
                roughness: 0.0,
                emissive: [0.0; 3],
            },
            ambient_light: [0.0; 3],
            camera_position: [0.0, 0.0, 5.0],
        }
    }

    fn one_vertex(kernel: &Kernel<f64>, p: [f64; 3], n: [f64; 3]) -> [f64; 4] {
        let block = Block::<Pack<f64, 1>> {
            positions: V3::splat(p),
            normals: V3::splat(n),
            colors: None,
        };
        kernel.block(&block, 0)[0].map(|c| c.0[0])
    }

    #[test]
    fn a_light_at_the_vertex_lights_finitely() {
        let at = [0.5, -0.25, 1.0];
        let s = scene(Punctual::Point { position: at });
        for clamp in [ColorClamp::On, ColorClamp::Off] {
            let kernel = Kernel::<f64>::new(
                &s,
                &Options {
                    clamp,
                    ..Options::default()
                },
            )
            .unwrap();
            let c = one_vertex(&kernel, at, [0.0, 0.0, 1.0]);
            assert!(c.iter().all(|x| x.is_finite()), "{c:?}");
            assert!(c[0] > 0.0);
        }
    }

    #[test]
    fn unlit_scenes_read_no_positions() {
        let mut s = scene(Punctual::Directional {
            direction: [0.0, 0.0, -1.0],
        });
        s.lights[0].intensity = 0.0;
        s.material.emissive = [0.25, 0.0, 0.0];
        let kernel = Kernel::<f64>::new(&s, &Options::default()).unwrap();
        assert!(!kernel.plan().positions);
        let c = one_vertex(&kernel, [f64::NAN; 3], [0.0, 0.0, 1.0]);
        assert_eq!(c, [0.25, 0.0, 0.0, 0.5]);
    }
}
