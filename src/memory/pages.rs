//! Zeroed scratch buffers for the mesh passes, on huge pages when they are large.
//!
//! Fresh memory costs one page fault per 4 KiB page on first write, about 1.3 µs each here: for
//! the tens of MB the normals of a 10^6-face mesh need, as much as the arithmetic. Up to 32 MiB,
//! glibc's heap hands back blocks freed by the previous call, already faulted in (measured: a
//! fresh 2 MiB-page mapping per call, the other choice, was three times slower every other call
//! after a trimesh run had freed its memory). Larger blocks glibc maps afresh on every call, so
//! those are anonymous mappings advised to use 2 MiB pages, a quarter of the cost.

use std::marker::PhantomData;
use std::ops::{Deref, DerefMut};

use bytemuck::Pod;

use crate::errors::error::Error;
use crate::memory::alloc::try_filled;

/// Buffers at least this large are mapped: glibc's largest mmap threshold on 64-bit systems.
const MAPPED_BYTES: usize = 32 << 20;

/// A zero-filled slice of `T`, owned.
pub(crate) enum Zeroed<T> {
    /// Small buffers come from the allocator.
    Heap(Vec<T>),
    /// Large ones are an anonymous mapping of `len` elements.
    Mapped(memmap2::MmapMut, usize, PhantomData<T>),
}

impl<T: Pod> Zeroed<T> {
    /// `len` zeros, for `what`.
    ///
    /// # Errors
    /// A memory error naming `what` when neither a mapping nor the heap can hold them.
    pub(crate) fn new(len: usize, what: &str) -> Result<Self, Error> {
        if let Some(bytes) = len.checked_mul(size_of::<T>()) {
            if bytes >= MAPPED_BYTES {
                if let Ok(map) = memmap2::MmapMut::map_anon(bytes) {
                    // Only a hint: without transparent huge pages the mapping still works.
                    #[cfg(target_os = "linux")]
                    let _ = map.advise(memmap2::Advice::HugePage);
                    return Ok(Self::Mapped(map, len, PhantomData));
                }
            }
        }
        // A failed mapping may still fit the heap; an overflowing size fails here too.
        Ok(Self::Heap(try_filled(len, T::zeroed(), what)?))
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
            let mut buffer = Zeroed::<u32>::new(len, "the test").unwrap();
            assert_eq!(buffer.len(), len);
            assert!(matches!(buffer, Zeroed::Mapped(..)) == (len > 10));
            assert!(buffer.iter().all(|&x| x == 0));
            for (i, x) in buffer.iter_mut().enumerate() {
                *x = i as u32;
            }
            assert!(buffer.iter().enumerate().all(|(i, &x)| x == i as u32));
        }
    }

    #[test]
    fn absurd_sizes_are_memory_errors() {
        // 2^60 bytes: beyond any address space, so both the mapping and the heap refuse.
        for len in [1 << 57, usize::MAX / 4] {
            let err = Zeroed::<u64>::new(len, "the test").err().unwrap();
            assert_eq!(
                err.kind,
                crate::errors::error::ErrorKind::Memory,
                "{}",
                err.message
            );
        }
    }
}
