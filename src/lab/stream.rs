//! The streaming floor of `shade`: the same tasks, reads, row-to-lane transposes, stores and
//! fresh result as a `shade` call, and no lighting, so `bench shade` can say how close each
//! scene comes to the memory traffic it cannot avoid.

use std::mem::MaybeUninit;

use crate::errors::error::Error;
use crate::errors::stop::Stop;
use crate::lighting::block::{Block, SideColors};
use crate::lighting::driver::{run_shader, BlockShader, Inputs};
use crate::numbers::real::Real;
use crate::simd::dispatch::Isa;
use crate::simd::lanes::Lanes;

/// A block shader that copies: RGBA = (n.x, n.y, n.z, p.x + p.y + p.z) with positions, else
/// (n.x, n.y, n.z, 1): every value read reaches the output, so none is skipped.
struct Stream {
    positions: bool,
}

impl<T: Real> BlockShader<T> for Stream {
    #[inline(always)]
    fn reads_positions(&self) -> bool {
        self.positions
    }
    #[inline(always)]
    fn sides(&self) -> usize {
        1
    }
    #[inline(always)]
    fn block<V: Lanes<T = T>>(&self, input: &Block<V>, _side: usize) -> SideColors<V> {
        let (p, n) = (input.positions, input.normals);
        let w = if self.positions {
            p.x + p.y + p.z
        } else {
            V::splat(T::ONE)
        };
        [[n.x, n.y, n.z, w], [V::splat(T::ZERO); 4]]
    }
}

/// Writes the streaming floor of `normals` (and `positions` when `read_positions`) into `out`
/// (n RGBA rows), with the tasks and instruction set of [`crate::lighting::model::shade`].
///
/// # Errors
/// A value error for mismatched lengths, a memory error for the task list, or
/// [`Error::interrupted`].
pub fn stream<T: Real>(
    positions: &[[T; 3]],
    normals: &[[T; 3]],
    read_positions: bool,
    out: &mut [MaybeUninit<T>],
    stop: &Stop,
) -> Result<(), Error> {
    let n = normals.len();
    if (read_positions && positions.len() != n) || out.len() != 4 * n {
        return Err(Error::value(format!(
            "stream needs {n} positions and {} output values, got {} and {}",
            4 * n,
            positions.len(),
            out.len()
        )));
    }
    let inputs = Inputs {
        positions,
        normals,
        colors: None,
    };
    let shader = Stream {
        positions: read_positions,
    };
    run_shader(&shader, Isa::detect(), inputs, out, stop)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::memory::uninit::as_uninit;
    #[test]
    fn the_stream_copies_every_value_it_reads() {
        let n = 100;
        let p: Vec<[f32; 3]> = (0..n).map(|i| [i as f32, 1.0, 2.0]).collect();
        let normals: Vec<[f32; 3]> = (0..n).map(|i| [0.5, i as f32, -1.0]).collect();
        for read in [false, true] {
            let mut out = vec![0.0_f32; 4 * n];
            stream(&p, &normals, read, as_uninit(&mut out), &Stop::new()).unwrap();
            for i in 0..n {
                let w = if read { i as f32 + 3.0 } else { 1.0 };
                assert_eq!(out[4 * i..4 * i + 4], [0.5, i as f32, -1.0, w]);
            }
        }
    }
}
