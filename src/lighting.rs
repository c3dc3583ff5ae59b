//! Lighting: the lighting equation over arrays of vertices. A call prepares the scene once in
//! `f64` ([`prepare`]), decides what the scene needs computed ([`plan`]), picks a kernel compiled
//! for the scene's shape ([`shape`]) and runs the one equation ([`kernel`], with the specular and
//! spot powers of [`power`]) block by block over rayon's threads ([`shade`]).
//!
//! The glTF metallic-roughness model ([`metallic_roughness`]) and three.js' `MeshPhongMaterial`
//! ([`mesh_phong`]) run through the same driver.
//!
//! Uses [`crate::threejs`], [`crate::gltf`], [`crate::gl`], [`crate::numbers`], [`crate::simd`], [`crate::memory`] and
//! [`crate::errors`].

pub mod kernel;
pub mod mesh_phong;
pub mod metallic_roughness;
pub mod plan;
pub mod power;
pub mod prepare;
pub mod shade;
pub mod shape;
