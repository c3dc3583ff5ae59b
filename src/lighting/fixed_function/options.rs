//! The options of a GL call besides the scene: the modelview, GL's enables, the accuracy.

use glam::DMat4;

use crate::errors::error::Error;
use crate::gl::material::ColorMaterial;
use crate::lighting::clamp::ColorClamp;

/// The arithmetic a `shade` call computes in.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Accuracy {
    /// The input's precision: `f32` for `f32` input, `f64` for `f64` (the default).
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
}

/// The per-vertex options of a `shade` call (everything `glEnable` and `glColorMaterial` set
/// that is not part of the [`Scene`](crate::gl::scene::Scene)).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ShadeOptions {
    /// The modelview M: positions become M·p, normals (M⁻¹)ᵀ·n; `None` is the identity.
    pub modelview: Option<DMat4>,
    /// `GL_NORMALIZE`: normals are scaled to unit length after the transform.
    pub normalize: bool,
    /// `GL_RESCALE_NORMAL`: normals are scaled by the modelview's rescale factor.
    pub rescale_normal: bool,
    /// `GL_COLOR_MATERIAL`, used with per-vertex colours.
    pub color_material: Option<ColorMaterial>,
    /// The arithmetic to compute in.
    pub accuracy: Accuracy,
    /// GL's parameter ranges: reject shininess and spot exponents above 128 (GL's
    /// `GL_INVALID_VALUE`), which glshade otherwise accepts.
    pub strict: bool,
    /// Whether the output colours are clamped to [0, 1] (a row with a non-finite input is NaN
    /// either way).
    pub clamp: ColorClamp,
}
