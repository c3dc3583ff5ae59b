//! Lighting the visible pixels of a frame of one or more meshes ([`Layer`]s), each through its
//! own [`crate::render::shader::Shader`] (the model of its scene, placed by its model matrix):
//!
//! - **Gouraud**: the vertices are lit, and the colours interpolated (GL's smooth shading).
//! - **Phong**: positions, normals (and colours) are interpolated to every visible pixel centre,
//!   and each mesh's pixels are lit in one `shade` call.
//! - **Flat**: each face is lit once with its face normal, at its provoking vertex (the last
//!   one, GL's default; the first, Direct3D's) or its centroid (where PyTorch3D lights it),
//!   and the colour is constant over the face (`glShadeModel(GL_FLAT)`; a `flat` varying).
//!
//! Every pixel's colour comes from the front or the back colours by the facing of its triangle;
//! with a separate specular colour the two are summed and clamped (GL's colour sum, §3.9).
//! Attributes are interpolated in `f64` with the perspective-correct weights of the pixel.

use rayon::prelude::*;

use crate::errors::error::Error;
use crate::errors::stop::Stop;
use crate::gl::vertex_colors::VertexColors;
use crate::memory::alloc::{count, try_collect, try_filled, try_par_collect};
use crate::memory::pages::Zeroed;
use crate::memory::uninit::as_uninit;
use crate::numbers::real::Real;
use crate::render::frame::Frame;
use crate::render::layer::{interpolate, shaded, Layer, ROWS_PER_TASK};
use crate::render::options::Provoking;
use crate::render::shader::RenderModel;
use crate::render::transfer::Transfer;

/// The drawn pixels grouped by layer, for Phong shading: layer l's pixels are the slots
/// `starts[l]..starts[l + 1]`, in row-major order within a layer.
struct Groups {
    /// The image index of the pixel in each slot.
    pixels: Zeroed<u32>,
    /// Where each layer's slots start, and the total at the end.
    starts: Vec<usize>,
    /// The slot of the k-th drawn pixel (row-major); `None` when it is k (one layer).
    slots: Option<Vec<u32>>,
}

impl Groups {
    /// The slot of the k-th drawn pixel.
    #[inline]
    fn slot(&self, k: usize) -> usize {
        self.slots.as_ref().map_or(k, |s| s[k] as usize)
    }
}

/// One lighting pass over a frame: what every mode reads.
pub struct Pass<'a, T, M: RenderModel> {
    /// The meshes, in drawing order (their faces' frame indices increasing).
    pub layers: &'a [Layer<'a, T, M>],
    /// The visible pixels.
    pub frame: Frame<'a>,
    /// The colour of the pixels no triangle covers, as it is written.
    pub background: [f64; 4],
    /// How the drawn pixels' RGB is encoded.
    pub transfer: Transfer,
    /// Whether colours are clamped to [0, 1].
    pub clamp: bool,
}

impl<T: Real, M: RenderModel> Pass<'_, T, M> {
    /// The index of the layer that the frame's face `face` belongs to.
    #[inline]
    fn layer_of(&self, face: u32) -> usize {
        if self.layers.len() == 1 {
            return 0;
        }
        self.layers.partition_point(|l| l.first_face <= face) - 1
    }

    /// The drawn pixels grouped by layer (a stable counting sort).
    ///
    /// # Errors
    /// A memory error for the groups, or [`Error::interrupted`].
    #[allow(clippy::cast_possible_truncation)] // layers and pixels fewer than 2^32
    fn groups(&self, stop: &Stop) -> Result<Groups, Error> {
        let drawn = self.frame.drawn(stop)?;
        let total = drawn.len();
        if self.layers.len() == 1 {
            return Ok(Groups {
                pixels: drawn,
                starts: vec![0, total],
                slots: None,
            });
        }
        let layer_of_pixel: Vec<u32> = try_par_collect(
            drawn
                .par_iter()
                .map(|&p| self.layer_of(self.frame.at(p).0.face) as u32),
            "the pixels' layers",
        )?;
        stop.check()?;
        let mut starts = try_filled(self.layers.len() + 1, 0, "the layer starts")?;
        for &l in &layer_of_pixel {
            starts[l as usize + 1] += 1;
        }
        for l in 0..self.layers.len() {
            starts[l + 1] += starts[l];
        }
        let mut fill = try_collect(starts.iter().copied(), "the layer cursors")?;
        let mut pixels = Zeroed::<u32>::new(total, "the grouped pixels")?;
        let mut slots = try_filled(total, 0, "the pixels' slots")?;
        for (k, (&l, &p)) in layer_of_pixel.iter().zip(drawn.iter()).enumerate() {
            let s = &mut fill[l as usize];
            pixels[*s] = p;
            slots[k] = *s as u32;
            *s += 1;
        }
        Ok(Groups {
            pixels,
            starts,
            slots: Some(slots),
        })
    }

    /// Gouraud: the vertices are lit with the layers' normals (one per vertex), the colours
    /// interpolated.
    ///
    /// # Errors
    /// Those of the shaders; a memory error for the vertex colours.
    pub fn gouraud(&self, image: &mut [T], stop: &Stop) -> Result<(), Error> {
        let colours = self
            .layers
            .iter()
            .map(|layer| layer.lit_vertices(stop))
            .collect::<Result<Vec<_>, _>>()?;
        self.frame
            .paint(image, self.background, self.transfer, stop, |t, x, y, _| {
                let l = self.layer_of(t.face);
                let layer = &self.layers[l];
                let n = layer.mesh.vertices.len();
                let rows = colours[l].as_chunks::<4>().0;
                let face = layer.face(t.face);
                let weights = t.weights_at(x, y);
                let texel = layer.modulation(face, weights);
                layer.shader.fragment(t.front, self.clamp, texel, |plane| {
                    // The weights' sum may exceed 1 by an ulp: clamp, so the image stays in [0, 1].
                    let c = interpolate(&rows[plane * n..(plane + 1) * n], face, weights);
                    if self.clamp {
                        c.map(|c| c.clamp(0.0, 1.0))
                    } else {
                        c
                    }
                })
            })
    }

    /// Flat: each face is lit at its provoking vertex (or centroid) with its normal (one per
    /// face).
    ///
    /// # Errors
    /// Those of the shaders; a memory error for the per-face buffers.
    pub fn flat(&self, provoking: Provoking, image: &mut [T], stop: &Stop) -> Result<(), Error> {
        let colours = self
            .layers
            .iter()
            .map(|layer| layer.lit_faces(provoking, stop))
            .collect::<Result<Vec<_>, _>>()?;
        self.frame
            .paint(image, self.background, self.transfer, stop, |t, x, y, _| {
                let l = self.layer_of(t.face);
                let layer = &self.layers[l];
                let i = (t.face - layer.first_face) as usize;
                let texel = layer.modulation(layer.face(t.face), t.weights_at(x, y));
                layer.shader.fragment(t.front, self.clamp, texel, |plane| {
                    shaded(&colours[l], layer.mesh.faces.len(), plane, i)
                })
            })
    }

    /// Phong: positions, normals (one per vertex) and colours are interpolated to every drawn
    /// pixel, and each layer's pixels are then lit in one call.
    ///
    /// # Errors
    /// Those of the shaders; a memory error for the pixel buffers.
    pub fn phong(&self, image: &mut [T], stop: &Stop) -> Result<(), Error> {
        let groups = self.groups(stop)?;
        let colours = self
            .layers
            .iter()
            .enumerate()
            .map(|(l, layer)| {
                let pixels = &groups.pixels[groups.starts[l]..groups.starts[l + 1]];
                self.lit_pixels(layer, pixels, stop)
            })
            .collect::<Result<Vec<_>, _>>()?;
        self.frame
            .paint(image, self.background, self.transfer, stop, |t, x, y, k| {
                let l = self.layer_of(t.face);
                let layer = &self.layers[l];
                let (start, n) = (groups.starts[l], groups.starts[l + 1] - groups.starts[l]);
                let texel = layer.modulation(layer.face(t.face), t.weights_at(x, y));
                layer.shader.fragment(t.front, self.clamp, texel, |plane| {
                    shaded(&colours[l], n, plane, groups.slot(k) - start)
                })
            })
    }

    /// `layer` lit at `pixels` (image indices of pixels it covers): the model's planes of RGBA
    /// rows, one per pixel.
    ///
    /// # Errors
    /// Those of the shader; a memory error for the pixel buffers.
    fn lit_pixels(
        &self,
        layer: &Layer<'_, T, M>,
        pixels: &[u32],
        stop: &Stop,
    ) -> Result<Zeroed<T>, Error> {
        let total = pixels.len();
        let width = layer.color_width();
        let mut positions = Zeroed::<[T; 3]>::new(total, "the pixel positions")?;
        let mut normals = Zeroed::<[T; 3]>::new(total, "the pixel normals")?;
        let len = count(&[total, width], "the pixel colors")?;
        let mut colors = Zeroed::<T>::new(len, "the pixel colors")?;
        positions
            .par_chunks_mut(ROWS_PER_TASK)
            .zip(normals.par_chunks_mut(ROWS_PER_TASK))
            .zip(pixels.par_chunks(ROWS_PER_TASK))
            .for_each(|((positions, normals), pixels)| {
                if stop.is_requested() {
                    return;
                }
                for ((p, n), &pixel) in positions.iter_mut().zip(normals).zip(pixels) {
                    let (t, x, y) = self.frame.at(pixel);
                    let (face, weights) = (layer.face(t.face), t.weights_at(x, y));
                    *p = interpolate(layer.mesh.vertices, face, weights).map(T::from_f64);
                    *n = interpolate(layer.normals, face, weights).map(T::from_f64);
                }
            });
        if width > 0 {
            colors
                .par_chunks_mut(ROWS_PER_TASK * width)
                .zip(pixels.par_chunks(ROWS_PER_TASK))
                .for_each(|(colors, pixels)| {
                    if stop.is_requested() {
                        return;
                    }
                    for (c, &pixel) in colors.chunks_exact_mut(width).zip(pixels) {
                        let (t, x, y) = self.frame.at(pixel);
                        layer.color_at(layer.face(t.face), t.weights_at(x, y), c);
                    }
                });
        }
        stop.check()?;
        let colors = (width > 0).then_some(VertexColors {
            data: &colors,
            width,
        });
        let len = count(&[layer.shader.outputs(), total, 4], "the pixel colours")?;
        let mut colours = Zeroed::<T>::new(len, "the pixel colours")?;
        layer
            .shader
            .shade(&positions, &normals, colors, as_uninit(&mut colours), stop)?;
        Ok(colours)
    }
}
