//! Relief shading of elevation grids, as matplotlib's `LightSource` computes it
//! (matplotlib/colors.py): surface normals from the grid's gradient and the whole-image
//! normalised intensity ([`hillshade`]), and the blends of an intensity with an RGB image
//! ([`blend`]), all in `f64`, row by row in parallel.
//!
//! Uses [`crate::memory`] and [`crate::errors`].

pub mod blend;
pub mod hillshade;
