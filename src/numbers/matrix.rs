//! Matrix helpers shared by the lighting (the normal matrix) and the camera: an inverse that
//! does not depend on the matrix's scale.

use glam::DMat3;

use crate::simd::float::{exponent, ldexp};
/// A⁻¹ and e for M = A·diag(2^e), where e_j = ⌊log2 max_i |m_ij|⌋ scales column j of A to
/// a largest entry in [1, 2) (exactly), so the inverse of M at any scale, uniform or column by
/// column, is formed from the same A; `None` when M is singular: a zero column, a zero
/// determinant of A, or an inverse that is not finite.
pub fn scaled_inverse(m: &DMat3) -> Option<(DMat3, [i32; 3])> {
    let columns = [m.x_axis, m.y_axis, m.z_axis];
    let top = columns.map(|c| c.abs().max_element());
    if !top.iter().all(|t| *t > 0.0 && t.is_finite()) {
        return None;
    }
    let e = top.map(exponent);
    let a = DMat3::from_cols(
        columns[0].map(|x| ldexp(x, -e[0])),
        columns[1].map(|x| ldexp(x, -e[1])),
        columns[2].map(|x| ldexp(x, -e[2])),
    );
    let inverse = a.inverse();
    (a.determinant() != 0.0 && inverse.is_finite()).then_some((inverse, e))
}
