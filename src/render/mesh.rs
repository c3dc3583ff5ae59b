//! What a render draws: a triangle mesh ([`Mesh`]), and a mesh placed in a frame of several
//! ([`Draw`]); apart from the renderer so that its passes can read them.

use glam::DMat4;

use crate::gl::vertex_colors::VertexColors;
use crate::render::placement::Placement;
use crate::render::raster::Cull;
use crate::render::texture::Texture;

/// A texture and the coordinates that map it onto a mesh.
#[derive(Clone, Copy, Debug)]
pub struct Textured<'a, T> {
    /// Texture coordinates per vertex, (n, 2): (0, 0) the image's lower-left corner.
    pub uv: &'a [[T; 2]],
    /// The image and its sampling.
    pub texture: Texture<'a>,
}

/// A triangle mesh in model coordinates.
#[derive(Clone, Copy, Debug)]
pub struct Mesh<'a, T> {
    /// Vertex positions, (n, 3).
    pub vertices: &'a [[T; 3]],
    /// Vertex indices of each triangle, (m, 3); counter-clockwise is the front.
    pub faces: &'a [[i64; 3]],
    /// Normals: one per vertex for Gouraud and Phong, one per face for flat shading; `None`
    /// computes them (angle-weighted vertex normals, or face normals).
    pub normals: Option<&'a [[T; 3]]>,
    /// Per-vertex colours for `GL_COLOR_MATERIAL`, (n, 3) or (n, 4).
    pub colors: Option<VertexColors<'a, T>>,
    /// A texture: GL's model multiplies each fragment's primary colour by its texel
    /// (`GL_MODULATE`); the metallic-roughness model multiplies its base colour by the
    /// texel decoded from sRGB, where the model is evaluated (glTF's `baseColorTexture`).
    pub textured: Option<Textured<'a, T>>,
}

/// One mesh of a frame of several ([`crate::render::render_draws`]): placed in the world by
/// `model` (where `placement` says), lit by `scene`, its triangles culled by `cull`.
#[derive(Debug)]
pub struct Draw<'a, T, M> {
    /// The mesh, in model coordinates.
    pub mesh: Mesh<'a, T>,
    /// What lights it.
    pub scene: &'a M,
    /// Model to world coordinates, affine (as [`crate::render::options::RenderOptions::model`]).
    pub model: DMat4,
    /// Which facing triangles are discarded.
    pub cull: Cull,
    /// Where `model` applies: in the model's evaluation, or to the vertices first.
    pub placement: Placement,
}

// By hand: a derive would ask `M: Copy`, though a draw holds only a reference to its scene.
impl<T: Copy, M> Clone for Draw<'_, T, M> {
    fn clone(&self) -> Self {
        *self
    }
}

impl<T: Copy, M> Copy for Draw<'_, T, M> {}
