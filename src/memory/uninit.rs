//! Memory handed to a kernel to be written, not read.

use std::mem::MaybeUninit;

/// `out` as memory that may be written, not read: the shading entry points write every element
/// of it and never a `MaybeUninit::uninit()`, so the initialised `out` stays initialised.
#[allow(unsafe_code)]
pub fn as_uninit<T>(out: &mut [T]) -> &mut [MaybeUninit<T>] {
    // SAFETY: MaybeUninit<T> has the layout of T; the callee only writes initialised values.
    unsafe { std::slice::from_raw_parts_mut(out.as_mut_ptr().cast(), out.len()) }
}
