//! The entry points of the metallic-roughness model: `shade` and `describe`, as for the GL
//! equation ([`crate::lighting::shade`]), with the same threads, blocks and instruction sets.

use std::mem::MaybeUninit;

use glam::DMat4;

use crate::errors::error::Error;
use crate::errors::stop::Stop;
use crate::gl::vertex_colors::VertexColors;
use crate::gltf::scene::ValidScene;
use crate::lighting::metallic_roughness::kernel::Kernel;
use crate::lighting::prepare::ColorClamp;
use crate::lighting::shade::{as_uninit, shade_widened, widened_description, Inputs, WidenedModel};
use crate::numbers::real::Real;

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
}

/// Lights `positions` with `normals` (both (n, 3), world coordinates unless `options.model`)
/// under `scene`, writing n linear RGBA rows into `out` (4n values), computed in `f64` (`f32`
/// arrays are widened, and the result rounded once).
///
/// Normals are normalised; a vertex colour (RGB or RGBA) multiplies the result, alpha
/// included, as pyrender's `color_multiplier` does. A vertex whose normal or colour is not
/// finite, or whose position is not finite when some light shines, gets NaN; every other
/// output is finite. Rows are independent: the result is the same for any number of threads
/// and on any CPU. `stop` is polled as by [`crate::lighting::shade::shade`].
///
/// # Errors
/// A value error for mismatched lengths or an invalid `model`; a memory error for the task
/// list; [`Error::interrupted`] when `stop` was requested before the call finished.
pub fn shade<T: Real>(
    scene: &ValidScene,
    positions: &[[T; 3]],
    normals: &[[T; 3]],
    colors: Option<VertexColors<'_, T>>,
    options: &Options,
    out: &mut [T],
    stop: &Stop,
) -> Result<(), Error> {
    shade_uninit(
        scene,
        positions,
        normals,
        colors,
        options,
        as_uninit(out),
        stop,
    )
}

/// [`shade`] into memory that need not be initialised: every element of `out` is written
/// when this returns `Ok`.
///
/// # Errors
/// As [`shade`].
pub fn shade_uninit<T: Real>(
    scene: &ValidScene,
    positions: &[[T; 3]],
    normals: &[[T; 3]],
    colors: Option<VertexColors<'_, T>>,
    options: &Options,
    out: &mut [MaybeUninit<T>],
    stop: &Stop,
) -> Result<(), Error> {
    let inputs = Inputs {
        positions,
        normals,
        colors,
    };
    // float32 arithmetic errs up to 3.3e-5 where the model is ill-conditioned (|n·v| near its
    // 0.001 floor, the highlight of roughness 0.04): f32 arrays are computed in f64.
    shade_widened(&Model { scene, options }, inputs, 1, out, stop)
}

/// One call's scene and options, whose kernel [`shade_widened`] builds.
struct Model<'a> {
    scene: &'a ValidScene,
    options: &'a Options,
}

impl WidenedModel for Model<'_> {
    type Kernel<T: Real> = Kernel<T>;
    fn kernel<T: Real>(&self) -> Result<Kernel<T>, Error> {
        Kernel::new(self.scene, self.options)
    }
}

/// One line saying what [`shade`] computes for `scene` with arrays of `T`: the arithmetic, the
/// instruction set and the plan.
///
/// # Errors
/// As [`shade`] for an invalid `model`.
pub fn describe<T: Real>(scene: &ValidScene, options: &Options) -> Result<String, Error> {
    let kernel = Kernel::<f64>::new(scene, options)?;
    Ok(widened_description::<T>(
        "metallic-roughness (pyrender's mesh.frag)",
        kernel.plan(),
    ))
}
