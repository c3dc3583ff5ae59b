//! One OpenGL light: the `GL_LIGHTi` state of GL 2.1 §2.14.2 (Table 2.10), in eye coordinates.

use crate::errors::error::Error;

/// The parameters of one light, named after the GL enums, in eye coordinates, as `f64`.
///
/// `position` is homogeneous: `w = 0` is a directional light shining *from* the direction
/// `(x, y, z)`, otherwise a point light at `(x, y, z) / w`. Colours are RGBA; GL uses only their
/// RGB in the lighting sums.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Light {
    /// `GL_POSITION`, homogeneous.
    pub position: [f64; 4],
    /// `GL_AMBIENT`, a_cli.
    pub ambient: [f64; 4],
    /// `GL_DIFFUSE`, d_cli.
    pub diffuse: [f64; 4],
    /// `GL_SPECULAR`, s_cli.
    pub specular: [f64; 4],
    /// `GL_SPOT_DIRECTION`, s_dli (any nonzero length; normalised before use).
    pub spot_direction: [f64; 3],
    /// `GL_SPOT_EXPONENT`, s_rli, ≥ 0.
    pub spot_exponent: f64,
    /// `GL_SPOT_CUTOFF` in degrees, c_rli: in [0, 90], or 180 for no spot.
    pub spot_cutoff: f64,
    /// `GL_CONSTANT_ATTENUATION`, k0 ≥ 0.
    pub constant_attenuation: f64,
    /// `GL_LINEAR_ATTENUATION`, k1 ≥ 0.
    pub linear_attenuation: f64,
    /// `GL_QUADRATIC_ATTENUATION`, k2 ≥ 0.
    pub quadratic_attenuation: f64,
    /// The inner cone of a soft spot edge in degrees, in [0, `spot_cutoff`], or 180 for GL's
    /// hard edge: the spot factor is scaled by clamp((cos θ − cos c_rli)/(cos inner − cos
    /// c_rli), 0, 1) (learnopengl's `cutOff`).
    pub spot_inner_cutoff: f64,
    /// The distance beyond which a positional light adds nothing, not even its ambient term
    /// (Direct3D 11's `Range` in Luna's `LightHelper.fx`), > 0 or +inf (none, GL).
    pub range: f64,
}

impl Default for Light {
    /// GL's `GL_LIGHT0` defaults, for every light (diffuse and specular white; "Defaults" on the
    /// documentation's Shading arrays page, docs/pages/guide/shading.md).
    fn default() -> Self {
        Self {
            position: [0.0, 0.0, 1.0, 0.0],
            ambient: [0.0, 0.0, 0.0, 1.0],
            diffuse: [1.0, 1.0, 1.0, 1.0],
            specular: [1.0, 1.0, 1.0, 1.0],
            spot_direction: [0.0, 0.0, -1.0],
            spot_exponent: 0.0,
            spot_cutoff: 180.0,
            constant_attenuation: 1.0,
            linear_attenuation: 0.0,
            quadratic_attenuation: 0.0,
            spot_inner_cutoff: 180.0,
            range: f64::INFINITY,
        }
    }
}

/// The columns of one row of a light table, in order, with their widths: what
/// [`Light::from_row`] reads (a test checks their sum against [`LIGHT_ROW_LEN`]).
#[cfg(test)]
const LIGHT_LAYOUT: [(&str, usize); 12] = [
    ("position", 4),
    ("ambient", 4),
    ("diffuse", 4),
    ("specular", 4),
    ("spot_direction", 3),
    ("spot_exponent", 1),
    ("spot_cutoff", 1),
    ("constant_attenuation", 1),
    ("linear_attenuation", 1),
    ("quadratic_attenuation", 1),
    ("spot_inner_cutoff", 1),
    ("range", 1),
];

/// The number of `f64` in one row of a light table: position, ambient, diffuse and specular
/// (4 each), spot_direction (3), spot_exponent, spot_cutoff and the constant, linear and
/// quadratic attenuation, spot_inner_cutoff and range (1 each), in that order.
pub const LIGHT_ROW_LEN: usize = 26;

fn take<const K: usize>(row: &[f64], at: &mut usize) -> [f64; K] {
    let mut v = [0.0; K];
    v.copy_from_slice(&row[*at..*at + K]);
    *at += K;
    v
}

impl Light {
    /// Reads one row laid out as [`LIGHT_ROW_LEN`] describes.
    ///
    /// No range check happens here: see [`Light::validate`].
    pub fn from_row(row: &[f64; LIGHT_ROW_LEN]) -> Self {
        let at = &mut 0;
        let position = take::<4>(row, at);
        let ambient = take::<4>(row, at);
        let diffuse = take::<4>(row, at);
        let specular = take::<4>(row, at);
        let spot_direction = take::<3>(row, at);
        let [spot_exponent, spot_cutoff, constant_attenuation, linear_attenuation, quadratic_attenuation, spot_inner_cutoff, range] =
            take::<7>(row, at);
        Self {
            position,
            ambient,
            diffuse,
            specular,
            spot_direction,
            spot_exponent,
            spot_cutoff,
            constant_attenuation,
            linear_attenuation,
            quadratic_attenuation,
            spot_inner_cutoff,
            range,
        }
    }

    /// True for a directional light (`position.w == 0`).
    pub fn is_directional(&self) -> bool {
        self.position[3] == 0.0
    }

    /// True when the light is a spot light (`spot_cutoff != 180`).
    pub fn is_spot(&self) -> bool {
        self.spot_cutoff != 180.0
    }

    /// True when a spot light's edge is soft (`spot_inner_cutoff < spot_cutoff`).
    pub fn has_soft_edge(&self) -> bool {
        self.is_spot() && self.spot_inner_cutoff < self.spot_cutoff
    }

    /// True when a positional light has a finite `range`.
    pub fn has_range(&self) -> bool {
        !self.is_directional() && self.range != f64::INFINITY
    }

    /// Checks GL's parameter ranges (§2.14.2) and the cases glshade rejects because GL leaves
    /// them undefined; `index` names the light in the message.
    ///
    /// # Errors
    /// A value error when a parameter is not finite (`range` may be +inf); when `spot_cutoff`
    /// or `spot_inner_cutoff` is outside [0, 90] ∪ {180}, or the inner cone is wider than the
    /// outer one; when `range` is not > 0; when `spot_exponent` or an attenuation is negative;
    /// when `position` is (0, 0, 0, 0); when a positional light has all three attenuations
    /// zero; or when a spot light has a zero `spot_direction`.
    pub fn validate(&self, index: usize) -> Result<(), Error> {
        let bad = |name: &str, expected: &str, found: String| {
            Err(Error::value(format!(
                "{name} of light {index} must be {expected}, got {found}"
            )))
        };
        let vectors: [(&str, &[f64]); 5] = [
            ("position", &self.position),
            ("ambient", &self.ambient),
            ("diffuse", &self.diffuse),
            ("specular", &self.specular),
            ("spot_direction", &self.spot_direction),
        ];
        for (name, v) in vectors {
            if !v.iter().all(|x| x.is_finite()) {
                return bad(name, "finite", format!("{v:?}"));
            }
        }
        let scalars = [
            ("spot_exponent", self.spot_exponent),
            ("constant_attenuation", self.constant_attenuation),
            ("linear_attenuation", self.linear_attenuation),
            ("quadratic_attenuation", self.quadratic_attenuation),
        ];
        for (name, x) in scalars {
            if !(x >= 0.0 && x.is_finite()) {
                return bad(name, "finite and >= 0", format!("{x}"));
            }
        }
        let c = self.spot_cutoff;
        if !((0.0..=90.0).contains(&c) || c == 180.0) {
            return bad("spot_cutoff", "in [0, 90] or exactly 180", format!("{c}"));
        }
        let inner = self.spot_inner_cutoff;
        if !((0.0..=90.0).contains(&inner) || inner == 180.0) {
            return bad(
                "spot_inner_cutoff",
                "in [0, 90] or exactly 180",
                format!("{inner}"),
            );
        }
        if inner != 180.0 && inner > c {
            return bad(
                "spot_inner_cutoff",
                &format!("at most spot_cutoff ({c}), or 180 for a hard edge"),
                format!("{inner}"),
            );
        }
        if self.range.is_nan() || self.range <= 0.0 {
            return bad("range", "> 0 (or inf: no range)", format!("{}", self.range));
        }
        if self.position == [0.0; 4] {
            return bad(
                "position",
                "a point (w != 0) or a nonzero direction (w = 0)",
                "[0, 0, 0, 0]".into(),
            );
        }
        if !self.is_directional()
            && self.constant_attenuation == 0.0
            && self.linear_attenuation == 0.0
            && self.quadratic_attenuation == 0.0
        {
            return bad(
                "constant_attenuation, linear_attenuation, quadratic_attenuation",
                "not all zero for a positional light (1/0 attenuation)",
                "0, 0, 0".into(),
            );
        }
        if self.is_spot() && self.spot_direction == [0.0; 3] {
            return bad(
                "spot_direction",
                "nonzero for a spot light",
                "[0, 0, 0]".into(),
            );
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn layout_widths_sum_to_row_len() {
        assert_eq!(
            LIGHT_LAYOUT.iter().map(|(_, w)| w).sum::<usize>(),
            LIGHT_ROW_LEN
        );
    }

    #[test]
    fn from_row_reads_the_layout_in_order() {
        let row: [f64; LIGHT_ROW_LEN] = std::array::from_fn(|i| i as f64);
        let l = Light::from_row(&row);
        assert_eq!(l.position, [0.0, 1.0, 2.0, 3.0]);
        assert_eq!(l.specular, [12.0, 13.0, 14.0, 15.0]);
        assert_eq!(l.spot_direction, [16.0, 17.0, 18.0]);
        assert_eq!(l.spot_exponent, 19.0);
        assert_eq!(l.quadratic_attenuation, 23.0);
        assert_eq!((l.spot_inner_cutoff, l.range), (24.0, 25.0));
    }

    #[test]
    fn defaults_are_valid_and_directional() {
        let l = Light::default();
        assert!(l.validate(0).is_ok());
        assert!(l.is_directional());
        assert!(!l.is_spot());
    }

    #[test]
    fn out_of_range_parameters_are_named() {
        let cases: [(Light, &str); 9] = [
            (
                Light {
                    spot_cutoff: 30.0,
                    spot_inner_cutoff: 40.0,
                    ..Light::default()
                },
                "spot_inner_cutoff of light 2 must be at most spot_cutoff (30)",
            ),
            (
                Light {
                    spot_inner_cutoff: -1.0,
                    ..Light::default()
                },
                "spot_inner_cutoff",
            ),
            (
                Light {
                    range: 0.0,
                    ..Light::default()
                },
                "range of light 2 must be > 0",
            ),
            (
                Light {
                    spot_cutoff: 95.0,
                    ..Light::default()
                },
                "spot_cutoff of light 2",
            ),
            (
                Light {
                    spot_cutoff: -1.0,
                    ..Light::default()
                },
                "spot_cutoff",
            ),
            (
                Light {
                    linear_attenuation: -0.5,
                    ..Light::default()
                },
                "linear_attenuation",
            ),
            (
                Light {
                    position: [0.0; 4],
                    ..Light::default()
                },
                "position",
            ),
            (
                Light {
                    diffuse: [f64::NAN, 0.0, 0.0, 1.0],
                    ..Light::default()
                },
                "diffuse",
            ),
            (
                Light {
                    spot_cutoff: 30.0,
                    spot_direction: [0.0; 3],
                    ..Light::default()
                },
                "spot_direction",
            ),
        ];
        for (light, name) in cases {
            let err = light.validate(2).unwrap_err();
            assert!(err.message.contains(name), "{}", err.message);
        }
        let unattenuated = Light {
            position: [0.0, 0.0, 1.0, 1.0],
            constant_attenuation: 0.0,
            ..Light::default()
        };
        assert!(unattenuated.validate(0).is_err());
        assert!(Light {
            constant_attenuation: 0.0,
            ..Light::default()
        }
        .validate(0)
        .is_ok());
    }
}
