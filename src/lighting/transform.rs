//! The transform of a call's positions and normals: GL's modelview, or a world model's model
//! matrix, with the normal matrix (its inverse transpose), in the kernel's type.

use glam::{DMat3, DMat4};

use crate::errors::error::Error;
use crate::lighting::round::cast_saturating;
use crate::numbers::matrix::scaled_inverse;
use crate::numbers::real::{normalize_and_length, Real};
use crate::simd::float::{exponent, ldexp};
use crate::simd::lanes::{Lanes, V3};

/// The modelview and its normal matrix, as columns in `T`.
#[derive(Clone, Copy, Debug)]
pub struct Transform<T: Real> {
    linear: [[T; 3]; 3],
    translation: [T; 3],
    normal: [[T; 3]; 3],
}

/// `columns · v`, summed column by column (x, then y, then z) like glam's `Mat3 * Vec3`.
#[inline(always)]
fn mul3<V: Lanes>(columns: &[[V::T; 3]; 3], v: V3<V>) -> V3<V> {
    V3::splat(columns[0]).scale(v.x)
        + V3::splat(columns[1]).scale(v.y)
        + V3::splat(columns[2]).scale(v.z)
}

impl<T: Real> Transform<T> {
    /// The eye-space positions M·(p, 1).
    #[inline(always)]
    pub fn point<V: Lanes<T = T>>(&self, p: V3<V>) -> V3<V> {
        mul3(&self.linear, p) + V3::splat(self.translation)
    }

    /// The eye-space normals (M⁻¹)ᵀ·n, times the rescale factor if asked for.
    #[inline(always)]
    pub fn normal<V: Lanes<T = T>>(&self, n: V3<V>) -> V3<V> {
        mul3(&self.normal, n)
    }

    /// [`Transform::normal`] of one vector, in the same operations (the same bits): for the
    /// kernel's lanes whose normal is recomputed at another scale.
    #[inline(always)]
    pub fn normal_of(&self, n: [T; 3]) -> [T; 3] {
        let c = &self.normal;
        std::array::from_fn(|k| c[0][k] * n[0] + c[1][k] * n[1] + c[2][k] * n[2])
    }

    /// The transform of an affine `modelview` (last row (0, 0, 0, 1)); with `rescale_normal`,
    /// the normal matrix is scaled by GL's 1/|third row of M⁻¹| (§2.11.3). The normal matrix is
    /// the true inverse transpose (see [`Transform::for_shading`] without `normalize`), and the
    /// positions are checked as if read.
    ///
    /// # Errors
    /// As [`Transform::for_shading`].
    #[cfg(test)]
    pub fn new(modelview: &DMat4, rescale_normal: bool) -> Result<Self, Error> {
        Self::for_shading(modelview, rescale_normal, false, true)
    }

    /// The transform of an affine `modelview` for a call with `GL_RESCALE_NORMAL`
    /// (`rescale_normal`) and `GL_NORMALIZE` (`normalize`) that reads positions or not
    /// (`positions`).
    ///
    /// The inverse is taken of the upper 3x3 scaled by an exact power of two (its largest entry
    /// in [1, 2)), so any uniform scale of the modelview that keeps it finite leaves the
    /// rescaled or normalised normals unchanged to rounding. With `rescale_normal` the scale
    /// cancels; with `normalize` alone the normal matrix is that well-scaled inverse transpose
    /// (any positive multiple gives the same unit normals); with neither it is the true
    /// (M⁻¹)ᵀ, whose entries saturate at ±`T::MAX` where they exceed `T`'s range (a non-unit
    /// normal scales the lighting, as in GL).
    ///
    /// Positions go through the modelview rounded to `T`: entries below `T`'s normal range
    /// round to subnormals or 0 like any value of `T` (use `f64` for such modelviews).
    ///
    /// # Errors
    /// A value error for a non-finite, projective or singular `modelview`, and, when
    /// `positions` are read, for an entry of its linear part or translation beyond `T`'s
    /// range (positions would overflow). Without positions such entries are never read.
    pub fn for_shading(
        modelview: &DMat4,
        rescale_normal: bool,
        normalize: bool,
        positions: bool,
    ) -> Result<Self, Error> {
        if !modelview.is_finite() {
            return Err(Error::value(format!(
                "modelview must be finite, got {modelview}"
            )));
        }
        let last_row = modelview.row(3);
        if last_row != glam::DVec4::W {
            return Err(Error::value(format!(
                "modelview must be affine (last row (0, 0, 0, 1)), got last row {last_row}"
            )));
        }
        let m3 = glam::DMat3::from_mat4(*modelview);
        let Some((inverse, e)) = scaled_inverse(&m3) else {
            return Err(Error::value(format!(
                "modelview must be invertible (its normal matrix is the inverse transpose), \
                 got determinant {} for the upper-left 3x3",
                m3.determinant()
            )));
        };
        // M = A·D with D = diag(2^e), so (M⁻¹)ᵀ = A⁻ᵀ·D⁻¹: column j of A⁻ᵀ times 2^−e_j, and
        // any factor common to the three columns cancels in the rescaled or normalised normal.
        let columns = |shift: [i32; 3], factor: f64| {
            let t = inverse.transpose();
            DMat3::from_cols(
                (t.x_axis * factor).map(|x| ldexp(x, shift[0])),
                (t.y_axis * factor).map(|x| ldexp(x, shift[1])),
                (t.z_axis * factor).map(|x| ldexp(x, shift[2])),
            )
        };
        let normal = if rescale_normal {
            // GL's factor 1/|row 2 of M⁻¹| = 2^e_2/|row 2 of A⁻¹|.
            let (_, length) = normalize_and_length::<f64>(inverse.row(2));
            columns(e.map(|ej| e[2] - ej), 1.0 / length)
        } else if normalize {
            let least = e.iter().copied().min().unwrap_or(0);
            let n = columns(e.map(|ej| least - ej), 1.0);
            let top = n
                .to_cols_array()
                .iter()
                .fold(0.0_f64, |m, x| m.max(x.abs()));
            columns(e.map(|ej| least - ej - exponent(top)), 1.0)
        } else {
            columns(e.map(|ej| -ej), 1.0)
        };
        let linear = [m3.x_axis, m3.y_axis, m3.z_axis].map(cast_saturating::<T>);
        let translation = cast_saturating::<T>(modelview.w_axis.truncate());
        let top = [m3.x_axis, m3.y_axis, m3.z_axis, modelview.w_axis.truncate()]
            .iter()
            .fold(0.0_f64, |m, v| m.max(v.abs().max_element()));
        if positions && top > T::MAX.to_f64() {
            return Err(Error::value(format!(
                "modelview entries must be within float{bits}'s range (|m| <= {max:.1e}) for \
                 float{bits} arithmetic, got max |m| = {top:e}; use float64 input or \
                 accuracy='exact'",
                bits = 8 * std::mem::size_of::<T>(),
                max = T::MAX.to_f64(),
            )));
        }
        Ok(Self {
            linear,
            translation,
            normal: [normal.x_axis, normal.y_axis, normal.z_axis].map(cast_saturating::<T>),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    use crate::simd::lanes::Pack;

    #[test]
    fn transform_uses_the_inverse_transpose() {
        let m = DMat4::from_scale(DVec3::new(2.0, 1.0, 1.0));
        let t = Transform::<f64>::new(&m, false).unwrap();
        let ones = V3::<Pack<f64, 1>>::splat([1.0; 3]);
        assert_eq!(t.point(ones).lane(0), [2.0, 1.0, 1.0]);
        assert_eq!(t.normal(ones).lane(0), [0.5, 1.0, 1.0]);
        let skew = DMat4::from_cols_array(&[
            0.8, 0.1, -0.2, 0.0, -0.1, 1.3, 0.3, 0.0, 0.2, -0.2, 0.7, 0.0, 0.1, -0.3, -2.0, 1.0,
        ]);
        let skew = Transform::<f32>::new(&skew, false).unwrap();
        let n = [0.3, -0.7, 0.45];
        assert_eq!(
            skew.normal_of(n),
            skew.normal(V3::<Pack<f32, 1>>::splat(n)).lane(0),
            "one vector in the lanes' operations"
        );
        let uniform = Transform::<f64>::new(&DMat4::from_scale(DVec3::splat(4.0)), true).unwrap();
        let z = V3::<Pack<f64, 1>>::splat([0.0, 0.0, 1.0]);
        assert_eq!(uniform.normal(z).lane(0), [0.0, 0.0, 1.0]);
        assert!(
            Transform::<f64>::new(&DMat4::from_scale(DVec3::new(1.0, 0.0, 1.0)), false).is_err()
        );
        let mut projective = DMat4::IDENTITY;
        projective.x_axis.w = 1.0;
        assert!(Transform::<f64>::new(&projective, false)
            .unwrap_err()
            .message
            .contains("affine"));
    }
}
