//! Where a draw's model matrix applies ([`Placement`]), and a mesh placed in world coordinates
//! per vertex ([`place`]), as pyrender's and three.js' vertex shaders place it.

use glam::{DMat3, DMat4, DVec3};
use rayon::prelude::*;

use crate::errors::error::Error;
use crate::errors::stop::Stop;
use crate::memory::pages::Zeroed;
use crate::numbers::matrix::scaled_inverse;
use crate::numbers::real::Real;
use crate::simd::float::ldexp;

/// Rows per parallel task of the placement.
const ROWS_PER_TASK: usize = 8192;

/// Where a draw's model matrix applies.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Placement {
    /// In the model's evaluation (`render`'s `model`): positions and normals are interpolated
    /// in model coordinates, and the normal is transformed (and normalised, for a world model
    /// or with `GL_NORMALIZE`) where the equation is evaluated.
    #[default]
    Model,
    /// Per vertex, before rasterising, as a vertex shader does: positions M·p and normals
    /// (M⁻¹)ᵀ·n normalised (a zero normal stays zero), so a pixel's normal is a blend of unit
    /// normals, normalised again where the equation is evaluated (pyrender's and three.js'
    /// shaders). The draw then renders with the identity.
    Vertices,
}

impl Placement {
    /// Parses `"model"` or `"vertices"`.
    ///
    /// # Errors
    /// A value error naming `placement` for any other string.
    pub fn parse(name: &str) -> Result<Self, Error> {
        match name {
            "model" => Ok(Self::Model),
            "vertices" => Ok(Self::Vertices),
            _ => Err(Error::value(format!(
                "placement must be 'model' or 'vertices', got '{name}'"
            ))),
        }
    }
}

/// A mesh's vertices and normals placed by [`place`].
pub(crate) struct Placed<T> {
    /// World positions, one per vertex.
    pub vertices: Zeroed<[T; 3]>,
    /// Unit world normals, one per row of the mesh's normals; `None` where it has none.
    pub normals: Option<Zeroed<[T; 3]>>,
}

/// `rows` mapped by `f` in parallel into a new buffer; `stop` is polled per task.
fn mapped<T: Real>(
    rows: &[[T; 3]],
    what: &str,
    stop: &Stop,
    f: impl Fn(DVec3) -> DVec3 + Sync,
) -> Result<Zeroed<[T; 3]>, Error> {
    let mut out = Zeroed::<[T; 3]>::new(rows.len(), what)?;
    out.par_chunks_mut(ROWS_PER_TASK)
        .zip(rows.par_chunks(ROWS_PER_TASK))
        .for_each(|(out, rows)| {
            if stop.is_requested() {
                return;
            }
            for (o, r) in out.iter_mut().zip(rows) {
                *o = f(DVec3::from_array(r.map(T::to_f64)))
                    .to_array()
                    .map(T::from_f64);
            }
        });
    stop.check()?;
    Ok(out)
}

/// A mesh's `vertices` and `normals` (one per vertex, or per face for flat shading) placed in
/// world coordinates by the affine `model`, in `f64` and rounded to `T`
/// ([`Placement::Vertices`]).
///
/// # Errors
/// A value error for a singular `model`; a memory error for the buffers, or
/// [`Error::interrupted`].
pub(crate) fn place<T: Real>(
    vertices: &[[T; 3]],
    normals: Option<&[[T; 3]]>,
    model: DMat4,
    stop: &Stop,
) -> Result<Placed<T>, Error> {
    let linear = DMat3::from_mat4(model);
    // M = A·diag(2^e), so (M⁻¹)ᵀ = A⁻ᵀ·diag(2^−e): column j of A⁻ᵀ scaled by 2^−e_j, here
    // by 2^(max e − e_j), a uniform multiple that keeps it finite (the normals are normalised).
    let (inverse, e) = scaled_inverse(&linear)
        .ok_or_else(|| Error::value("model must be invertible, got a singular matrix"))?;
    let top = e.iter().copied().max().unwrap_or(0);
    let at = inverse.transpose();
    let normal_matrix = DMat3::from_cols(
        at.x_axis * ldexp(1.0, top - e[0]),
        at.y_axis * ldexp(1.0, top - e[1]),
        at.z_axis * ldexp(1.0, top - e[2]),
    );
    let vertices = mapped(vertices, "the placed vertices", stop, |p| {
        model.transform_point3(p)
    })?;
    let normals = normals
        .map(|n| {
            mapped(n, "the placed normals", stop, |n| {
                (normal_matrix * n).normalize_or_zero()
            })
        })
        .transpose()?;
    Ok(Placed { vertices, normals })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn vertices_are_placed_and_normals_made_unit() {
        let vertices = [[1.0_f64, 2.0, 3.0], [0.0, 0.0, 0.0]];
        let normals = [[0.0_f64, 0.0, 2.0], [0.0, 0.0, 0.0]];
        // A non-uniform scale then a translation: normals through the inverse transpose.
        let model = DMat4::from_translation(DVec3::new(1.0, 0.0, -1.0))
            * DMat4::from_scale(DVec3::new(2.0, 1.0, 0.5));
        let placed = place(&vertices, Some(&normals[..]), model, &Stop::new()).unwrap();
        assert_eq!(&*placed.vertices, &[[3.0, 2.0, 0.5], [1.0, 0.0, -1.0]]);
        let n = placed.normals.unwrap();
        assert_eq!(&*n, &[[0.0, 0.0, 1.0], [0.0, 0.0, 0.0]]);
        let tilted = [[1.0_f64, 0.0, 1.0], [0.0, 0.0, 1.0]];
        let placed_tilted = |model| {
            let placed = place(&vertices, Some(&tilted[..]), model, &Stop::new()).unwrap();
            placed.normals.unwrap()
        };
        let n = placed_tilted(model);
        // (M⁻¹)ᵀ·(1, 0, 1) = (0.5, 0, 2), normalised.
        let expected = DVec3::new(0.5, 0.0, 2.0).normalize();
        assert!((DVec3::from_array(n[0]) - expected).length() < 1e-15);
        // Columns of very different scales: the plain inverse transpose's directions.
        let model = DMat4::from_rotation_y(0.7) * DMat4::from_scale(DVec3::new(1e3, 1.0, 1e-3));
        let n = placed_tilted(model);
        let plain = DMat3::from_mat4(model).inverse().transpose();
        for (placed, given) in n.iter().zip(tilted) {
            let expected = (plain * DVec3::from_array(given)).normalize();
            assert!((DVec3::from_array(*placed) - expected).length() < 1e-15);
        }
    }
}
