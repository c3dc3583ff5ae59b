//! The one error type of the core: every failure names the argument, what was expected and what
//! was found, so the Python binding can pass the message through unchanged.

use std::fmt;

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
    /// The full message, e.g. `"spot_cutoff of light 3 must be in [0, 90] or 180, got 95"`.
    pub message: String,
}

impl Error {
    /// A value error with the given message.
    pub fn value(message: impl Into<String>) -> Self {
        Self {
            kind: ErrorKind::Value,
            message: message.into(),
        }
    }

    /// An index error with the given message.
    pub fn index(message: impl Into<String>) -> Self {
        Self {
            kind: ErrorKind::Index,
            message: message.into(),
        }
    }

    /// A memory error with the given message, e.g. `"cannot allocate 96 bytes for the ids"`.
    pub fn memory(message: impl Into<String>) -> Self {
        Self {
            kind: ErrorKind::Memory,
            message: message.into(),
        }
    }

    /// The error of a call whose [`crate::Stop`] was requested: message `"interrupted"`.
    pub fn interrupted() -> Self {
        Self {
            kind: ErrorKind::Interrupted,
            message: "interrupted".to_owned(),
        }
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.message)
    }
}

impl std::error::Error for Error {}
