//! `MeshPhongMaterial` over a block of vertices: r111's `meshphong_frag` without maps,
//! term by term (`bsdfs`, `lights_pars_begin`, `lights_phong_pars_fragment`):
//!
//! ```text
//! E_i  = saturate(n·l)·colour_i·falloff_i·cone_i         (×π with legacy lights)
//! F_i  = specular + (1 − specular)·2^((−5.55473·lh − 6.98316)·lh),  lh = saturate(l·h)
//! D_i  = (shininess/2 + 1)/π · saturate(n·h)^shininess
//! E_a  = Σ ambient + Σ mix(ground, sky, 0.5·n·d + 0.5)   (×π with legacy lights)
//! c    = (Σ E_i + E_a)·diffuse/π + Σ E_i·F_i·D_i/4 + emissive·emissiveIntensity
//! ```
//!
//! with h = normalize(l + v), diffuse = `color` times the vertex colour (RGB), alpha =
//! `opacity` times the vertex colour's alpha. Falloff: physically correct lights
//! 1/max(d^decay, 0.01)·saturate(1 − (d/distance)⁴)² (the second factor only for distance > 0);
//! legacy lights saturate(1 − d/distance)^decay for distance > 0 and decay > 0, else 1. Cone:
//! 0 unless l·a > cos(angle) (a the unit `position − target`), then smoothstep(cos(angle),
//! cos(angle·(1 − penumbra)), l·a), a step for penumbra 0 (GLSL leaves smoothstep undefined for
//! equal edges; r111's test `angleCos > coneCos` comes first, so GPUs give 1 inside).
//! The shininess is at least 10⁻⁴, as three.js passes it (so (n·h)^s is 0 at n·h = 0, never
//! GLSL's undefined 0^0); a decay of 0 is x^0 = 1. The sum is held at `T::MAX`, so every
//! output is finite for finite input.

use std::fmt;

use crate::errors::error::Error;
use crate::lighting::block::{Block, SideColors};
use crate::lighting::fixed_function::power::{cos_pow, Scale};
use crate::lighting::mesh_phong::options::Options;
use crate::lighting::mesh_phong::plan::Plan;
use crate::lighting::round::{cast_saturating, rgb};
use crate::lighting::world::{kept, placed, rgb_of, unit, Frame, WorldKernel};
use crate::numbers::elementary::ElementaryLanes;
use crate::numbers::real::Real;
use crate::simd::float::Float;
use crate::simd::lanes::{normalize_and_length_fast, normalize_and_lengths_fast, Lanes, V3};
use crate::threejs::light::Kind as LightKind;
use crate::threejs::material::Side;
use crate::threejs::scene::{ValidScene, Viewer};

/// Fresnel's exponent in base 2 is `(FRESNEL[0]·lh + FRESNEL[1])·lh` (`F_Schlick`).
const FRESNEL: [f64; 2] = [-5.55473, -6.98316];

/// The least shininess three.js passes its shader (`WebGLRenderer`'s `refreshUniformsPhong`:
/// `Math.max(material.shininess, 1e-4)`, "to prevent pow(0.0, 0.0)").
const LEAST_SHININESS: f64 = 1e-4;

/// The least d^decay of physically correct lights (`max(pow(d, decay), 0.01)`).
const LEAST_FALLOFF_DENOMINATOR: f64 = 0.01;

/// How a point or spot light falls off with the distance d, in `T`.
#[derive(Clone, Copy, Debug)]
enum Falloff<T: Real> {
    /// Legacy lights without a distance or decay: 1.
    None,
    /// Legacy lights: saturate(1 − d/distance)^decay.
    Legacy { inverse_distance: T, decay: T },
    /// Physically correct lights: 1/max(d^decay, 0.01), times saturate(1 − (d/distance)⁴)²
    /// when the distance is finite (`inverse_distance` > 0).
    Physical { inverse_distance: T, decay: T },
}

/// Where one direct light's rays come from, in `T`.
#[derive(Clone, Copy, Debug)]
enum Source<T: Real> {
    /// The unit direction towards the light.
    Directional { l: [T; 3] },
    /// The light's position and falloff.
    Point {
        position: [T; 3],
        falloff: Falloff<T>,
    },
    /// The light's position, the unit axis towards it, cos(angle) and 1/(penumbraCos −
    /// coneCos) (∞ for penumbra 0: a step), and the falloff.
    Spot {
        position: [T; 3],
        axis: [T; 3],
        cone_cos: T,
        inverse_width: T,
        falloff: Falloff<T>,
    },
}

/// One direct light, prepared.
#[derive(Clone, Copy, Debug)]
struct Light<T: Real> {
    source: Source<T>,
    /// colour × intensity (×π with legacy lights), saturated at `COLOR_SATURATION`.
    radiance: [T; 3],
}

/// One hemisphere light, prepared: irradiance = ground + (sky − ground)·(0.5·n·d + 0.5).
#[derive(Clone, Copy, Debug)]
struct Hemisphere<T: Real> {
    direction: [T; 3],
    ground: [T; 3],
    sky_minus_ground: [T; 3],
}

/// `x^e` for x ≥ 0 and a per-call e ≥ 0: 1 for e = 0 (a decay of 0), by multiplication for
/// e = 1 and 2 (the common decays), else exp(e·ln x) (0 at x = 0).
#[inline(always)]
fn pow<V: ElementaryLanes>(x: V, e: V::T) -> V {
    if e == V::T::ZERO {
        return V::splat(V::T::ONE);
    }
    if e == V::T::ONE {
        return x;
    }
    if e == V::T::from_f64(2.0) {
        return x * x;
    }
    let zero = V::splat(V::T::ZERO);
    V::select(x.gt(zero), (x.ln() * V::splat(e)).exp(), zero)
}

impl<T: Real> Falloff<T> {
    /// The falloff of a light of this `distance` and `decay`.
    fn new(distance: f64, decay: f64, physical: bool) -> Self {
        let inverse_distance = T::from_f64(if distance > 0.0 { 1.0 / distance } else { 0.0 });
        let decay = T::from_f64(decay);
        if physical {
            Self::Physical {
                inverse_distance,
                decay,
            }
        } else if distance > 0.0 && decay > T::ZERO {
            Self::Legacy {
                inverse_distance,
                decay,
            }
        } else {
            Self::None
        }
    }

    /// The factor at distances `d`, of reciprocals `inverse` (1/d, ∞ at d = 0).
    #[inline(always)]
    fn at<V: ElementaryLanes<T = T>>(&self, d: V, inverse: V) -> V {
        let one = V::splat(T::ONE);
        match *self {
            Self::None => one,
            Self::Legacy {
                inverse_distance,
                decay,
            } => pow(
                (one - d * V::splat(inverse_distance)).clamp(T::ZERO, T::ONE),
                decay,
            ),
            Self::Physical {
                inverse_distance,
                decay,
            } => {
                // 1/max(d^decay, 0.01) as min((1/d)^decay, 100): no division.
                let most = V::splat(T::from_f64(1.0 / LEAST_FALLOFF_DENOMINATOR));
                let f = pow(inverse, decay).min(most);
                if inverse_distance == T::ZERO {
                    return f;
                }
                let r = d * V::splat(inverse_distance);
                let r2 = r * r;
                let w = (one - r2 * r2).clamp(T::ZERO, T::ONE);
                f * (w * w)
            }
        }
    }
}

/// The model for one call: the material, lights and options in `T`, and the plan.
pub struct Kernel<T: Real> {
    lights: Vec<Light<T>>,
    hemispheres: Vec<Hemisphere<T>>,
    /// Σ ambient colour × intensity (×π with legacy lights).
    ambient: [T; 3],
    /// `color`/π, the Lambert BRDF of the material.
    diffuse: [T; 3],
    /// `specular`: Schlick's f0.
    specular: [T; 3],
    shininess: T,
    /// (shininess/2 + 1)/(4π): the normalisation and the implicit visibility term.
    normalisation: T,
    /// emissive × emissiveIntensity.
    emissive: [T; 3],
    opacity: T,
    /// The normal is negated (`BackSide`).
    flip: bool,
    viewer: Viewer,
    /// The camera's position or the unit view direction, in `T`.
    view: [T; 3],
    /// The model matrix, the finite test and the clamp.
    frame: Frame<T>,
    plan: Plan,
}

impl<T: Real> Kernel<T> {
    /// (Σ E_i, Σ E_i·F_i·D_i/4) over the direct lights, RGB, at unit normals `n`, points `p`
    /// and unit view vectors `v`.
    #[inline(always)]
    fn direct<V: ElementaryLanes<T = T>>(&self, p: V3<V>, n: V3<V>, v: V3<V>) -> [V3<V>; 2] {
        let zero = V::splat(T::ZERO);
        let one = V::splat(T::ONE);
        let ln2 = V::splat(T::from_f64(std::f64::consts::LN_2));
        let specular = V3::splat(self.specular);
        let unit = Scale::unit();
        let (mut irradiance, mut reflected) = (V3::<V>::zero(), V3::<V>::zero());
        for light in &self.lights {
            let (l, factor) = match light.source {
                Source::Directional { l } => (V3::splat(l), None),
                Source::Point { position, falloff } => {
                    let (l, d, inverse) = normalize_and_lengths_fast(V3::splat(position) - p);
                    (l, Some(falloff.at(d, inverse)))
                }
                Source::Spot {
                    position,
                    axis,
                    cone_cos,
                    inverse_width,
                    falloff,
                } => {
                    let (l, d, inverse) = normalize_and_lengths_fast(V3::splat(position) - p);
                    let c = l.dot(V3::splat(axis));
                    let t =
                        ((c - V::splat(cone_cos)) * V::splat(inverse_width)).clamp(T::ZERO, T::ONE);
                    let smooth =
                        t * t * (V::splat(T::from_f64(3.0)) - V::splat(T::from_f64(2.0)) * t);
                    let cone = V::select(c.gt(V::splat(cone_cos)), smooth, zero);
                    (l, Some(cone * falloff.at(d, inverse)))
                }
            };
            let nl = n.dot(l).clamp(T::ZERO, T::ONE);
            // `match`, not `Option::map_or` (see `simd::lanes::each`).
            let e = match factor {
                Some(f) => nl * f,
                None => nl,
            };
            let h = normalize_and_length_fast(l + v).0;
            let nh = n.dot(h).clamp(T::ZERO, T::ONE);
            let lh = l.dot(h).clamp(T::ZERO, T::ONE);
            let fresnel = ((V::splat(T::from_f64(FRESNEL[0])) * lh
                + V::splat(T::from_f64(FRESNEL[1])))
                * lh
                * ln2)
                .exp();
            // (n·h)^s by squaring on the complement |n − h|²/2 for integer s (cos_pow).
            let d = V::splat(self.normalisation) * cos_pow(nh, n, h, self.shininess, &unit);
            let f = V3 {
                x: (one - specular.x).mul_add(fresnel, specular.x),
                y: (one - specular.y).mul_add(fresnel, specular.y),
                z: (one - specular.z).mul_add(fresnel, specular.z),
            };
            let c = V3::splat(light.radiance).scale(e);
            irradiance = irradiance + c;
            reflected = c.mul_elements(f).scale(d) + reflected;
        }
        [irradiance, reflected]
    }

    /// The indirect irradiance E_a at unit normals `n`: the ambient lights and the hemispheres.
    #[inline(always)]
    fn indirect<V: Lanes<T = T>>(&self, n: V3<V>) -> V3<V> {
        let half = V::splat(T::HALF);
        let mut e = V3::<V>::splat(self.ambient);
        for h in &self.hemispheres {
            let w = n.dot(V3::splat(h.direction)).mul_add(half, half);
            e = e + V3::splat(h.sky_minus_ground).scale(w) + V3::splat(h.ground);
        }
        e
    }
}

impl<T: Real> WorldKernel<T> for Kernel<T> {
    type Scene = ValidScene;
    type Options = Options;

    fn new(scene: &ValidScene, options: &Options) -> Result<Self, Error> {
        let plan = Plan::new(scene);
        let physical = scene.physically_correct_lights;
        // Legacy lights multiply every irradiance by π (`irradiance *= PI`).
        let pi = if physical { 1.0 } else { std::f64::consts::PI };
        let radiance = |color: [f64; 3], intensity: f64| color.map(|c| c * intensity * pi);
        let lights = kept(&plan.lights, &scene.lights)
            .map(|light| {
                let source = match light.kind {
                    LightKind::Directional { direction } => {
                        Source::Directional { l: unit(direction) }
                    }
                    LightKind::Point {
                        position,
                        distance,
                        decay,
                    } => Source::Point {
                        position: cast_saturating(position.into()),
                        falloff: Falloff::new(distance, decay, physical),
                    },
                    LightKind::Spot {
                        position,
                        direction,
                        distance,
                        decay,
                        ..
                    } => {
                        let (cone_cos, penumbra_cos) = light.cone().unwrap_or((1.0, 1.0));
                        let (position, axis) = placed(position, direction);
                        Source::Spot {
                            position,
                            axis,
                            cone_cos: T::from_f64(cone_cos),
                            inverse_width: T::from_f64(1.0 / (penumbra_cos - cone_cos)),
                            falloff: Falloff::new(distance, decay, physical),
                        }
                    }
                    LightKind::Ambient | LightKind::Hemisphere { .. } => {
                        unreachable!("the plan's direct lights are directional, point or spot")
                    }
                };
                Light {
                    source,
                    radiance: rgb(&radiance(light.color, light.intensity)),
                }
            })
            .collect();
        let hemispheres = plan
            .hemispheres
            .iter()
            .map(|&i| {
                let light = &scene.lights[i];
                let LightKind::Hemisphere {
                    direction,
                    ground_color,
                } = light.kind
                else {
                    unreachable!("the plan's hemisphere lights are hemisphere lights")
                };
                let sky = radiance(light.color, light.intensity);
                let ground = radiance(ground_color, light.intensity);
                Hemisphere {
                    direction: unit(direction),
                    ground: rgb(&ground),
                    sky_minus_ground: rgb(&std::array::from_fn::<f64, 3, _>(|k| {
                        sky[k] - ground[k]
                    })),
                }
            })
            .collect();
        let mut ambient = [0.0; 3];
        for light in scene.lights.iter().filter(|l| l.kind == LightKind::Ambient) {
            let r = radiance(light.color, light.intensity);
            ambient = std::array::from_fn(|k| ambient[k] + r[k]);
        }
        let m = &scene.material;
        let s = m.shininess.max(LEAST_SHININESS);
        let view = match scene.viewer {
            Viewer::Position(p) => cast_saturating(p.into()),
            Viewer::Direction(d) => unit(d),
        };
        let frame = Frame::new(options.model.as_ref(), options.clamp, plan.positions)?;
        Ok(Self {
            lights,
            hemispheres,
            ambient: rgb(&ambient),
            diffuse: rgb(&m.color.map(|c| c / std::f64::consts::PI)),
            specular: rgb(&m.specular),
            shininess: T::from_f64(s),
            normalisation: T::from_f64((0.5 * s + 1.0) / (4.0 * std::f64::consts::PI)),
            emissive: rgb(&m.emissive.map(|e| e * m.emissive_intensity)),
            opacity: T::from_f64(m.opacity),
            flip: m.side == Side::Back,
            viewer: scene.viewer,
            view,
            frame,
            plan,
        })
    }

    fn parts(&self) -> (&Frame<T>, &dyn fmt::Display) {
        (&self.frame, &self.plan)
    }

    fn sides(&self) -> usize {
        self.plan.sides
    }

    #[inline(always)]
    fn block<V: Lanes<T = T>>(&self, input: &Block<V>, side: usize) -> SideColors<V> {
        let (p, mut n, finite) = self.frame.inputs(input);
        // The back of a double-sided material, and a back-sided one, light the negated normal.
        if self.flip != (side == 1) {
            n = -n;
        }
        let n = normalize_and_length_fast(n).0;
        let [mut irradiance, specular] = if self.lights.is_empty() {
            [V3::zero(); 2]
        } else {
            let v = match self.viewer {
                Viewer::Position(_) => normalize_and_length_fast(V3::splat(self.view) - p).0,
                Viewer::Direction(_) => V3::splat(self.view),
            };
            self.direct(p, n, v)
        };
        irradiance = irradiance + self.indirect(n);
        let mut diffuse = V3::splat(self.diffuse);
        let mut alpha = V::splat(self.opacity);
        if let Some(c) = &input.colors {
            diffuse = diffuse.mul_elements(rgb_of(c));
            alpha = alpha * c[3];
        }
        let max = V::splat(T::MAX);
        let rgb = irradiance.mul_add(diffuse, specular + V3::splat(self.emissive));
        let rgb = V3 {
            x: rgb.x.min(max),
            y: rgb.y.min(max),
            z: rgb.z.min(max),
        };
        self.frame.emit(rgb, alpha, finite)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lighting::clamp::ColorClamp;
    use crate::simd::lanes::Pack;
    use crate::threejs::light::Light as ThreeLight;
    use crate::threejs::material::MeshPhongMaterial;
    use crate::threejs::scene::Scene;

    fn scene(kind: LightKind) -> Scene {
        Scene {
            lights: vec![ThreeLight {
                kind,
                color: [1.0, 0.5, 0.25],
                intensity: 3.0,
            }],
            material: MeshPhongMaterial {
                color: [0.8, 0.6, 0.4],
                ..MeshPhongMaterial::default()
            },
            viewer: Viewer::Position([0.0, 0.0, 5.0]),
            physically_correct_lights: true,
        }
    }

    fn one_vertex(kernel: &Kernel<f64>, p: [f64; 3], n: [f64; 3], side: usize) -> [f64; 4] {
        let block = Block::<Pack<f64, 1>> {
            positions: V3::splat(p),
            normals: V3::splat(n),
            colors: None,
        };
        kernel.block(&block, side)[0].map(|c| c.0[0])
    }

    #[test]
    fn a_hemisphere_light_reads_no_positions() {
        let mut s = scene(LightKind::Hemisphere {
            direction: [0.0, 2.0, 0.0],
            ground_color: [0.0, 0.0, 1.0],
        });
        s.material.emissive = [0.25, 0.0, 0.0];
        s.material.opacity = 0.5;
        let options = Options {
            clamp: ColorClamp::Off,
            ..Options::default()
        };
        let kernel = Kernel::<f64>::new(&s.clone().validated().unwrap(), &options).unwrap();
        assert!(!kernel.plan.positions);
        // n·d = 1: the sky colour alone, × 3 / π × colour, plus the emission.
        let c = one_vertex(&kernel, [f64::NAN; 3], [0.0, 1.0, 0.0], 0);
        let pi = std::f64::consts::PI;
        let expected = [0.25 + 3.0 * 0.8 / pi, 1.5 * 0.6 / pi, 0.75 * 0.4 / pi, 0.5];
        for (c, e) in c.iter().zip(expected) {
            assert!((c - e).abs() < 1e-15, "{c} {e}");
        }
    }

    #[test]
    fn the_back_of_a_double_sided_material_lights_the_negated_normal() {
        let mut s = scene(LightKind::Directional {
            direction: [0.0, 0.0, 1.0],
        });
        s.material.side = Side::Double;
        let kernel =
            Kernel::<f64>::new(&s.clone().validated().unwrap(), &Options::default()).unwrap();
        assert_eq!(kernel.plan.sides, 2);
        let p = [0.0, 0.0, 0.0];
        let back = one_vertex(&kernel, p, [0.0, 0.0, -1.0], 1);
        let front = one_vertex(&kernel, p, [0.0, 0.0, 1.0], 0);
        assert_eq!(back, front);
        assert!(front[0] > 0.5);
        s.material.side = Side::Back;
        let kernel =
            Kernel::<f64>::new(&s.clone().validated().unwrap(), &Options::default()).unwrap();
        assert_eq!(one_vertex(&kernel, p, [0.0, 0.0, -1.0], 0), front);
    }

    #[test]
    fn a_spot_without_penumbra_is_a_step() {
        let s = scene(LightKind::Spot {
            position: [0.0, 0.0, 1.0],
            direction: [0.0, 0.0, 1.0],
            distance: 0.0,
            decay: 0.0,
            angle: std::f64::consts::FRAC_PI_4,
            penumbra: 0.0,
        });
        let kernel =
            Kernel::<f64>::new(&s.clone().validated().unwrap(), &Options::default()).unwrap();
        let n = [0.0, 0.0, 1.0];
        let inside = one_vertex(&kernel, [0.99, 0.0, 0.0], n, 0);
        let outside = one_vertex(&kernel, [1.01, 0.0, 0.0], n, 0);
        assert!(inside[0] > 0.1, "{inside:?}");
        assert_eq!(outside[..3], [0.0; 3]);
    }
}
