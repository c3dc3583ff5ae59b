//! Stopping a long call early: the caller (e.g. the binding, on Ctrl-C) requests a [`Stop`] from
//! any thread, and the call's tasks poll it between slabs of work, each well under 50 ms.

use std::sync::atomic::{AtomicBool, Ordering};

use crate::errors::error::Error;

/// A request to end a long computation early, shared between its caller and its threads.
///
/// Pass the same `Stop` to a call and to whatever may end it; once requested it stays requested,
/// and every call given it returns [`crate::ErrorKind::Interrupted`] (use a fresh one per call).
#[derive(Debug, Default)]
pub struct Stop(AtomicBool);

impl Stop {
    /// A stop not requested yet.
    pub const fn new() -> Self {
        Self(AtomicBool::new(false))
    }

    /// Asks every call polling this stop to end early; callable from any thread.
    pub fn request(&self) {
        self.0.store(true, Ordering::Release);
    }

    /// Whether [`Stop::request`] has been called.
    pub fn is_requested(&self) -> bool {
        self.0.load(Ordering::Relaxed)
    }

    /// `Err(Error::interrupted())` once requested: the poll between tasks, one relaxed load.
    ///
    /// # Errors
    /// [`Error::interrupted`] when the stop has been requested.
    #[inline]
    pub(crate) fn check(&self) -> Result<(), Error> {
        if self.is_requested() {
            Err(Error::interrupted())
        } else {
            Ok(())
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_request_is_seen_and_stays() {
        let stop = Stop::new();
        assert!(!stop.is_requested() && stop.check().is_ok());
        stop.request();
        assert!(stop.is_requested());
        assert_eq!(
            stop.check().unwrap_err().kind,
            crate::errors::error::ErrorKind::Interrupted
        );
        assert_eq!(stop.check().unwrap_err().message, "interrupted");
    }
}
