//! The accuracy option, which every model takes: compute in the arrays' type, or in `f64`.

use crate::errors::error::Error;

/// The arithmetic a `shade` call computes in.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Accuracy {
    /// The input's precision: `f32` for `f32` input, `f64` for `f64` (the default). Each
    /// model states its error bound against [`Accuracy::Exact`].
    #[default]
    Fast,
    /// `f64` throughout, whatever the input; `f32` results are rounded once at the end.
    Exact,
}

impl Accuracy {
    /// Parses `"fast"` or `"exact"`.
    ///
    /// # Errors
    /// A value error naming `accuracy` for any other string.
    pub fn parse(name: &str) -> Result<Self, Error> {
        match name {
            "fast" => Ok(Self::Fast),
            "exact" => Ok(Self::Exact),
            _ => Err(Error::value(format!(
                "accuracy must be 'fast' or 'exact', got '{name}'"
            ))),
        }
    }

    /// The option's name: `"fast"` or `"exact"`.
    pub fn name(self) -> &'static str {
        match self {
            Self::Fast => "fast",
            Self::Exact => "exact",
        }
    }

    /// Whether a call on arrays of `T` computes in `f64` from widened copies: exact
    /// accuracy on `f32` arrays.
    pub fn widens<T>(self) -> bool {
        self == Self::Exact && std::mem::size_of::<T>() < 8
    }
}
