//! The glTF 2.0 metallic-roughness model as pyrender 0.1.45's `shaders/mesh.frag` evaluates it,
//! over blocks of vertices through the same driver as the GL equation
//! ([`crate::lighting::driver::run_shader`]): per call the material and lights are prepared and
//! a plan decides which terms run ([`plan`]); per block the kernel ([`kernel`]) sums each
//! light's BRDF ([`brdf`]: Schlick's Fresnel, Smith-Schlick occlusion, the GGX distribution).
//! [`options`] holds a call's options and [`model`] makes the state a
//! [`WorldModel`](crate::lighting::world::WorldModel).
//!
//! Uses [`crate::gltf`], [`crate::gl`] (vertex colours), [`crate::numbers`], [`crate::simd`],
//! [`crate::memory`] and [`crate::errors`].

pub mod brdf;
pub mod kernel;
pub mod model;
pub mod options;
pub mod plan;
