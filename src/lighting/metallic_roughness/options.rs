//! The options of a call of the metallic-roughness model besides the scene: the model matrix,
//! the clamp, what vertex colours are and the accuracy.

use glam::DMat4;

use crate::lighting::accuracy::Accuracy;
use crate::lighting::clamp::ColorClamp;

/// What a call's per-vertex colours are.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum ColorRole {
    /// pyrender's `COLOR_0`: they multiply the result, alpha included.
    #[default]
    Multiply,
    /// Linear base colours (a `baseColorTexture`'s decoded texels): they multiply the
    /// material's base colour factor, RGBA, before the model is evaluated.
    BaseColor,
}

/// The options of a metallic-roughness call.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Options {
    /// Model to world coordinates: positions become M·p, normals (M⁻¹)ᵀ·n before they are
    /// normalised; `None` is the identity (the arrays are in world coordinates).
    pub model: Option<DMat4>,
    /// Whether the colours are clamped to [0, 1] (pyrender clamps after its gamma, which
    /// commutes with the clamp).
    pub clamp: ColorClamp,
    /// What the per-vertex colours are.
    pub colors: ColorRole,
    /// The arithmetic: the arrays' type, or `f64` whatever it is.
    pub accuracy: Accuracy,
}
