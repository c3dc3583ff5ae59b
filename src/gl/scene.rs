//! Everything the lighting equation reads besides the vertices: the lights, the front and back
//! materials and the light model (GL 2.1 §2.14.1, `glLightModel`).

use std::ops::Deref;

use crate::errors::error::Error;
use crate::gl::light::Light;
use crate::gl::material::Material;

/// The specular term's vector.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Specular {
    /// GL's halfway vector: `(n ⊙ ĥ)^s`, ĥ = normalize(VP + VPe).
    #[default]
    Blinn,
    /// The reflection vector: `(R ⊙ VPe)^s`, R = 2(n·VP)n − VP.
    Phong,
}

impl Specular {
    /// Parses `"blinn"` or `"phong"`.
    ///
    /// # Errors
    /// A value error naming `specular` for any other string.
    pub fn parse(name: &str) -> Result<Self, Error> {
        match name {
            "blinn" => Ok(Self::Blinn),
            "phong" => Ok(Self::Phong),
            _ => Err(Error::value(format!(
                "specular must be 'blinn' or 'phong', got {name:?}"
            ))),
        }
    }
}

/// A lit scene: lights in eye coordinates, materials and the light model.
#[derive(Clone, Debug, PartialEq)]
pub struct Scene {
    /// The enabled lights, in summation order.
    pub lights: Vec<Light>,
    /// The front material.
    pub material: Material,
    /// The back material, used with `two_side` only.
    pub back_material: Material,
    /// `GL_LIGHT_MODEL_AMBIENT`, a_cs.
    pub global_ambient: [f64; 4],
    /// The viewer, homogeneous: `(x, y, z, 0)` is a viewer infinitely far in direction (x, y, z)
    /// (GL's default `(0, 0, 1, 0)`), `(x, y, z, w)` a viewer at the point (x, y, z)/w
    /// (`(0, 0, 0, 1)` is `GL_LIGHT_MODEL_LOCAL_VIEWER`).
    pub viewer: [f64; 4],
    /// `GL_LIGHT_MODEL_TWO_SIDE`: also compute the back colour, with the back material and −n.
    pub two_side: bool,
    /// `GL_SEPARATE_SPECULAR_COLOR`: the specular sum goes to a secondary colour.
    pub separate_specular: bool,
    /// The specular vector.
    pub specular: Specular,
    /// GL's f_i (eq. 2.2): no specular from a light unless n·VP > 0. `false` drops the gate, as
    /// learnopengl's shaders do: the specular term is then added wherever n ≠ 0 and VP ≠ 0,
    /// the diffuse term is still (n ⊙ VP).
    pub specular_gate: bool,
}

impl Default for Scene {
    /// GL's initial light model and material, with no light enabled.
    fn default() -> Self {
        Self {
            lights: Vec::new(),
            material: Material::default(),
            back_material: Material::default(),
            global_ambient: [0.2, 0.2, 0.2, 1.0],
            viewer: [0.0, 0.0, 1.0, 0.0],
            two_side: false,
            separate_specular: false,
            specular: Specular::Blinn,
            specular_gate: true,
        }
    }
}

impl Scene {
    /// How many RGBA colours are computed per vertex: 1, or 2 with `two_side` or
    /// `separate_specular`, or 4 with both. Their order is [`Scene::output_names`].
    pub fn output_count(&self) -> usize {
        (1 + usize::from(self.two_side)) * (1 + usize::from(self.separate_specular))
    }

    /// The names of the colours in output order (GL's `gl_FrontColor`, `gl_FrontSecondaryColor`,
    /// `gl_BackColor`, `gl_BackSecondaryColor`, as far as the scene computes them).
    pub fn output_names(&self) -> &'static [&'static str] {
        match (self.two_side, self.separate_specular) {
            (false, false) => &["color"],
            (false, true) => &["primary", "secondary"],
            (true, false) => &["front", "back"],
            (true, true) => &[
                "front_primary",
                "front_secondary",
                "back_primary",
                "back_secondary",
            ],
        }
    }

    /// Checks every light, both materials and the light model.
    ///
    /// # Errors
    /// The first failure of [`Light::validate`] or [`Material::validate`], or a value error
    /// for a non-finite `global_ambient` or `viewer`, or a viewer of (0, 0, 0, 0).
    pub fn validate(&self) -> Result<(), Error> {
        for (i, light) in self.lights.iter().enumerate() {
            light.validate(i)?;
        }
        self.material.validate("material")?;
        self.back_material.validate("back_material")?;
        for (name, v) in [
            ("global_ambient", self.global_ambient),
            ("viewer", self.viewer),
        ] {
            if !v.iter().all(|x| x.is_finite()) {
                return Err(Error::value(format!("{name} must be finite, got {v:?}")));
            }
        }
        if self.viewer == [0.0; 4] {
            return Err(Error::value(
                "viewer must be a point (w != 0) or a nonzero direction (w = 0), got [0, 0, 0, 0]",
            ));
        }
        Ok(())
    }

    /// The scene, checked once by [`Scene::validate`]: what `shade` and `render` take, so a
    /// scene reused over many calls is not checked again on each.
    ///
    /// # Errors
    /// Those of [`Scene::validate`].
    pub fn validated(self) -> Result<ValidScene, Error> {
        self.validate()?;
        Ok(ValidScene(self))
    }
}

/// A [`Scene`] that passed [`Scene::validate`], made only by [`Scene::validated`]; it reads as
/// the scene through `Deref` and cannot be changed.
#[derive(Clone, Debug, PartialEq)]
pub struct ValidScene(Scene);

impl ValidScene {
    /// The validated scene.
    pub fn scene(&self) -> &Scene {
        &self.0
    }
}

impl Deref for ValidScene {
    type Target = Scene;
    fn deref(&self) -> &Scene {
        &self.0
    }
}

impl Scene {
    /// Checks GL's own limits on exponents, which glshade otherwise relaxes: shininess and spot
    /// exponents in [0, 128] (GL generates `GL_INVALID_VALUE` beyond).
    ///
    /// # Errors
    /// A value error naming the parameter, GL's range and the value found.
    pub fn validate_gl_ranges(&self) -> Result<(), Error> {
        const GL_MAX_EXPONENT: f64 = 128.0;
        for (name, m) in [
            ("material", &self.material),
            ("back_material", &self.back_material),
        ] {
            if m.shininess > GL_MAX_EXPONENT {
                return Err(Error::value(format!(
                    "{name}.shininess must be in [0, 128] with strict=True (GL's range), got {}",
                    m.shininess
                )));
            }
        }
        for (i, light) in self.lights.iter().enumerate() {
            if light.spot_exponent > GL_MAX_EXPONENT {
                return Err(Error::value(format!(
                    "spot_exponent of light {i} must be in [0, 128] with strict=True (GL's \
                     range), got {}",
                    light.spot_exponent
                )));
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn outputs_follow_the_light_model() {
        let mut s = Scene::default();
        assert_eq!((s.output_count(), s.output_names()), (1, &["color"][..]));
        s.two_side = true;
        s.separate_specular = true;
        assert_eq!(s.output_count(), 4);
        assert_eq!(s.output_names().len(), 4);
    }

    #[test]
    fn validation_reports_the_light_index() {
        let mut s = Scene {
            lights: vec![
                Light::default(),
                Light {
                    spot_cutoff: 91.0,
                    ..Light::default()
                },
            ],
            ..Scene::default()
        };
        assert!(s.validate().unwrap_err().message.contains("light 1"));
        assert_eq!(
            s.clone().validated().unwrap_err(),
            s.validate().unwrap_err()
        );
        s.lights.clear();
        s.viewer = [0.0; 4];
        assert!(s.validate().unwrap_err().message.starts_with("viewer"));
        assert!(Specular::parse("cook-torrance").is_err());
        let valid = Scene::default().validated().unwrap();
        assert_eq!(valid.scene(), &Scene::default());
        assert_eq!(valid.output_count(), 1);
    }
}
