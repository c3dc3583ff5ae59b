//! What lights a render's vertices or pixels: GL's lighting equation with its options, the
//! glTF metallic-roughness model or three.js' `MeshPhongMaterial`, both placed in world
//! coordinates. The passes ([`crate::render::passes`])
//! ask it for colour planes and for a fragment's colour from them.

use std::mem::MaybeUninit;

use crate::errors::error::Error;
use crate::errors::stop::Stop;
use crate::gl::scene::ValidScene;
use crate::gl::vertex_colors::VertexColors;
use crate::gltf::scene::ValidScene as GltfScene;
use crate::lighting::mesh_phong::shade::{
    shade_uninit as shade_mesh_phong, sides, Options as MeshPhongOptions,
};
use crate::lighting::metallic_roughness::shade::{shade_uninit as shade_gltf, Options};
use crate::lighting::prepare::{ColorClamp, ShadeOptions};
use crate::lighting::shade::shade_uninit;
use crate::numbers::real::Real;
use crate::threejs::scene::ValidScene as ThreejsScene;

/// The lighting model of one render and what it needs besides the vertices.
pub enum Shader<'a> {
    /// GL's equation, in eye coordinates through the modelview of `options`.
    Gl {
        /// Lights, materials and light model.
        scene: &'a ValidScene,
        /// The `shade` options, with the modelview.
        options: ShadeOptions,
    },
    /// The metallic-roughness model, in world coordinates through the model of `options`, with
    /// the camera's position in the scene.
    MetallicRoughness {
        /// Lights, material, ambient light and the camera's position.
        scene: GltfScene,
        /// The model matrix and the clamp.
        options: Options,
    },
    /// three.js' `MeshPhongMaterial`, in world coordinates through the model of `options`,
    /// with the render's camera in the scene.
    MeshPhong {
        /// Lights, material, camera and light convention.
        scene: ThreejsScene,
        /// The model matrix and the clamp.
        options: MeshPhongOptions,
    },
}

impl Shader<'_> {
    /// How many colour planes a call writes: GL's outputs (front, back, primary, secondary),
    /// a double-sided `MeshPhongMaterial`'s front and back, or one.
    pub fn outputs(&self) -> usize {
        match self {
            Self::Gl { scene, .. } => scene.output_count(),
            Self::MetallicRoughness { .. } => 1,
            Self::MeshPhong { scene, .. } => sides(scene),
        }
    }

    /// Whether colours are clamped to [0, 1].
    pub fn clamp(&self) -> bool {
        let clamp = match self {
            Self::Gl { options, .. } => options.clamp,
            Self::MetallicRoughness { options, .. } => options.clamp,
            Self::MeshPhong { options, .. } => options.clamp,
        };
        clamp == ColorClamp::On
    }

    /// Lights the rows into [`Shader::outputs`] planes of RGBA rows in `out`.
    ///
    /// # Errors
    /// Those of the model's `shade`.
    pub fn shade<T: Real>(
        &self,
        positions: &[[T; 3]],
        normals: &[[T; 3]],
        colors: Option<VertexColors<'_, T>>,
        out: &mut [MaybeUninit<T>],
        stop: &Stop,
    ) -> Result<(), Error> {
        match self {
            Self::Gl { scene, options } => {
                shade_uninit(scene, positions, normals, colors, options, out, stop)
            }
            Self::MetallicRoughness { scene, options } => {
                shade_gltf(scene, positions, normals, colors, options, out, stop)
            }
            Self::MeshPhong { scene, options } => {
                shade_mesh_phong(scene, positions, normals, colors, options, out, stop)
            }
        }
    }

    /// Whether a texture multiplies the fragments (GL's `GL_MODULATE`), rather than a colour
    /// where the model is evaluated (the metallic-roughness model's base colour,
    /// `MeshPhongMaterial`'s diffuse colour).
    pub fn modulates(&self) -> bool {
        matches!(self, Self::Gl { .. })
    }

    /// A fragment's RGBA from its colours in output order (`colour(k)` is plane k): for GL the
    /// side by the triangle's facing, the primary times `texel` (`GL_MODULATE`) and the colour
    /// sum ([`fragment`]); for a double-sided `MeshPhongMaterial` the side by the facing; else
    /// the one plane.
    pub fn fragment(
        &self,
        front: bool,
        clamp: bool,
        texel: Option<[f64; 4]>,
        colour: impl Fn(usize) -> [f64; 4],
    ) -> [f64; 4] {
        match self {
            Self::Gl { scene, .. } => fragment(scene, front, clamp, texel, colour),
            Self::MetallicRoughness { .. } => colour(0),
            Self::MeshPhong { scene, .. } => colour(usize::from(!front && sides(scene) == 2)),
        }
    }
}

/// The RGBA of a GL fragment from its colours in the scene's output order (`colour(k)` is
/// colour k, front before back, primary before secondary): the back ones for a back-facing
/// triangle of a two-sided scene, the primary times `texel` (GL's texture environment
/// `GL_MODULATE`, which comes before the colour sum), the primary and secondary summed, and
/// clamped unless `clamp` is off (high dynamic range).
#[inline]
fn fragment(
    scene: &crate::gl::scene::Scene,
    front: bool,
    clamp: bool,
    texel: Option<[f64; 4]>,
    colour: impl Fn(usize) -> [f64; 4],
) -> [f64; 4] {
    let per_side = 1 + usize::from(scene.separate_specular);
    let base = per_side * usize::from(scene.two_side && !front);
    let mut c = colour(base);
    if let Some(t) = texel {
        c = std::array::from_fn(|k| c[k] * t[k]);
    }
    if scene.separate_specular {
        let s = colour(base + 1);
        for k in 0..3 {
            let sum = c[k] + s[k];
            c[k] = if clamp { sum.clamp(0.0, 1.0) } else { sum };
        }
    }
    c
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gl::scene::Scene;

    #[test]
    fn fragments_pick_the_side_and_sum_the_specular() {
        let colours = [
            [0.5, 0.25, 0.0, 0.5],
            [0.75, 0.0, 0.5, 1.0],
            [0.1, 0.2, 0.3, 0.4],
            [0.0, 0.0, 0.0, 1.0],
        ];
        let mut scene = Scene::default();
        assert_eq!(
            fragment(&scene, false, true, None, |k| colours[k]),
            colours[0]
        );
        scene.two_side = true;
        assert_eq!(
            fragment(&scene, false, true, None, |k| colours[k]),
            colours[1]
        );
        scene.separate_specular = true;
        assert_eq!(
            fragment(&scene, true, true, None, |k| colours[k]),
            [1.0, 0.25, 0.5, 0.5]
        );
        assert_eq!(
            fragment(&scene, false, true, None, |k| colours[k]),
            colours[2]
        );
    }
}
