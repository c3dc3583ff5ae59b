//! Per-vertex colours: the colour array `GL_COLOR_MATERIAL` reads (`glColorPointer`), shared by
//! `shade` and the renderer's meshes.

/// Per-vertex colours for `GL_COLOR_MATERIAL`: `data` holds `width` (3 or 4) values per vertex,
/// row after row; a missing alpha is 1.
#[derive(Clone, Copy, Debug)]
pub struct VertexColors<'a, T> {
    /// The colours, C order.
    pub data: &'a [T],
    /// Values per vertex: 3 (RGB) or 4 (RGBA).
    pub width: usize,
}
