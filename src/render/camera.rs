//! The camera: GL's view and projection matrices (§2.11), built like `gluLookAt`,
//! `gluPerspective` and `glOrtho`, or given explicitly.
//!
//! Matrices are glam's column-major `DMat4`; a point p of the mesh reaches clip coordinates as
//! `projection · view · model · (p, 1)`. The view maps world to eye coordinates, where lights
//! and the viewer of the [`Scene`](crate::gl::scene::Scene) live, the camera sits at the origin and
//! looks down −z with +y up.

use glam::{DMat4, DVec3, DVec4};

use crate::errors::error::Error;

/// A view and a projection matrix.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Camera {
    /// World to eye coordinates; affine and invertible (its inverse transpose transforms
    /// normals).
    pub view: DMat4,
    /// Eye to clip coordinates; any finite matrix (perspective, orthographic or other).
    pub projection: DMat4,
}

impl Default for Camera {
    /// GL's initial state: identity view and projection, so the visible volume is the cube
    /// [−1, 1]³ of eye coordinates, seen along −z.
    fn default() -> Self {
        Self {
            view: DMat4::IDENTITY,
            projection: DMat4::IDENTITY,
        }
    }
}

fn finite(name: &str, values: &[f64]) -> Result<(), Error> {
    if values.iter().all(|x| x.is_finite()) {
        Ok(())
    } else {
        Err(Error::value(format!(
            "{name} must be finite, got {values:?}"
        )))
    }
}

impl Camera {
    /// Checks that the projection is finite and the view an invertible affine transform.
    ///
    /// # Errors
    /// A value error naming `view` or `projection`.
    pub fn validate(&self) -> Result<(), Error> {
        check_affine(&self.view, "view")?;
        finite("projection", &self.projection.to_cols_array())
    }
}

/// Checks that `m` transforms points as GL's modelview must: finite, affine (last row
/// (0, 0, 0, 1)) and invertible, since normals go through its inverse transpose.
///
/// # Errors
/// A value error naming `name`.
pub fn check_affine(m: &DMat4, name: &str) -> Result<(), Error> {
    finite(name, &m.to_cols_array())?;
    let last_row = m.row(3);
    if last_row != DVec4::W {
        return Err(Error::value(format!(
            "{name} must be affine (last row (0, 0, 0, 1)), got last row {last_row}"
        )));
    }
    // Inverted at a power-of-two scale: the determinant itself under- or overflows for
    // entries beyond about 1e±100, which says nothing about invertibility.
    let m3 = glam::DMat3::from_mat4(*m);
    if crate::numbers::matrix::scaled_inverse(&m3).is_none() {
        return Err(Error::value(format!(
            "{name} must be invertible (normals go through its inverse transpose), got \
             determinant {} for the upper-left 3x3",
            m3.determinant()
        )));
    }
    Ok(())
}

/// `gluLookAt`: the view of a camera at `eye` looking at `target`, with `up` projecting to +y.
///
/// # Errors
/// A value error for non-finite arguments, `eye == target`, or `up` parallel to the view
/// direction (or zero).
pub fn look_at(eye: DVec3, target: DVec3, up: DVec3) -> Result<DMat4, Error> {
    finite(
        "eye, target and up",
        &[eye, target, up].map(|v| v.to_array()).concat(),
    )?;
    let direction = target - eye;
    if direction == DVec3::ZERO {
        return Err(Error::value(format!(
            "target must differ from eye, got both {eye}"
        )));
    }
    let (forward, up_unit) = (direction.normalize(), up.normalize_or_zero());
    // Below this sine the side vector f × up is rounding noise, with no direction.
    if forward.cross(up_unit).length() <= 8.0 * f64::EPSILON {
        return Err(Error::value(format!(
            "up must not be zero or parallel to the view direction, got up {up} for direction \
             {direction}"
        )));
    }
    Ok(glam::dcamera::rh::view::look_to_mat4(eye, forward, up_unit))
}

/// `gluPerspective`: a perspective projection with a vertical field of view of `fovy` degrees,
/// `aspect` = width / height, and clip planes at distances `near` and `far`.
///
/// # Errors
/// A value error unless 0 < `fovy` < 180, `aspect` > 0 and 0 < `near` < `far`, all finite.
pub fn perspective(fovy: f64, aspect: f64, near: f64, far: f64) -> Result<DMat4, Error> {
    finite("fovy, aspect, near and far", &[fovy, aspect, near, far])?;
    if !(fovy > 0.0 && fovy < 180.0) {
        return Err(Error::value(format!(
            "fovy must be in (0, 180) degrees, got {fovy}"
        )));
    }
    if aspect <= 0.0 {
        return Err(Error::value(format!("aspect must be > 0, got {aspect}")));
    }
    if !(near > 0.0 && near < far) {
        return Err(Error::value(format!(
            "near and far must satisfy 0 < near < far, got near {near}, far {far}"
        )));
    }
    Ok(glam::dcamera::rh::proj::opengl::perspective(
        fovy.to_radians(),
        aspect,
        near,
        far,
    ))
}

/// `glOrtho`: an orthographic projection of the box [left, right] × [bottom, top] ×
/// [−near, −far] of eye coordinates.
///
/// # Errors
/// A value error for non-finite values or an empty extent (`left == right`, `bottom == top` or
/// `near == far`).
pub fn orthographic(
    left: f64,
    right: f64,
    bottom: f64,
    top: f64,
    near: f64,
    far: f64,
) -> Result<DMat4, Error> {
    finite(
        "left, right, bottom, top, near and far",
        &[left, right, bottom, top, near, far],
    )?;
    for (name, a, b) in [
        ("left and right", left, right),
        ("bottom and top", bottom, top),
        ("near and far", near, far),
    ] {
        if a == b {
            return Err(Error::value(format!("{name} must differ, got {a} twice")));
        }
    }
    Ok(glam::dcamera::rh::proj::opengl::orthographic(
        left, right, bottom, top, near, far,
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: DVec4, b: DVec4) -> bool {
        (a - b).abs().max_element() < 1e-12
    }

    #[test]
    fn look_at_puts_the_target_on_the_negative_z_axis() {
        let view = look_at(
            DVec3::new(1.0, 2.0, 3.0),
            DVec3::new(1.0, 2.0, -2.0),
            DVec3::Y * 7.0,
        )
        .unwrap();
        let t = view * DVec4::new(1.0, 2.0, -2.0, 1.0);
        assert!(close(t, DVec4::new(0.0, 0.0, -5.0, 1.0)), "{t}");
        let up = view * DVec4::new(1.0, 3.0, 3.0, 1.0);
        assert!(close(up, DVec4::new(0.0, 1.0, 0.0, 1.0)), "{up}");
        assert!(look_at(DVec3::ZERO, DVec3::ZERO, DVec3::Y).is_err());
        assert!(look_at(DVec3::ZERO, DVec3::Y, DVec3::Y * 2.0).is_err());
        assert!(look_at(DVec3::ZERO, DVec3::Z, DVec3::ZERO).is_err());
    }

    #[test]
    fn perspective_maps_near_and_far_to_the_depth_range_ends() {
        let p = perspective(90.0, 2.0, 1.0, 10.0).unwrap();
        let near = p * DVec4::new(2.0, 1.0, -1.0, 1.0);
        assert!(
            close(near / near.w, DVec4::new(1.0, 1.0, -1.0, 1.0)),
            "{near}"
        );
        let far = p * DVec4::new(0.0, 0.0, -10.0, 1.0);
        assert!((far.z / far.w - 1.0).abs() < 1e-12);
        assert!(perspective(180.0, 1.0, 1.0, 2.0).is_err());
        assert!(perspective(60.0, 0.0, 1.0, 2.0).is_err());
        assert!(perspective(60.0, 1.0, 0.0, 2.0).is_err());
        assert!(perspective(60.0, 1.0, 3.0, 2.0).is_err());
    }

    #[test]
    fn orthographic_maps_the_box_to_the_cube() {
        let p = orthographic(-1.0, 3.0, 0.0, 2.0, 1.0, 5.0).unwrap();
        let corner = p * DVec4::new(3.0, 0.0, -5.0, 1.0);
        assert!(close(corner, DVec4::new(1.0, -1.0, 1.0, 1.0)), "{corner}");
        assert!(orthographic(1.0, 1.0, 0.0, 1.0, 0.0, 1.0).is_err());
        assert!(orthographic(0.0, 1.0, 0.0, 1.0, f64::NAN, 1.0).is_err());
    }

    #[test]
    fn the_view_must_be_affine_invertible_and_finite() {
        let mut camera = Camera::default();
        assert!(camera.validate().is_ok());
        camera.view.w_axis.w = 2.0;
        assert!(camera.validate().unwrap_err().message.starts_with("view"));
        camera.view = DMat4::from_scale(DVec3::new(1.0, 0.0, 1.0));
        assert!(camera
            .validate()
            .unwrap_err()
            .message
            .contains("invertible"));
        camera = Camera::default();
        camera.projection.x_axis.x = f64::INFINITY;
        assert!(camera
            .validate()
            .unwrap_err()
            .message
            .starts_with("projection"));
    }
}
