//! The options of a call of `MeshPhongMaterial` besides the scene: the model matrix, the clamp,
//! the accuracy.

use glam::DMat4;

use crate::lighting::accuracy::Accuracy;
use crate::lighting::clamp::ColorClamp;

/// The options of a `MeshPhongMaterial` call.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Options {
    /// Model to world coordinates (three.js' `matrixWorld`): positions become M·p, normals
    /// (M⁻¹)ᵀ·n before they are normalised; `None` is the identity.
    pub model: Option<DMat4>,
    /// Whether the colours are clamped to [0, 1] (a WebGL colour buffer of bytes clamps; a
    /// float render target does not).
    pub clamp: ColorClamp,
    /// The arithmetic: the arrays' type, or `f64` whatever it is.
    pub accuracy: Accuracy,
}
