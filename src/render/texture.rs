//! A 2-D texture and GL's sampling of it without mipmaps (GL 4.6 §8.14–8.15, ES 3.0 §3.8.10):
//! texel coordinates u·w and v·h, GL's three wrap modes on integer texel indices, and the
//! nearest or the bilinear filter (four texels weighted by the fractions of u·w − ½, v·h − ½).
//!
//! Texture coordinates follow GL and trimesh: (0, 0) is the lower-left corner of the image and
//! (1, 1) its upper-right, so texel row j counts up from the image's last row (numpy images,
//! like pyrender's uploads, store the top row first; pyrender flips them onto GL's rows).

use crate::errors::error::Error;

/// `GL_TEXTURE_MAG_FILTER` (and the minification filter, without mipmaps).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Filter {
    /// `GL_NEAREST`: the texel the coordinate falls in.
    Nearest,
    /// `GL_LINEAR`: the bilinear blend of the four nearest texel centres (pyrender's and
    /// GL's default magnification filter).
    #[default]
    Linear,
}

/// `GL_TEXTURE_WRAP_S` or `_T`: what an index outside [0, size) reads.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Wrap {
    /// `GL_REPEAT`: the index modulo the size (glTF's and GL's default).
    #[default]
    Repeat,
    /// `GL_MIRRORED_REPEAT`: repeats, every other copy mirrored.
    MirroredRepeat,
    /// `GL_CLAMP_TO_EDGE`: the nearest edge texel.
    ClampToEdge,
}

impl Filter {
    /// Parses `"nearest"` or `"linear"`.
    ///
    /// # Errors
    /// A value error naming `filter` for any other string.
    pub fn parse(name: &str) -> Result<Self, Error> {
        match name {
            "nearest" => Ok(Self::Nearest),
            "linear" => Ok(Self::Linear),
            _ => Err(Error::value(format!(
                "filter must be 'nearest' or 'linear', got '{name}'"
            ))),
        }
    }
}

impl Wrap {
    /// Parses `"repeat"`, `"mirrored_repeat"` or `"clamp_to_edge"`.
    ///
    /// # Errors
    /// A value error naming `wrap` for any other string.
    pub fn parse(name: &str) -> Result<Self, Error> {
        match name {
            "repeat" => Ok(Self::Repeat),
            "mirrored_repeat" => Ok(Self::MirroredRepeat),
            "clamp_to_edge" => Ok(Self::ClampToEdge),
            _ => Err(Error::value(format!(
                "wrap must be 'repeat', 'mirrored_repeat' or 'clamp_to_edge', got '{name}'"
            ))),
        }
    }

    /// A texel coordinate `x` of a row or column of `size` texels, moved by whole periods
    /// (2·size, a period of both repeats) or clamped into ±2^52, where its integer part fits
    /// an `i64` and which reads the same texels: beyond 2^52 an `f64` has no fraction.
    #[inline]
    fn reduced(self, x: f64, size: usize) -> f64 {
        const WHOLE: f64 = 4_503_599_627_370_496.0; // 2^52
        if x.abs() < WHOLE {
            return x;
        }
        match self {
            Self::ClampToEdge => x.clamp(-WHOLE, WHOLE),
            Self::Repeat | Self::MirroredRepeat => x.rem_euclid(2.0 * size as f64),
        }
    }

    /// The texel index GL reads for index `i` of a row or column of `size` texels.
    #[inline]
    #[allow(clippy::cast_possible_wrap, clippy::cast_sign_loss)] // size < 2^63; result in [0, size)
    fn index(self, i: i64, size: usize) -> usize {
        let n = size as i64;
        let wrapped = match self {
            Self::Repeat => i.rem_euclid(n),
            Self::ClampToEdge => i.clamp(0, n - 1),
            Self::MirroredRepeat => {
                // GL's mirror(a) = a ≥ 0 ? a : −(1 + a), of (i mod 2n) − n.
                let a = i.rem_euclid(2 * n) - n;
                let mirrored = if a >= 0 { a } else { -(1 + a) };
                n - 1 - mirrored
            }
        };
        wrapped as usize
    }
}

/// A texture's values as the caller stores them, `height` rows of `width` texels of
/// [`Texture::channels`] values each, the image's top row first: read in place, never
/// converted as a whole.
#[derive(Clone, Copy, Debug)]
pub enum Texels<'a> {
    /// Normalised bytes, c / 255 (GL's `GL_UNSIGNED_BYTE`).
    U8(&'a [u8]),
    /// Normalised 16-bit values, c / 65535 (`GL_UNSIGNED_SHORT`).
    U16(&'a [u16]),
    /// `float32`.
    F32(&'a [f32]),
    /// `float64`, held as `float32` as GL's `GL_RGBA32F` holds it.
    F64(&'a [f64]),
}

impl Texels<'_> {
    /// How many values there are.
    pub fn len(&self) -> usize {
        match self {
            Self::U8(t) => t.len(),
            Self::U16(t) => t.len(),
            Self::F32(t) => t.len(),
            Self::F64(t) => t.len(),
        }
    }

    /// Whether there are none.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Value `k` as a `GL_RGBA32F` texture holds it: normalised integers divided by their
    /// largest value and rounded to `f32`, floats rounded to `f32`.
    #[inline]
    #[allow(clippy::cast_possible_truncation)] // the rounding to f32 is GL's
    fn value(&self, k: usize) -> f64 {
        f64::from(match self {
            Self::U8(t) => (f64::from(t[k]) / 255.0) as f32,
            Self::U16(t) => (f64::from(t[k]) / 65535.0) as f32,
            Self::F32(t) => t[k],
            Self::F64(t) => t[k] as f32,
        })
    }
}

/// An image sampled as a GL texture.
#[derive(Clone, Copy, Debug)]
pub struct Texture<'a> {
    /// Texels per row.
    pub width: usize,
    /// Rows.
    pub height: usize,
    /// Values per texel: 4 (RGBA), 3 (RGB, alpha 1), 2 (grey and alpha) or 1 (grey, alpha 1);
    /// grey is read into R, G and B, as GL's `GL_LUMINANCE` textures are.
    pub channels: usize,
    /// The texels.
    pub texels: Texels<'a>,
    /// The filter.
    pub filter: Filter,
    /// The wrap modes along u (s) and v (t).
    pub wrap: [Wrap; 2],
}

impl Texture<'_> {
    /// Checks the size against the texels.
    ///
    /// # Errors
    /// A value error for an empty texture, a channel count outside 1 to 4, or a value count
    /// that is not height × width × channels.
    pub fn validate(&self) -> Result<(), Error> {
        let expected = self
            .width
            .checked_mul(self.height)
            .and_then(|n| n.checked_mul(self.channels));
        let channels = (1..=4).contains(&self.channels);
        if !channels || self.width == 0 || self.height == 0 || expected != Some(self.texels.len()) {
            return Err(Error::value(format!(
                "the texture must have height x width x channels values with height and width \
                 >= 1 and 1 to 4 channels, got {} values for {} x {} x {}",
                self.texels.len(),
                self.height,
                self.width,
                self.channels
            )));
        }
        Ok(())
    }

    /// The texel at column `i` and GL row `j` (counted from the image's bottom row), wrapped.
    #[inline]
    fn texel(&self, i: i64, j: i64) -> [f64; 4] {
        let column = self.wrap[0].index(i, self.width);
        let row = self.height - 1 - self.wrap[1].index(j, self.height);
        let at = (row * self.width + column) * self.channels;
        let value = |k| self.texels.value(at + k);
        match self.channels {
            1 => {
                let grey = value(0);
                [grey, grey, grey, 1.0]
            }
            2 => {
                let grey = value(0);
                [grey, grey, grey, value(1)]
            }
            3 => [value(0), value(1), value(2), 1.0],
            _ => std::array::from_fn(value),
        }
    }

    /// GL's filtered value at texture coordinates `uv`; NaN for a coordinate that is not
    /// finite.
    pub fn sample(&self, uv: [f64; 2]) -> [f64; 4] {
        if !(uv[0].is_finite() && uv[1].is_finite()) {
            return [f64::NAN; 4];
        }
        let (x, y) = (
            self.wrap[0].reduced(uv[0] * self.width as f64, self.width),
            self.wrap[1].reduced(uv[1] * self.height as f64, self.height),
        );
        match self.filter {
            Filter::Nearest => self.texel(x.floor() as i64, y.floor() as i64),
            Filter::Linear => {
                let (x, y) = (x - 0.5, y - 0.5);
                let (i, j) = (x.floor(), y.floor());
                let (a, b) = (x - i, y - j);
                let (i, j) = (i as i64, j as i64);
                let [t00, t10, t01, t11] = [
                    self.texel(i, j),
                    self.texel(i + 1, j),
                    self.texel(i, j + 1),
                    self.texel(i + 1, j + 1),
                ];
                std::array::from_fn(|k| {
                    (1.0 - a) * (1.0 - b) * t00[k]
                        + a * (1.0 - b) * t10[k]
                        + (1.0 - a) * b * t01[k]
                        + a * b * t11[k]
                })
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A 2 x 2 texture: red, green on the top row; blue, white on the bottom.
    const TEXELS: [f32; 16] = [
        1.0, 0.0, 0.0, 1.0, 0.0, 1.0, 0.0, 1.0, //
        0.0, 0.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0,
    ];

    fn texture(filter: Filter, wrap: Wrap) -> Texture<'static> {
        Texture {
            width: 2,
            height: 2,
            channels: 4,
            texels: Texels::F32(&TEXELS),
            filter,
            wrap: [wrap; 2],
        }
    }

    #[test]
    fn v_counts_up_from_the_bottom_row() {
        let t = texture(Filter::Nearest, Wrap::Repeat);
        assert_eq!(
            t.sample([0.25, 0.25]),
            [0.0, 0.0, 1.0, 1.0],
            "lower left: blue"
        );
        assert_eq!(
            t.sample([0.25, 0.75]),
            [1.0, 0.0, 0.0, 1.0],
            "upper left: red"
        );
        assert_eq!(
            t.sample([0.75, 0.75]),
            [0.0, 1.0, 0.0, 1.0],
            "upper right: green"
        );
    }

    #[test]
    fn bilinear_blends_the_four_nearest_centres() {
        let t = texture(Filter::Linear, Wrap::ClampToEdge);
        assert_eq!(t.sample([0.5, 0.5]), [0.5, 0.5, 0.5, 1.0]);
        assert_eq!(
            t.sample([0.25, 0.25]),
            [0.0, 0.0, 1.0, 1.0],
            "a texel centre"
        );
        assert_eq!(
            t.sample([0.0, 0.25]),
            [0.0, 0.0, 1.0, 1.0],
            "clamped at the edge"
        );
        let repeat = texture(Filter::Linear, Wrap::Repeat).sample([0.0, 0.25]);
        assert_eq!(
            repeat,
            [0.5, 0.5, 1.0, 1.0],
            "blue and white across the seam"
        );
    }

    #[test]
    fn wrap_modes_follow_gl() {
        let index = |w: Wrap, i| w.index(i, 3);
        let repeat: Vec<usize> = (-4..5).map(|i| index(Wrap::Repeat, i)).collect();
        assert_eq!(repeat, [2, 0, 1, 2, 0, 1, 2, 0, 1]);
        let mirrored: Vec<usize> = (-4..5).map(|i| index(Wrap::MirroredRepeat, i)).collect();
        assert_eq!(mirrored, [2, 2, 1, 0, 0, 1, 2, 2, 1]);
        let clamped: Vec<usize> = (-2..5).map(|i| index(Wrap::ClampToEdge, i)).collect();
        assert_eq!(clamped, [0, 0, 0, 1, 2, 2, 2]);
        assert!(texture(Filter::Linear, Wrap::Repeat).sample([f64::NAN, 0.0])[0].is_nan());
        assert!(texture(Filter::Linear, Wrap::Repeat).sample([1e300, -1e300])[0].is_finite());
    }

    #[test]
    fn every_storage_reads_as_gl_holds_it() {
        // One texel of each channel count and type; GL's RGBA32F rounds to float32.
        let read = |texels: Texels<'_>, channels| {
            let t = Texture {
                width: 1,
                height: 1,
                channels,
                texels,
                filter: Filter::Nearest,
                wrap: [Wrap::Repeat; 2],
            };
            t.validate().unwrap();
            t.sample([0.5, 0.5])
        };
        let third = f64::from((1.0_f64 / 3.0) as f32);
        assert_eq!(read(Texels::U8(&[255]), 1), [1.0, 1.0, 1.0, 1.0]);
        assert_eq!(read(Texels::U8(&[85, 0]), 2), [third, third, third, 0.0]);
        assert_eq!(
            read(Texels::U16(&[65535, 0, 21845]), 3),
            [1.0, 0.0, third, 1.0]
        );
        assert_eq!(
            read(Texels::F64(&[1.0 / 3.0, 0.5, 2.0, 0.25]), 4),
            [third, 0.5, 2.0, 0.25]
        );
        let wrong = Texture {
            channels: 5,
            ..texture(Filter::Nearest, Wrap::Repeat)
        };
        assert!(wrong.validate().is_err());
    }
}
