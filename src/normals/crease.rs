//! Normals with creases: one normal per face corner, the sum over the vertex's faces whose
//! normal lies within an angle of the corner's own face normal, so smooth surfaces stay smooth
//! and edges sharper than the angle stay sharp. This is three.js's `toCreasedNormals`
//! (examples/jsm/utils/BufferGeometryUtils.js, read at commit 014d454b: a face's normal n_f
//! takes every face normal n_g at the vertex with n_f·n_g > cos(angle)), with glshade's
//! weightings (three.js sums unit normals: `Weighting::Uniform`) and vertices identified by
//! index, not by position.

use glam::DVec3;
use rayon::prelude::*;

use crate::errors::error::Error;
use crate::errors::stop::Stop;
use crate::normals::adjacency::{index, Adjacency};
use crate::normals::{
    adjacency_and_terms, check_rows, unit_or_zero, FaceTerms, Weighting, CANCELLED_ULPS,
    ROWS_PER_TASK,
};
use crate::numbers::real::Real;

/// Writes one normal per face corner into `out` (three rows per face, in face order): for the
/// corner of face f at vertex v, the normalised sum of the contributions under `weighting` of
/// the faces g around v whose unit normals satisfy n_f·n_g > cos(`angle`), `angle` in degrees
/// (f itself always, unless degenerate). At `angle` 180 every face but an opposite one joins:
/// the vertex normals of [`super::vertex_normals`]. A corner gets (0, 0, 0) where no face
/// joins (a degenerate face at an angle up to 90) or the sum cancels, as there.
///
/// # Errors
/// A value error for an `angle` outside [0, 180] or an `out` without three rows per face; those
/// of [`super::vertex_normals`] otherwise.
pub fn crease_normals<T: Real>(
    vertices: &[[T; 3]],
    faces: &[[i64; 3]],
    weighting: Weighting,
    angle: f64,
    out: &mut [[T; 3]],
    stop: &Stop,
) -> Result<(), Error> {
    if !(0.0..=180.0).contains(&angle) {
        return Err(Error::value(format!(
            "angle must be in [0, 180] degrees, got {angle}"
        )));
    }
    check_rows(out, faces.len().saturating_mul(3))?;
    let (adjacency, terms) = adjacency_and_terms(vertices, faces, weighting, stop)?;
    let corners = Corners {
        faces,
        adjacency: &adjacency,
        cosine: angle.to_radians().cos(),
        cancel: CANCELLED_ULPS * T::EPSILON.to_f64(),
    };
    match &terms {
        FaceTerms::Area(cross) => {
            let cross: &[[f64; 4]] = cross;
            let unit = |g: usize| {
                let [x, y, z, length] = cross[g];
                if length > 0.0 {
                    DVec3::new(x, y, z) / length
                } else {
                    DVec3::ZERO
                }
            };
            corners.write(out, stop, unit, |k| {
                let [x, y, z, length] = cross[k / 3];
                (DVec3::new(x, y, z), length)
            });
        }
        FaceTerms::Uniform(normals) => {
            let normals: &[[f64; 3]] = normals;
            let unit = |g: usize| DVec3::from_array(normals[g]);
            corners.write(out, stop, unit, |k| {
                let v = DVec3::from_array(normals[k / 3]);
                (v, if v == DVec3::ZERO { 0.0 } else { 1.0 })
            });
        }
        FaceTerms::Angle(normals, weights) => {
            let (normals, weights): (&[[f64; 3]], &[[f64; 3]]) = (normals, weights);
            let unit = |g: usize| DVec3::from_array(normals[g]);
            corners.write(out, stop, unit, |k| {
                let weight = weights[k / 3][k % 3];
                (DVec3::from_array(normals[k / 3]) * weight, weight)
            });
        }
    }
    stop.check()
}

/// What every corner's sum reads.
struct Corners<'a> {
    faces: &'a [[i64; 3]],
    adjacency: &'a Adjacency,
    /// cos(angle): a face joins where the dot product of the unit normals exceeds it.
    cosine: f64,
    cancel: f64,
}

impl Corners<'_> {
    /// Every corner's normal into `out`, from the unit normal of face g, `unit(g)`, and the
    /// term and length corner k adds, `term(k)`; tasks that start after `stop` is requested
    /// are skipped.
    fn write<T, U, C>(&self, out: &mut [[T; 3]], stop: &Stop, unit: U, term: C)
    where
        T: Real,
        U: Fn(usize) -> DVec3 + Sync,
        C: Fn(usize) -> (DVec3, f64) + Sync,
    {
        out.par_chunks_mut(3 * ROWS_PER_TASK)
            .enumerate()
            .for_each(|(t, dst)| {
                if stop.is_requested() {
                    return;
                }
                for (j, d) in dst.iter_mut().enumerate() {
                    let corner = 3 * t * ROWS_PER_TASK + j;
                    let face = corner / 3;
                    let own = unit(face);
                    let (mut sum, mut magnitude) = (DVec3::ZERO, 0.0);
                    let vertex = index(self.faces[face][corner % 3]);
                    for &k in self.adjacency.corners_of(vertex) {
                        let k = k as usize;
                        // The corner's own face joins whatever the angle: at 0, n·n is 1 or
                        // an ulp either side of it, never reliably above cos(0).
                        if k / 3 == face || own.dot(unit(k / 3)) > self.cosine {
                            let (v, length) = term(k);
                            sum += v;
                            magnitude += length;
                        }
                    }
                    *d = unit_or_zero(sum, magnitude, self.cancel);
                }
            });
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::normals::tests::cube;

    #[test]
    fn a_cube_keeps_its_faces_flat_below_90_degrees() {
        let (v, f) = cube();
        let mut out = vec![[0.0; 3]; 36];
        for (weighting, angle) in [
            (Weighting::Angle, 30.0),
            (Weighting::Area, 30.0),
            (Weighting::Uniform, 30.0),
            (Weighting::Angle, 0.0),
        ] {
            crease_normals(&v, &f, weighting, angle, &mut out, &Stop::new()).unwrap();
            for (corner, n) in out.iter().enumerate() {
                let [a, b, c] = f[corner / 3].map(|i| DVec3::from_array(v[index(i)]));
                let face = (b - a).cross(c - a).normalize();
                assert_eq!(DVec3::from_array(*n), face, "corner {corner}");
            }
        }
    }

    #[test]
    fn angles_outside_0_to_180_are_refused() {
        let (v, f) = cube();
        let mut out = vec![[0.0; 3]; 36];
        for angle in [-1.0, 180.5, f64::NAN] {
            assert!(
                crease_normals(&v, &f, Weighting::Angle, angle, &mut out, &Stop::new()).is_err()
            );
        }
    }
}
