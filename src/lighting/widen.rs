//! Float64 widening: a call on `f32` arrays computed in `f64` (the arrays widened, the result
//! rounded once), for every model's `"exact"` accuracy.

use std::mem::MaybeUninit;

use crate::errors::error::Error;
use crate::errors::stop::Stop;
use crate::gl::vertex_colors::VertexColors;
use crate::lighting::driver::Inputs;
use crate::memory::alloc::try_with_capacity;
use crate::memory::pages::Zeroed;
use crate::memory::uninit::as_uninit;
use crate::numbers::real::Real;

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

/// `compute` over the arrays of `inputs` widened to `f64` (positions only when
/// `read_positions`: unread, they are not copied), its `f64` result rounded once into `out`,
/// saturated at `T::MAX`: the arithmetic of every model's `"exact"` accuracy on `f32` arrays.
///
/// # Errors
/// A memory error for the widened copies, [`Error::interrupted`], or those of `compute`.
pub fn in_float64<T: Real>(
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
