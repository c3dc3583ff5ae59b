//! The one dispatch on the model of a scene: a native scene of any model ([`AnyScene`]), the
//! options of a `shade` call as the binding takes them ([`Settings`]) turned into each model's
//! own ([`BindingModel`]), and the work done with whichever model a scene is ([`OnModel`]).
//! `shade`, `describe` and `render` all go through [`AnyScene::with`].

use numpy::PyReadonlyArray2;
use pyo3::prelude::*;

use super::arrays::matrix;
use super::gltf::GltfScene;
use super::runtime::to_pyerr;
use super::scene::Scene;
use super::threejs::ThreejsScene;
use crate::gl::material::ColorMaterial;
use crate::gl::scene::ValidScene as GlState;
use crate::gltf::scene::ValidScene as GltfState;
use crate::lighting::accuracy::Accuracy;
use crate::lighting::clamp::ColorClamp;
use crate::lighting::fixed_function::options::ShadeOptions;
use crate::lighting::model::Model;
use crate::lighting::world::WorldModel;
use crate::render::shader::RenderModel;
use crate::threejs::scene::ValidScene as ThreejsState;

/// The native scene of any model: `glshade.Scene`'s, `glshade.gltf.Scene`'s or
/// `glshade.threejs.Scene`'s.
#[derive(FromPyObject)]
pub enum AnyScene<'py> {
    /// GL state.
    Gl(Bound<'py, Scene>),
    /// glTF state (metallic-roughness).
    Gltf(Bound<'py, GltfScene>),
    /// three.js state (`MeshPhongMaterial`).
    Threejs(Bound<'py, ThreejsScene>),
}

/// Work done with the state of one model.
pub trait OnModel {
    /// What the work returns.
    type Output;
    /// Does the work with `scene`.
    fn call<M: BindingModel>(self, scene: &M) -> Self::Output;
}

impl AnyScene<'_> {
    /// Does `work` with the state of this scene's model.
    pub fn with<W: OnModel>(&self, work: W) -> W::Output {
        match self {
            Self::Gl(scene) => work.call(&scene.get().state),
            Self::Gltf(scene) => work.call(&scene.get().state),
            Self::Threejs(scene) => work.call(&scene.get().state),
        }
    }

    /// The state of this scene if its model is `M`.
    pub fn state<M: BindingModel>(&self) -> Option<&M> {
        M::of(self)
    }
}

/// A model's state, told apart among the scenes of every model.
pub trait OfScene: Sized {
    /// The state of `scene` if it is of this model.
    fn of<'a>(scene: &'a AnyScene<'_>) -> Option<&'a Self>;
}

/// `OfScene` for the state held by one variant of [`AnyScene`].
macro_rules! of_scene {
    ($($state:ty => $variant:ident),*) => {$(
        impl OfScene for $state {
            fn of<'a>(scene: &'a AnyScene<'_>) -> Option<&'a Self> {
                match scene {
                    AnyScene::$variant(s) => Some(&s.get().state),
                    _ => None,
                }
            }
        }
    )*};
}

of_scene!(GlState => Gl, GltfState => Gltf, ThreejsState => Threejs);

/// The options of a `shade` or `describe` call: what every model takes (`accuracy`, `clamp`),
/// and GL's own, which the package passes for a `glshade.Scene` only.
#[allow(clippy::struct_excessive_bools)] // GL's enables, as the call takes them
pub struct Settings<'py> {
    /// `"fast"` or `"exact"`: the arrays' type, or `f64` whatever it is.
    pub accuracy: &'py str,
    /// The clamp of the colours to [0, 1].
    pub clamp: bool,
    /// GL's modelview.
    pub modelview: Option<PyReadonlyArray2<'py, f64>>,
    /// `GL_NORMALIZE`.
    pub normalize: bool,
    /// `GL_RESCALE_NORMAL`.
    pub rescale_normal: bool,
    /// `GL_COLOR_MATERIAL`'s mode.
    pub color_material: Option<&'py str>,
    /// `GL_COLOR_MATERIAL`'s face.
    pub color_material_face: &'py str,
    /// GL's parameter ranges.
    pub strict: bool,
}

/// A model the binding calls: its options from the call's settings.
pub trait BindingModel: RenderModel + OfScene {
    /// The model's options for a `shade` call with `settings`.
    ///
    /// # Errors
    /// A `ValueError` for an unknown name or a bad matrix.
    fn options(settings: &Settings<'_>) -> PyResult<Self::Options>;
}

/// The accuracy and the clamp, which every model takes (the accuracy's name checked).
fn common(settings: &Settings<'_>) -> PyResult<(Accuracy, ColorClamp)> {
    let accuracy = Accuracy::parse(settings.accuracy).map_err(to_pyerr)?;
    Ok((accuracy, ColorClamp::from(settings.clamp)))
}

impl BindingModel for GlState {
    fn options(settings: &Settings<'_>) -> PyResult<ShadeOptions> {
        let (accuracy, clamp) = common(settings)?;
        let modelview = settings.modelview.as_ref();
        let color_material = settings
            .color_material
            .map(|mode| ColorMaterial::parse(mode, settings.color_material_face))
            .transpose()
            .map_err(to_pyerr)?;
        Ok(ShadeOptions {
            modelview: modelview.map(|m| matrix(m, "modelview")).transpose()?,
            normalize: settings.normalize,
            rescale_normal: settings.rescale_normal,
            color_material,
            accuracy,
            strict: settings.strict,
            clamp,
        })
    }
}

/// A world model called on arrays in world coordinates (the render alone gives a model matrix).
impl<W> BindingModel for W
where
    W: WorldModel + RenderModel + OfScene + Model<Options = <W as WorldModel>::Options>,
{
    fn options(settings: &Settings<'_>) -> PyResult<<W as WorldModel>::Options> {
        let (accuracy, clamp) = common(settings)?;
        Ok(W::options(clamp, accuracy))
    }
}
