//! Errors and stopping: the one error type every layer returns ([`error::Error`], naming the
//! argument, what was expected and what was found) and the request to stop a long call early
//! ([`stop::Stop`], polled by every parallel loop).
//!
//! The bottom layer: it uses no other module of the crate.

pub mod error;
pub mod stop;
