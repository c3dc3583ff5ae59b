//! Lighting: the shading models over arrays of vertices, side by side, and what they share.
//!
//! Every model is a [`model::Model`] (its checked scene and the options of a call) and is
//! called through [`model::shade`] and [`model::describe`]. A call runs its kernel block by
//! block over rayon's threads ([`driver`]), each block loaded into lanes and emitted in the
//! same vocabulary ([`block`]); `f32` arrays computed in `f64` are widened and rounded once
//! ([`widen`]). The models:
//!
//! | model | state | what it is |
//! |---|---|---|
//! | [`fixed_function`] | [`crate::gl`] | OpenGL 2.1's fixed-function lighting equation, in eye coordinates |
//! | [`metallic_roughness`] | [`crate::gltf`] | glTF 2.0's metallic-roughness model as pyrender's shader evaluates it |
//! | [`mesh_phong`] | [`crate::threejs`] | three.js' `MeshPhongMaterial` as release 111's shader evaluates it |
//!
//! The two world models share one path ([`world`]); what only GL has (shape kernels, the
//! modelview, two-sided colour planes) stays in [`fixed_function`]. Shared by several models:
//! the accuracy option ([`accuracy`]), the clamp option ([`clamp`]), the transform of
//! positions and normals ([`transform`]) and per-call values rounded to the kernel's type
//! ([`round`]); three.js' specular power is GL's (`fixed_function::power::cos_pow`).
//!
//! Uses [`crate::threejs`], [`crate::gltf`], [`crate::gl`], [`crate::numbers`],
//! [`crate::simd`], [`crate::memory`] and [`crate::errors`].

pub mod accuracy;
pub mod block;
pub mod clamp;
pub mod driver;
pub mod fixed_function;
pub mod mesh_phong;
pub mod metallic_roughness;
pub mod model;
pub mod round;
pub mod transform;
pub mod widen;
pub mod world;
