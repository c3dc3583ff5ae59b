//! Transfer functions: the encodings a render applies to its linear colours (`transfer`), and
//! sRGB's decoding of a texture's texels.
//!
//! Encoding is done in the image's type, as numpy does it on an array of that type, so a
//! render encodes its pixels to the bits `glshade.srgb_encode` gives its linear image. Both
//! curves are extended to negative values as sign(x)·f(|x|) (CSS Color 4's extended sRGB); NaN
//! stays NaN.

use crate::errors::error::Error;
use crate::simd::float::Float;

/// IEC 61966-2-1's constants: the linear segment's end, its slope, the power segment's offset
/// and exponent.
const LINEAR_END: f64 = 0.003_130_8;
const SLOPE: f64 = 12.92;
const OFFSET: f64 = 0.055;
const GAMMA: f64 = 2.4;

/// How a render encodes the RGB of its drawn pixels (alpha never).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Transfer {
    /// As the lighting equation gives them (GL without `GL_FRAMEBUFFER_SRGB`).
    #[default]
    Linear,
    /// sRGB's encoding (IEC 61966-2-1): 12.92·x up to 0.0031308, else 1.055·x^(1/2.4) − 0.055.
    Srgb,
    /// x^(1/2.2), pyrender's output.
    Gamma22,
}

impl Transfer {
    /// Parses `"linear"`, `"srgb"` or `"gamma2.2"`.
    ///
    /// # Errors
    /// A value error naming `transfer` for any other string.
    pub fn parse(name: &str) -> Result<Self, Error> {
        match name {
            "linear" => Ok(Self::Linear),
            "srgb" => Ok(Self::Srgb),
            "gamma2.2" => Ok(Self::Gamma22),
            _ => Err(Error::value(format!(
                "transfer must be 'linear', 'srgb' or 'gamma2.2', got '{name}'"
            ))),
        }
    }

    /// `x` encoded, in `x`'s type (the constants rounded to it, as numpy rounds a Python float
    /// that meets an array).
    #[inline]
    pub fn encode<T: Float>(self, x: T) -> T {
        let m = x.abs();
        let encoded = match self {
            Self::Linear => return x,
            Self::Srgb => {
                if m <= T::from_f64(LINEAR_END) {
                    T::from_f64(SLOPE) * m
                } else {
                    T::from_f64(1.0 + OFFSET) * m.powf(T::from_f64(1.0 / GAMMA))
                        - T::from_f64(OFFSET)
                }
            }
            Self::Gamma22 => m.powf(T::from_f64(1.0 / 2.2)),
        };
        encoded.copysign(x)
    }
}

/// A texel decoded from sRGB as pyrender's `srgb_to_linear` does it (IEC 61966-2-1's curve:
/// c/12.92 below 0.04045, ((c + 0.055)/1.055)^2.4 above); alpha as it is.
pub fn srgb_to_linear(c: [f64; 4]) -> [f64; 4] {
    let decode = |x: f64| {
        if x < 0.04045 {
            x / 12.92
        } else {
            ((x + 0.055) / 1.055).powf(2.4)
        }
    };
    [decode(c[0]), decode(c[1]), decode(c[2]), c[3]]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn encodings_follow_their_curves_and_mirror_negative_values() {
        let t = Transfer::Srgb;
        assert_eq!(t.encode(0.0_f64), 0.0);
        assert_eq!(t.encode(1.0_f64), 1.055 * 1.0_f64.powf(1.0 / 2.4) - 0.055);
        assert!((t.encode(0.18_f64) - 0.461_356_129).abs() < 1e-9);
        assert_eq!(t.encode(LINEAR_END), 12.92 * LINEAR_END);
        assert_eq!(t.encode(-0.5_f32), -t.encode(0.5_f32));
        assert!(t.encode(f64::NAN).is_nan());
        assert_eq!(
            Transfer::Gamma22.encode(0.25_f32),
            0.25_f32.powf((1.0 / 2.2_f64) as f32)
        );
        assert_eq!(Transfer::Linear.encode(-3.0_f64), -3.0);
        assert!(Transfer::parse("sRGB").is_err());
    }

    #[test]
    fn decoding_undoes_encoding() {
        for x in [0.0, 0.001, 0.02, 0.18, 0.5, 1.0] {
            let back = srgb_to_linear([Transfer::Srgb.encode(x), 0.0, 0.0, 1.0])[0];
            assert!((back - x).abs() < 1e-15, "{x}: {back}");
        }
    }
}
