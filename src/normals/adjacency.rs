//! The vertex-to-face adjacency of a triangle mesh, which turns the sum over a vertex's faces
//! into a gather: each vertex reads its faces in face order, so sums do not depend on threads.

use crate::errors::error::Error;
use crate::errors::stop::Stop;
use crate::memory::alloc::{try_collect, try_filled};
use crate::memory::pages::Zeroed;

/// Corners per slab of the sequential counting sort, between polls of the stop: about a
/// millisecond of work each.
const CORNERS_PER_SLAB: usize = 1 << 18;

/// A vertex index that `normals::check_faces` has proven to be in `0..vertex_count`.
#[inline]
#[allow(clippy::cast_sign_loss)]
pub(crate) fn index(v: i64) -> usize {
    v as usize
}

/// The face corners of every vertex in compressed-sparse-row form: those of vertex `v` are
/// `corners[offsets[v]..offsets[v + 1]]`, each `3·face + corner`, in increasing face order.
/// `u32` halves the memory traffic of the gather; meshes are limited to [`Self::MAX_FACES`].
pub(crate) struct Adjacency {
    offsets: Vec<u32>,
    corners: Zeroed<u32>,
}

impl Adjacency {
    /// The most faces an adjacency holds: their corners are numbered in `u32`.
    pub(crate) const MAX_FACES: usize = u32::MAX as usize / 3;

    /// A counting sort of the corners of checked `faces` (at most [`Self::MAX_FACES`]) by
    /// vertex: stable, so each vertex lists its faces in order. `stop` is polled every
    /// [`CORNERS_PER_SLAB`] corners or vertices.
    ///
    /// # Errors
    /// A memory error for the offsets or the corners, or [`Error::interrupted`].
    pub(crate) fn new(faces: &[[i64; 3]], vertex_count: usize, stop: &Stop) -> Result<Self, Error> {
        let mut offsets = try_filled(vertex_count + 1, 0u32, "the vertex-to-face offsets")?;
        for slab in faces.as_flattened().chunks(CORNERS_PER_SLAB) {
            stop.check()?;
            for &v in slab {
                offsets[index(v) + 1] += 1;
            }
        }
        let mut total = 0;
        for slab in offsets[1..].chunks_mut(CORNERS_PER_SLAB) {
            stop.check()?;
            for offset in slab {
                total += *offset;
                *offset = total;
            }
        }
        let mut next = try_collect(
            offsets[..vertex_count].iter().copied(),
            "the vertex-to-face cursors",
        )?;
        let mut corners = Zeroed::new(faces.len() * 3, "the vertex-to-face corners")?;
        let dst: &mut [u32] = &mut corners;
        for (s, slab) in faces.as_flattened().chunks(CORNERS_PER_SLAB).enumerate() {
            stop.check()?;
            let first = s * CORNERS_PER_SLAB;
            for (k, &v) in (first as u32..).zip(slab) {
                let slot = &mut next[index(v)];
                dst[*slot as usize] = k;
                *slot += 1;
            }
        }
        Ok(Self { offsets, corners })
    }

    /// The corners (`3·face + corner`) of vertex `v`, in face order.
    #[inline]
    pub(crate) fn corners_of(&self, v: usize) -> &[u32] {
        &self.corners[self.offsets[v] as usize..self.offsets[v + 1] as usize]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_vertex_lists_its_corners_in_face_order() {
        let faces = [[0, 1, 2], [2, 1, 3], [3, 0, 2]];
        let adjacency = Adjacency::new(&faces, 5, &Stop::new()).unwrap();
        assert_eq!(adjacency.corners_of(0), [0, 7]);
        assert_eq!(adjacency.corners_of(1), [1, 4]);
        assert_eq!(adjacency.corners_of(2), [2, 3, 8]);
        assert_eq!(adjacency.corners_of(3), [5, 6]);
        assert!(adjacency.corners_of(4).is_empty());
    }
}
