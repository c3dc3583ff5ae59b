//! The options of a GL call besides the scene: the modelview, GL's enables, the accuracy.

use glam::DMat4;

use crate::gl::material::ColorMaterial;
use crate::lighting::accuracy::Accuracy;
use crate::lighting::clamp::ColorClamp;

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
