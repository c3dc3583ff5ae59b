//! The lab's native part, built with the `lab` feature (the Python binding turns it on): the
//! streaming floor that `python -m glshade bench shade` measures each scene against
//! ([`stream`]). Nothing in the core uses it.
//!
//! Uses [`crate::lighting`] and the layers below it.

pub mod stream;
