//! Lighting the visible pixels, through the render's [`Shader`] (the model of its scene):
//!
//! - **Gouraud**: the vertices are lit, and the colours interpolated (GL's smooth shading).
//! - **Phong**: positions, normals (and colours) are interpolated to every visible pixel centre,
//!   and all those pixels are lit in one `shade` call.
//! - **Flat**: each face is lit once with its face normal, at its provoking vertex (the last
//!   one, GL's default; the first, Direct3D's) or its centroid (where PyTorch3D lights it),
//!   and the colour is constant over the face (`glShadeModel(GL_FLAT)`; a `flat` varying).
//!
//! Every pixel's colour comes from the front or the back colours by the facing of its triangle;
//! with a separate specular colour the two are summed and clamped (GL's colour sum, §3.9).
//! Attributes are interpolated in `f64` with the perspective-correct weights of the pixel.

use glam::DVec3;
use rayon::prelude::*;

use crate::errors::error::Error;
use crate::errors::stop::Stop;
use crate::gl::vertex_colors::VertexColors;
use crate::memory::alloc::{count, try_collect, try_par_collect};
use crate::memory::pages::Zeroed;
use crate::memory::uninit::as_uninit;
use crate::normals::adjacency::index;
use crate::normals::face_normals;
use crate::numbers::real::Real;
use crate::render::mesh::Mesh;
use crate::render::options::Provoking;
use crate::render::raster::{Triangle, Viewport};
use crate::render::shader::{RenderModel, Shader};
use crate::render::texture::srgb_to_linear;
use crate::render::visibility::{window_row, Triangles, NO_TRIANGLE};

/// Faces per parallel task of the flat pass's gather of the provoking colours.
const FACES_PER_TASK: usize = 4096;

/// Σ weights[j] · rows[face[j]]: an attribute of the face's corners at a pixel.
#[inline]
fn interpolate<T: Real, const K: usize>(
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
fn shaded<T: Real>(out: &[T], n: usize, plane: usize, i: usize) -> [f64; 4] {
    let at = (plane * n + i) * 4;
    std::array::from_fn(|k| out[at + k].to_f64())
}

/// `data` cut into consecutive pieces of `counts[r]·width` values, one per image row.
///
/// # Errors
/// A memory error for the list of pieces.
fn split_rows<'a, X>(
    mut data: &'a mut [X],
    counts: &[usize],
    width: usize,
) -> Result<Vec<&'a mut [X]>, Error> {
    let pieces = counts.iter().map(|&count| {
        let (head, tail) = std::mem::take(&mut data).split_at_mut(count * width);
        data = tail;
        head
    });
    try_collect(pieces, "the image rows")
}

/// The visible pixels: which triangle is seen at each.
pub struct Frame<'a> {
    /// The image size.
    pub viewport: Viewport,
    /// The triangles, by id.
    pub triangles: &'a Triangles,
    /// The triangle id at each pixel, image rows top-down ([`NO_TRIANGLE`] where none).
    pub ids: &'a [u32],
    /// How many pixels each image row draws.
    counts: Vec<usize>,
}

impl<'a> Frame<'a> {
    /// The frame of a visibility buffer.
    ///
    /// # Errors
    /// A memory error for the row counts.
    pub fn new(
        viewport: Viewport,
        triangles: &'a Triangles,
        ids: &'a [u32],
    ) -> Result<Self, Error> {
        let counts = try_par_collect(
            ids.par_chunks(viewport.width)
                .map(|row| row.iter().filter(|&&id| id != NO_TRIANGLE).count()),
            "the row counts",
        )?;
        Ok(Self {
            viewport,
            triangles,
            ids,
            counts,
        })
    }

    /// The index of the first drawn pixel of each row among all drawn pixels, in row-major order.
    fn starts(&self) -> Result<Vec<usize>, Error> {
        let mut total = 0;
        let starts = self.counts.iter().map(|&c| {
            total += c;
            total - c
        });
        try_collect(starts, "the row starts")
    }

    /// Writes `colour(triangle, x, y, k)` (pixel (x, y) in window coordinates, the k-th drawn
    /// pixel) at every drawn pixel of `image` and `background` elsewhere, skipping the rows
    /// that start after `stop` is requested.
    ///
    /// # Errors
    /// A memory error for the row starts, or [`Error::interrupted`].
    fn paint<T: Real>(
        &self,
        image: &mut [T],
        background: [f64; 4],
        stop: &Stop,
        colour: impl Fn(&Triangle, usize, usize, usize) -> [f64; 4] + Sync,
    ) -> Result<(), Error> {
        let width = self.viewport.width;
        let starts = self.starts()?;
        image
            .par_chunks_mut(width * 4)
            .zip(self.ids.par_chunks(width))
            .enumerate()
            .for_each(|(row, (pixels, ids))| {
                if stop.is_requested() {
                    return;
                }
                let y = window_row(self.viewport, row);
                let mut k = starts[row];
                for (x, (pixel, &id)) in pixels.chunks_exact_mut(4).zip(ids).enumerate() {
                    let rgba = if id == NO_TRIANGLE {
                        background
                    } else {
                        k += 1;
                        colour(self.triangles.get(id), x, y, k - 1)
                    };
                    for (d, s) in pixel.iter_mut().zip(rgba) {
                        *d = T::from_f64(s);
                    }
                }
            });
        stop.check()
    }
}

/// One lighting pass over a frame: what every mode reads.
pub struct Pass<'a, T, M: RenderModel> {
    /// The lighting model and its options.
    pub shader: Shader<'a, M>,
    /// The mesh.
    pub mesh: &'a Mesh<'a, T>,
    /// The visible pixels.
    pub frame: Frame<'a>,
    /// The colour of the pixels no triangle covers.
    pub background: [f64; 4],
}

impl<T: Real, M: RenderModel> Pass<'_, T, M> {
    /// The texel that multiplies the fragment of `face` at `weights` (GL's model with a
    /// texture; `None` otherwise).
    #[inline]
    fn modulation(&self, face: [i64; 3], weights: DVec3) -> Option<[f64; 4]> {
        let textured = self.mesh.textured.filter(|_| M::MODULATES)?;
        Some(
            textured
                .texture
                .sample(interpolate(textured.uv, face, weights)),
        )
    }

    /// The colours the shader reads per vertex: the mesh's, or for the metallic-roughness
    /// model with a texture its texels at the vertices, decoded from sRGB (its base colours).
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
            .par_chunks_mut(4 * FACES_PER_TASK)
            .zip(textured.uv.par_chunks(FACES_PER_TASK))
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

    /// The mesh's colours, or `texels` (from [`Pass::vertex_colors`]) in their place.
    fn colors_or<'b>(&'b self, texels: Option<&'b Zeroed<T>>) -> Option<VertexColors<'b, T>> {
        match texels {
            Some(data) => Some(VertexColors { data, width: 4 }),
            None => self.mesh.colors,
        }
    }

    /// Gouraud: the vertices are lit with `normals` (one per vertex), the colours interpolated.
    ///
    /// # Errors
    /// Those of [`Shader::shade`]; a memory error for the vertex colours.
    pub fn gouraud(&self, normals: &[[T; 3]], image: &mut [T], stop: &Stop) -> Result<(), Error> {
        let clamp = self.shader.clamp();
        let mesh = self.mesh;
        let n = mesh.vertices.len();
        let len = count(&[self.shader.outputs(), n, 4], "the vertex colours")?;
        let mut colours = Zeroed::<T>::new(len, "the vertex colours")?;
        let texels = self.vertex_colors(stop)?;
        self.shader.shade(
            mesh.vertices,
            normals,
            self.colors_or(texels.as_ref()),
            as_uninit(&mut colours),
            stop,
        )?;
        let rows = colours.as_chunks::<4>().0;
        self.frame
            .paint(image, self.background, stop, |t, x, y, _| {
                let face = mesh.faces[t.face as usize];
                let weights = t.weights_at(x, y);
                let texel = self.modulation(face, weights);
                self.shader.fragment(t.front, clamp, texel, |plane| {
                    // The weights' sum may exceed 1 by an ulp: clamp, so the image stays in [0, 1].
                    let c = interpolate(&rows[plane * n..(plane + 1) * n], face, weights);
                    if clamp {
                        c.map(|c| c.clamp(0.0, 1.0))
                    } else {
                        c
                    }
                })
            })
    }

    /// Flat: each face is lit at its provoking vertex (or centroid) with its normal, the
    /// mesh's (one per face) or the face normal.
    ///
    /// # Errors
    /// Those of [`Shader::shade`] and [`face_normals`]; a memory error for the per-face buffers.
    pub fn flat(&self, provoking: Provoking, image: &mut [T], stop: &Stop) -> Result<(), Error> {
        let clamp = self.shader.clamp();
        let mesh = self.mesh;
        let m = mesh.faces.len();
        let computed;
        let normals = if let Some(n) = mesh.normals {
            n
        } else {
            let mut n = Zeroed::<[T; 3]>::new(m, "the face normals")?;
            face_normals(mesh.vertices, mesh.faces, &mut n, stop)?;
            computed = n;
            &computed
        };
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
                data.par_chunks_mut(FACES_PER_TASK * c.width)
                    .zip(mesh.faces.par_chunks(FACES_PER_TASK))
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
        self.shader
            .shade(&positions, normals, colors, as_uninit(&mut colours), stop)?;
        self.frame
            .paint(image, self.background, stop, |t, x, y, _| {
                let texel = self.modulation(mesh.faces[t.face as usize], t.weights_at(x, y));
                self.shader.fragment(t.front, clamp, texel, |plane| {
                    shaded(&colours, m, plane, t.face as usize)
                })
            })
    }

    /// Phong: positions, `normals` (one per vertex) and colours are interpolated to every drawn
    /// pixel, which are then lit in one call.
    ///
    /// # Errors
    /// Those of [`Shader::shade`]; a memory error for the pixel buffers.
    pub fn phong(&self, normals: &[[T; 3]], image: &mut [T], stop: &Stop) -> Result<(), Error> {
        let clamp = self.shader.clamp();
        let (mesh, frame) = (self.mesh, &self.frame);
        let total: usize = frame.counts.iter().sum();
        // The metallic-roughness model reads a texture's texels where it is evaluated.
        let base_texture = mesh.textured.filter(|_| !M::MODULATES);
        let color_width = if base_texture.is_some() {
            4
        } else {
            mesh.colors.map_or(0, |c| c.width)
        };
        let mut positions = Zeroed::<[T; 3]>::new(total, "the pixel positions")?;
        let mut pixel_normals = Zeroed::<[T; 3]>::new(total, "the pixel normals")?;
        let len = count(&[total, color_width], "the pixel colors")?;
        let mut colors = Zeroed::<T>::new(len, "the pixel colors")?;
        split_rows(&mut positions, &frame.counts, 1)?
            .into_par_iter()
            .zip(split_rows(&mut pixel_normals, &frame.counts, 1)?)
            .zip(split_rows(&mut colors, &frame.counts, color_width)?)
            .zip(frame.ids.par_chunks(frame.viewport.width))
            .enumerate()
            .for_each(|(row, (((positions, normals_out), colors), ids))| {
                if stop.is_requested() {
                    return;
                }
                let y = window_row(frame.viewport, row);
                let drawn = ids.iter().enumerate().filter(|(_, &id)| id != NO_TRIANGLE);
                for (k, (x, &id)) in drawn.enumerate() {
                    let t = frame.triangles.get(id);
                    let face = mesh.faces[t.face as usize];
                    let weights = t.weights_at(x, y);
                    positions[k] = interpolate(mesh.vertices, face, weights).map(T::from_f64);
                    normals_out[k] = interpolate(normals, face, weights).map(T::from_f64);
                    if let Some(textured) = base_texture {
                        let uv = interpolate(textured.uv, face, weights);
                        let texel = srgb_to_linear(textured.texture.sample(uv));
                        let out = &mut colors[k * 4..(k + 1) * 4];
                        for (d, t) in out.iter_mut().zip(texel) {
                            *d = T::from_f64(t);
                        }
                    } else if let Some(c) = mesh.colors {
                        let out = &mut colors[k * color_width..(k + 1) * color_width];
                        for (channel, value) in out.iter_mut().enumerate() {
                            let at = face.map(|i| c.data[index(i) * color_width + channel]);
                            *value = T::from_f64(weights.dot(DVec3::from_array(at.map(T::to_f64))));
                        }
                    }
                }
            });
        stop.check()?;
        let colors = (color_width > 0).then_some(VertexColors {
            data: &colors,
            width: color_width,
        });
        let len = count(&[self.shader.outputs(), total, 4], "the pixel colours")?;
        let mut colours = Zeroed::<T>::new(len, "the pixel colours")?;
        self.shader.shade(
            &positions,
            &pixel_normals,
            colors,
            as_uninit(&mut colours),
            stop,
        )?;
        self.frame
            .paint(image, self.background, stop, |t, x, y, k| {
                let texel = self.modulation(mesh.faces[t.face as usize], t.weights_at(x, y));
                self.shader.fragment(t.front, clamp, texel, |plane| {
                    shaded(&colours, total, plane, k)
                })
            })
    }
}
