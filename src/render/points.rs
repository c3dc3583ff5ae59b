//! Points as GL draws them without smoothing (`GL_POINTS`): each point is lit once, at its
//! vertex, and covers the pixels whose centres lie in a square of `size` pixels centred on its
//! window position (GL 3.3 §3.4), or in the disc of that diameter (a fragment shader's discard
//! outside `gl_PointCoord`'s circle), at its window depth, depth-tested as triangles are
//! (`GL_LESS`: the first drawn wins a tie). A point whose centre lies outside the clip volume is
//! not drawn (GL 2.1 §2.12: clipping passes a point unchanged or discards it).
//!
//! The square follows Mesa's llvmpipe, the GL these renders are checked against: the position
//! less half a pixel, snapped to 1/256 of a pixel, and the pixels `x0 <= i < x0 + size` where
//! `x0` is that less half the size (left and bottom edges in, right and top out).

use glam::DVec4;

use crate::errors::error::Error;
use crate::errors::stop::Stop;
use crate::memory::alloc::{count, try_collect};
use crate::memory::pages::Zeroed;
use crate::memory::uninit::as_uninit;
use crate::numbers::real::Real;
use crate::render::camera::{check_affine, Camera};
use crate::render::layer::shaded;
use crate::render::mesh::Mesh;
use crate::render::options::RenderOptions;
use crate::render::raster::Viewport;
use crate::render::shader::{RenderModel, Shader};
use crate::render::visibility::window_row;

/// The largest point size, in pixels (llvmpipe's `GL_POINT_SIZE_RANGE` ends at 255).
pub const MAX_POINT_SIZE: f64 = 255.0;

/// The pixels a point covers.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum PointShape {
    /// GL's point without smoothing: a square.
    #[default]
    Square,
    /// The disc of the square's width: the centres within half the size of the point.
    Round,
}

impl PointShape {
    /// Parses `"square"` or `"round"`.
    ///
    /// # Errors
    /// A value error naming `point_shape` for any other string.
    pub fn parse(name: &str) -> Result<Self, Error> {
        match name {
            "square" => Ok(Self::Square),
            "round" => Ok(Self::Round),
            _ => Err(Error::value(format!(
                "point_shape must be 'square' or 'round', got '{name}'"
            ))),
        }
    }
}

/// How points are drawn: their size in pixels and their shape.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PointStyle {
    /// The side of the square (or the disc's diameter) in pixels, in (0, [`MAX_POINT_SIZE`]].
    pub size: f64,
    /// Square or round.
    pub shape: PointShape,
}

impl PointStyle {
    /// Checks the size.
    ///
    /// # Errors
    /// A value error naming `point_size` outside (0, 255].
    pub fn validate(&self) -> Result<(), Error> {
        if self.size > 0.0 && self.size <= MAX_POINT_SIZE {
            Ok(())
        } else {
            Err(Error::value(format!(
                "point_size must be in (0, {MAX_POINT_SIZE}] pixels, got {}",
                self.size
            )))
        }
    }

    /// Calls `each(column, window_row)` for every pixel of the viewport the point at window
    /// position (`x`, `y`) covers.
    fn cover(&self, x: f64, y: f64, viewport: Viewport, mut each: impl FnMut(usize, usize)) {
        let half = self.size / 2.0;
        // The first and last pixel along an axis of `pixels`, or None off the viewport.
        let span = |at: f64, pixels: usize| {
            let start = ((at - 0.5) * 256.0).round_ties_even() / 256.0 - half;
            let first = start.ceil().max(0.0);
            #[allow(clippy::cast_precision_loss)] // sizes below 2^14
            let last = ((start + self.size).ceil() - 1.0).min(pixels as f64 - 1.0);
            #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)] // in [0, pixels)
            (first <= last).then_some((first as usize, last as usize))
        };
        let (Some((x0, x1)), Some((y0, y1))) = (span(x, viewport.width), span(y, viewport.height))
        else {
            return;
        };
        for j in y0..=y1 {
            for i in x0..=x1 {
                #[allow(clippy::cast_precision_loss)] // sizes below 2^14
                let (dx, dy) = (i as f64 + 0.5 - x, j as f64 + 0.5 - y);
                if self.shape == PointShape::Square || dx * dx + dy * dy <= half * half {
                    each(i, j);
                }
            }
        }
    }
}

/// The RGBA of each point: lit by `scene` with its normal where `points` has normals (GL lights
/// a point at its vertex, with the front material), else its colour as it is (white without
/// colours), clamped unless `options.clamp` is off.
///
/// # Errors
/// Those of the shader; a memory error for the colours.
fn colours<T: Real, M: RenderModel>(
    scene: &M,
    points: &Mesh<'_, T>,
    camera: &Camera,
    options: &RenderOptions,
    stop: &Stop,
) -> Result<Vec<[f64; 4]>, Error> {
    let n = points.vertices.len();
    let clamp = options.clamp == crate::lighting::clamp::ColorClamp::On;
    let Some(normals) = points.normals else {
        let colour = |i: usize| {
            let mut rgba = [1.0; 4];
            if let Some(c) = points.colors {
                for (k, v) in rgba.iter_mut().zip(&c.data[i * c.width..(i + 1) * c.width]) {
                    *k = v.to_f64();
                }
            }
            if clamp {
                rgba.map(|v| v.clamp(0.0, 1.0))
            } else {
                rgba
            }
        };
        return try_collect((0..n).map(colour), "the point colours");
    };
    let shader = Shader::new(scene, camera, options, false)?;
    let len = count(&[shader.outputs(), n, 4], "the point colours")?;
    let mut out = Zeroed::<T>::new(len, "the point colours")?;
    shader.shade(
        points.vertices,
        normals,
        points.colors,
        as_uninit(&mut out),
        stop,
    )?;
    try_collect(
        (0..n).map(|i| shader.fragment(true, clamp, None, |plane| shaded(&out, n, plane, i))),
        "the point colours",
    )
}

/// Draws `points` (their vertices, with one normal each to be lit, or without to be drawn in
/// their colours; no faces) seen by `camera` into `image` ((height, width, 4) RGBA, row 0 at the
/// top) and `depth` ((height, width) window depth, 1 where nothing is drawn), as [`PointStyle`]
/// says, the rest cleared to `options.background`; `options.transfer` encodes the drawn RGB.
///
/// # Errors
/// A value error for a bad size, camera, model matrix, style or a normal or colour count other
/// than the points'; those of the shader; [`Error::interrupted`] when `stop` was requested.
#[allow(clippy::too_many_arguments)] // the frame's arguments, as `render`'s
pub fn render_points<T: Real, M: RenderModel>(
    scene: &M,
    points: &Mesh<'_, T>,
    camera: &Camera,
    options: &RenderOptions,
    style: PointStyle,
    image: &mut [T],
    depth: &mut [T],
    stop: &Stop,
) -> Result<(), Error> {
    super::validate_frame(camera, options, image.len(), depth.len())?;
    check_affine(&options.model, "model")?;
    style.validate()?;
    let n = points.vertices.len();
    if points.normals.is_some_and(|m| m.len() != n) {
        return Err(Error::value(format!(
            "normals must have one row per point ({n}), got {}",
            points.normals.map_or(0, <[_]>::len)
        )));
    }
    if let Some(c) = points.colors {
        if c.data.len() != n * c.width {
            return Err(Error::value(format!(
                "colors must have one row per point ({n}), got {}",
                c.data.len() / c.width.max(1)
            )));
        }
    }
    let colours = colours(scene, points, camera, options, stop)?;
    for (pixel, z) in image.chunks_exact_mut(4).zip(depth.iter_mut()) {
        for (d, s) in pixel.iter_mut().zip(options.background) {
            *d = T::from_f64(s);
        }
        *z = T::ONE;
    }
    let viewport = options.viewport;
    let clip_of = camera.projection * camera.view * options.model;
    let (width, height) = (viewport.width as f64, viewport.height as f64);
    for (i, p) in points.vertices.iter().enumerate() {
        if i % 4096 == 0 {
            stop.check()?;
        }
        let clip = clip_of * DVec4::new(p[0].to_f64(), p[1].to_f64(), p[2].to_f64(), 1.0);
        let w = clip.w;
        if !(w > 0.0 && clip.x.abs() <= w && clip.y.abs() <= w && clip.z.abs() <= w) {
            continue; // outside the clip volume, or not finite
        }
        let ndc = clip.truncate() / w;
        let (x, y) = ((ndc.x + 1.0) * 0.5 * width, (ndc.y + 1.0) * 0.5 * height);
        let z = T::from_f64((ndc.z + 1.0) * 0.5);
        let rgba = colours[i];
        style.cover(x, y, viewport, |column, row| {
            let k = window_row(viewport, row) * viewport.width + column;
            if z < depth[k] {
                depth[k] = z;
                let pixel = &mut image[4 * k..4 * k + 4];
                for (d, s) in pixel[..3].iter_mut().zip(rgba) {
                    *d = options.transfer.encode(T::from_f64(s));
                }
                pixel[3] = T::from_f64(rgba[3]);
            }
        });
    }
    stop.check()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn covered(x: f64, y: f64, size: f64, shape: PointShape) -> Vec<(usize, usize)> {
        let mut out = Vec::new();
        let viewport = Viewport {
            width: 10,
            height: 8,
        };
        PointStyle { size, shape }.cover(x, y, viewport, |i, j| out.push((i, j)));
        out
    }

    #[test]
    fn a_point_covers_the_centres_in_its_square() {
        // Size 1: the pixel the position falls in.
        assert_eq!(covered(3.3, 2.7, 1.0, PointShape::Square), vec![(3, 2)]);
        // Size 3 centred on a pixel centre: the 3 x 3 around it.
        let nine = covered(4.5, 4.5, 3.0, PointShape::Square);
        assert_eq!(nine.len(), 9);
        assert!(nine.contains(&(3, 3)) && nine.contains(&(5, 5)));
        // Size 2 at a pixel corner: the four pixels around it.
        assert_eq!(
            covered(5.0, 3.0, 2.0, PointShape::Square),
            vec![(4, 2), (5, 2), (4, 3), (5, 3)]
        );
        // Round: the corners of an 8-pixel square are left out.
        let disc = covered(5.0, 4.0, 8.0, PointShape::Round);
        assert!(disc.len() < 64 && disc.contains(&(4, 3)) && !disc.contains(&(1, 0)));
        // Clipped by the viewport, not wrapped.
        assert_eq!(covered(0.2, 0.2, 3.0, PointShape::Square).len(), 4);
        assert!(covered(-5.0, 3.0, 3.0, PointShape::Square).is_empty());
    }

    #[test]
    fn sizes_outside_0_to_255_are_refused() {
        for size in [0.0, -1.0, 255.5, f64::NAN] {
            let style = PointStyle {
                size,
                shape: PointShape::Square,
            };
            assert!(style.validate().is_err(), "{size}");
        }
        assert!(PointShape::parse("disc").is_err());
    }
}
