//! One mesh of a frame as the passes light it ([`Layer`]): its model placed for the camera,
//! its mesh and normals, and where its faces start among the frame's.

use glam::DVec3;
use rayon::prelude::*;

use crate::errors::error::Error;
use crate::errors::stop::Stop;
use crate::gl::vertex_colors::VertexColors;
use crate::memory::alloc::{count, try_par_collect};
use crate::memory::pages::Zeroed;
use crate::memory::uninit::as_uninit;
use crate::normals::adjacency::index;
use crate::numbers::real::Real;
use crate::render::mesh::Mesh;
use crate::render::options::Provoking;
use crate::render::shader::{RenderModel, Shader};
use crate::render::transfer::srgb_to_linear;

/// Rows per parallel task of a layer's gathers.
pub const ROWS_PER_TASK: usize = 4096;

/// Σ weights[j] · rows[face[j]]: an attribute of the face's corners at a pixel.
#[inline]
pub fn interpolate<T: Real, const K: usize>(
    rows: &[[T; K]],
    face: [i64; 3],
    weights: DVec3,
) -> [f64; K] {
    let [a, b, c] = face.map(|i| &rows[index(i)]);
    std::array::from_fn(|k| {
        weights.x * a[k].to_f64() + weights.y * b[k].to_f64() + weights.z * c[k].to_f64()
    })
}

/// Row `i` of plane `plane` of a `shade` output over `n` rows.
#[inline]
pub fn shaded<T: Real>(out: &[T], n: usize, plane: usize, i: usize) -> [f64; 4] {
    let at = (plane * n + i) * 4;
    std::array::from_fn(|k| out[at + k].to_f64())
}

/// One mesh of a frame, ready to light.
pub struct Layer<'a, T, M: RenderModel> {
    /// Its model, placed for the camera with the mesh's model matrix.
    pub shader: Shader<'a, M>,
    /// The mesh.
    pub mesh: &'a Mesh<'a, T>,
    /// Its normals: one per vertex for Gouraud and Phong, one per face for flat shading.
    pub normals: &'a [[T; 3]],
    /// The frame's index of its first face (triangles carry the frame's face indices).
    pub first_face: u32,
}

impl<T: Real, M: RenderModel> Layer<'_, T, M> {
    /// The face of the mesh with the frame's face index `face`.
    #[inline]
    pub fn face(&self, face: u32) -> [i64; 3] {
        self.mesh.faces[(face - self.first_face) as usize]
    }

    /// The texel that multiplies the fragment of `face` at `weights` (GL's model with a
    /// texture; `None` otherwise).
    #[inline]
    pub fn modulation(&self, face: [i64; 3], weights: DVec3) -> Option<[f64; 4]> {
        let textured = self.mesh.textured.filter(|_| M::MODULATES)?;
        Some(
            textured
                .texture
                .sample(interpolate(textured.uv, face, weights)),
        )
    }

    /// The colour the model reads where it is evaluated at `face` and `weights`, into `out`
    /// (as wide as [`Layer::color_width`]): the texel decoded from sRGB for a model whose
    /// texture is a base colour, else the interpolated vertex colour.
    #[inline]
    pub fn color_at(&self, face: [i64; 3], weights: DVec3, out: &mut [T]) {
        if let Some(textured) = self.mesh.textured.filter(|_| !M::MODULATES) {
            let texel = srgb_to_linear(textured.texture.sample(interpolate(
                textured.uv,
                face,
                weights,
            )));
            for (d, t) in out.iter_mut().zip(texel) {
                *d = T::from_f64(t);
            }
        } else if let Some(c) = self.mesh.colors {
            for (channel, value) in out.iter_mut().enumerate() {
                let at = face.map(|i| c.data[index(i) * c.width + channel]);
                *value = T::from_f64(weights.dot(DVec3::from_array(at.map(T::to_f64))));
            }
        }
    }

    /// How many colour values the model reads per point: 4 for a base colour texture, the
    /// vertex colours' width, or 0.
    pub fn color_width(&self) -> usize {
        if self.mesh.textured.is_some() && !M::MODULATES {
            4
        } else {
            self.mesh.colors.map_or(0, |c| c.width)
        }
    }

    /// The colours the shader reads per vertex: the mesh's, or for a model whose texture is a
    /// base colour its texels at the vertices, decoded from sRGB.
    ///
    /// # Errors
    /// A memory error for the texels, or [`Error::interrupted`].
    fn vertex_colors(&self, stop: &Stop) -> Result<Option<Zeroed<T>>, Error> {
        let Some(textured) = self.mesh.textured.filter(|_| !M::MODULATES) else {
            return Ok(None);
        };
        let len = count(&[textured.uv.len(), 4], "the texels at the vertices")?;
        let mut texels = Zeroed::<T>::new(len, "the texels at the vertices")?;
        texels
            .par_chunks_mut(4 * ROWS_PER_TASK)
            .zip(textured.uv.par_chunks(ROWS_PER_TASK))
            .for_each(|(dst, uv)| {
                if stop.is_requested() {
                    return;
                }
                for (d, uv) in dst.chunks_exact_mut(4).zip(uv) {
                    let texel = srgb_to_linear(textured.texture.sample(uv.map(T::to_f64)));
                    for (d, t) in d.iter_mut().zip(texel) {
                        *d = T::from_f64(t);
                    }
                }
            });
        stop.check()?;
        Ok(Some(texels))
    }

    /// The mesh's colours, or `texels` (from [`Layer::vertex_colors`]) in their place.
    fn colors_or<'b>(&'b self, texels: Option<&'b Zeroed<T>>) -> Option<VertexColors<'b, T>> {
        match texels {
            Some(data) => Some(VertexColors { data, width: 4 }),
            None => self.mesh.colors,
        }
    }

    /// The vertices lit with the layer's normals: the model's planes of RGBA rows (Gouraud).
    ///
    /// # Errors
    /// Those of [`Shader::shade`]; a memory error for the colours.
    pub fn lit_vertices(&self, stop: &Stop) -> Result<Zeroed<T>, Error> {
        let n = self.mesh.vertices.len();
        let len = count(&[self.shader.outputs(), n, 4], "the vertex colours")?;
        let mut colours = Zeroed::<T>::new(len, "the vertex colours")?;
        let texels = self.vertex_colors(stop)?;
        self.shader.shade(
            self.mesh.vertices,
            self.normals,
            self.colors_or(texels.as_ref()),
            as_uninit(&mut colours),
            stop,
        )?;
        Ok(colours)
    }

    /// Each face lit once with its normal at its provoking vertex (or centroid), with that
    /// vertex's colour: the model's planes of RGBA rows, one per face (flat).
    ///
    /// # Errors
    /// Those of [`Shader::shade`]; a memory error for the per-face buffers.
    pub fn lit_faces(&self, provoking: Provoking, stop: &Stop) -> Result<Zeroed<T>, Error> {
        let mesh = self.mesh;
        let m = mesh.faces.len();
        let positions = try_par_collect(
            mesh.faces
                .par_iter()
                .map(|f| std::array::from_fn(|k| provoking.of(f, |i| mesh.vertices[i][k]))),
            "the provoking positions",
        )?;
        let texels = self.vertex_colors(stop)?;
        let source = self.colors_or(texels.as_ref());
        let colors: Option<Zeroed<T>> = match source {
            Some(c) => {
                let len = count(&[m, c.width], "the provoking colours")?;
                let mut data = Zeroed::<T>::new(len, "the provoking colours")?;
                data.par_chunks_mut(ROWS_PER_TASK * c.width)
                    .zip(mesh.faces.par_chunks(ROWS_PER_TASK))
                    .for_each(|(dst, faces)| {
                        if stop.is_requested() {
                            return;
                        }
                        for (d, f) in dst.chunks_exact_mut(c.width).zip(faces) {
                            for (j, d) in d.iter_mut().enumerate() {
                                *d = provoking.of(f, |i| c.data[i * c.width + j]);
                            }
                        }
                    });
                stop.check()?;
                Some(data)
            }
            None => None,
        };
        let colors = source.zip(colors.as_deref()).map(|(c, data)| VertexColors {
            data,
            width: c.width,
        });
        let len = count(&[self.shader.outputs(), m, 4], "the face colours")?;
        let mut colours = Zeroed::<T>::new(len, "the face colours")?;
        self.shader.shade(
            &positions,
            self.normals,
            colors,
            as_uninit(&mut colours),
            stop,
        )?;
        Ok(colours)
    }
}
