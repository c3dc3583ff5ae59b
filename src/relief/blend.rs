//! matplotlib's blends of an RGB image with an intensity map in [0, 1]
//! (`LightSource.blend_hsv`, `blend_soft_light`, `blend_overlay`), per pixel, with its
//! `rgb_to_hsv` and `hsv_to_rgb`.

use rayon::prelude::*;

use crate::errors::error::Error;
use crate::errors::stop::Stop;

/// Pixels per parallel task.
const PIXELS_PER_TASK: usize = 1 << 14;

/// How an intensity modulates a colour.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Blend {
    /// `blend_hsv`: the intensity, as 2i − 1 in [−1, 1], moves the saturation towards
    /// `max_sat` or `min_sat` (unless it is 0) and the value towards `max_val` or `min_val`.
    Hsv {
        /// `hsv_min_val`.
        min_val: f64,
        /// `hsv_max_val`.
        max_val: f64,
        /// `hsv_min_sat`.
        min_sat: f64,
        /// `hsv_max_sat`.
        max_sat: f64,
    },
    /// `blend_soft_light` ("pegtop"): 2·i·c + (1 − 2i)·c².
    SoftLight,
    /// `blend_overlay`: 2·i·c where c ≤ ½, else 1 − 2(1 − i)(1 − c).
    Overlay,
}

/// matplotlib's `rgb_to_hsv` of one colour in [0, 1].
fn rgb_to_hsv([r, g, b]: [f64; 3]) -> [f64; 3] {
    let max = r.max(g).max(b);
    let delta = max - r.min(g).min(b);
    let s = if max > 0.0 { delta / max } else { 0.0 };
    // Later matches win, as numpy's successive masked assignments do.
    let mut h = 0.0;
    if delta > 0.0 {
        if r == max {
            h = (g - b) / delta;
        }
        if g == max {
            h = 2.0 + (b - r) / delta;
        }
        if b == max {
            h = 4.0 + (r - g) / delta;
        }
    }
    [(h / 6.0).rem_euclid(1.0), s, max]
}

/// matplotlib's `hsv_to_rgb` of one colour.
#[allow(clippy::cast_possible_truncation, clippy::many_single_char_names)]
fn hsv_to_rgb([h, s, v]: [f64; 3]) -> [f64; 3] {
    if s == 0.0 {
        return [v, v, v];
    }
    let i = (h * 6.0) as i64; // numpy's astype(int): towards zero
    let f = h * 6.0 - i as f64;
    let p = v * (1.0 - s);
    let q = v * (1.0 - s * f);
    let t = v * (1.0 - s * (1.0 - f));
    match i {
        1 => [q, v, p],
        2 => [p, v, t],
        3 => [p, q, v],
        4 => [t, p, v],
        5 => [v, p, q],
        _ if i.rem_euclid(6) == 0 => [v, t, p],
        // numpy leaves such pixels as np.empty_like made them; none arise for h in [0, 1].
        _ => [f64::NAN; 3],
    }
}

impl Blend {
    /// The blend of colour `c` with intensity `i`.
    fn apply(self, c: [f64; 3], i: f64) -> [f64; 3] {
        match self {
            Self::SoftLight => c.map(|c| 2.0 * i * c + (1.0 - 2.0 * i) * (c * c)),
            Self::Overlay => c.map(|c| {
                if c <= 0.5 {
                    2.0 * i * c
                } else {
                    1.0 - 2.0 * (1.0 - i) * (1.0 - c)
                }
            }),
            Self::Hsv {
                min_val,
                max_val,
                min_sat,
                max_sat,
            } => {
                let i = 2.0 * i - 1.0;
                let [h, mut s, mut v] = rgb_to_hsv(c);
                if s.abs() > 1e-10 && i > 0.0 {
                    s = (1.0 - i) * s + i * max_sat;
                }
                if s.abs() > 1e-10 && i < 0.0 {
                    s = (1.0 + i) * s - i * min_sat;
                }
                if i > 0.0 {
                    v = (1.0 - i) * v + i * max_val;
                }
                if i < 0.0 {
                    v = (1.0 + i) * v - i * min_val;
                }
                hsv_to_rgb([h, s.clamp(0.0, 1.0), v.clamp(0.0, 1.0)])
            }
        }
    }
}

/// Writes the blend of every pixel of `rgb` (RGB rows) with its `intensity` into `out`.
///
/// # Errors
/// A value error for lengths that do not match, or for `Blend::Hsv` a colour outside [0, 1]
/// (matplotlib's `rgb_to_hsv` refuses it), naming the pixel; [`Error::interrupted`].
pub fn blend(
    rgb: &[[f64; 3]],
    intensity: &[f64],
    mode: Blend,
    out: &mut [[f64; 3]],
    stop: &Stop,
) -> Result<(), Error> {
    if intensity.len() != rgb.len() || out.len() != rgb.len() {
        return Err(Error::value(format!(
            "rgb, intensity and out must have one row per pixel ({}), got {} and {}",
            rgb.len(),
            intensity.len(),
            out.len()
        )));
    }
    if matches!(mode, Blend::Hsv { .. }) {
        let outside = |c: &[f64; 3]| c.iter().any(|x| !(0.0..=1.0).contains(x) && !x.is_nan());
        if let Some(k) = rgb.par_iter().position_first(outside) {
            return Err(Error::value(format!(
                "rgb must be in [0, 1] for the hsv blend, got {:?} at pixel {k}",
                rgb[k]
            )));
        }
    }
    out.par_chunks_mut(PIXELS_PER_TASK)
        .zip(rgb.par_chunks(PIXELS_PER_TASK))
        .zip(intensity.par_chunks(PIXELS_PER_TASK))
        .for_each(|((dst, c), i)| {
            if stop.is_requested() {
                return;
            }
            for ((d, &c), &i) in dst.iter_mut().zip(c).zip(i) {
                *d = mode.apply(c, i);
            }
        });
    stop.check()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hsv_round_trips() {
        for c in [
            [1.0, 0.5, 0.25],
            [0.2, 0.9, 0.4],
            [0.3, 0.3, 0.8],
            [0.5, 0.5, 0.5],
        ] {
            let back = hsv_to_rgb(rgb_to_hsv(c));
            for k in 0..3 {
                assert!((back[k] - c[k]).abs() < 1e-15, "{c:?} -> {back:?}");
            }
        }
    }

    #[test]
    fn a_mid_intensity_changes_nothing_in_overlay_and_hsv() {
        let c = [0.2, 0.6, 0.9];
        assert_eq!(Blend::Overlay.apply(c, 0.5)[0], 0.2);
        let hsv = Blend::Hsv {
            min_val: 0.0,
            max_val: 1.0,
            min_sat: 1.0,
            max_sat: 0.0,
        };
        let out = hsv.apply(c, 0.5);
        assert!((0..3).all(|k| (out[k] - c[k]).abs() < 1e-15));
    }
}
