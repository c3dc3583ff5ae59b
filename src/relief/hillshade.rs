//! matplotlib's `LightSource.hillshade` and `shade_normals`: normals (−∂z/∂x, −∂z/∂y, 1),
//! normalised, from `numpy.gradient`'s differences (central inside, one-sided at the edges),
//! their dot product with the light's direction, and the contrast stretch of the whole image
//! to [0, 1].

use rayon::prelude::*;

use crate::errors::error::Error;
use crate::errors::stop::Stop;
use crate::memory::alloc::try_par_collect;

/// Rows per parallel task of the grid.
const ROWS_PER_TASK: usize = 64;

/// Values per parallel task of the flat passes.
const PER_TASK: usize = 1 << 16;

/// matplotlib's least intensity range that is stretched to [0, 1].
const LEAST_RANGE: f64 = 1e-6;

/// `numpy.gradient`'s derivative along one axis at index `i` of `n` values `at(j)`, spacing `h`
/// (`edge_order=1`): (f[i+1] − f[i−1])/(2h) inside, one-sided differences at the ends.
#[inline]
fn derivative(at: impl Fn(usize) -> f64, i: usize, n: usize, h: f64) -> f64 {
    if i == 0 {
        (at(1) - at(0)) / h
    } else if i == n - 1 {
        (at(n - 1) - at(n - 2)) / h
    } else {
        (at(i + 1) - at(i - 1)) / (2.0 * h)
    }
}

/// The unit normal at row `r`, column `c` of an elevation grid of `rows` × `cols` values `z`
/// (already scaled by the vertical exaggeration), row 0 at the top (as images and `imshow`
/// have it, so y grows downwards: matplotlib's `dy = −dy`), spacings `dx` (columns) and `dy`.
#[inline]
fn normal_at(
    z: &[f64],
    rows: usize,
    cols: usize,
    r: usize,
    c: usize,
    dx: f64,
    dy: f64,
) -> [f64; 3] {
    let e_dx = derivative(|j| z[r * cols + j], c, cols, dx);
    let e_dy = derivative(|i| z[i * cols + c], r, rows, -dy);
    let n = [-e_dx, -e_dy, 1.0];
    // matplotlib's _vector_magnitude: the squares summed in order, then the root.
    let length = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
    n.map(|x| x / length)
}

/// The dot product of two 3-vectors, summed in order (numpy's `dot` of a (…, 3) array).
#[inline]
fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// `hillshade`: the intensity of every point of an elevation grid of `rows` × `cols` (row 0 at
/// the top), heights times `vert_exag`, spacings `dx` (columns) and `dy` (rows), lit from the
/// unit `direction`, stretched as by [`intensity`], into `out`.
///
/// # Errors
/// A value error for a grid with fewer than 2 rows or columns (numpy's gradient needs two),
/// lengths that do not match, a memory error for the scaled heights, or
/// [`Error::interrupted`].
#[allow(clippy::too_many_arguments)]
pub fn hillshade(
    elevation: &[f64],
    rows: usize,
    cols: usize,
    vert_exag: f64,
    dx: f64,
    dy: f64,
    direction: [f64; 3],
    fraction: f64,
    out: &mut [f64],
    stop: &Stop,
) -> Result<(), Error> {
    if rows < 2 || cols < 2 {
        return Err(Error::value(format!(
            "elevation must have at least 2 rows and 2 columns (numpy.gradient's differences), \
             got {rows} x {cols}"
        )));
    }
    if elevation.len() != rows * cols || out.len() != rows * cols {
        return Err(Error::value(format!(
            "elevation and out must hold {rows} x {cols} values, got {} and {}",
            elevation.len(),
            out.len()
        )));
    }
    // numpy scales the whole grid first: `vert_exag * elevation`, rounded once per value.
    let z: Vec<f64> = try_par_collect(
        elevation.par_iter().map(|&e| vert_exag * e),
        "the scaled heights",
    )?;
    out.par_chunks_mut(ROWS_PER_TASK * cols)
        .enumerate()
        .for_each(|(t, dst)| {
            if stop.is_requested() {
                return;
            }
            for (k, d) in dst.iter_mut().enumerate() {
                let (r, c) = (t * ROWS_PER_TASK + k / cols, k % cols);
                *d = dot(normal_at(&z, rows, cols, r, c, dx, dy), direction);
            }
        });
    stop.check()?;
    stretch(out, fraction);
    Ok(())
}

/// `shade_normals`: the dot product of each normal with the unit `direction` towards the light,
/// stretched over the whole image as matplotlib stretches it: (`fraction`·i − min i)/(max i −
/// min i) where the range exceeds 1e-6 and no intensity is NaN (else `fraction`·i), then
/// clipped to [0, 1], NaN kept.
///
/// # Errors
/// A value error for lengths that do not match, or [`Error::interrupted`].
pub fn intensity(
    normals: &[[f64; 3]],
    direction: [f64; 3],
    fraction: f64,
    out: &mut [f64],
    stop: &Stop,
) -> Result<(), Error> {
    if out.len() != normals.len() {
        return Err(Error::value(format!(
            "out must hold {} values, got {}",
            normals.len(),
            out.len()
        )));
    }
    out.par_chunks_mut(PER_TASK)
        .zip(normals.par_chunks(PER_TASK))
        .for_each(|(dst, src)| {
            if stop.is_requested() {
                return;
            }
            for (d, &n) in dst.iter_mut().zip(src) {
                *d = dot(n, direction);
            }
        });
    stop.check()?;
    stretch(out, fraction);
    Ok(())
}

/// matplotlib's contrast stretch of intensities `i`, in place: (f·i − min i)/(max i − min i)
/// where the range of i exceeds 1e-6, then clipped to [0, 1]. A NaN intensity makes the
/// minimum and maximum NaN, so nothing is stretched (numpy's `min` and `max` propagate NaN)
/// and NaN stays NaN.
fn stretch(values: &mut [f64], fraction: f64) {
    let (low, high) = if values.par_iter().any(|x| x.is_nan()) {
        (f64::NAN, f64::NAN)
    } else {
        values
            .par_iter()
            .fold(
                || (f64::INFINITY, f64::NEG_INFINITY),
                |(lo, hi), &x| (lo.min(x), hi.max(x)),
            )
            .reduce(
                || (f64::INFINITY, f64::NEG_INFINITY),
                |a, b| (a.0.min(b.0), a.1.max(b.1)),
            )
    };
    let stretched = high - low > LEAST_RANGE;
    values.par_chunks_mut(PER_TASK).for_each(|dst| {
        for d in dst {
            let mut x = *d * fraction;
            if stretched {
                x = (x - low) / (high - low);
            }
            *d = if x.is_nan() { x } else { x.clamp(0.0, 1.0) };
        }
    });
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_plane_tilted_towards_the_light_is_uniform_and_unstretched() {
        // z = x: every normal is (−1, 0, 1)/√2, the range 0, nothing stretched.
        let (rows, cols) = (3, 4);
        let elevation: Vec<f64> = (0..rows * cols).map(|k| (k % cols) as f64).collect();
        let s = std::f64::consts::FRAC_1_SQRT_2;
        let n = normal_at(&elevation, rows, cols, 1, 2, 1.0, 1.0);
        assert!((n[0] + s).abs() < 1e-15 && n[1] == 0.0);
        let mut i = vec![0.0; rows * cols];
        let light = [-1.0, 0.0, 0.0];
        hillshade(
            &elevation,
            rows,
            cols,
            1.0,
            1.0,
            1.0,
            light,
            1.0,
            &mut i,
            &Stop::new(),
        )
        .unwrap();
        assert!(i.iter().all(|&x| (x - s).abs() < 1e-15));
    }

    #[test]
    fn a_single_row_is_refused() {
        let mut out = vec![0.0; 4];
        let light = [0.0, 0.0, 1.0];
        let err = hillshade(
            &[0.0; 4],
            1,
            4,
            1.0,
            1.0,
            1.0,
            light,
            1.0,
            &mut out,
            &Stop::new(),
        )
        .unwrap_err();
        assert!(err.message.contains("at least 2 rows"), "{}", err.message);
    }
}
