//! The material of one face (GL 2.1 §2.14.1 Table 2.10) and `COLOR_MATERIAL` (§2.14.3).

use crate::errors::error::Error;

/// The material parameters of one face, named after the GL enums, as `f64` RGBA.
///
/// Only the alpha of `diffuse` reaches the output (GL: "only the diffuse alpha component is used").
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Material {
    /// `GL_AMBIENT`, a_cm.
    pub ambient: [f64; 4],
    /// `GL_DIFFUSE`, d_cm.
    pub diffuse: [f64; 4],
    /// `GL_SPECULAR`, s_cm.
    pub specular: [f64; 4],
    /// `GL_EMISSION`, e_cm.
    pub emission: [f64; 4],
    /// `GL_SHININESS`, s_rm ≥ 0 (GL allows [0, 128]; glshade also accepts larger exponents).
    pub shininess: f64,
}

impl Default for Material {
    /// GL's initial material.
    fn default() -> Self {
        Self {
            ambient: [0.2, 0.2, 0.2, 1.0],
            diffuse: [0.8, 0.8, 0.8, 1.0],
            specular: [0.0, 0.0, 0.0, 1.0],
            emission: [0.0, 0.0, 0.0, 1.0],
            shininess: 0.0,
        }
    }
}

/// The columns of a material row, in order, with their widths (a test checks their sum against
/// [`MATERIAL_ROW_LEN`]).
#[cfg(test)]
const MATERIAL_LAYOUT: [(&str, usize); 5] = [
    ("ambient", 4),
    ("diffuse", 4),
    ("specular", 4),
    ("emission", 4),
    ("shininess", 1),
];

/// The number of `f64` in a material row: ambient, diffuse, specular and emission (4 each),
/// then shininess (1).
pub const MATERIAL_ROW_LEN: usize = 17;

impl Material {
    /// Reads a row laid out as [`MATERIAL_ROW_LEN`] describes; see [`Material::validate`] for the ranges.
    pub fn from_row(row: &[f64; MATERIAL_ROW_LEN]) -> Self {
        let rgba = |k: usize| -> [f64; 4] { std::array::from_fn(|i| row[4 * k + i]) };
        Self {
            ambient: rgba(0),
            diffuse: rgba(1),
            specular: rgba(2),
            emission: rgba(3),
            shininess: row[16],
        }
    }

    /// Checks that every value is finite and the shininess is ≥ 0; `name` names the material
    /// (`"material"` or `"back_material"`) in the message.
    ///
    /// # Errors
    /// A value error naming the parameter and the value found.
    pub fn validate(&self, name: &str) -> Result<(), Error> {
        let colours = [
            ("ambient", self.ambient),
            ("diffuse", self.diffuse),
            ("specular", self.specular),
            ("emission", self.emission),
        ];
        for (field, v) in colours {
            if !v.iter().all(|x| x.is_finite()) {
                return Err(Error::value(format!(
                    "{name}.{field} must be finite, got {v:?}"
                )));
            }
        }
        let s = self.shininess;
        if !(s >= 0.0 && s.is_finite()) {
            return Err(Error::value(format!(
                "{name}.shininess must be finite and >= 0, got {s}"
            )));
        }
        Ok(())
    }
}

/// Which material parameters follow the per-vertex colour (`glColorMaterial`'s `mode`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ColorMaterialMode {
    /// `GL_AMBIENT`.
    Ambient,
    /// `GL_DIFFUSE` (the colour's alpha becomes the output alpha).
    Diffuse,
    /// `GL_SPECULAR`.
    Specular,
    /// `GL_EMISSION`.
    Emission,
    /// `GL_AMBIENT_AND_DIFFUSE`, GL's default mode.
    AmbientAndDiffuse,
}

/// Which faces' materials follow the per-vertex colour (`glColorMaterial`'s `face`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Face {
    /// `GL_FRONT`.
    Front,
    /// `GL_BACK`.
    Back,
    /// `GL_FRONT_AND_BACK`, GL's default.
    FrontAndBack,
}

/// `GL_COLOR_MATERIAL` state: which parameters of which faces track the vertex colour.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ColorMaterial {
    /// The tracked parameter(s).
    pub mode: ColorMaterialMode,
    /// The tracked face(s).
    pub face: Face,
}

impl ColorMaterial {
    /// Parses GL's names in lower case: `mode` in {"ambient", "diffuse", "specular", "emission",
    /// "ambient_and_diffuse"}, `face` in {"front", "back", "front_and_back"}.
    ///
    /// # Errors
    /// A value error naming the argument and the accepted values.
    pub fn parse(mode: &str, face: &str) -> Result<Self, Error> {
        let mode = match mode {
            "ambient" => ColorMaterialMode::Ambient,
            "diffuse" => ColorMaterialMode::Diffuse,
            "specular" => ColorMaterialMode::Specular,
            "emission" => ColorMaterialMode::Emission,
            "ambient_and_diffuse" => ColorMaterialMode::AmbientAndDiffuse,
            _ => {
                return Err(Error::value(format!(
                    "color_material must be one of 'ambient', 'diffuse', 'specular', 'emission', \
                     'ambient_and_diffuse', got '{mode}'"
                )))
            }
        };
        let face = match face {
            "front" => Face::Front,
            "back" => Face::Back,
            "front_and_back" => Face::FrontAndBack,
            _ => {
                return Err(Error::value(format!(
                    "color_material_face must be one of 'front', 'back', 'front_and_back', got '{face}'"
                )))
            }
        };
        Ok(Self { mode, face })
    }

    /// True when the material of side `back` (false: front) tracks the colour.
    pub fn applies_to(&self, back: bool) -> bool {
        matches!(
            (self.face, back),
            (Face::FrontAndBack, _) | (Face::Front, false) | (Face::Back, true)
        )
    }

    /// `material` with the tracked parameters replaced by `color` (RGBA).
    pub fn apply(&self, material: &Material, color: [f64; 4]) -> Material {
        let mut m = *material;
        match self.mode {
            ColorMaterialMode::Ambient => m.ambient = color,
            ColorMaterialMode::Diffuse => m.diffuse = color,
            ColorMaterialMode::Specular => m.specular = color,
            ColorMaterialMode::Emission => m.emission = color,
            ColorMaterialMode::AmbientAndDiffuse => {
                m.ambient = color;
                m.diffuse = color;
            }
        }
        m
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn layout_widths_sum_to_row_len() {
        assert_eq!(
            MATERIAL_LAYOUT.iter().map(|(_, w)| w).sum::<usize>(),
            MATERIAL_ROW_LEN
        );
    }

    #[test]
    fn from_row_reads_the_layout() {
        let row: [f64; MATERIAL_ROW_LEN] = std::array::from_fn(|i| i as f64);
        let m = Material::from_row(&row);
        assert_eq!(m.diffuse, [4.0, 5.0, 6.0, 7.0]);
        assert_eq!(m.emission, [12.0, 13.0, 14.0, 15.0]);
        assert_eq!(m.shininess, 16.0);
    }

    #[test]
    fn validation_names_the_field() {
        let m = Material {
            shininess: -1.0,
            ..Material::default()
        };
        assert!(m
            .validate("back_material")
            .unwrap_err()
            .message
            .starts_with("back_material.shininess"));
        assert!(Material::default().validate("material").is_ok());
    }

    #[test]
    fn color_material_parses_and_applies() {
        let cm = ColorMaterial::parse("ambient_and_diffuse", "front").unwrap();
        assert!(cm.applies_to(false) && !cm.applies_to(true));
        let m = cm.apply(&Material::default(), [0.1, 0.2, 0.3, 0.4]);
        assert_eq!(m.ambient, [0.1, 0.2, 0.3, 0.4]);
        assert_eq!(m.diffuse, [0.1, 0.2, 0.3, 0.4]);
        assert_eq!(m.specular, Material::default().specular);
        assert!(ColorMaterial::parse("shininess", "front").is_err());
        assert!(ColorMaterial::parse("diffuse", "both").is_err());
    }
}
