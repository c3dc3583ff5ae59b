//! Per-call precomputation: everything in the lighting equation that does not depend on the
//! vertex, done once in `f64` and rounded once to the kernel's type (Mesa's `_mesa_update_material`
//! and `compute_light_positions` do the same per state change).

use glam::{DMat4, DVec3};

use crate::error::Error;
use crate::light::Light;
use crate::material::{ColorMaterial, Material};
use crate::real::{normalize_or_zero, Real, Vector3};
use crate::scene::{Scene, Specular};

/// Every colour, per-light weight and per-vertex colour is clamped to ±2^240 before it is
/// multiplied. Four such factors times 2^32 lights stay below 2^1023, so no finite input can
/// produce `inf·0` or `inf − inf` in the `f64` sums. The bound is reachable only by `f64` input
/// (f32 values stop at 2^128), and only by sums far beyond anything that survives the clamp:
/// without `normalize`, |n| = 1.3 and s = 128 legitimately give 10^35.
pub const SATURATION: f64 = f64::from_bits((1023 + 240) << 52);

/// `x` clamped to [−[`SATURATION`], [`SATURATION`]].
#[inline]
pub fn saturate(x: f64) -> f64 {
    x.clamp(-SATURATION, SATURATION)
}

/// The RGB of an RGBA colour, saturated.
#[inline]
pub fn rgb(c: [f64; 4]) -> DVec3 {
    DVec3::new(saturate(c[0]), saturate(c[1]), saturate(c[2]))
}

/// Rounds an `f64` vector to the kernel's type.
fn cast<T: Real>(v: DVec3) -> T::Vec3 {
    T::Vec3::from_array(v.to_array().map(T::from_f64))
}

/// A spot light's cone, in the kernel's type.
#[derive(Clone, Copy, Debug)]
pub struct Spot<T: Real> {
    /// ŝ_dli, the unit spot direction.
    pub direction: T::Vec3,
    /// cos(c_rli); exactly 0 for a 90° cutoff (f32 `cos(π/2)` is −4.4e-8, f64 +6.1e-17).
    pub cos_cutoff: T,
    /// s_rli.
    pub exponent: T,
}

impl<T: Real> Spot<T> {
    /// spot_i of eq. 2.5 for the unit light-to-vertex vector `to_vertex` (P_pli→V): 0 outside the
    /// cone, `(to_vertex ⊙ ŝ)^exponent` inside, with the edge inside (`≥`) and 0^0 = 1.
    #[inline]
    pub fn factor(&self, to_vertex: T::Vec3) -> T {
        let c = to_vertex.dot(self.direction).max(T::ZERO);
        if c < self.cos_cutoff {
            return T::ZERO;
        }
        cos_pow(c, to_vertex, self.direction, self.exponent, T::ZERO)
    }
}

/// `(max(â·b̂, 0))^s · e^(s·ln_scale)` for unit `a`, `b` whose dot product is `cos`, with 0^0 = 1.
///
/// 1 − â·b̂ is taken as |â − b̂|²/2, which has no cancellation near the highlight, and the power as
/// `exp(s·ln(1 − x))`: the error stays a few ulp at any exponent instead of growing as s·ulp.
/// `ln_scale` carries `ln |a|` when `a` stands for a vector that was not unit to begin with.
#[inline]
pub fn cos_pow<T: Real>(cos: T, a: T::Vec3, b: T::Vec3, s: T, ln_scale: T) -> T {
    if s == T::ZERO {
        return T::ONE;
    }
    if cos <= T::ZERO {
        return T::ZERO;
    }
    let d = a - b;
    let x = T::HALF * d.dot(d);
    if x >= T::ONE {
        return T::ZERO;
    }
    (s * ((-x).ln_1p() + ln_scale)).exp().min(T::MAX)
}

/// Where a light's rays come from.
#[derive(Clone, Copy, Debug)]
pub enum Source<T: Real> {
    /// `position.w == 0`: VP is a per-light constant, attenuation 1, and the spot factor a
    /// per-light constant too (eq. 2.5 applies to directional lights with P_pli→V = −VP).
    Directional {
        /// VP_pli, unit.
        vp: T::Vec3,
        /// ĥ for an infinite viewer with Blinn specular (a per-light constant then), else `None`.
        halfway: Option<T::Vec3>,
        /// spot_i.
        spot: T,
    },
    /// `position.w != 0`: a point light at `position`.
    Positional {
        /// The light's eye-space point, (x, y, z)/w.
        position: T::Vec3,
        /// k0, k1, k2.
        attenuation: [T; 3],
        /// The cone, or `None` for `spot_cutoff == 180`.
        spot: Option<Spot<T>>,
    },
}

/// One light, ready for the kernel: geometry in `T`, colours in `f64`.
#[derive(Clone, Copy, Debug)]
pub struct PreparedLight<T: Real> {
    /// The light's geometry.
    pub source: Source<T>,
    /// a_cli (RGB, saturated).
    pub ambient: DVec3,
    /// d_cli.
    pub diffuse: DVec3,
    /// s_cli.
    pub specular: DVec3,
}

/// The viewer: VP_e is a constant for an infinite viewer, per vertex for a local one.
#[derive(Clone, Copy, Debug)]
pub enum Viewer<T: Real> {
    /// The unit direction towards the viewer.
    Infinite(T::Vec3),
    /// The viewer's eye-space point.
    Local(T::Vec3),
}

/// The modelview and its normal matrix, as columns in `T`.
#[derive(Clone, Copy, Debug)]
pub struct Transform<T: Real> {
    linear: [T::Vec3; 3],
    translation: T::Vec3,
    normal: [T::Vec3; 3],
}

#[inline]
fn mul3<T: Real>(columns: &[T::Vec3; 3], v: T::Vec3) -> T::Vec3 {
    let [x, y, z] = v.to_array();
    columns[0] * x + columns[1] * y + columns[2] * z
}

impl<T: Real> Transform<T> {
    /// The eye-space position M·(p, 1).
    #[inline]
    pub fn point(&self, p: T::Vec3) -> T::Vec3 {
        mul3::<T>(&self.linear, p) + self.translation
    }

    /// The eye-space normal (M⁻¹)ᵀ·n, times the rescale factor if asked for.
    #[inline]
    pub fn normal(&self, n: T::Vec3) -> T::Vec3 {
        mul3::<T>(&self.normal, n)
    }

    /// The transform of an affine `modelview` (last row (0, 0, 0, 1)); with `rescale_normal`,
    /// the normal matrix is scaled by GL's 1/|third row of M⁻¹| (§2.11.3).
    ///
    /// # Errors
    /// A value error for a non-finite, projective or singular `modelview`.
    pub fn new(modelview: &DMat4, rescale_normal: bool) -> Result<Self, Error> {
        if !modelview.is_finite() {
            return Err(Error::value(format!(
                "modelview must be finite, got {modelview}"
            )));
        }
        let last_row = modelview.row(3);
        if last_row != glam::DVec4::W {
            return Err(Error::value(format!(
                "modelview must be affine (last row (0, 0, 0, 1)), got last row {last_row}"
            )));
        }
        let m3 = glam::DMat3::from_mat4(*modelview);
        let inverse = m3.inverse();
        if m3.determinant() == 0.0 || !inverse.is_finite() {
            return Err(Error::value(format!(
                "modelview must be invertible (its normal matrix is the inverse transpose), \
                 got determinant {} for the upper-left 3x3",
                m3.determinant()
            )));
        }
        let scale = if rescale_normal {
            1.0 / inverse.row(2).length()
        } else {
            1.0
        };
        let normal = inverse.transpose() * scale;
        Ok(Self {
            linear: [m3.x_axis, m3.y_axis, m3.z_axis].map(cast::<T>),
            translation: cast::<T>(modelview.w_axis.truncate()),
            normal: [normal.x_axis, normal.y_axis, normal.z_axis].map(cast::<T>),
        })
    }
}

/// The per-vertex options of a `shade` call (everything `glEnable` and `glColorMaterial` set
/// that is not part of the [`Scene`]).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ShadeOptions {
    /// The modelview M: positions become M·p, normals (M⁻¹)ᵀ·n; `None` is the identity.
    pub modelview: Option<DMat4>,
    /// `GL_NORMALIZE`: normals are scaled to unit length after the transform.
    pub normalize: bool,
    /// `GL_RESCALE_NORMAL`: normals are scaled by the modelview's rescale factor.
    pub rescale_normal: bool,
    /// `GL_COLOR_MATERIAL`, used with per-vertex colours.
    pub color_material: Option<ColorMaterial>,
}

/// A scene and its options, prepared for one kernel type.
#[derive(Clone, Debug)]
pub struct Prepared<T: Real> {
    /// The lights, in summation order.
    pub lights: Vec<PreparedLight<T>>,
    /// Front and back materials (the back one is used with two-sided lighting only).
    pub materials: [Material; 2],
    /// Front and back shininess in the kernel's type.
    pub shininess: [T; 2],
    /// a_cs (RGB, saturated).
    pub global_ambient: DVec3,
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
}

/// The point (x, y, z)/w of a homogeneous `h` with w != 0, in the kernel's type.
///
/// # Errors
/// A value error naming `what()` when the point is beyond the type's range.
fn eye_point<T: Real>(h: [f64; 4], what: impl Fn() -> String) -> Result<T::Vec3, Error> {
    let point = cast::<T>(DVec3::new(h[0], h[1], h[2]) / h[3]);
    if point.is_finite() {
        Ok(point)
    } else {
        Err(Error::value(format!(
            "{} must lie within the range of the input dtype, got {h:?}",
            what()
        )))
    }
}

fn prepare_light<T: Real>(
    light: &Light,
    index: usize,
    viewer: Option<DVec3>,
    blinn: bool,
) -> Result<PreparedLight<T>, Error> {
    let [x, y, z, _] = light.position;
    let spot = light.is_spot().then(|| Spot {
        direction: cast::<T>(normalize_or_zero::<f64>(DVec3::from_array(
            light.spot_direction,
        ))),
        cos_cutoff: T::from_f64(if light.spot_cutoff == 90.0 {
            0.0
        } else {
            light.spot_cutoff.to_radians().cos()
        }),
        exponent: T::from_f64(light.spot_exponent),
    });
    let source = if light.is_directional() {
        let vp = normalize_or_zero::<f64>(DVec3::new(x, y, z));
        let halfway = match viewer {
            Some(view) if blinn => Some(cast::<T>(normalize_or_zero::<f64>(vp + view))),
            _ => None,
        };
        let vp = cast::<T>(vp);
        Source::Directional {
            vp,
            halfway,
            spot: spot.map_or(T::ONE, |s| s.factor(-vp)),
        }
    } else {
        let position = eye_point::<T>(light.position, || format!("position of light {index}"))?;
        let attenuation = [
            light.constant_attenuation,
            light.linear_attenuation,
            light.quadratic_attenuation,
        ]
        .map(T::from_f64);
        Source::Positional {
            position,
            attenuation,
            spot,
        }
    };
    Ok(PreparedLight {
        source,
        ambient: rgb(light.ambient),
        diffuse: rgb(light.diffuse),
        specular: rgb(light.specular),
    })
}

impl<T: Real> Prepared<T> {
    /// Validates `scene` and `options` and precomputes the per-light constants.
    ///
    /// # Errors
    /// Any failure of [`Scene::validate`] or [`Transform::new`].
    pub fn new(scene: &Scene, options: &ShadeOptions) -> Result<Self, Error> {
        scene.validate()?;
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
            .map(|m| Transform::new(m, options.rescale_normal))
            .transpose()?;
        let materials = [scene.material, scene.back_material];
        Ok(Self {
            lights,
            materials,
            shininess: materials.map(|m| T::from_f64(m.shininess)),
            global_ambient: rgb(scene.global_ambient),
            viewer,
            transform,
            normalize: options.normalize,
            sides: 1 + usize::from(scene.two_side),
            separate_specular: scene.separate_specular,
            specular: scene.specular,
            specular_gate: scene.specular_gate,
            color_material: options.color_material,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Vec3;

    #[test]
    fn cos_pow_matches_powf_and_pins_zero_to_the_zero() {
        let a = Vec3::new(0.6, 0.8, 0.0);
        let b = Vec3::X;
        let c = a.dot(b);
        assert!((cos_pow::<f32>(c, a, b, 3.0, 0.0) - 0.216).abs() < 1e-6);
        assert_eq!(cos_pow::<f32>(0.0, Vec3::X, Vec3::Y, 0.0, 0.0), 1.0);
        assert_eq!(cos_pow::<f32>(-0.5, -a, b, 0.0, 0.0), 1.0);
        assert_eq!(cos_pow::<f32>(-0.5, -a, b, 2.0, 0.0), 0.0);
        assert_eq!(cos_pow::<f32>(1.0, b, b, 1e6, 0.0), 1.0);
    }

    #[test]
    fn cos_pow_is_stable_at_high_exponents() {
        // θ = 1e-3 rad: (cos θ)^1e6 = exp(1e6·ln cos θ) ≈ e^-0.5.
        let theta = 1e-3_f64;
        let exact = (1e6 * theta.cos().ln()).exp();
        let a = Vec3::new(theta.sin() as f32, 0.0, theta.cos() as f32);
        let got = f64::from(cos_pow::<f32>(a.z, a, Vec3::Z, 1e6, 0.0));
        assert!((got - exact).abs() / exact < 2e-3, "{got} vs {exact}");
        let naive = f64::from(a.z.powf(1e6));
        assert!((naive - exact).abs() > (got - exact).abs());
    }

    #[test]
    fn spot_edge_is_inside_and_cutoff_90_is_exact() {
        let light = Light {
            spot_cutoff: 90.0,
            spot_direction: [0.0, 0.0, -1.0],
            ..Light::default()
        };
        let p = prepare_light::<f32>(
            &Light {
                position: [0.0, 0.0, 1.0, 1.0],
                ..light
            },
            0,
            None,
            true,
        )
        .unwrap();
        let Source::Positional {
            spot: Some(spot), ..
        } = p.source
        else {
            panic!("positional spot expected")
        };
        assert_eq!(spot.cos_cutoff, 0.0);
        // Perpendicular to the axis: on the edge, inside, 0^0 = 1.
        assert_eq!(spot.factor(Vec3::X), 1.0);
        let sharp = Spot {
            exponent: 2.0,
            ..spot
        };
        assert_eq!(sharp.factor(Vec3::X), 0.0);
        assert_eq!(sharp.factor(-Vec3::Z), 1.0);
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
        assert_eq!(halfway, Some(DVec3::Z));
    }

    #[test]
    fn transform_uses_the_inverse_transpose() {
        let m = DMat4::from_scale(DVec3::new(2.0, 1.0, 1.0));
        let t = Transform::<f64>::new(&m, false).unwrap();
        assert_eq!(t.point(DVec3::ONE), DVec3::new(2.0, 1.0, 1.0));
        assert_eq!(t.normal(DVec3::ONE), DVec3::new(0.5, 1.0, 1.0));
        let uniform = Transform::<f64>::new(&DMat4::from_scale(DVec3::splat(4.0)), true).unwrap();
        assert_eq!(uniform.normal(DVec3::Z), DVec3::Z);
        assert!(
            Transform::<f64>::new(&DMat4::from_scale(DVec3::new(1.0, 0.0, 1.0)), false).is_err()
        );
        let mut projective = DMat4::IDENTITY;
        projective.x_axis.w = 1.0;
        assert!(Transform::<f64>::new(&projective, false)
            .unwrap_err()
            .message
            .contains("affine"));
    }
}
