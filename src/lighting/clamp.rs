//! Whether a model's colours are clamped to [0, 1], an option every model takes.

/// `GL_CLAMP_VERTEX_COLOR` (`ARB_color_buffer_float`, GL 3.0): whether the lit colours are
/// clamped to [0, 1]. GL clamps by default; off keeps the sums, for high dynamic range.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum ColorClamp {
    /// Clamped to [0, 1], GL 2.1's only behaviour.
    #[default]
    On,
    /// The sums as they are: values above 1 where the terms add up beyond it.
    Off,
}

impl From<bool> for ColorClamp {
    /// `true` is [`ColorClamp::On`], as the binding's `clamp` flag reads.
    fn from(clamp: bool) -> Self {
        if clamp {
            Self::On
        } else {
            Self::Off
        }
    }
}
