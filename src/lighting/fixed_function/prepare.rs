//! Per-call precomputation: everything in the lighting equation that does not depend on the
//! vertex, done once in `f64` and rounded once to the kernel's type (Mesa's `_mesa_update_material`
//! and `compute_light_positions` do the same per state change).

use glam::DVec3;

use crate::errors::error::Error;
use crate::gl::light::Light;
use crate::gl::material::{ColorMaterial, Material};
use crate::gl::scene::{Scene, Specular, ValidScene};
use crate::lighting::clamp::ColorClamp;
use crate::lighting::fixed_function::options::ShadeOptions;
use crate::lighting::fixed_function::power::{spot_factor, Halfway, SoftEdge, Spot};
use crate::lighting::round::rgb;
use crate::lighting::transform::Transform;
use crate::numbers::real::{normalize_or_zero, Real};
use crate::simd::lanes::{Lanes, Scalar, V3};

/// The RGBA of `c`, saturated and rounded to `T`.
#[inline]
fn rgba<T: Real>(c: [f64; 4]) -> [T; 4] {
    let [r, g, b] = rgb::<T>(&c);
    let sat = T::COLOR_SATURATION.to_f64();
    [r, g, b, T::from_f64(c[3].clamp(-sat, sat))]
}

/// A nonnegative exponent or attenuation coefficient rounded to `T`, saturated at `T::MAX`:
/// beyond it `x^s` is 0 or 1 and `1/k` is 0 alike, and ±inf would meet a 0 (1^inf, inf·0).
#[inline]
fn saturate<T: Real>(x: f64) -> T {
    T::from_f64(x.min(T::MAX.to_f64()))
}

/// Rounds an `f64` vector to the kernel's type.
fn cast<T: Real>(v: DVec3) -> [T; 3] {
    v.to_array().map(T::from_f64)
}

/// Where a light's rays come from.
#[derive(Clone, Copy, Debug)]
pub enum Source<T: Real> {
    /// `position.w == 0`: VP is a per-light constant, attenuation 1, and the spot factor a
    /// per-light constant too (eq. 2.5 applies to directional lights with P_pli→V = −VP).
    Directional {
        /// VP_pli, unit.
        vp: [T; 3],
        /// ĥ for an infinite viewer with Blinn specular (a per-light constant then), else `None`.
        halfway: Option<Halfway<T>>,
        /// spot_i.
        spot: T,
    },
    /// `position.w != 0`: a point light at `position`.
    Positional {
        /// The light's eye-space point, (x, y, z)/w.
        position: [T; 3],
        /// k0, k1, k2.
        attenuation: [T; 3],
        /// The cone, or `None` for `spot_cutoff == 180`.
        spot: Option<Spot<T>>,
        /// The distance beyond which the light adds nothing, or `None` for none (GL).
        range: Option<T>,
    },
}

/// One light, ready for the kernel, in its type.
#[derive(Clone, Copy, Debug)]
pub struct PreparedLight<T: Real> {
    /// The light's geometry.
    pub source: Source<T>,
    /// a_cli (RGB, saturated).
    pub ambient: [T; 3],
    /// d_cli.
    pub diffuse: [T; 3],
    /// s_cli.
    pub specular: [T; 3],
}

/// The viewer: VP_e is a constant for an infinite viewer, per vertex for a local one.
#[derive(Clone, Copy, Debug)]
pub enum Viewer<T: Real> {
    /// The unit direction towards the viewer.
    Infinite([T; 3]),
    /// The viewer's eye-space point.
    Local([T; 3]),
}

/// One side's material in the kernel's type: RGBA colours saturated, and the shininess.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SideMaterial<T: Real> {
    /// a_cm.
    pub ambient: [T; 4],
    /// d_cm (its alpha is the output alpha).
    pub diffuse: [T; 4],
    /// s_cm.
    pub specular: [T; 4],
    /// e_cm.
    pub emission: [T; 4],
    /// s_rm.
    pub shininess: T,
}

impl<T: Real> SideMaterial<T> {
    fn new(m: &Material) -> Self {
        Self {
            ambient: rgba(m.ambient),
            diffuse: rgba(m.diffuse),
            specular: rgba(m.specular),
            emission: rgba(m.emission),
            shininess: saturate(m.shininess),
        }
    }
}

/// A scene and its options, prepared for one kernel type.
#[derive(Clone, Debug)]
pub struct Prepared<T: Real> {
    /// The lights, in summation order.
    pub lights: Vec<PreparedLight<T>>,
    /// Front and back materials (the back one is used with two-sided lighting only).
    pub materials: [SideMaterial<T>; 2],
    /// a_cs (RGB, saturated).
    pub global_ambient: [T; 3],
    /// The viewer.
    pub viewer: Viewer<T>,
    /// The modelview, if any.
    pub transform: Option<Transform<T>>,
    /// `GL_NORMALIZE`.
    pub normalize: bool,
    /// 1, or 2 with two-sided lighting.
    pub sides: usize,
    /// `GL_SEPARATE_SPECULAR_COLOR`.
    pub separate_specular: bool,
    /// Blinn or Phong.
    pub specular: Specular,
    /// f_i of eq. 2.2 on (GL) or off (learnopengl); see [`Scene::specular_gate`].
    pub specular_gate: bool,
    /// `GL_COLOR_MATERIAL`.
    pub color_material: Option<ColorMaterial>,
    /// Whether the outputs are clamped to [0, 1].
    pub clamp: ColorClamp,
}

/// The point (x, y, z)/w of a homogeneous `h` with w != 0, in the kernel's type.
///
/// # Errors
/// A value error naming `what()` when the point is beyond the type's range.
fn eye_point<T: Real>(h: [f64; 4], what: impl Fn() -> String) -> Result<[T; 3], Error> {
    let point = cast::<T>(DVec3::new(h[0], h[1], h[2]) / h[3]);
    if point.iter().all(|x| x.is_finite()) {
        Ok(point)
    } else {
        Err(Error::value(format!(
            "{} must lie within float{bits}'s range (|(x, y, z)/w| <= {max:.1e}) for \
             float{bits} arithmetic, got {h:?}; use float64 input or accuracy='exact'",
            what(),
            bits = 8 * std::mem::size_of::<T>(),
            max = T::MAX.to_f64(),
        )))
    }
}

/// True when a call on `scene` reads positions (a positional light or a local viewer), as the
/// call's plan decides from the prepared lights and viewer.
fn reads_positions(scene: &Scene) -> bool {
    scene.viewer[3] != 0.0 || scene.lights.iter().any(|l| !l.is_directional())
}

/// cos of an angle in degrees, exactly 0 at 90 (f64 `cos(π/2)` is 6.1e-17).
fn cos_degrees(degrees: f64) -> f64 {
    if degrees == 90.0 {
        0.0
    } else {
        degrees.to_radians().cos()
    }
}

fn prepare_light<T: Real>(
    light: &Light,
    index: usize,
    viewer: Option<DVec3>,
    blinn: bool,
) -> Result<PreparedLight<T>, Error> {
    let [x, y, z, _] = light.position;
    let cos_cutoff = cos_degrees(light.spot_cutoff);
    let spot = light.is_spot().then(|| Spot {
        direction: cast::<T>(normalize_or_zero::<f64>(DVec3::from_array(
            light.spot_direction,
        ))),
        cos_cutoff: T::from_f64(cos_cutoff),
        exponent: saturate(light.spot_exponent),
        edge: light.has_soft_edge().then(|| SoftEdge {
            // At least the least normal number: a width that rounds to 0 would make 0/0.
            width: T::from_f64(
                (cos_degrees(light.spot_inner_cutoff) - cos_cutoff).max(T::MIN_POSITIVE.to_f64()),
            ),
        }),
    });
    let source = if light.is_directional() {
        let vp = normalize_or_zero::<f64>(DVec3::new(x, y, z));
        let halfway = match viewer {
            Some(view) if blinn => {
                Some(Halfway::new(cast::<T>(normalize_or_zero::<f64>(vp + view))))
            }
            _ => None,
        };
        let vp = cast::<T>(vp);
        let spot = spot.map_or(T::ONE, |s| {
            let to_vertex = -V3::<T::Vector<Scalar>>::splat(vp);
            spot_factor(&s, to_vertex, true).lane(0)
        });
        Source::Directional { vp, halfway, spot }
    } else {
        let position = eye_point::<T>(light.position, || format!("position of light {index}"))?;
        let attenuation = [
            light.constant_attenuation,
            light.linear_attenuation,
            light.quadratic_attenuation,
        ]
        .map(saturate);
        Source::Positional {
            position,
            attenuation,
            spot,
            range: light.has_range().then(|| saturate(light.range)),
        }
    };
    Ok(PreparedLight {
        source,
        ambient: rgb(&light.ambient),
        diffuse: rgb(&light.diffuse),
        specular: rgb(&light.specular),
    })
}

impl<T: Real> Prepared<T> {
    /// Validates `options` against the already validated `scene` and precomputes the per-light
    /// constants.
    ///
    /// # Errors
    /// Any failure of [`Scene::validate_gl_ranges`] (with `options.strict`) or
    /// [`Transform::for_shading`], or a light or viewer point beyond `T`'s range.
    pub fn new(scene: &ValidScene, options: &ShadeOptions) -> Result<Self, Error> {
        let scene: &Scene = scene.scene();
        if options.strict {
            scene.validate_gl_ranges()?;
        }
        let [x, y, z, w] = scene.viewer;
        let infinite_view = (w == 0.0).then(|| normalize_or_zero::<f64>(DVec3::new(x, y, z)));
        let viewer = if let Some(v) = infinite_view {
            Viewer::Infinite(cast::<T>(v))
        } else {
            let point = eye_point::<T>(scene.viewer, || "viewer".to_owned())?;
            Viewer::Local(point)
        };
        let blinn = scene.specular == Specular::Blinn;
        let lights = scene
            .lights
            .iter()
            .enumerate()
            .map(|(i, light)| prepare_light::<T>(light, i, infinite_view, blinn))
            .collect::<Result<Vec<_>, _>>()?;
        let transform = options
            .modelview
            .as_ref()
            .map(|m| {
                Transform::for_shading(
                    m,
                    options.rescale_normal,
                    options.normalize,
                    reads_positions(scene),
                )
            })
            .transpose()?;
        Ok(Self {
            lights,
            materials: [&scene.material, &scene.back_material].map(SideMaterial::new),
            global_ambient: rgb(&scene.global_ambient),
            viewer,
            transform,
            normalize: options.normalize,
            sides: 1 + usize::from(scene.two_side),
            separate_specular: scene.separate_specular,
            specular: scene.specular,
            specular_gate: scene.specular_gate,
            color_material: options.color_material,
            clamp: options.clamp,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::simd::lanes::Pack;

    fn one(v: [f32; 3]) -> V3<Pack<f32, 1>> {
        V3::splat(v)
    }

    #[test]
    fn spot_edge_is_inside_and_cutoff_90_is_exact() {
        let light = Light {
            position: [0.0, 0.0, 1.0, 1.0],
            spot_cutoff: 90.0,
            spot_direction: [0.0, 0.0, -1.0],
            ..Light::default()
        };
        let p = prepare_light::<f32>(&light, 0, None, true).unwrap();
        let Source::Positional {
            spot: Some(spot), ..
        } = p.source
        else {
            panic!("positional spot expected")
        };
        assert_eq!(spot.cos_cutoff, 0.0);
        // Perpendicular to the axis: on the edge, inside, 0^0 = 1.
        assert_eq!(spot_factor(&spot, one([1.0, 0.0, 0.0]), true).0, [1.0]);
        let sharp = Spot {
            exponent: 2.0,
            ..spot
        };
        assert_eq!(spot_factor(&sharp, one([1.0, 0.0, 0.0]), true).0, [0.0]);
        assert_eq!(spot_factor(&sharp, one([0.0, 0.0, -1.0]), true).0, [1.0]);
    }

    #[test]
    fn soft_edge_ramps_linearly_in_the_cosine() {
        // learnopengl's cutOff 12.5 and outerCutOff 17.5 degrees.
        let light = Light {
            position: [0.0, 0.0, 0.0, 1.0],
            spot_cutoff: 17.5,
            spot_inner_cutoff: 12.5,
            range: 2.0,
            ..Light::default()
        };
        let p = prepare_light::<f64>(&light, 0, None, true).unwrap();
        let Source::Positional {
            spot: Some(spot),
            range,
            ..
        } = p.source
        else {
            panic!("positional spot expected")
        };
        assert_eq!(range, Some(2.0));
        let (inner, outer) = (12.5_f64.to_radians().cos(), 17.5_f64.to_radians().cos());
        for degrees in [0.0, 12.5, 14.0, 15.0, 17.0, 17.5, 30.0_f64] {
            let theta = degrees.to_radians();
            let to_vertex = [theta.sin(), 0.0, -theta.cos()];
            let got = spot_factor(&spot, V3::<Pack<f64, 1>>::splat(to_vertex), true).0[0];
            let expected = ((theta.cos() - outer) / (inner - outer)).clamp(0.0, 1.0);
            assert!(
                (got - expected).abs() < 1e-12,
                "{degrees}: {got} {expected}"
            );
            let hard = spot_factor(&spot, V3::<Pack<f64, 1>>::splat(to_vertex), false).0[0];
            assert_eq!(hard, if degrees <= 17.5 { 1.0 } else { 0.0 });
        }
    }

    #[test]
    fn a_soft_edge_narrower_than_the_dtype_is_a_finite_step() {
        // cos 10° and cos(10° + 1e-14°) are equal even in f64: the width would be 0, and 0/0
        // NaN on the edge. It is held at f32's least normal number instead: a step, 0 from the
        // edge outwards, 1 inside.
        let light = Light {
            position: [0.0, 0.0, 0.0, 1.0],
            spot_cutoff: 10.0 + 1e-14,
            spot_inner_cutoff: 10.0,
            ..Light::default()
        };
        let p = prepare_light::<f32>(&light, 0, None, true).unwrap();
        let Source::Positional {
            spot: Some(spot), ..
        } = p.source
        else {
            panic!("positional spot expected")
        };
        assert_eq!(spot.edge.map(|e| e.width), Some(f32::MIN_POSITIVE));
        for (degrees, expected) in [(0.0_f64, 1.0), (5.0, 1.0), (10.0, 0.0), (20.0, 0.0)] {
            let theta = degrees.to_radians();
            let to_vertex = [theta.sin() as f32, 0.0, -theta.cos() as f32];
            let got = spot_factor(&spot, V3::<Pack<f32, 1>>::splat(to_vertex), true).0[0];
            assert!(got.is_finite() && got == expected, "{degrees}: {got}");
        }
    }

    #[test]
    fn directional_spot_is_a_constant() {
        let light = Light {
            position: [0.0, 0.0, 1.0, 0.0],
            spot_cutoff: 30.0,
            spot_direction: [0.0, 0.0, 1.0],
            ..Light::default()
        };
        let p = prepare_light::<f64>(&light, 0, Some(DVec3::Z), true).unwrap();
        let Source::Directional { spot, halfway, .. } = p.source else {
            panic!("directional expected")
        };
        assert_eq!(
            spot, 0.0,
            "the light shines along -z, the cone points along +z"
        );
        assert_eq!(halfway.map(|h| h.direction), Some([0.0, 0.0, 1.0]));
    }
}
