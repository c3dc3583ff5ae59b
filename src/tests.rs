//! The crate's tests that cross modules, in one place with one shared [`support`] module: each
//! file checks one property of the whole core (every unit's own tests sit beside its code).
//!
//! [`layers`]: no layer uses a layer above it; [`cycles`]: no file imports a file that imports
//! it back; [`specialisation`]: the specialised kernels against the general one, bit for bit,
//! on every instruction set; [`shape`]: the shapes' kernels likewise; [`range`]: finite input
//! gives finite output in [0, 1]; [`normal_range`]: normals of any length; [`property`]:
//! properties of `shade` over generated scenes; [`robust`]: every entry point stops when asked,
//! and sizes beyond memory are errors, not aborts; [`machine_code`]: the SIMD kernels call no
//! function but their cold paths; [`world`]: what every world model does alike; [`lean`]: float32's
//! lean arithmetic within the fast mode's bound.

mod cycles;
mod layers;
mod lean;
mod machine_code;
mod normal_range;
mod property;
mod range;
mod robust;
mod shape;
mod specialisation;
pub(crate) mod support;
mod world;
