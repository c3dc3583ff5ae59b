//! Rendering a triangle mesh with flat, Gouraud or Phong shading: GL 2.1's pipeline (§2.11–3.5)
//! around the one lighting equation. Vertices go to clip coordinates, faces are clipped
//! ([`clip`]) and set up ([`raster`]), the nearest triangle is found at every pixel
//! ([`visibility`]), and the visible pixels are lit ([`passes`]).
//!
//! The render layer, top of the core: besides those four, [`camera`] (view and projection),
//! [`mesh`] (what is drawn), [`options`] (how) and [`shader`] (the model of the scene, placed
//! for the camera: GL's, glTF's or three.js'). Uses
//! every layer below it: [`crate::normals`], [`crate::lighting`], [`crate::gl`],
//! [`crate::gltf`], [`crate::threejs`], [`crate::numbers`], [`crate::simd`], [`crate::memory`]
//! and [`crate::errors`].

pub mod camera;
pub mod clip;
pub mod mesh;
pub mod options;
pub mod passes;
pub mod raster;
pub mod shader;
pub mod texture;
pub mod visibility;

use glam::{DMat4, DVec4};
use rayon::prelude::*;

use crate::errors::error::Error;
use crate::errors::stop::Stop;
use crate::gl::vertex_colors::VertexColors;
use crate::memory::alloc::{count, try_par_collect, try_reserve, try_with_capacity};
use crate::memory::pages::Zeroed;
use crate::normals::adjacency::index;
use crate::normals::{check_faces, vertex_normals, Weighting};
use crate::numbers::real::Real;
use crate::render::camera::{check_affine, Camera};
use crate::render::clip::clip_triangle;
use crate::render::mesh::Mesh;
use crate::render::options::{RenderOptions, Shading};
use crate::render::passes::{Frame, Pass};
use crate::render::raster::{Cull, Triangle, Viewport};
use crate::render::shader::{RenderModel, Shader};
use crate::render::visibility::{visibility, Triangles, CHUNK_BITS, MAX_CHUNKS};

/// Faces per parallel task in triangle setup: a chunk of triangles, since clipping makes at most
/// seven of a face.
const FACES_PER_TASK: usize = 4096;
const _: () = assert!(7 * FACES_PER_TASK < 1 << CHUNK_BITS);

/// Checks the arguments of [`render`] that the lighting equation does not check itself.
fn validate<T: Real>(
    mesh: &Mesh<'_, T>,
    camera: &Camera,
    options: &RenderOptions,
    pixels: usize,
    depth: usize,
) -> Result<(), Error> {
    options.viewport.validate()?;
    let Viewport { width, height } = options.viewport;
    let area = count(&[width, height], "the image")?;
    if Some(pixels) != area.checked_mul(4) || depth != area {
        return Err(Error::value(format!(
            "the image must hold {height} x {width} x 4 values and the depth {height} x {width}, \
             got {pixels} and {depth}"
        )));
    }
    camera.validate()?;
    check_affine(&options.model, "model")?;
    if !options.background.iter().all(|c| c.is_finite()) {
        return Err(Error::value(format!(
            "background must be finite, got {:?}",
            options.background
        )));
    }
    check_faces(mesh.faces, mesh.vertices.len())?;
    let most = MAX_CHUNKS * FACES_PER_TASK;
    if mesh.faces.len() > most {
        return Err(Error::value(format!(
            "faces must number at most {most}, got {}",
            mesh.faces.len()
        )));
    }
    let (rows, what) = match options.shading {
        Shading::Flat => (mesh.faces.len(), "one per face for flat shading"),
        _ => (mesh.vertices.len(), "one per vertex"),
    };
    if let Some(normals) = mesh.normals {
        if normals.len() != rows {
            return Err(Error::value(format!(
                "normals must have {rows} rows ({what}), got {}",
                normals.len()
            )));
        }
    }
    if let Some(textured) = mesh.textured {
        textured.texture.validate()?;
        if textured.uv.len() != mesh.vertices.len() {
            return Err(Error::value(format!(
                "uv must have one row per vertex ({}), got {}",
                mesh.vertices.len(),
                textured.uv.len()
            )));
        }
    }
    if let Some(c) = mesh.colors {
        if c.data.len() != mesh.vertices.len() * c.width {
            return Err(Error::value(format!(
                "colors must have one row per vertex ({}), got {}",
                mesh.vertices.len(),
                c.data.len() / c.width.max(1)
            )));
        }
    }
    Ok(())
}

/// The triangles to rasterise, face by face in order, after clipping and culling; `stop` is
/// polled per task of [`FACES_PER_TASK`] faces.
///
/// # Errors
/// A memory error for the clip coordinates or the triangles, or [`Error::interrupted`].
fn setup<T: Real>(
    mesh: &Mesh<'_, T>,
    to_clip: DMat4,
    viewport: Viewport,
    cull: Cull,
    stop: &Stop,
) -> Result<Triangles, Error> {
    let clip: Vec<DVec4> = try_par_collect(
        mesh.vertices
            .par_iter()
            .map(|v| to_clip * DVec4::new(v[0].to_f64(), v[1].to_f64(), v[2].to_f64(), 1.0)),
        "the clip coordinates",
    )?;
    let results = try_par_collect(
        mesh.faces
            .par_chunks(FACES_PER_TASK)
            .enumerate()
            .map(|(chunk, faces)| {
                stop.check()?;
                let mut out = try_with_capacity(faces.len(), "the triangles")?;
                for (k, face) in faces.iter().enumerate() {
                    // Clipping makes at most seven triangles of a face: room first, then no
                    // allocation in `extend`.
                    try_reserve(&mut out, 7, "the triangles")?;
                    let face_index = (chunk * FACES_PER_TASK + k) as u32;
                    clip_triangle(face.map(|i| clip[index(i)]), |corners| {
                        out.extend(Triangle::new(face_index, corners, viewport, cull));
                    });
                }
                Ok(out)
            }),
        "the triangle chunks",
    )?;
    let mut chunks = try_with_capacity(results.len(), "the triangle chunks")?;
    for chunk in results {
        chunks.push(chunk?);
    }
    Ok(Triangles { chunks })
}

/// Renders `mesh` seen by `camera` under `scene` into `image` ((height, width, 4) RGBA, row 0
/// at the top) and `depth` ((height, width) window depth in [0, 1], 1 where nothing is drawn),
/// lit by the model of `scene` ([`RenderModel`]).
///
/// GL's scene: lights and the viewer are in eye coordinates, as for
/// [`crate::lighting::model::shade`]; positions reach eye coordinates through
/// `camera.view · options.model`. A world model's scene (glTF's metallic-roughness model,
/// three.js' `MeshPhongMaterial`) is in world coordinates, its viewer replaced by the camera's
/// and its normals always normalised (`options.normalize`, `rescale_normal` and
/// `color_material` do not apply); it takes vertex colours or a texture, not both.
///
/// Pixels no triangle covers get `options.background`. A face with a vertex that is not
/// finite after the transform is not drawn; a NaN normal or colour gives NaN pixels, as in
/// `shade`. The result is the same for any number of threads.
///
/// `stop` is polled by every pass, at least once per task of rows, faces or triangles; once it
/// is requested the rest of the work is skipped and `image` and `depth` are left part-drawn.
///
/// # Errors
/// A value error for a bad size, camera, model, background, normals, colours or shading
/// option; an index error for a face index out of range; a memory error when a scratch buffer
/// cannot be allocated; [`Error::interrupted`] when `stop` was requested before the call
/// finished.
pub fn render<T: Real, M: RenderModel>(
    scene: &M,
    mesh: &Mesh<'_, T>,
    camera: &Camera,
    options: &RenderOptions,
    image: &mut [T],
    depth: &mut [T],
    stop: &Stop,
) -> Result<(), Error> {
    validate(mesh, camera, options, image.len(), depth.len())?;
    if let Some(takes) = M::COLORS_OR_TEXTURE {
        if mesh.textured.is_some() && mesh.colors.is_some() {
            return Err(Error::value(format!("{takes}, not both")));
        }
    }
    let shader = Shader::new(scene, camera, options, mesh.textured.is_some())?;
    draw(shader, mesh, camera, options, image, depth, stop)
}

/// The pipeline of [`render`] after validation, lit by `shader`.
fn draw<T: Real, M: RenderModel>(
    shader: Shader<'_, M>,
    mesh: &Mesh<'_, T>,
    camera: &Camera,
    options: &RenderOptions,
    image: &mut [T],
    depth: &mut [T],
    stop: &Stop,
) -> Result<(), Error> {
    // A call on no vertices checks the options against the scene before any work is done.
    let no_colors = mesh.colors.map(|c| VertexColors {
        data: &c.data[..0],
        width: c.width,
    });
    shader.shade::<T>(&[], &[], no_colors, &mut [], stop)?;

    let viewport = options.viewport;
    let to_clip = camera.projection * camera.view * options.model;
    let triangles = setup(mesh, to_clip, viewport, options.cull, stop)?;
    // Zeroed: a large buffer is mapped, not written; visibility clears it band by band.
    let mut ids = Zeroed::<u32>::new(viewport.width * viewport.height, "the triangle ids")?;
    visibility(&triangles, viewport, &mut ids, depth, stop)?;
    let pass = Pass {
        shader,
        mesh,
        frame: Frame::new(viewport, &triangles, &ids)?,
        background: options.background,
    };
    if options.shading == Shading::Flat {
        return pass.flat(options.provoking, image, stop);
    }
    let computed;
    let normals = if let Some(n) = mesh.normals {
        n
    } else {
        let mut n = Zeroed::<[T; 3]>::new(mesh.vertices.len(), "the vertex normals")?;
        vertex_normals(mesh.vertices, mesh.faces, Weighting::Angle, &mut n, stop)?;
        computed = n;
        &computed
    };
    if options.shading == Shading::Gouraud {
        pass.gouraud(normals, image, stop)
    } else {
        pass.phong(normals, image, stop)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gl::material::Material;
    use crate::gl::scene::Scene;
    use crate::render::options::Provoking;

    fn emission_scene() -> Scene {
        Scene {
            material: Material {
                ambient: [0.0; 4],
                diffuse: [0.0, 0.0, 0.0, 1.0],
                emission: [0.25, 0.5, 0.75, 1.0],
                ..Material::default()
            },
            global_ambient: [0.0; 4],
            ..Scene::default()
        }
    }

    /// A square of side 2 at depth `z`, in two triangles.
    const QUAD: [[f64; 3]; 4] = [
        [-1.0, -1.0, 0.2],
        [1.0, -1.0, 0.2],
        [1.0, 1.0, 0.2],
        [-1.0, 1.0, 0.2],
    ];
    const QUAD_FACES: [[i64; 3]; 2] = [[0, 1, 2], [0, 2, 3]];

    fn draw(mesh: &Mesh<'_, f64>, options: &RenderOptions) -> Result<(Vec<f64>, Vec<f64>), Error> {
        let Viewport { width, height } = options.viewport;
        let mut image = vec![0.0; width * height * 4];
        let mut depth = vec![0.0; width * height];
        render(
            &emission_scene().validated().unwrap(),
            mesh,
            &Camera::default(),
            options,
            &mut image,
            &mut depth,
            &Stop::new(),
        )?;
        Ok((image, depth))
    }

    fn quad() -> Mesh<'static, f64> {
        Mesh {
            vertices: &QUAD,
            faces: &QUAD_FACES,
            normals: None,
            colors: None,
            textured: None,
        }
    }

    #[test]
    fn a_screen_filling_quad_covers_every_pixel() {
        for shading in [Shading::Flat, Shading::Gouraud, Shading::Phong] {
            let options = RenderOptions {
                viewport: Viewport {
                    width: 7,
                    height: 5,
                },
                shading,
                ..RenderOptions::default()
            };
            let (image, depth) = draw(&quad(), &options).unwrap();
            let expected = [0.25, 0.5, 0.75, 1.0];
            let close = |p: &[f64]| p.iter().zip(expected).all(|(a, b)| (a - b).abs() < 1e-15);
            assert!(image.chunks(4).all(close), "{shading:?}");
            assert!(depth.iter().all(|&z| (z - 0.6).abs() < 1e-15));
        }
    }

    #[test]
    fn bad_arguments_are_rejected_before_any_work() {
        let mut options = RenderOptions::default();
        options.viewport.width = 0;
        assert!(draw(&quad(), &options)
            .unwrap_err()
            .message
            .starts_with("width"));
        let faces = [[0, 1, 4]];
        let mesh = Mesh {
            faces: &faces,
            ..quad()
        };
        let err = draw(&mesh, &RenderOptions::default()).unwrap_err();
        assert_eq!(err.kind, crate::errors::error::ErrorKind::Index);
        let normals = [[0.0, 0.0, 1.0]; 4];
        let mesh = Mesh {
            normals: Some(&normals),
            ..quad()
        };
        let flat = RenderOptions {
            shading: Shading::Flat,
            ..RenderOptions::default()
        };
        assert!(draw(&mesh, &flat)
            .unwrap_err()
            .message
            .contains("one per face"));
    }

    #[test]
    fn every_pass_sees_a_requested_stop() {
        // `render` itself stops at its first check; each later pass must stop on its own.
        let (stop, viewport) = (
            Stop::new(),
            Viewport {
                width: 7,
                height: 5,
            },
        );
        let to_clip = DMat4::IDENTITY;
        let triangles = setup(&quad(), to_clip, viewport, Cull::None, &stop).unwrap();
        let mut ids = vec![0; 35];
        let mut depth = vec![0.0_f64; 35];
        visibility(&triangles, viewport, &mut ids, &mut depth, &stop).unwrap();
        stop.request();
        let interrupted = |e: Error| e.kind == crate::errors::error::ErrorKind::Interrupted;
        assert!(interrupted(
            setup(&quad(), to_clip, viewport, Cull::None, &stop).unwrap_err()
        ));
        let err = visibility(&triangles, viewport, &mut ids, &mut depth, &stop).unwrap_err();
        assert!(interrupted(err));
        let scene = emission_scene().validated().unwrap();
        let camera = Camera::default();
        let pass = Pass {
            shader: Shader::new(&scene, &camera, &RenderOptions::default(), false).unwrap(),
            mesh: &quad(),
            frame: Frame::new(viewport, &triangles, &ids).unwrap(),
            background: [0.0; 4],
        };
        let normals = [[0.0, 0.0, 1.0]; 4];
        let mut image = vec![0.0; 35 * 4];
        assert!(interrupted(
            pass.flat(Provoking::Last, &mut image, &stop).unwrap_err()
        ));
        assert!(interrupted(
            pass.gouraud(&normals, &mut image, &stop).unwrap_err()
        ));
        assert!(interrupted(
            pass.phong(&normals, &mut image, &stop).unwrap_err()
        ));
    }

    #[test]
    fn gouraud_colours_stay_in_the_unit_interval() {
        // White vertices: the interpolation weights of a pixel may sum to 1 + ulp.
        let scene = Scene {
            material: Material {
                emission: [1.0; 4],
                ..Material::default()
            },
            ..emission_scene()
        };
        let vertices: Vec<[f64; 3]> = (0..60)
            .map(|i| {
                let t = f64::from(i) * 0.731;
                [0.9 * t.sin(), 0.8 * t.cos(), 0.3 * (t * 1.7).sin()]
            })
            .collect();
        let faces: Vec<[i64; 3]> = (0..58).map(|i| [i, i + 1, i + 2]).collect();
        let mesh = Mesh {
            vertices: &vertices,
            faces: &faces,
            normals: None,
            colors: None,
            textured: None,
        };
        let options = RenderOptions {
            viewport: Viewport {
                width: 97,
                height: 89,
            },
            shading: Shading::Gouraud,
            ..RenderOptions::default()
        };
        let (width, height) = (97, 89);
        let mut image = vec![0.0; width * height * 4];
        let mut depth = vec![0.0; width * height];
        render(
            &scene.validated().unwrap(),
            &mesh,
            &Camera::default(),
            &options,
            &mut image,
            &mut depth,
            &Stop::new(),
        )
        .unwrap();
        assert!(depth.iter().any(|&z| z < 1.0));
        assert!(image.iter().all(|&c| (0.0..=1.0).contains(&c)));
    }

    #[test]
    fn results_do_not_depend_on_the_thread_count() {
        // A fan of thin triangles through the near and far planes and past the guard band.
        let vertices: Vec<[f64; 3]> = (0..200)
            .map(|i| {
                let t = f64::from(i) * 0.37;
                [3.0 * t.sin(), 2.0 * t.cos(), 1.5 * (t * 0.5).sin()]
            })
            .collect();
        let faces: Vec<[i64; 3]> = (0..198).map(|i| [0, i + 1, i + 2]).collect();
        let mesh = Mesh {
            vertices: &vertices,
            faces: &faces,
            normals: None,
            colors: None,
            textured: None,
        };
        let options = RenderOptions {
            viewport: Viewport {
                width: 90,
                height: 70,
            },
            ..RenderOptions::default()
        };
        let run = |threads: usize| {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap();
            pool.install(|| draw(&mesh, &options).unwrap())
        };
        let (one, three) = (run(1), run(3));
        assert!(one.1.iter().any(|&z| z < 1.0));
        assert_eq!(one, three);
    }
}
