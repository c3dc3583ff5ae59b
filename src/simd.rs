//! SIMD: the scalar types the kernels compute in ([`float::Float`]: `f32` and `f64` behind one
//! trait), the lanes of one register of each instruction set ([`lanes::Lanes`]: SSE2, AVX2,
//! AVX-512 and a portable fallback, every one giving the same bits) and the instruction set
//! chosen at run time ([`dispatch::Isa`]).
//!
//! Uses no other module of the crate: a kernel written over [`lanes::Lanes`] and run through
//! [`dispatch::Isa::run`] is compiled once per instruction set.

pub mod dispatch;
pub mod float;
pub mod lanes;
