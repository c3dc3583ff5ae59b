//! `shade`: the lighting equation over arrays of vertices, in parallel.
//!
//! The vertices are split into tasks of [`ROWS_PER_TASK`] rows spread over rayon's threads; each
//! task runs the kernel ([`crate::lighting::kernel`]) block by block with the widest instruction
//! set the CPU has ([`crate::simd::dispatch`]). Every row is computed independently of every other,
//! so the result does not depend on the number of threads or the instruction set.

use std::marker::PhantomData;
use std::mem::MaybeUninit;

use rayon::prelude::*;

use crate::errors::error::Error;
use crate::errors::stop::Stop;
use crate::gl::scene::{Scene, ValidScene};
use crate::lighting::kernel::{Block, Kernel, SideColors};
use crate::lighting::plan::Plan;
use crate::lighting::prepare::{Accuracy, ColorClamp, Prepared, ShadeOptions};
use crate::lighting::shape::{on_shape, OnShape, Shape};
use crate::memory::alloc::try_with_capacity;
use crate::memory::pages::Zeroed;
use crate::numbers::real::{block_lanes, BlockLanes, Real};
use crate::simd::dispatch::{Isa, LaneWork};
use crate::simd::float::Float;
use crate::simd::lanes::{InstructionSet, Lanes, MAX_LANES, V3};

use crate::gl::vertex_colors::VertexColors;

/// Rows per parallel task: enough work to amortise rayon's scheduling for one light, few enough
/// that a 10^4-row call still spreads over every core.
const ROWS_PER_TASK: usize = 8192;

/// Values per slab of Exact mode's serial widening and narrowing, between polls of the stop:
/// well under a millisecond each.
const WIDEN_SLAB: usize = 1 << 16;

/// `convert` of every item, slab by slab, polling `stop` between slabs.
///
/// # Errors
/// A memory error naming `what`, or [`Error::interrupted`].
fn widened<X: Copy, Y>(
    items: &[X],
    convert: impl Fn(&X) -> Y,
    stop: &Stop,
    what: &str,
) -> Result<Vec<Y>, Error> {
    let mut wide = try_with_capacity(items.len(), what)?;
    for slab in items.chunks(WIDEN_SLAB) {
        stop.check()?;
        wide.extend(slab.iter().map(&convert));
    }
    Ok(wide)
}

/// The arrays of one call.
#[derive(Clone, Copy)]
pub(crate) struct Inputs<'a, T> {
    pub positions: &'a [[T; 3]],
    pub normals: &'a [[T; 3]],
    pub colors: Option<VertexColors<'a, T>>,
}

/// What a task runs on each block: the lighting equation ([`Kernel`]), or the streaming floor
/// (`crate::lab::stream`), which reads and writes the same and computes nothing.
pub(crate) trait BlockShader<T: Real>: Sync {
    /// Positions are read.
    fn reads_positions(&self) -> bool;
    /// Sides written: 1, or 2 with two-sided lighting.
    fn sides(&self) -> usize;
    /// The colours of one side of a block; must be `#[inline(always)]`.
    fn block<V: Lanes<T = T>>(&self, input: &Block<V>, side: usize) -> SideColors<V>;
    /// Runs `work` (a task of this shader) with the registers of `isa`.
    fn dispatch<W: LaneWork>(isa: Isa, work: W) {
        isa.run(work);
    }
}

impl<T: Real, S: Shape> BlockShader<T> for Kernel<'_, T, S> {
    #[inline(always)]
    fn reads_positions(&self) -> bool {
        Kernel::reads_positions(self)
    }
    #[inline(always)]
    fn sides(&self) -> usize {
        Kernel::sides(self)
    }
    #[inline(always)]
    fn block<V: Lanes<T = T>>(&self, input: &Block<V>, side: usize) -> SideColors<V> {
        Kernel::block(self, input, side)
    }
    fn dispatch<W: LaneWork>(isa: Isa, work: W) {
        S::run(isa, work);
    }
}

/// One task: rows `first..first + rows` of every output plane.
struct Task<'a, 'b, T: Real, S: BlockShader<T>> {
    kernel: &'a S,
    inputs: Inputs<'a, T>,
    first: usize,
    planes: &'b mut [&'a mut [MaybeUninit<T>]],
}

/// The `V::N` rows of `a` from `first` as lanes; a short block of `valid` rows repeats its
/// first row in the missing lanes (finite, and never written back).
#[inline(always)]
fn rows<V: Lanes>(a: &[[V::T; 3]], first: usize, valid: usize) -> V3<V> {
    if valid == V::N {
        return V::load_rows3(&a[first..first + V::N]);
    }
    let mut padded = [[V::T::ZERO; 3]; MAX_LANES];
    for (j, row) in padded.iter_mut().enumerate().take(V::N) {
        *row = a[first + if j < valid { j } else { 0 }];
    }
    V::load_rows3(&padded[..V::N])
}

/// The RGBA colours of rows `first..first + valid` as lanes (a missing alpha is 1), padded
/// like [`rows`].
#[inline(always)]
fn color_rows<V: Lanes>(c: VertexColors<'_, V::T>, first: usize, valid: usize) -> [V; 4] {
    let mut planes = [[V::T::ONE; MAX_LANES]; 4];
    for j in 0..V::N {
        let row = first + if j < valid { j } else { 0 };
        for (k, plane) in planes.iter_mut().enumerate().take(c.width) {
            plane[j] = c.data[row * c.width + k];
        }
    }
    [
        V::load(&planes[0]),
        V::load(&planes[1]),
        V::load(&planes[2]),
        V::load(&planes[3]),
    ]
}

/// Writes `rgba` to rows `start..start + valid` of `plane` (RGBA rows, flat).
#[inline(always)]
fn store<V: Lanes>(rgba: [V; 4], plane: &mut [MaybeUninit<V::T>], start: usize, valid: usize) {
    let rows = plane[4 * start..4 * (start + valid)].as_chunks_mut::<4>().0;
    if valid == V::N {
        V::store_rows4(rgba, rows);
    } else {
        let mut full = [[MaybeUninit::uninit(); 4]; MAX_LANES];
        V::store_rows4(rgba, &mut full[..V::N]);
        rows.copy_from_slice(&full[..valid]);
    }
}

impl<T: Real, S: BlockShader<T>> Task<'_, '_, T, S> {
    /// Loads the block of rows starting at row `first` (absolute); a short last block of
    /// `valid` rows is padded (see [`rows`]).
    #[inline(always)]
    fn load<V: Lanes<T = T>>(&self, first: usize, valid: usize) -> Block<V> {
        let inputs = self.inputs;
        Block {
            positions: if self.kernel.reads_positions() {
                rows(inputs.positions, first, valid)
            } else {
                V3::zero()
            },
            normals: rows(inputs.normals, first, valid),
            // Not `Option::map`: a closure might stay out of line, without the target features.
            #[allow(clippy::manual_map)]
            colors: match inputs.colors {
                Some(c) => Some(color_rows(c, first, valid)),
                None => None,
            },
        }
    }
}

impl<T: Real, S: BlockShader<T>> LaneWork for Task<'_, '_, T, S> {
    #[inline(always)]
    fn run<I: InstructionSet>(self) {
        self.blocks::<BlockLanes<T, I>>();
    }
}

impl<T: Real, S: BlockShader<T>> Task<'_, '_, T, S> {
    /// Shades every row of the task, `V::N` at a time.
    #[inline(always)]
    fn blocks<V: Lanes<T = T>>(self) {
        let count = self.planes[0].len() / 4;
        let sides = self.kernel.sides();
        let per_side = self.planes.len() / sides;
        let mut start = 0;
        while start < count {
            let valid = V::N.min(count - start);
            let block = self.load::<V>(self.first + start, valid);
            // Planes come side by side: the front's colours, then the back's. A loop over a
            // count the shape may fix, so one side compiles to straight code.
            for side in 0..sides {
                let colours = self.kernel.block(&block, side);
                let planes = &mut self.planes[side * per_side..(side + 1) * per_side];
                for (plane, rgba) in planes.iter_mut().zip(colours) {
                    store(rgba, plane, start, valid);
                }
            }
            start += valid;
        }
    }
}

/// Checks the lengths of one call's arrays: one normal (and colour row, of width 3 or 4) per
/// position, and `planes` planes of RGBA rows in `out`.
///
/// # Errors
/// A value error naming the array, the length expected and the length found.
pub(crate) fn check_rows<T: Real>(
    positions: &[[T; 3]],
    normals: &[[T; 3]],
    colors: Option<VertexColors<'_, T>>,
    planes: usize,
    out_len: usize,
) -> Result<(), Error> {
    let n = positions.len();
    if normals.len() != n {
        return Err(Error::value(format!(
            "normals must have one row per position ({n}), got {} rows",
            normals.len()
        )));
    }
    if let Some(c) = colors {
        if !(c.width == 3 || c.width == 4) || c.data.len() != n * c.width {
            return Err(Error::value(format!(
                "colors must have shape ({n}, 3) or ({n}, 4), got {} values of width {}",
                c.data.len(),
                c.width
            )));
        }
    }
    if out_len != planes * n * 4 {
        return Err(Error::value(format!(
            "out must hold {planes} x {n} x 4 values, got {out_len}"
        )));
    }
    Ok(())
}

/// Checks the arguments of [`shade`] that do not depend on the scene.
fn check_arrays<T: Real>(
    scene: &Scene,
    positions: &[[T; 3]],
    normals: &[[T; 3]],
    colors: Option<VertexColors<'_, T>>,
    options: &ShadeOptions,
    out_len: usize,
) -> Result<(), Error> {
    match (colors.is_some(), options.color_material.is_some()) {
        (true, false) => return Err(Error::value("colors need a color_material mode, got None")),
        (false, true) => return Err(Error::value("color_material needs colors, got None")),
        _ => {}
    }
    check_rows(positions, normals, colors, scene.output_count(), out_len)
}

/// Lights `positions` with `normals` (both (n, 3), model coordinates) under `scene`, writing
/// every colour the scene computes into `out`.
///
/// `out` holds `scene.output_count()` planes of n RGBA rows, one after the other, in the order
/// of [`Scene::output_names`], each clamped to [0, 1]. A vertex whose normal or colour is not
/// finite, or whose position is not finite when the scene reads positions (a positional
/// light or a local viewer), gets NaN in every plane; every other output is finite. Vertices
/// are shaded in parallel; the result is identical for any number of threads and on any CPU.
///
/// `options.accuracy` picks the arithmetic: [`Accuracy::Fast`] computes in `T`,
/// [`Accuracy::Exact`] in `f64` whatever `T` is.
///
/// `stop` is polled before every task of `ROWS_PER_TASK` (8192) rows; once it is requested the
/// remaining tasks are skipped and `out` is left partly written.
///
/// # Errors
/// A value error for an invalid modelview or options, mismatched lengths, colours without
/// `color_material` (or the reverse), or an `out` of the wrong length; a memory error when a
/// scratch buffer cannot be allocated; [`Error::interrupted`] when `stop` was requested before
/// the call finished.
pub fn shade<T: Real>(
    scene: &ValidScene,
    positions: &[[T; 3]],
    normals: &[[T; 3]],
    colors: Option<VertexColors<'_, T>>,
    options: &ShadeOptions,
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

/// `out` as memory that may be written, not read: [`shade_uninit`] writes every element of
/// it and never a `MaybeUninit::uninit()`, so the initialised `out` stays initialised.
#[allow(unsafe_code)]
pub(crate) fn as_uninit<T>(out: &mut [T]) -> &mut [MaybeUninit<T>] {
    // SAFETY: MaybeUninit<T> has the layout of T; the callee only writes initialised values.
    unsafe { std::slice::from_raw_parts_mut(out.as_mut_ptr().cast(), out.len()) }
}

/// [`shade`] into memory that need not be initialised (a fresh numpy array): every element
/// of `out` is written when this returns `Ok`, none is read (on `Err`, some may be unwritten).
///
/// # Errors
/// As [`shade`].
pub fn shade_uninit<T: Real>(
    scene: &ValidScene,
    positions: &[[T; 3]],
    normals: &[[T; 3]],
    colors: Option<VertexColors<'_, T>>,
    options: &ShadeOptions,
    out: &mut [MaybeUninit<T>],
    stop: &Stop,
) -> Result<(), Error> {
    check_arrays(scene, positions, normals, colors, options, out.len())?;
    let widen = options.accuracy == Accuracy::Exact && std::mem::size_of::<T>() < 8;
    if !widen {
        let prepared = Prepared::<T>::new(scene, options)?;
        let plan = Plan::new(&prepared);
        return run(
            &prepared,
            &plan,
            Isa::detect(),
            positions,
            normals,
            colors,
            out,
            stop,
        );
    }
    let prepared = Prepared::<f64>::new(scene, options)?;
    let plan = Plan::new(&prepared);
    let inputs = Inputs {
        positions,
        normals,
        colors,
    };
    in_float64(inputs, plan.positions, out, stop, |inputs, wide, stop| {
        run(
            &prepared,
            &plan,
            Isa::detect(),
            inputs.positions,
            inputs.normals,
            inputs.colors,
            wide,
            stop,
        )
    })
}

/// `compute` over the arrays of `inputs` widened to `f64` (positions only when
/// `read_positions`: unread, they are not copied), its `f64` result rounded once into `out`,
/// saturated at `T::MAX`: the arithmetic of [`Accuracy::Exact`] for `f32` arrays.
///
/// # Errors
/// A memory error for the widened copies, [`Error::interrupted`], or those of `compute`.
pub(crate) fn in_float64<T: Real>(
    inputs: Inputs<'_, T>,
    read_positions: bool,
    out: &mut [MaybeUninit<T>],
    stop: &Stop,
    compute: impl FnOnce(Inputs<'_, f64>, &mut [MaybeUninit<f64>], &Stop) -> Result<(), Error>,
) -> Result<(), Error> {
    let row = |r: &[T; 3]| r.map(T::to_f64);
    let data = match inputs.colors {
        Some(c) => widened(c.data, |x: &T| x.to_f64(), stop, "the colors in float64")?,
        None => Vec::new(),
    };
    let colors = inputs.colors.map(|c| VertexColors {
        data: &data[..],
        width: c.width,
    });
    // Unread unless a light is positional or the viewer local: no copy then.
    let positions = if read_positions {
        widened(inputs.positions, row, stop, "the positions in float64")?
    } else {
        Vec::new()
    };
    let normals = widened(inputs.normals, row, stop, "the normals in float64")?;
    // Zeroed: a large buffer is mapped, not written, before the kernel writes every value.
    let mut result = Zeroed::<f64>::new(out.len(), "the float64 colours")?;
    let wide = Inputs {
        positions: &positions,
        normals: &normals,
        colors,
    };
    compute(wide, as_uninit(&mut result), stop)?;
    // Saturated at T's largest value: a finite f64 beyond f32's range stays finite (NaN stays).
    let max = T::MAX.to_f64();
    for (d, s) in out.chunks_mut(WIDEN_SLAB).zip(result.chunks(WIDEN_SLAB)) {
        stop.check()?;
        for (d, &s) in d.iter_mut().zip(s) {
            d.write(T::from_f64(s.clamp(-max, max)));
        }
    }
    Ok(())
}

/// A lighting model outside GL state whose kernel is built per call: glTF's metallic-roughness
/// model, three.js' `MeshPhongMaterial`. [`shade_widened`] runs it.
pub(crate) trait WidenedModel {
    /// The kernel for arrays of `T`.
    type Kernel<T: Real>: BlockShader<T>;
    /// Prepares the kernel for arrays of `T`.
    ///
    /// # Errors
    /// Those of the model's preparation (an invalid model matrix).
    fn kernel<T: Real>(&self) -> Result<Self::Kernel<T>, Error>;
}

/// Runs `model` over every row of `inputs` into `planes` planes of RGBA rows in `out`, in `f64`
/// arithmetic: `f64` arrays directly, `f32` arrays widened ([`in_float64`]) and the result
/// rounded once, so the models' ill-conditioned corners (powers near the highlight, small
/// denominators) cost no float32 rounding.
///
/// # Errors
/// A value error for mismatched lengths, those of [`WidenedModel::kernel`], a memory error, or
/// [`Error::interrupted`].
pub(crate) fn shade_widened<T: Real, M: WidenedModel>(
    model: &M,
    inputs: Inputs<'_, T>,
    planes: usize,
    out: &mut [MaybeUninit<T>],
    stop: &Stop,
) -> Result<(), Error> {
    check_rows(
        inputs.positions,
        inputs.normals,
        inputs.colors,
        planes,
        out.len(),
    )?;
    if std::mem::size_of::<T>() == 8 {
        let kernel = model.kernel::<T>()?;
        return run_shader(&kernel, Isa::detect(), inputs, out, stop);
    }
    let kernel = model.kernel::<f64>()?;
    in_float64(
        inputs,
        kernel.reads_positions(),
        out,
        stop,
        |wide, dst, stop| run_shader(&kernel, Isa::detect(), wide, dst, stop),
    )
}

/// The line `describe` gives for a [`WidenedModel`] with arrays of `T`: the model's `name`, the
/// arithmetic, the instruction set, the lanes per block and the `plan`.
pub(crate) fn widened_description<T: Real>(name: &str, plan: &dyn std::fmt::Display) -> String {
    let isa = Isa::detect();
    let arrays = if std::mem::size_of::<T>() == 8 {
        ""
    } else {
        " (float32 arrays widened)"
    };
    format!(
        "{name}: float64 arithmetic{arrays}, {}, {} vertices per block; {plan}",
        isa.name(),
        block_lanes::<f64>(isa),
    )
}

/// Runs the kernel of `prepared` and `plan` over every row with instruction set `isa`,
/// skipping the tasks that start after `stop` is requested.
///
/// # Errors
/// A memory error for the task list, or [`Error::interrupted`].
pub(crate) fn run<T: Real>(
    prepared: &Prepared<T>,
    plan: &Plan,
    isa: Isa,
    positions: &[[T; 3]],
    normals: &[[T; 3]],
    colors: Option<VertexColors<'_, T>>,
    out: &mut [MaybeUninit<T>],
    stop: &Stop,
) -> Result<(), Error> {
    let inputs = Inputs {
        positions,
        normals,
        colors,
    };
    run_shaped(prepared, plan, isa, inputs, out, stop)
}

/// [`run`] with the kernel compiled for the call's shape of scene.
fn run_shaped<T: Real>(
    prepared: &Prepared<T>,
    plan: &Plan,
    isa: Isa,
    inputs: Inputs<'_, T>,
    out: &mut [MaybeUninit<T>],
    stop: &Stop,
) -> Result<(), Error> {
    struct Run<'a, 'b, T: Real> {
        prepared: &'a Prepared<T>,
        plan: &'a Plan,
        isa: Isa,
        inputs: Inputs<'a, T>,
        out: &'b mut [MaybeUninit<T>],
        stop: &'a Stop,
    }
    impl<T: Real> OnShape for Run<'_, '_, T> {
        type Output = Result<(), Error>;
        fn call<S: Shape>(self) -> Self::Output {
            let kernel = Kernel::<T, S>::new(self.prepared, self.plan);
            run_shader(&kernel, self.isa, self.inputs, self.out, self.stop)
        }
    }
    let work = Run {
        prepared,
        plan,
        isa,
        inputs,
        out,
        stop,
    };
    on_shape(plan, prepared, isa, work)
}

/// [`run`] with one shape's kernel, or any other [`BlockShader`].
pub(crate) fn run_shader<T: Real, S: BlockShader<T>>(
    kernel: &S,
    isa: Isa,
    inputs: Inputs<'_, T>,
    out: &mut [MaybeUninit<T>],
    stop: &Stop,
) -> Result<(), Error> {
    let n = inputs.normals.len();
    if n == 0 {
        return stop.check();
    }
    // Regroup the planes chunk by chunk, so each task owns the same rows of every plane.
    let (count, planes) = (n.div_ceil(ROWS_PER_TASK), out.len() / (n * 4));
    let mut tasks: Vec<Vec<&mut [MaybeUninit<T>]>> = try_with_capacity(count, "the task list")?;
    for _ in 0..count {
        tasks.push(try_with_capacity(planes, "the task list")?);
    }
    for plane in out.chunks_mut(n * 4) {
        for (task, rows) in tasks.iter_mut().zip(plane.chunks_mut(ROWS_PER_TASK * 4)) {
            task.push(rows);
        }
    }
    let work = |(t, mut planes): (usize, Vec<&mut [MaybeUninit<T>]>)| {
        if stop.is_requested() {
            return;
        }
        let task = Task {
            kernel,
            inputs,
            first: t * ROWS_PER_TASK,
            planes: &mut planes,
        };
        S::dispatch(isa, task);
    };
    if tasks.len() == 1 {
        tasks.into_iter().enumerate().for_each(work);
    } else {
        tasks.into_par_iter().enumerate().for_each(work);
    }
    stop.check()
}

/// The one-line description of what `shade` computes for `scene` and `options` in `T`: the
/// arithmetic, the instruction set and the plan (which terms of which lights are computed).
///
/// # Errors
/// As [`shade`] for invalid options.
pub fn describe<T: Real>(scene: &ValidScene, options: &ShadeOptions) -> Result<String, Error> {
    let isa = Isa::detect();
    let exact = options.accuracy == Accuracy::Exact;
    let (bytes, (shape, lanes, grey_sums), plan) = if exact || std::mem::size_of::<T>() == 8 {
        let prepared = Prepared::<f64>::new(scene, options)?;
        let plan = Plan::new(&prepared);
        (8, shape_of(&plan, &prepared, isa), plan)
    } else {
        let prepared = Prepared::<T>::new(scene, options)?;
        let plan = Plan::new(&prepared);
        (4, shape_of(&plan, &prepared, isa), plan)
    };
    let mode = match options.accuracy {
        Accuracy::Fast => "fast",
        Accuracy::Exact => "exact",
    };
    let range = if options.clamp == ColorClamp::Off {
        "; unclamped (high dynamic range)"
    } else {
        ""
    };
    let grey = if grey_sums && !plan.lights.is_empty() {
        "; grey lights: one channel summed"
    } else {
        ""
    };
    Ok(format!(
        "{mode}: float{} arithmetic, {}, {shape} kernel, {lanes} vertices per block; \
         {plan}{grey}{range}",
        bytes * 8,
        isa.name(),
    ))
}

/// The name of the shape whose kernel runs `plan`, its lanes per block with `isa`, and whether
/// it sums the light sums in one channel ([`Kernel::sums_grey`]).
fn shape_of<T: Real>(plan: &Plan, prepared: &Prepared<T>, isa: Isa) -> (&'static str, usize, bool) {
    struct Name<'p, T>(Isa, &'p Plan, PhantomData<T>);
    impl<T: Real> OnShape for Name<'_, T> {
        type Output = (&'static str, usize, bool);
        fn call<S: Shape>(self) -> Self::Output {
            let grey = Kernel::<T, S>::sums_grey(self.1);
            (S::NAME, block_lanes::<T>(self.0), grey)
        }
    }
    on_shape(plan, prepared, isa, Name::<T>(isa, plan, PhantomData))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gl::light::Light;
    use crate::gl::material::{ColorMaterial, Material};

    fn shade_one<T: Real>(scene: &Scene, p: [T; 3], n: [T; 3], options: &ShadeOptions) -> Vec<T> {
        let mut out = vec![T::ZERO; scene.output_count() * 4];
        let scene = scene.clone().validated().unwrap();
        shade(&scene, &[p], &[n], None, options, &mut out, &Stop::new()).unwrap();
        out
    }

    fn close(a: &[f64], b: &[f64]) -> bool {
        a.len() == b.len() && a.iter().zip(b).all(|(x, y)| (x - y).abs() < 1e-12)
    }

    fn headlight_scene() -> Scene {
        Scene {
            lights: vec![Light::default()],
            ..Scene::default()
        }
    }

    #[test]
    fn without_the_clamp_the_sums_exceed_one_in_both_types() {
        // Three headlights facing the normal: 0.04 + 3 · 0.8 in each channel, alpha 1.
        let scene = Scene {
            lights: vec![Light::default(); 3],
            ..Scene::default()
        };
        let off = ShadeOptions {
            clamp: ColorClamp::Off,
            ..ShadeOptions::default()
        };
        let wide = shade_one::<f64>(&scene, [0.0; 3], [0.0, 0.0, 1.0], &off);
        assert!(close(&wide, &[2.44, 2.44, 2.44, 1.0]), "{wide:?}");
        let narrow = shade_one::<f32>(&scene, [0.0; 3], [0.0, 0.0, 1.0], &off);
        assert!(narrow
            .iter()
            .zip(&wide)
            .all(|(x, y)| (f64::from(*x) - y).abs() < 1e-6));
        let clamped = shade_one::<f64>(&scene, [0.0; 3], [0.0, 0.0, 1.0], &ShadeOptions::default());
        assert_eq!(clamped, [1.0; 4]);
    }

    #[test]
    fn headlight_on_a_facing_normal() {
        // e + a·a_cs + a·a_cl + 1·d·d_cl = 0 + 0.04 + 0 + 0.8; specular colour is 0.
        let out = shade_one::<f64>(
            &headlight_scene(),
            [0.0; 3],
            [0.0, 0.0, 1.0],
            &ShadeOptions::default(),
        );
        assert!(close(&out, &[0.84, 0.84, 0.84, 1.0]), "{out:?}");
        let out32 = shade_one::<f32>(
            &headlight_scene(),
            [0.0; 3],
            [0.0, 0.0, 1.0],
            &ShadeOptions::default(),
        );
        assert!((out32[0] - 0.84).abs() < 1e-6);
    }

    #[test]
    fn back_facing_keeps_ambient_only_and_two_side_lights_the_back() {
        let mut scene = headlight_scene();
        scene.material.specular = [1.0, 1.0, 1.0, 1.0];
        let out = shade_one::<f64>(&scene, [0.0; 3], [0.0, 0.0, -1.0], &ShadeOptions::default());
        assert!(close(&out, &[0.04, 0.04, 0.04, 1.0]), "{out:?}");
        scene.two_side = true;
        scene.back_material.diffuse = [0.5, 0.25, 0.0, 0.5];
        let out = shade_one::<f64>(&scene, [0.0; 3], [0.0, 0.0, -1.0], &ShadeOptions::default());
        // Back: 0.04 + 1·back diffuse + 0^0 specular (shininess 0) with back specular (0, 0, 0).
        assert!(
            close(&out, &[0.04, 0.04, 0.04, 1.0, 0.54, 0.29, 0.04, 0.5]),
            "{out:?}"
        );
    }

    #[test]
    fn shininess_zero_gives_the_full_specular_when_lit() {
        let mut scene = headlight_scene();
        scene.material.specular = [0.1, 0.2, 0.3, 1.0];
        scene.separate_specular = true;
        let n = [0.0, 0.6, 0.8];
        let out = shade_one::<f64>(&scene, [0.0; 3], n, &ShadeOptions::default());
        assert!(close(&out[4..], &[0.1, 0.2, 0.3, 1.0]), "{out:?}");
    }

    #[test]
    fn attenuation_follows_eq_2_4() {
        let light = Light {
            position: [0.0, 0.0, 2.0, 1.0],
            constant_attenuation: 1.0,
            linear_attenuation: 0.5,
            quadratic_attenuation: 0.25,
            ..Light::default()
        };
        let scene = Scene {
            lights: vec![light],
            global_ambient: [0.0; 4],
            ..Scene::default()
        };
        let out = shade_one::<f64>(&scene, [0.0; 3], [0.0, 0.0, 1.0], &ShadeOptions::default());
        assert!((out[0] - 0.8 / (1.0 + 1.0 + 1.0)).abs() < 1e-15);
    }

    #[test]
    fn light_at_the_vertex_is_finite() {
        let light = Light {
            position: [1.0, 2.0, 3.0, 1.0],
            constant_attenuation: 0.0,
            quadratic_attenuation: 1.0,
            ambient: [0.0, 0.5, -1.0, 1.0],
            ..Light::default()
        };
        let scene = Scene {
            lights: vec![light],
            global_ambient: [0.0; 4],
            ..Scene::default()
        };
        let out = shade_one::<f32>(
            &scene,
            [1.0, 2.0, 3.0],
            [0.0, 0.0, 1.0],
            &ShadeOptions::default(),
        );
        assert_eq!(out, vec![0.0, 1.0, 0.0, 1.0]);
    }

    fn shade_rows(scene: &Scene, positions: &[[f32; 3]], normals: &[[f32; 3]]) -> Vec<f32> {
        let mut out = vec![0.0_f32; positions.len() * 4];
        let options = ShadeOptions::default();
        let scene = scene.clone().validated().unwrap();
        shade(
            &scene,
            positions,
            normals,
            None,
            &options,
            &mut out,
            &Stop::new(),
        )
        .unwrap();
        out
    }

    #[test]
    fn nan_stays_in_its_row() {
        let mut scene = headlight_scene();
        let positions = [[0.0_f32; 3], [f32::NAN, 0.0, 0.0], [0.0; 3], [0.0; 3]];
        let normals = [
            [0.0, 0.0, 1.0],
            [0.0, 0.0, 1.0],
            [f32::INFINITY, 0.0, 1.0],
            [0.0; 3],
        ];
        let out = shade_rows(&scene, &positions, &normals);
        // A directional light under an infinite viewer never reads positions.
        assert!(out[..8].iter().chain(&out[12..]).all(|x| x.is_finite()));
        assert!(out[8..12].iter().all(|x| x.is_nan()));
        scene.viewer = [0.0, 0.0, 0.0, 1.0];
        let out = shade_rows(&scene, &positions, &normals);
        assert!(out[4..12].iter().all(|x| x.is_nan()));
        assert!(out[..4].iter().chain(&out[12..]).all(|x| x.is_finite()));
    }

    #[test]
    fn color_material_replaces_the_tracked_parameters() {
        let scene = headlight_scene().validated().unwrap();
        let options = ShadeOptions {
            color_material: Some(ColorMaterial::parse("diffuse", "front_and_back").unwrap()),
            ..ShadeOptions::default()
        };
        let colors = VertexColors {
            data: &[0.5, 0.25, 1.0, 0.5][..],
            width: 4,
        };
        let mut out = vec![0.0; 4];
        shade::<f64>(
            &scene,
            &[[0.0; 3]],
            &[[0.0, 0.0, 1.0]],
            Some(colors),
            &options,
            &mut out,
            &Stop::new(),
        )
        .unwrap();
        assert!(close(&out, &[0.54, 0.29, 1.0, 0.5]), "{out:?}");
    }

    #[test]
    fn mismatched_lengths_are_rejected() {
        let mut out = vec![0.0; 8];
        let err = shade::<f64>(
            &headlight_scene().validated().unwrap(),
            &[[0.0; 3]; 2],
            &[[0.0; 3]],
            None,
            &ShadeOptions::default(),
            &mut out,
            &Stop::new(),
        )
        .unwrap_err();
        assert!(err.message.starts_with("normals"));
    }

    /// One light of diffuse 0.9 and 999 of 2.9e-8 (each below half an ulp of 0.9), facing a
    /// unit normal: the sum in `f32`, in this order and reversed.
    fn bright_and_dim(reversed: bool, count: usize, accuracy: Accuracy) -> (f32, f64) {
        let light = |d: f64| Light {
            position: [0.0, 0.0, 1.0, 0.0],
            diffuse: [d, d, d, 1.0],
            specular: [0.0; 4],
            ..Light::default()
        };
        let mut lights: Vec<Light> = std::iter::once(0.9)
            .chain(std::iter::repeat_n(2.9e-8, count - 1))
            .map(light)
            .collect();
        if reversed {
            lights.reverse();
        }
        let scene = Scene {
            lights,
            material: Material {
                ambient: [0.0; 4],
                diffuse: [1.0; 4],
                ..Material::default()
            },
            global_ambient: [0.0; 4],
            ..Scene::default()
        };
        let options = ShadeOptions {
            accuracy,
            ..ShadeOptions::default()
        };
        let out = shade_one::<f32>(&scene, [0.0; 3], [0.0, 0.0, 1.0], &options);
        // The terms as the kernel forms them (colours rounded to f32), summed exactly enough.
        let exact = f64::from(0.9_f32) + (count - 1) as f64 * f64::from(2.9e-8_f32);
        (out[0], exact)
    }

    #[test]
    fn light_sums_do_not_depend_on_the_order_of_the_lights() {
        // "fast" sums blocks of 8 lights in f32 and adds the blocks' sums with their rounding
        // errors kept apart: within SUM_BLOCK ulp of Σ|terms| in any order (a plain f32 sum
        // from the bright light on loses all 999 dim terms, 28 ulp). "exact" sums in f64:
        // within 1 ulp of the correctly rounded total.
        for count in [9, 1000] {
            for (accuracy, ulps) in [(Accuracy::Fast, f32::SUM_BLOCK), (Accuracy::Exact, 1)] {
                let (forward, exact) = bright_and_dim(false, count, accuracy);
                let (backward, _) = bright_and_dim(true, count, accuracy);
                let rounded = exact as f32;
                let ulp = f32::from_bits(rounded.to_bits() + 1) - rounded;
                for got in [forward, backward] {
                    assert!(
                        (got - rounded).abs() <= ulps as f32 * ulp,
                        "{count}, {accuracy:?}: {got} vs {rounded}"
                    );
                }
            }
        }
    }

    #[test]
    fn results_do_not_depend_on_the_thread_count() {
        let scene = Scene {
            lights: (0..5)
                .map(|i| Light {
                    position: [f64::from(i), 1.0, 2.0, 1.0],
                    spot_cutoff: 60.0,
                    spot_exponent: 3.0,
                    linear_attenuation: 0.3,
                    ..Light::default()
                })
                .collect(),
            material: Material {
                specular: [1.0; 4],
                shininess: 40.0,
                ..Material::default()
            },
            viewer: [0.0, 0.0, 0.0, 1.0],
            ..Scene::default()
        }
        .validated()
        .unwrap();
        let n = 5000;
        let positions: Vec<[f32; 3]> = (0..n)
            .map(|i| {
                let t = i as f32 * 0.01;
                [t.sin(), t.cos(), -1.0 - t.sin() * t]
            })
            .collect();
        let normals: Vec<[f32; 3]> = (0..n)
            .map(|i| {
                let t = i as f32 * 0.37;
                [t.cos(), t.sin(), 0.5]
            })
            .collect();
        let run = |threads: usize| {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap();
            let mut out = vec![0.0_f32; n * 4];
            pool.install(|| {
                shade(
                    &scene,
                    &positions,
                    &normals,
                    None,
                    &ShadeOptions::default(),
                    &mut out,
                    &Stop::new(),
                )
                .unwrap();
            });
            out.iter().map(|x| x.to_bits()).collect::<Vec<_>>()
        };
        assert_eq!(run(1), run(3));
    }
}
