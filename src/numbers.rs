//! Numbers: the elementary functions over lanes ([`elementary`]), from IEEE basic operations so
//! every CPU gives the same bits;
//! [`real::Real`], a float tied to its lanes and elementary functions, which every kernel is
//! generic over, with the scale-safe normalisation; and the scaled matrix inverse behind the
//! normal matrix and the camera ([`matrix`]).
//!
//! Uses [`crate::simd`].

pub mod elementary;
pub mod matrix;
pub mod real;
