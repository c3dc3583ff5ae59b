//! The visibility pass: for every pixel, the nearest triangle whose interior covers its centre
//! (depth test `GL_LESS` against a depth buffer cleared to 1, GL's defaults), and its depth.
//!
//! Only the triangle's index is stored per pixel; attributes are interpolated afterwards, once
//! per visible pixel. Rows are split into bands of [`BAND_ROWS`] that run in parallel; each band
//! draws its triangles in submission order, so the result is the same for any thread count.

use rayon::prelude::*;

use crate::errors::error::Error;
use crate::errors::stop::Stop;
use crate::memory::alloc::{try_collect, try_filled};
use crate::numbers::real::Real;
use crate::render::raster::{Triangle, Viewport};

/// The triangle id of a pixel no triangle covers.
pub const NO_TRIANGLE: u32 = u32::MAX;

/// Bits of a triangle id that index within its chunk.
pub const CHUNK_BITS: u32 = 15;

/// The most chunks [`Triangles`] can hold: their ids stay below [`NO_TRIANGLE`].
pub const MAX_CHUNKS: usize = (1 << (32 - CHUNK_BITS)) - 1;

/// Triangles in submission order, in chunks of fewer than 2^[`CHUNK_BITS`] (set up in
/// parallel, stored without concatenating them); a triangle's id is its chunk's index times
/// 2^`CHUNK_BITS` plus its index in the chunk.
#[derive(Clone, Debug, Default)]
pub struct Triangles {
    /// The chunks, in order; at most [`MAX_CHUNKS`], each shorter than 2^[`CHUNK_BITS`].
    pub chunks: Vec<Vec<Triangle>>,
}

impl Triangles {
    /// The triangle with id `id`.
    #[inline]
    pub fn get(&self, id: u32) -> &Triangle {
        &self.chunks[(id >> CHUNK_BITS) as usize][(id & ((1 << CHUNK_BITS) - 1)) as usize]
    }

    /// The triangles of every chunk with their ids, chunk by chunk in order.
    fn chunks(&self) -> impl Iterator<Item = impl Iterator<Item = (u32, &Triangle)>> {
        self.chunks.iter().enumerate().map(|(c, chunk)| {
            let base = (c as u32) << CHUNK_BITS;
            chunk
                .iter()
                .enumerate()
                .map(move |(i, t)| (base | i as u32, t))
        })
    }
}

/// Image rows per parallel task: a 1024-row image gives 32 tasks, enough to balance uneven rows
/// over up to 16 threads, while few triangles straddle two bands (each band sets up the rows of
/// its triangles again; 16 rows measured 15% slower on a 100,000-triangle torus).
pub const BAND_ROWS: usize = 32;

/// The GL window row of image row `row`, and back (image rows run top-down, window rows
/// bottom-up).
#[inline]
pub fn window_row(viewport: Viewport, row: usize) -> usize {
    viewport.height - 1 - row
}

/// The triangles of each band of image rows, as ids in submission order: `(starts, ids)` with
/// band b's triangles at `ids[starts[b]..starts[b + 1]]`. Sequential: `stop` is polled per
/// chunk of triangles.
///
/// # Errors
/// A memory error for the bins, or [`Error::interrupted`].
fn bin(
    triangles: &Triangles,
    viewport: Viewport,
    stop: &Stop,
) -> Result<(Vec<usize>, Vec<u32>), Error> {
    let bands = viewport.height.div_ceil(BAND_ROWS);
    let band_range = |t: &Triangle| {
        let (y0, y1) = t.rows();
        let (top, bottom) = (window_row(viewport, y1), window_row(viewport, y0));
        top / BAND_ROWS..=bottom / BAND_ROWS
    };
    let mut starts = try_filled(bands + 1, 0, "the band starts")?;
    for chunk in triangles.chunks() {
        stop.check()?;
        for (_, t) in chunk {
            for b in band_range(t) {
                starts[b + 1] += 1;
            }
        }
    }
    for b in 0..bands {
        starts[b + 1] += starts[b];
    }
    let mut fill = try_collect(starts.iter().copied(), "the band cursors")?;
    let mut ids = try_filled(starts[bands], 0, "the binned triangles")?;
    for chunk in triangles.chunks() {
        stop.check()?;
        for (id, t) in chunk {
            for b in band_range(t) {
                ids[fill[b]] = id;
                fill[b] += 1;
            }
        }
    }
    Ok((starts, ids))
}

/// Fills `ids` (a triangle id per pixel, image rows top-down, [`NO_TRIANGLE`] where nothing is
/// drawn) and `depth` (window depth, 1 where nothing is drawn) from `triangles`. `stop` is
/// polled per band and per triangle drawn in it, since one band may draw every triangle.
///
/// # Errors
/// A memory error for the bins, or [`Error::interrupted`] when `stop` was requested before
/// the pass finished.
pub fn visibility<T: Real>(
    triangles: &Triangles,
    viewport: Viewport,
    ids: &mut [u32],
    depth: &mut [T],
    stop: &Stop,
) -> Result<(), Error> {
    let width = viewport.width;
    let (starts, binned) = bin(triangles, viewport, stop)?;
    let band = BAND_ROWS * width;
    ids.par_chunks_mut(band)
        .zip(depth.par_chunks_mut(band))
        .enumerate()
        .for_each(|(b, (ids, depth))| {
            if stop.is_requested() {
                return;
            }
            // Cleared band by band: in parallel, and between polls.
            ids.fill(NO_TRIANGLE);
            depth.fill(T::ONE);
            let first_row = b * BAND_ROWS;
            let rows = ids.len() / width;
            // Window rows of this band, bottom-up: the image rows run the other way.
            let lowest = window_row(viewport, first_row + rows - 1);
            let highest = window_row(viewport, first_row);
            for &id in &binned[starts[b]..starts[b + 1]] {
                if stop.is_requested() {
                    return;
                }
                let t = triangles.get(id);
                let (y0, y1) = t.rows();
                for y in y0.max(lowest)..=y1.min(highest) {
                    let offset = (highest - y) * width;
                    t.for_each_in_row(y, |x| {
                        let k = offset + x;
                        let z = T::from_f64(t.depth_at(x, y));
                        if z < depth[k] {
                            depth[k] = z;
                            ids[k] = id;
                        }
                    });
                }
            }
        });
    stop.check()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::clip::ClipVertex;
    use crate::render::raster::Cull;
    use glam::{DVec3, DVec4};

    /// A triangle over the whole 40 x 40 viewport at NDC depth `z`, CCW.
    fn screen_triangle(face: u32, z: f64, viewport: Viewport) -> Triangle {
        let corners = [(-1.0, -1.0), (3.0, -1.0), (-1.0, 3.0)]
            .into_iter()
            .zip([DVec3::X, DVec3::Y, DVec3::Z])
            .map(|((x, y), weights)| ClipVertex {
                clip: DVec4::new(x, y, z, 1.0),
                weights,
            })
            .collect::<Vec<_>>();
        Triangle::new(
            face,
            [corners[0], corners[1], corners[2]],
            viewport,
            Cull::None,
        )
        .unwrap()
    }

    #[test]
    fn the_nearest_triangle_wins_and_ties_keep_the_first() {
        let viewport = Viewport {
            width: 40,
            height: 37,
        };
        let triangles = Triangles {
            chunks: vec![
                vec![screen_triangle(0, 0.5, viewport)],
                vec![
                    screen_triangle(1, -0.5, viewport),
                    screen_triangle(2, -0.5, viewport),
                ],
                vec![screen_triangle(3, 0.0, viewport)],
            ],
        };
        let mut ids = vec![0; 40 * 37];
        let mut depth = vec![0.0_f32; 40 * 37];
        visibility(&triangles, viewport, &mut ids, &mut depth, &Stop::new()).unwrap();
        assert!(ids.iter().all(|&i| i == 1 << CHUNK_BITS));
        assert_eq!(triangles.get(1 << CHUNK_BITS).face, 1);
        assert!(depth.iter().all(|&z| z == 0.25));
    }

    #[test]
    fn nothing_drawn_leaves_the_clear_values() {
        let viewport = Viewport {
            width: 3,
            height: 20,
        };
        let mut ids = vec![0; 60];
        let mut depth = vec![0.0_f64; 60];
        visibility(
            &Triangles::default(),
            viewport,
            &mut ids,
            &mut depth,
            &Stop::new(),
        )
        .unwrap();
        assert!(ids.iter().all(|&i| i == NO_TRIANGLE));
        assert!(depth.iter().all(|&z| z == 1.0));
    }
}
