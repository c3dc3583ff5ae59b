//! Zeroed scratch buffers for the mesh passes, on huge pages where the OS offers them.
//!
//! A fresh buffer costs one page fault per 4 KiB page on first write, about 1 µs each on
//! Linux: for the tens of MB the normals of a 10^6-face mesh need, more than the arithmetic.
//! Large buffers are therefore anonymous mappings advised to use 2 MiB pages, as numpy does for
//! its own arrays of 4 MiB and more.

use std::marker::PhantomData;
use std::ops::{Deref, DerefMut};

use bytemuck::Pod;

/// Buffers at least this large are mapped (numpy's threshold for huge pages).
const MAPPED_BYTES: usize = 4 << 20;

/// A zero-filled slice of `T`, owned.
pub(crate) enum Zeroed<T> {
    /// Small buffers come from the allocator.
    Heap(Vec<T>),
    /// Large ones are an anonymous mapping of `len` elements.
    Mapped(memmap2::MmapMut, usize, PhantomData<T>),
}

impl<T: Pod> Zeroed<T> {
    /// `len` zeros.
    pub(crate) fn new(len: usize) -> Self {
        let bytes = len * size_of::<T>();
        if bytes >= MAPPED_BYTES {
            if let Ok(map) = memmap2::MmapMut::map_anon(bytes) {
                // Only a hint: without transparent huge pages the mapping still works.
                #[cfg(target_os = "linux")]
                let _ = map.advise(memmap2::Advice::HugePage);
                return Self::Mapped(map, len, PhantomData);
            }
        }
        Self::Heap(vec![T::zeroed(); len])
    }
}

impl<T: Pod> Deref for Zeroed<T> {
    type Target = [T];
    fn deref(&self) -> &[T] {
        match self {
            Self::Heap(v) => v,
            Self::Mapped(map, len, _) => &bytemuck::cast_slice(map)[..*len],
        }
    }
}

impl<T: Pod> DerefMut for Zeroed<T> {
    fn deref_mut(&mut self) -> &mut [T] {
        match self {
            Self::Heap(v) => v,
            Self::Mapped(map, len, _) => &mut bytemuck::cast_slice_mut(map)[..*len],
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn small_and_large_buffers_start_at_zero_and_hold_what_is_written() {
        for len in [0, 10, MAPPED_BYTES / 4 + 1] {
            let mut buffer = Zeroed::<u32>::new(len);
            assert_eq!(buffer.len(), len);
            assert!(matches!(buffer, Zeroed::Mapped(..)) == (len > 10));
            assert!(buffer.iter().all(|&x| x == 0));
            for (i, x) in buffer.iter_mut().enumerate() {
                *x = i as u32;
            }
            assert!(buffer.iter().enumerate().all(|(i, &x)| x == i as u32));
        }
    }
}
