//! Large result buffers kept for the next call, as the caching allocators of Dr.Jit, PyTorch and
//! JAX keep theirs.
//!
//! A fresh mapping costs a page fault and a zeroed 4 KiB page on first write: for a 64 MB result
//! (4·10⁶ RGBA float32 vertices) about as long as shading them with one light. glibc hands
//! blocks below 32 MiB back to the next request already faulted in ([`super::pages`]), but maps
//! larger ones afresh every time. A [`Recycled`] buffer of at least [`RECYCLED_BYTES`] goes back
//! to a pool of at most [`KEPT`] buffers when it is dropped, and the next request that fits takes
//! it, its pages already in memory. The pool holds at most `KEPT` × [`LARGEST_KEPT`] bytes.

use std::sync::Mutex;

use memmap2::MmapMut;

/// Requests at least this large are served from the pool: glibc's largest mmap threshold on
/// 64-bit systems, below which its heap already reuses freed blocks.
pub const RECYCLED_BYTES: usize = 32 << 20;

/// Buffers the pool holds at most: two, so that a loop that keeps the previous result while it
/// computes the next one (`a = shade(...)` in a loop frees `a` after the call) reuses memory.
pub const KEPT: usize = 2;

/// A buffer larger than this is unmapped when dropped, never kept.
pub const LARGEST_KEPT: usize = 1 << 30;

/// Mappings are whole 2 MiB huge pages, so that a transparent huge page can back every part.
const GRANULE: usize = 2 << 20;

/// The buffers waiting for a request, oldest first.
static POOL: Mutex<Vec<MmapMut>> = Mutex::new(Vec::new());

/// A page-aligned, writable buffer of at least the requested size, returned to the pool when
/// dropped. Its contents are whatever the last user wrote: callers write before they read.
pub struct Recycled {
    map: Option<MmapMut>,
}

impl Recycled {
    /// A buffer of at least `bytes` bytes: the smallest pooled one that holds them and is at
    /// most twice their size (a larger one would keep memory the result never uses), or a
    /// fresh mapping advised to use huge pages. `None` below [`RECYCLED_BYTES`] (the heap's
    /// business) and when the system refuses the mapping (the caller then asks the heap).
    pub fn take(bytes: usize) -> Option<Self> {
        if bytes < RECYCLED_BYTES {
            return None;
        }
        let fits = |m: &MmapMut| m.len() >= bytes && m.len() / 2 <= bytes;
        let pooled = {
            let mut pool = POOL
                .lock()
                .unwrap_or_else(std::sync::PoisonError::into_inner);
            let best = (0..pool.len())
                .filter(|&i| fits(&pool[i]))
                .min_by_key(|&i| pool[i].len());
            best.map(|i| pool.remove(i))
        };
        if let Some(map) = pooled {
            return Some(Self { map: Some(map) });
        }
        let map = MmapMut::map_anon(bytes.checked_next_multiple_of(GRANULE)?).ok()?;
        // Only a hint: without transparent huge pages the mapping still works.
        #[cfg(target_os = "linux")]
        let _ = map.advise(memmap2::Advice::HugePage);
        Some(Self { map: Some(map) })
    }

    /// The first byte, page-aligned.
    pub fn as_mut_ptr(&mut self) -> *mut u8 {
        self.map
            .as_mut()
            .map_or(std::ptr::null_mut(), |m| m.as_mut_ptr())
    }
}

impl Drop for Recycled {
    fn drop(&mut self) {
        let Some(map) = self.map.take() else { return };
        if map.len() > LARGEST_KEPT {
            return;
        }
        let mut pool = POOL
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner);
        pool.push(map);
        if pool.len() > KEPT {
            // The oldest is unmapped outside the lock.
            let oldest = pool.remove(0);
            drop(pool);
            drop(oldest);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The tests share the process-wide pool, so they run as one test in order.
    #[test]
    fn freed_buffers_are_reused_when_they_fit_and_the_pool_stays_small() {
        assert!(
            Recycled::take(RECYCLED_BYTES - 1).is_none(),
            "the heap's size"
        );
        let mut a = Recycled::take(RECYCLED_BYTES + 1).unwrap();
        let len = a.map.as_ref().unwrap().len();
        assert!(len > RECYCLED_BYTES && len.is_multiple_of(GRANULE));
        // Written, then freed and taken again: the same pages (their contents kept).
        let first = a.as_mut_ptr();
        a.map.as_mut().unwrap()[0] = 7;
        drop(a);
        let mut b = Recycled::take(RECYCLED_BYTES + 100).unwrap();
        assert_eq!(b.as_mut_ptr(), first);
        assert_eq!(b.map.as_ref().unwrap()[0], 7);
        // A request of less than half its size does not pin it: a fresh mapping.
        drop(b);
        let small = RECYCLED_BYTES;
        let mut big = Recycled::take(3 * small).unwrap();
        let big_ptr = big.as_mut_ptr();
        drop(big);
        let mut c = Recycled::take(small).unwrap();
        assert_ne!(c.as_mut_ptr(), big_ptr);
        drop(c);
        // Never more than KEPT buffers wait.
        let many: Vec<_> = (0..4)
            .map(|k| Recycled::take(RECYCLED_BYTES + k * GRANULE).unwrap())
            .collect();
        drop(many);
        assert!(POOL.lock().unwrap().len() <= KEPT);
    }
}
