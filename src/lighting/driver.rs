//! The parallel driver every model runs through: the rows of a call split into tasks of
//! [`ROWS_PER_TASK`] rows over rayon's threads, each task loading blocks of lanes, running a
//! [`BlockShader`] on them with the widest instruction set the CPU has
//! ([`crate::simd::dispatch`]) and storing RGBA rows. Every row is computed independently of
//! every other, so a result does not depend on the number of threads or the instruction set.

use std::mem::MaybeUninit;

use rayon::prelude::*;

use crate::errors::error::Error;
use crate::errors::stop::Stop;
use crate::gl::vertex_colors::VertexColors;
use crate::lighting::block::{Block, SideColors};
use crate::memory::alloc::try_with_capacity;
use crate::numbers::real::{BlockLanes, Real, LEAN_GROUP};
use crate::simd::dispatch::{Isa, LaneWork};
use crate::simd::float::Float;
use crate::simd::lanes::{InstructionSet, Lanes, MAX_LANES, V3};

/// Rows per parallel task: enough work to amortise rayon's scheduling for one light, few enough
/// that a 10^4-row call still spreads over every core.
const ROWS_PER_TASK: usize = 8192;

/// The arrays of one call.
#[derive(Clone, Copy)]
pub struct Inputs<'a, T> {
    pub positions: &'a [[T; 3]],
    pub normals: &'a [[T; 3]],
    pub colors: Option<VertexColors<'a, T>>,
}

/// What a task runs on each block: a model's kernel, or the streaming floor
/// (`crate::lab::stream`), which reads and writes the same and computes nothing.
pub trait BlockShader<T: Real>: Sync {
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

/// One task: rows `first..first + rows` of every output plane.
struct Task<'a, 'b, T: Real, S: BlockShader<T>> {
    kernel: &'a S,
    inputs: Inputs<'a, T>,
    first: usize,
    planes: &'b mut [&'a mut [MaybeUninit<T>]],
}

/// The row a short block of `valid` rows repeats in its missing lane `j`: the first row of the
/// lane's [`LEAN_GROUP`] (finite, and never written back), so a group of a wide block holds what
/// the same rows hold in a narrow one.
#[inline(always)]
fn padded_row(j: usize, valid: usize) -> usize {
    if j < valid {
        return j;
    }
    let group = j - j % LEAN_GROUP;
    if group < valid {
        group
    } else {
        0
    }
}

/// The `V::N` rows of `a` from `first` as lanes; a short block of `valid` rows is padded
/// ([`padded_row`]).
#[inline(always)]
fn rows<V: Lanes>(a: &[[V::T; 3]], first: usize, valid: usize) -> V3<V> {
    if valid == V::N {
        return V::load_rows3(&a[first..first + V::N]);
    }
    let mut padded = [[V::T::ZERO; 3]; MAX_LANES];
    for (j, row) in padded.iter_mut().enumerate().take(V::N) {
        *row = a[first + padded_row(j, valid)];
    }
    V::load_rows3(&padded[..V::N])
}

/// The RGBA colours of rows `first..first + valid` as lanes (a missing alpha is 1), padded
/// like [`rows`].
#[inline(always)]
fn color_rows<V: Lanes>(c: VertexColors<'_, V::T>, first: usize, valid: usize) -> [V; 4] {
    let mut planes = [[V::T::ONE; MAX_LANES]; 4];
    for j in 0..V::N {
        let row = first + padded_row(j, valid);
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

/// The block of `inputs`' rows starting at row `first` (positions only where `positions`;
/// zeros otherwise); a short last block of `valid` rows is padded (see [`padded_row`]).
#[inline(always)]
pub(crate) fn load_block<V: Lanes>(
    inputs: Inputs<'_, V::T>,
    positions: bool,
    first: usize,
    valid: usize,
) -> Block<V> {
    Block {
        positions: if positions {
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
            let first = self.first + start;
            let block = load_block::<V>(self.inputs, self.kernel.reads_positions(), first, valid);
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
pub fn check_rows<T: Real>(
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

/// Runs `kernel` over every row of `inputs` into the planes of `out` with instruction set
/// `isa`, skipping the tasks that start after `stop` is requested.
///
/// # Errors
/// A memory error for the task list, or [`Error::interrupted`].
pub fn run_shader<T: Real, S: BlockShader<T>>(
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
