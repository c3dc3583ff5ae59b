//! The lab's native part, built with the `lab` feature (the Python binding turns it on): the
//! streaming floor that `python -m glshade bench shade` measures each scene against
//! ([`stream`]), and the lean bound of one directional light ([`lean`]). Nothing in the core
//! uses them.
//!
//! Uses [`crate::lighting`] and the layers below it.

pub mod lean;
pub mod stream;
