//! three.js' `MeshPhongMaterial` as release 111's `meshphong_frag` evaluates it (and the
//! current release, which is r111 with physically correct lights), over blocks of vertices
//! through the same driver as the GL equation ([`crate::lighting::driver::run_shader`]): per
//! call the lights are prepared and a plan decides which terms run ([`plan`]); per block the
//! kernel ([`kernel`]) sums the lights' Lambert and normalised Blinn-Phong terms with Schlick's
//! Fresnel. [`options`] holds a call's options and [`model`] makes the state a
//! [`WorldModel`](crate::lighting::world::WorldModel).
//!
//! Uses [`crate::threejs`], [`crate::gl`] (vertex colours), [`crate::numbers`],
//! [`crate::simd`], [`crate::memory`] and [`crate::errors`].

pub mod kernel;
pub mod model;
pub mod options;
pub mod plan;
