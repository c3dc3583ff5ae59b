//! What lights a render: the model of its scene ([`RenderModel`]), placed for the render's
//! camera with the options of its calls ([`Shader`]). The passes ([`crate::render::passes`])
//! ask the shader for colour planes and for a fragment's colour from them, whatever the model.
//!
//! GL's scene is in eye coordinates and takes the render's GL options; the world models'
//! scenes are in world coordinates, their viewer replaced by the render's camera.

use std::borrow::Cow;
use std::mem::MaybeUninit;

use crate::errors::error::Error;
use crate::errors::stop::Stop;
use crate::gl::scene::{Scene as GlScene, ValidScene as GlState};
use crate::gl::vertex_colors::VertexColors;
use crate::gltf::scene::{Scene as GltfScene, ValidScene as GltfState};
use crate::lighting::fixed_function::options::ShadeOptions;
use crate::lighting::mesh_phong::options::Options as MeshPhongOptions;
use crate::lighting::metallic_roughness::options::{ColorRole, Options as GltfOptions};
use crate::lighting::model::{shade_uninit, Model};
use crate::numbers::real::Real;
use crate::render::camera::Camera;
use crate::render::options::RenderOptions;
use crate::threejs::scene::{Scene as ThreejsScene, ValidScene as ThreejsState, Viewer};

/// A model a render can light with: how its scene is placed for the render's camera, and how
/// a fragment's colour comes from the colour planes of a call.
pub trait RenderModel: Model + Clone {
    /// A texture multiplies the fragments (GL's `GL_MODULATE`), rather than a colour where
    /// the model is evaluated (the metallic-roughness model's base colour,
    /// `MeshPhongMaterial`'s diffuse colour).
    const MODULATES: bool = false;

    /// For a model that takes vertex colours or a texture but not both: the model and what it
    /// takes, for the error.
    const COLORS_OR_TEXTURE: Option<&'static str> = None;

    /// The scene as `camera` sees it, and the options of its calls for a render with
    /// `options` (`textured`: the mesh has a texture).
    ///
    /// # Errors
    /// A value error for a scene the placement makes invalid.
    fn placed(
        &self,
        camera: &Camera,
        options: &RenderOptions,
        textured: bool,
    ) -> Result<(Cow<'_, Self>, Self::Options), Error>;

    /// A fragment's RGBA from its colours in output order (`colour(k)` is plane k), its
    /// triangle's facing and the `texel` that multiplies it (with [`RenderModel::MODULATES`]):
    /// the one plane unless the model says otherwise.
    #[inline]
    fn fragment(
        &self,
        front: bool,
        clamp: bool,
        texel: Option<[f64; 4]>,
        colour: impl Fn(usize) -> [f64; 4],
    ) -> [f64; 4] {
        let _ = (front, clamp, texel);
        colour(0)
    }
}

/// The camera's frame in world coordinates (the inverse of the view), where a world model's
/// viewer is.
fn frame(camera: &Camera) -> glam::DMat4 {
    camera.view.inverse()
}

/// GL's equation, in eye coordinates through `camera.view · options.model`.
impl RenderModel for GlState {
    const MODULATES: bool = true;

    fn placed(
        &self,
        camera: &Camera,
        options: &RenderOptions,
        _textured: bool,
    ) -> Result<(Cow<'_, Self>, ShadeOptions), Error> {
        let shade_options = ShadeOptions {
            modelview: Some(camera.view * options.model),
            normalize: options.normalize,
            rescale_normal: options.rescale_normal,
            color_material: options.color_material,
            clamp: options.clamp,
            ..ShadeOptions::default()
        };
        Ok((Cow::Borrowed(self), shade_options))
    }

    /// The side by the triangle's facing, the primary times `texel` (GL's `GL_MODULATE`) and
    /// the colour sum, clamped unless `clamp` is off.
    #[inline]
    fn fragment(
        &self,
        front: bool,
        clamp: bool,
        texel: Option<[f64; 4]>,
        colour: impl Fn(usize) -> [f64; 4],
    ) -> [f64; 4] {
        fragment(self, front, clamp, texel, colour)
    }
}

/// The metallic-roughness model: the scene's camera position replaced by the camera's eye;
/// vertex colours multiply the result (pyrender's `color_multiplier`), a texture's decoded
/// texels the base colour.
impl RenderModel for GltfState {
    const COLORS_OR_TEXTURE: Option<&'static str> =
        Some("the metallic-roughness model takes vertex colours or a base colour texture");

    fn placed(
        &self,
        camera: &Camera,
        options: &RenderOptions,
        textured: bool,
    ) -> Result<(Cow<'_, Self>, GltfOptions), Error> {
        let placed = GltfScene {
            camera_position: frame(camera).w_axis.truncate().to_array(),
            ..(**self).clone()
        };
        let colors = if textured {
            ColorRole::BaseColor
        } else {
            ColorRole::Multiply
        };
        let options = GltfOptions {
            model: Some(options.model),
            clamp: options.clamp,
            colors,
            ..GltfOptions::default()
        };
        Ok((Cow::Owned(placed.validated()?), options))
    }
}

/// `MeshPhongMaterial`: the scene's camera replaced by the render's (its eye, or for an
/// orthographic projection its +z axis, the shader's `isOrthographic` view direction); vertex
/// colours or a texture's texels multiply the material's `color` (three.js' `vertexColors`
/// and `map`); a double-sided material lights a back-facing triangle with its back colour.
impl RenderModel for ThreejsState {
    const COLORS_OR_TEXTURE: Option<&'static str> =
        Some("MeshPhongMaterial takes vertex colours or a colour texture (map)");

    fn placed(
        &self,
        camera: &Camera,
        options: &RenderOptions,
        _textured: bool,
    ) -> Result<(Cow<'_, Self>, MeshPhongOptions), Error> {
        let (eye, p) = (frame(camera), camera.projection);
        // An affine projection (bottom row 0, 0, 0, 1) is orthographic.
        let orthographic = p.x_axis.w == 0.0 && p.y_axis.w == 0.0 && p.z_axis.w == 0.0;
        let viewer = if orthographic && p.w_axis.w != 0.0 {
            Viewer::Direction(eye.z_axis.truncate().to_array())
        } else {
            Viewer::Position(eye.w_axis.truncate().to_array())
        };
        let placed = ThreejsScene {
            viewer,
            ..(**self).clone()
        };
        let options = MeshPhongOptions {
            model: Some(options.model),
            clamp: options.clamp,
            ..MeshPhongOptions::default()
        };
        Ok((Cow::Owned(placed.validated()?), options))
    }

    /// The back plane for a back-facing triangle of a double-sided material.
    #[inline]
    fn fragment(
        &self,
        front: bool,
        _clamp: bool,
        _texel: Option<[f64; 4]>,
        colour: impl Fn(usize) -> [f64; 4],
    ) -> [f64; 4] {
        colour(usize::from(!front && self.outputs() == 2))
    }
}

/// The model of one render, placed for its camera, with the options of its calls.
pub struct Shader<'a, M: RenderModel> {
    scene: Cow<'a, M>,
    options: M::Options,
}

impl<'a, M: RenderModel> Shader<'a, M> {
    /// `scene` placed for `camera` with the options of a render with `options`.
    ///
    /// # Errors
    /// Those of [`RenderModel::placed`].
    pub fn new(
        scene: &'a M,
        camera: &Camera,
        options: &RenderOptions,
        textured: bool,
    ) -> Result<Self, Error> {
        let (scene, shade_options) = scene.placed(camera, options, textured)?;
        Ok(Self {
            scene,
            options: shade_options,
        })
    }

    /// How many colour planes a call writes.
    pub fn outputs(&self) -> usize {
        self.scene.outputs()
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
        let scene: &M = &self.scene;
        shade_uninit(scene, positions, normals, colors, &self.options, out, stop)
    }

    /// A fragment's RGBA ([`RenderModel::fragment`]).
    #[inline]
    pub fn fragment(
        &self,
        front: bool,
        clamp: bool,
        texel: Option<[f64; 4]>,
        colour: impl Fn(usize) -> [f64; 4],
    ) -> [f64; 4] {
        self.scene.fragment(front, clamp, texel, colour)
    }
}

/// The RGBA of a GL fragment from its colours in the scene's output order (`colour(k)` is
/// colour k, front before back, primary before secondary): the back ones for a back-facing
/// triangle of a two-sided scene, the primary times `texel` (GL's texture environment
/// `GL_MODULATE`, which comes before the colour sum), the primary and secondary summed, and
/// clamped unless `clamp` is off (high dynamic range).
#[inline]
fn fragment(
    scene: &GlScene,
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

    #[test]
    fn fragments_pick_the_side_and_sum_the_specular() {
        let colours = [
            [0.5, 0.25, 0.0, 0.5],
            [0.75, 0.0, 0.5, 1.0],
            [0.1, 0.2, 0.3, 0.4],
            [0.0, 0.0, 0.0, 1.0],
        ];
        let mut scene = GlScene::default();
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
