//! The lab's native part: the streaming floor that `python -m glshade bench shade` measures
//! each scene against ([`stream`], built with the binding, which ships it), and, with the
//! `lab` feature only, the lean bound of one directional light (`lean`, for
//! `benches/lean_directional.py`). Nothing in the core uses them.
//!
//! Uses [`crate::lighting`] and the layers below it.

#[cfg(feature = "lab")]
pub mod lean;
pub mod stream;
