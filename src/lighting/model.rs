//! The one interface of a shading model, and the entry points every model is called through.
//!
//! A model is its scene type (the state folder's checked scene: GL's, glTF's or three.js') and
//! the options of a call besides the arrays. What every model shares is here: how many colour
//! planes a call writes, how much work a vertex is, how a call's rows are lit and the line
//! that says what is computed. What only one model has (GL's shape kernels and its modelview, the
//! world models' model matrix) lives in its own folder, behind
//! [`Model::shade_rows`] and [`Model::describe`].
//!
//! | state (`crate::…`) | model (`crate::lighting::…`) | Python |
//! |---|---|---|
//! | `gl` | `fixed_function` | `glshade.Scene` |
//! | `gltf` | `metallic_roughness` | `glshade.gltf.Scene` |
//! | `threejs` | `mesh_phong` | `glshade.threejs.Scene` |

use std::fmt;
use std::mem::MaybeUninit;

use crate::errors::error::Error;
use crate::errors::stop::Stop;
use crate::gl::vertex_colors::VertexColors;
use crate::lighting::driver::{check_rows, Inputs};
use crate::memory::uninit::as_uninit;
use crate::numbers::real::Real;

/// A shading model: its checked scene, lit over arrays of `f32` or `f64` rows.
pub trait Model: Sync {
    /// The options of a call besides the scene and the arrays.
    type Options: Sync;

    /// The colour planes a call writes per vertex, in the model's output order (GL's front,
    /// back, primary and secondary colours; a double-sided material's front and back; or one).
    fn outputs(&self) -> usize;

    /// The lights the model sums per vertex: a measure of a call's work.
    fn light_count(&self) -> usize;

    /// Lights the rows of `inputs` (their lengths checked) into [`Model::outputs`] planes of
    /// RGBA rows in `out`, writing every element.
    ///
    /// # Errors
    /// A value error for options the model refuses, a memory error, or
    /// [`Error::interrupted`].
    fn shade_rows<T: Real>(
        &self,
        inputs: Inputs<'_, T>,
        options: &Self::Options,
        out: &mut [MaybeUninit<T>],
        stop: &Stop,
    ) -> Result<(), Error>;

    /// The one-line description of what a call with `options` on arrays of `T` computes: the
    /// arithmetic, the instruction set and the plan (which terms of which lights run).
    ///
    /// # Errors
    /// As [`Model::shade_rows`] for invalid options.
    fn describe<T: Real>(&self, options: &Self::Options) -> Result<String, Error>;
}

/// Lights `positions` with `normals` (both (n, 3); GL: model coordinates, eye coordinates
/// without a modelview; the world models: world coordinates unless a model matrix is given)
/// under `scene`, writing every colour the model computes into `out`.
///
/// `out` holds `scene.outputs()` planes of n RGBA rows, one after the other, in the model's
/// output order (GL: [`crate::gl::scene::Scene::output_names`]). `colors` ((n, 3) or (n, 4)
/// rows, flat) are GL's `GL_COLOR_MATERIAL` colours, or the colours that multiply a world
/// model's result or material colour. A vertex whose normal or colour is not finite, or whose
/// position is not finite when the model reads positions, gets NaN in every plane; every
/// other output is finite. Vertices are shaded in parallel; the result is identical for any
/// number of threads and on any CPU.
///
/// `stop` is polled before every task of 8192 rows; once it is requested the remaining tasks
/// are skipped and `out` is left partly written.
///
/// # Errors
/// A value error for mismatched lengths, an `out` of the wrong length or options the model
/// refuses (an invalid matrix; GL: colours without `color_material` or the reverse); a memory
/// error when a scratch buffer cannot be allocated; [`Error::interrupted`] when `stop` was
/// requested before the call finished.
pub fn shade<T: Real, M: Model>(
    scene: &M,
    positions: &[[T; 3]],
    normals: &[[T; 3]],
    colors: Option<VertexColors<'_, T>>,
    options: &M::Options,
    out: &mut [T],
    stop: &Stop,
) -> Result<(), Error> {
    let inputs = Inputs {
        positions,
        normals,
        colors,
    };
    shade_inputs(scene, inputs, options, as_uninit(out), stop)
}

/// [`shade`] into memory that need not be initialised (a fresh numpy array): every element
/// of `out` is written when this returns `Ok`, none is read (on `Err`, some may be unwritten).
///
/// # Errors
/// As [`shade`].
pub fn shade_uninit<T: Real, M: Model>(
    scene: &M,
    positions: &[[T; 3]],
    normals: &[[T; 3]],
    colors: Option<VertexColors<'_, T>>,
    options: &M::Options,
    out: &mut [MaybeUninit<T>],
    stop: &Stop,
) -> Result<(), Error> {
    let inputs = Inputs {
        positions,
        normals,
        colors,
    };
    shade_inputs(scene, inputs, options, out, stop)
}

/// [`shade_uninit`] of one call's [`Inputs`]: the lengths checked, then the model run.
///
/// # Errors
/// As [`shade`].
pub fn shade_inputs<T: Real, M: Model>(
    scene: &M,
    inputs: Inputs<'_, T>,
    options: &M::Options,
    out: &mut [MaybeUninit<T>],
    stop: &Stop,
) -> Result<(), Error> {
    check_rows(
        inputs.positions,
        inputs.normals,
        inputs.colors,
        scene.outputs(),
        out.len(),
    )?;
    scene.shade_rows(inputs, options, out, stop)
}

/// The one-line description of what [`shade`] computes for `scene` and `options` on arrays of
/// `T` (see [`Model::describe`]).
///
/// # Errors
/// As [`shade`] for invalid options.
pub fn describe<T: Real, M: Model>(scene: &M, options: &M::Options) -> Result<String, Error> {
    scene.describe::<T>(options)
}

/// The start of every plan's line: what a call reads, "positions and normals" (and
/// `per_vertex`, what is formed from them) or "normals only".
///
/// # Errors
/// Those of the formatter.
pub fn write_reads(f: &mut fmt::Formatter<'_>, positions: bool, per_vertex: &str) -> fmt::Result {
    if positions {
        write!(f, "reads positions and normals{per_vertex}")
    } else {
        write!(f, "reads normals only")
    }
}
