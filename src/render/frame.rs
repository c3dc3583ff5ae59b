//! The visible pixels of a frame: which triangle the visibility pass found at each, and the
//! painting of the image from a colour per drawn pixel.

use rayon::prelude::*;

use crate::errors::error::Error;
use crate::errors::stop::Stop;
use crate::memory::alloc::{try_collect, try_par_collect};
use crate::memory::pages::Zeroed;
use crate::numbers::real::Real;
use crate::render::raster::{Triangle, Viewport};
use crate::render::transfer::Transfer;
use crate::render::visibility::{window_row, Triangles, NO_TRIANGLE};

/// `data` cut into consecutive pieces of `counts[r]·width` values, one per image row.
///
/// # Errors
/// A memory error for the list of pieces.
fn split_rows<'a, X>(
    mut data: &'a mut [X],
    counts: &[usize],
    width: usize,
) -> Result<Vec<&'a mut [X]>, Error> {
    let pieces = counts.iter().map(|&count| {
        let (head, tail) = std::mem::take(&mut data).split_at_mut(count * width);
        data = tail;
        head
    });
    try_collect(pieces, "the image rows")
}

/// The visible pixels: which triangle is seen at each.
pub struct Frame<'a> {
    /// The image size.
    pub viewport: Viewport,
    /// The triangles, by id.
    pub triangles: &'a Triangles,
    /// The triangle id at each pixel, image rows top-down ([`NO_TRIANGLE`] where none).
    pub ids: &'a [u32],
    /// How many pixels each image row draws.
    counts: Vec<usize>,
}

impl<'a> Frame<'a> {
    /// The frame of a visibility buffer.
    ///
    /// # Errors
    /// A memory error for the row counts.
    pub fn new(
        viewport: Viewport,
        triangles: &'a Triangles,
        ids: &'a [u32],
    ) -> Result<Self, Error> {
        let counts = try_par_collect(
            ids.par_chunks(viewport.width)
                .map(|row| row.iter().filter(|&&id| id != NO_TRIANGLE).count()),
            "the row counts",
        )?;
        Ok(Self {
            viewport,
            triangles,
            ids,
            counts,
        })
    }

    /// How many pixels are drawn.
    pub fn drawn_count(&self) -> usize {
        self.counts.iter().sum()
    }

    /// The index in the image (row · width + x, rows top-down) of every drawn pixel, in
    /// row-major order.
    ///
    /// # Errors
    /// A memory error for the list, or [`Error::interrupted`].
    #[allow(clippy::cast_possible_truncation)] // an image has fewer than 2^28 pixels
    pub fn drawn(&self, stop: &Stop) -> Result<Zeroed<u32>, Error> {
        let width = self.viewport.width;
        let mut drawn = Zeroed::<u32>::new(self.drawn_count(), "the drawn pixels")?;
        split_rows(&mut drawn, &self.counts, 1)?
            .into_par_iter()
            .zip(self.ids.par_chunks(width))
            .enumerate()
            .for_each(|(row, (out, ids))| {
                if stop.is_requested() {
                    return;
                }
                let visible = ids.iter().enumerate().filter(|(_, &id)| id != NO_TRIANGLE);
                for (slot, (x, _)) in out.iter_mut().zip(visible) {
                    *slot = (row * width + x) as u32;
                }
            });
        stop.check()?;
        Ok(drawn)
    }

    /// The triangle seen at image index `pixel` (from [`Frame::drawn`]) and its window
    /// coordinates (x, y).
    #[inline]
    pub fn at(&self, pixel: u32) -> (&Triangle, usize, usize) {
        let (width, pixel) = (self.viewport.width, pixel as usize);
        let (row, x) = (pixel / width, pixel % width);
        let t = self.triangles.get(self.ids[pixel]);
        (t, x, window_row(self.viewport, row))
    }

    /// The index of the first drawn pixel of each row among all drawn pixels, in row-major order.
    fn starts(&self) -> Result<Vec<usize>, Error> {
        let mut total = 0;
        let starts = self.counts.iter().map(|&c| {
            total += c;
            total - c
        });
        try_collect(starts, "the row starts")
    }

    /// Writes `colour(triangle, x, y, k)` (pixel (x, y) in window coordinates, the k-th drawn
    /// pixel), its RGB encoded by `transfer`, at every drawn pixel of `image` and `background`
    /// elsewhere, skipping the rows that start after `stop` is requested.
    ///
    /// # Errors
    /// A memory error for the row starts, or [`Error::interrupted`].
    pub fn paint<T: Real>(
        &self,
        image: &mut [T],
        background: [f64; 4],
        transfer: Transfer,
        stop: &Stop,
        colour: impl Fn(&Triangle, usize, usize, usize) -> [f64; 4] + Sync,
    ) -> Result<(), Error> {
        let width = self.viewport.width;
        let starts = self.starts()?;
        image
            .par_chunks_mut(width * 4)
            .zip(self.ids.par_chunks(width))
            .enumerate()
            .for_each(|(row, (pixels, ids))| {
                if stop.is_requested() {
                    return;
                }
                let y = window_row(self.viewport, row);
                let mut k = starts[row];
                for (x, (pixel, &id)) in pixels.chunks_exact_mut(4).zip(ids).enumerate() {
                    if id == NO_TRIANGLE {
                        for (d, s) in pixel.iter_mut().zip(background) {
                            *d = T::from_f64(s);
                        }
                        continue;
                    }
                    let rgba = colour(self.triangles.get(id), x, y, k);
                    k += 1;
                    for (d, s) in pixel[..3].iter_mut().zip(rgba) {
                        *d = transfer.encode(T::from_f64(s));
                    }
                    pixel[3] = T::from_f64(rgba[3]);
                }
            });
        stop.check()
    }
}
