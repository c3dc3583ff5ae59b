//! The options of a render besides the scene, the mesh and the camera.

use glam::DMat4;

use crate::errors::error::Error;
use crate::gl::material::ColorMaterial;
use crate::lighting::clamp::ColorClamp;
use crate::normals::adjacency::index;
use crate::numbers::real::Real;
use crate::render::raster::{Cull, Viewport};
use crate::render::transfer::Transfer;

/// Where the lighting equation is evaluated.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Shading {
    /// Once per face, with the face normal.
    Flat,
    /// Once per vertex; colours are interpolated.
    Gouraud,
    /// Once per pixel, with interpolated positions and normals.
    #[default]
    Phong,
}

impl Shading {
    /// Parses `"flat"`, `"gouraud"` or `"phong"`.
    ///
    /// # Errors
    /// A value error naming `shading` for any other string.
    pub fn parse(name: &str) -> Result<Self, Error> {
        match name {
            "flat" => Ok(Self::Flat),
            "gouraud" => Ok(Self::Gouraud),
            "phong" => Ok(Self::Phong),
            _ => Err(Error::value(format!(
                "shading must be 'flat', 'gouraud' or 'phong', got '{name}'"
            ))),
        }
    }
}

/// Where flat shading lights a face: the vertex whose colour GL's flat shading takes
/// (`glProvokingVertex`), or the face's centroid.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Provoking {
    /// The last vertex (`GL_LAST_VERTEX_CONVENTION`, GL's default).
    #[default]
    Last,
    /// The first vertex (`GL_FIRST_VERTEX_CONVENTION`: Direct3D's, Vulkan's and Metal's).
    First,
    /// The mean of the three positions (where PyTorch3D's `flat_shading` and glshade's
    /// `shade_mesh(per="face")` light a face) and of the three vertex colours.
    Centroid,
}

impl Provoking {
    /// Parses `"last"`, `"first"` or `"centroid"`.
    ///
    /// # Errors
    /// A value error naming `provoking_vertex` for any other string.
    pub fn parse(name: &str) -> Result<Self, Error> {
        match name {
            "last" => Ok(Self::Last),
            "first" => Ok(Self::First),
            "centroid" => Ok(Self::Centroid),
            _ => Err(Error::value(format!(
                "provoking_vertex must be 'last', 'first' or 'centroid', got '{name}'"
            ))),
        }
    }

    /// The face's value of a per-vertex quantity `at(vertex)`: one vertex's, or the mean of
    /// the three (in f64, then rounded once).
    pub fn of<T: Real>(self, face: &[i64; 3], at: impl Fn(usize) -> T) -> T {
        match self {
            Self::Last => at(index(face[2])),
            Self::First => at(index(face[0])),
            Self::Centroid => {
                let sum: f64 = face.iter().map(|&i| at(index(i)).to_f64()).sum();
                T::from_f64(sum / 3.0)
            }
        }
    }
}

/// Everything of a render besides the scene, the mesh and the camera.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RenderOptions {
    /// The image size.
    pub viewport: Viewport,
    /// Flat, Gouraud or Phong.
    pub shading: Shading,
    /// Where flat shading lights a face.
    pub provoking: Provoking,
    /// Face culling.
    pub cull: Cull,
    /// Model to world coordinates (affine).
    pub model: DMat4,
    /// The clear colour, RGBA, written as it is (not encoded by `transfer`).
    pub background: [f64; 4],
    /// How the drawn pixels' RGB is encoded (alpha and the depth never are).
    pub transfer: Transfer,
    /// `GL_NORMALIZE`, applied wherever the equation is evaluated (after interpolation for
    /// Phong).
    pub normalize: bool,
    /// `GL_RESCALE_NORMAL`.
    pub rescale_normal: bool,
    /// `GL_COLOR_MATERIAL`, with [`Mesh::colors`](crate::render::mesh::Mesh::colors).
    pub color_material: Option<ColorMaterial>,
    /// Whether the colours (the equation's and the colour sum) are clamped to [0, 1].
    pub clamp: ColorClamp,
}

impl Default for RenderOptions {
    /// A 512 x 512 Phong render with GL's defaults otherwise, and `GL_NORMALIZE` on.
    fn default() -> Self {
        Self {
            viewport: Viewport {
                width: 512,
                height: 512,
            },
            shading: Shading::Phong,
            provoking: Provoking::Last,
            cull: Cull::None,
            model: DMat4::IDENTITY,
            background: [0.0; 4],
            transfer: Transfer::Linear,
            normalize: true,
            rescale_normal: false,
            color_material: None,
            clamp: ColorClamp::On,
        }
    }
}
