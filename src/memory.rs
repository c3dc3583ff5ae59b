//! Memory: fallible allocation of every buffer whose size grows with the input
//! ([`alloc`]: a request the allocator cannot meet is an error, never an abort) and zeroed
//! scratch pages for the mesh passes ([`pages`]) and large results kept for the next call
//! ([`recycle`]).
//!
//! Uses only [`crate::errors`].

pub mod alloc;
pub mod pages;
// The binding's result buffers: nothing in the core allocates them.
#[cfg_attr(not(feature = "python"), allow(dead_code))]
pub mod recycle;
pub mod uninit;
