//! OpenGL 2.1's fixed-function lighting equation (§2.14.1) over GL state ([`crate::gl`]). A
//! call prepares the scene once in `f64` ([`prepare`], with the call's [`options`]), decides
//! what the scene needs computed ([`plan`]), picks a kernel compiled for the scene's shape
//! ([`shape`]) and runs the one equation ([`kernel`], with the specular and spot powers of
//! [`power`]) through the shared driver; [`model`] makes GL state a
//! [`Model`](crate::lighting::model::Model).
//!
//! Uses the shared parts of [`crate::lighting`], [`crate::gl`], [`crate::numbers`],
//! [`crate::simd`], [`crate::memory`] and [`crate::errors`].

pub mod kernel;
pub mod model;
pub mod options;
pub mod plan;
pub mod power;
pub mod prepare;
pub mod shape;
