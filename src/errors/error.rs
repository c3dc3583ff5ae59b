//! The one error type of the core: every failure names the argument, what was expected and what
//! was found, so the Python binding can pass the message through unchanged.

use std::borrow::Cow;
use std::fmt::{self, Write};

/// Which Python exception an [`Error`] maps to: a rejected argument (`Value`, `Index`), a
/// buffer the allocator could not provide (`Memory`), or a call its caller stopped
/// (`Interrupted`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ErrorKind {
    /// A value outside its range, a wrong shape or an unknown name (`ValueError`).
    Value,
    /// An index out of range (`IndexError`).
    Index,
    /// A scratch buffer could not be allocated, or its size overflows (`MemoryError`).
    Memory,
    /// The caller's [`crate::Stop`] was requested before the call finished; the binding picks
    /// the exception (e.g. a pending `KeyboardInterrupt`).
    Interrupted,
}

/// A rejected input: the kind of the failure and a message naming the argument, the expected
/// and the found value.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Error {
    /// The class of the failure.
    pub kind: ErrorKind,
    /// The full message, e.g. `"spot_cutoff of light 3 must be in [0, 90] or 180, got 95"`;
    /// static where building it must not allocate.
    pub message: Cow<'static, str>,
}

impl Error {
    /// A value error with the given message.
    pub fn value(message: impl Into<Cow<'static, str>>) -> Self {
        Self {
            kind: ErrorKind::Value,
            message: message.into(),
        }
    }

    /// An index error with the given message.
    pub fn index(message: impl Into<Cow<'static, str>>) -> Self {
        Self {
            kind: ErrorKind::Index,
            message: message.into(),
        }
    }

    /// A memory error with the given message, e.g. `"cannot allocate 96 bytes for the ids"`.
    pub fn memory(message: impl Into<Cow<'static, str>>) -> Self {
        Self {
            kind: ErrorKind::Memory,
            message: message.into(),
        }
    }

    /// The error of a call whose [`crate::Stop`] was requested: message `"interrupted"`.
    pub fn interrupted() -> Self {
        Self {
            kind: ErrorKind::Interrupted,
            message: Cow::Borrowed("interrupted"),
        }
    }

    /// A memory error formatted without aborting when the allocator is exhausted: the message
    /// is written into a buffer reserved fallibly, else it is `fallback` (no allocation).
    pub fn memory_fmt(message: fmt::Arguments<'_>, fallback: &'static str) -> Self {
        let mut text = String::new();
        let written = text.try_reserve_exact(MEMORY_MESSAGE_BYTES).is_ok()
            && Bounded(&mut text).write_fmt(message).is_ok();
        Self::memory(if written {
            Cow::Owned(text)
        } else {
            Cow::Borrowed(fallback)
        })
    }
}

/// Room reserved for a memory error's message; a longer one falls back to the static text.
const MEMORY_MESSAGE_BYTES: usize = 256;

/// A writer into a `String` that fails rather than grow it: growing would allocate.
struct Bounded<'a>(&'a mut String);

impl Write for Bounded<'_> {
    fn write_str(&mut self, s: &str) -> fmt::Result {
        if self.0.len() + s.len() > self.0.capacity() {
            return Err(fmt::Error);
        }
        self.0.push_str(s);
        Ok(())
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.message)
    }
}

impl std::error::Error for Error {}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_memory_message_is_formatted_within_its_reserve_or_falls_back() {
        let short = Error::memory_fmt(format_args!("cannot allocate {} bytes", 96), "fallback");
        assert_eq!(short.message, "cannot allocate 96 bytes");
        assert!(matches!(short.message, Cow::Owned(_)));
        let long = "x".repeat(MEMORY_MESSAGE_BYTES + 1);
        let long = Error::memory_fmt(format_args!("{long}"), "fallback");
        assert_eq!(long.message, "fallback");
        assert_eq!(long.kind, ErrorKind::Memory);
    }
}
