//! Rendering triangle meshes with flat, Gouraud or Phong shading: GL 2.1's pipeline (§2.11–3.5)
//! around the one lighting equation. Vertices go to clip coordinates, faces are clipped
//! ([`clip`]) and set up ([`raster`]), the nearest triangle is found at every pixel
//! ([`visibility`]), and the visible pixels are lit ([`passes`]). A frame holds one mesh
//! ([`render`]) or several, each with its own model matrix, scene and culling
//! ([`render_draws`]), depth-tested together as GL draws them one after another.
//!
//! The render layer, top of the core: besides those four, [`camera`] (view and projection),
//! [`mesh`] (what is drawn), [`options`] (how), [`shader`] (the model of the scene, placed
//! for the camera: GL's, glTF's or three.js'), [`frame`] (the visible pixels) and [`layer`]
//! (one mesh of a frame, lit). Uses
//! every layer below it: [`crate::normals`], [`crate::lighting`], [`crate::gl`],
//! [`crate::gltf`], [`crate::threejs`], [`crate::numbers`], [`crate::simd`], [`crate::memory`]
//! and [`crate::errors`].

pub mod camera;
pub mod clip;
pub mod frame;
pub mod layer;
pub mod mesh;
pub mod options;
pub mod passes;
pub mod placement;
pub mod points;
pub mod raster;
pub mod shader;
pub mod texture;
pub mod transfer;
pub mod visibility;

use glam::{DMat4, DVec4};
use rayon::prelude::*;

use crate::errors::error::Error;
use crate::errors::stop::Stop;
use crate::gl::vertex_colors::VertexColors;
use crate::lighting::clamp::ColorClamp;
use crate::memory::alloc::{count, try_collect, try_par_collect, try_reserve, try_with_capacity};
use crate::memory::pages::Zeroed;
use crate::normals::adjacency::index;
use crate::normals::{check_faces, face_normals, vertex_normals, Weighting};
use crate::numbers::real::Real;
use crate::render::camera::{check_affine, Camera};
use crate::render::clip::clip_triangle;
use crate::render::frame::Frame;
use crate::render::layer::Layer;
use crate::render::mesh::{Draw, Mesh};
use crate::render::options::{RenderOptions, Shading};
use crate::render::passes::Pass;
use crate::render::placement::{place, Placement};
use crate::render::raster::{Triangle, Viewport};
use crate::render::shader::{RenderModel, Shader};
use crate::render::visibility::{visibility, Triangles, CHUNK_BITS, MAX_CHUNKS};

/// Faces per parallel task in triangle setup: a chunk of triangles, since clipping makes at most
/// seven of a face.
const FACES_PER_TASK: usize = 4096;
const _: () = assert!(7 * FACES_PER_TASK < 1 << CHUNK_BITS);

/// Checks the frame's arguments of [`render_draws`]: the sizes, the camera and the background.
fn validate_frame(
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
    if !options.background.iter().all(|c| c.is_finite()) {
        return Err(Error::value(format!(
            "background must be finite, got {:?}",
            options.background
        )));
    }
    Ok(())
}

/// Checks a draw's mesh and model matrix, and what its model takes.
fn validate<T: Real, M: RenderModel>(draw: &Draw<'_, T, M>, shading: Shading) -> Result<(), Error> {
    let mesh = &draw.mesh;
    check_affine(&draw.model, "model")?;
    check_faces(mesh.faces, mesh.vertices.len())?;
    let (rows, what) = match shading {
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
    if let Some(takes) = M::COLORS_OR_TEXTURE {
        if mesh.textured.is_some() && mesh.colors.is_some() {
            return Err(Error::value(format!("{takes}, not both")));
        }
    }
    Ok(())
}

/// The frame's index of each draw's first face, and the total; a value error when the frame
/// has more faces, or more chunks of them, than triangle ids can number.
fn first_faces<T, M>(draws: &[Draw<'_, T, M>]) -> Result<(Vec<u32>, usize), Error> {
    let (mut total, mut chunks) = (0_usize, 0_usize);
    let mut firsts = try_with_capacity(draws.len(), "the first faces")?;
    for draw in draws {
        #[allow(clippy::cast_possible_truncation)] // below MAX_CHUNKS · FACES_PER_TASK < 2^32
        firsts.push(total as u32);
        total = total.saturating_add(draw.mesh.faces.len());
        chunks = chunks.saturating_add(draw.mesh.faces.len().div_ceil(FACES_PER_TASK));
    }
    let most = MAX_CHUNKS * FACES_PER_TASK;
    if total > most {
        return Err(Error::value(format!(
            "faces must number at most {most}, got {total}"
        )));
    }
    if chunks > MAX_CHUNKS {
        return Err(Error::value(format!(
            "the meshes' faces must fill at most {MAX_CHUNKS} chunks of {FACES_PER_TASK} \
             faces (each mesh's own), got {chunks}"
        )));
    }
    Ok((firsts, total))
}

/// The triangles to rasterise, draw by draw and face by face in order, after clipping and
/// culling; `stop` is polled per task of [`FACES_PER_TASK`] faces.
///
/// # Errors
/// A memory error for the clip coordinates or the triangles, or [`Error::interrupted`].
fn setup<T: Real, M: Sync>(
    draws: &[Draw<'_, T, M>],
    first_faces: &[u32],
    camera: &Camera,
    viewport: Viewport,
    stop: &Stop,
) -> Result<Triangles, Error> {
    let clips = draws
        .iter()
        .map(|draw| {
            let to_clip = camera.projection * camera.view * draw.model;
            try_par_collect(
                draw.mesh.vertices.par_iter().map(|v| {
                    to_clip * DVec4::new(v[0].to_f64(), v[1].to_f64(), v[2].to_f64(), 1.0)
                }),
                "the clip coordinates",
            )
        })
        .collect::<Result<Vec<Vec<DVec4>>, _>>()?;
    // Every draw's chunks of faces, in order: the tasks run in parallel across draws.
    let chunks = draws
        .iter()
        .map(|d| d.mesh.faces.len().div_ceil(FACES_PER_TASK));
    let mut tasks = try_with_capacity(chunks.clone().sum(), "the triangle tasks")?;
    for (d, count) in chunks.enumerate() {
        tasks.extend((0..count).map(|c| (d, c)));
    }
    let results = try_par_collect(
        tasks.par_iter().map(|&(d, chunk)| {
            stop.check()?;
            let (draw, clip) = (&draws[d], &clips[d]);
            let start = chunk * FACES_PER_TASK;
            let faces =
                &draw.mesh.faces[start..(start + FACES_PER_TASK).min(draw.mesh.faces.len())];
            let mut out = try_with_capacity(faces.len(), "the triangles")?;
            for (k, face) in faces.iter().enumerate() {
                // Clipping makes at most seven triangles of a face: room first, then no
                // allocation in `extend`.
                try_reserve(&mut out, 7, "the triangles")?;
                #[allow(clippy::cast_possible_truncation)] // checked by `first_faces`
                let face_index = first_faces[d] + (start + k) as u32;
                clip_triangle(face.map(|i| clip[index(i)]), |corners| {
                    out.extend(Triangle::new(face_index, corners, viewport, draw.cull));
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
    let draw = Draw {
        mesh: *mesh,
        scene,
        model: options.model,
        cull: options.cull,
        placement: Placement::Model,
    };
    render_draws(&[draw], camera, options, image, depth, stop)
}

/// Renders `draws` into one frame as [`render`] renders one mesh: every draw's triangles
/// depth-tested together in the order given (the first drawn wins a tie, as GL's `GL_LESS`),
/// each placed by its own model matrix where its [`Placement`] says, lit by its own scene and
/// culled by its own rule (`options.model` and `options.cull` are not read); the other options
/// are the frame's.
///
/// # Errors
/// Those of [`render`], a mesh's prefixed with its index in `draws` when there are several;
/// a value error when the draws have more faces than triangle ids can number.
pub fn render_draws<T: Real, M: RenderModel>(
    draws: &[Draw<'_, T, M>],
    camera: &Camera,
    options: &RenderOptions,
    image: &mut [T],
    depth: &mut [T],
    stop: &Stop,
) -> Result<(), Error> {
    validate_frame(camera, options, image.len(), depth.len())?;
    let named = |d: usize| {
        move |mut e: Error| {
            if draws.len() > 1 {
                e.message = format!("draws[{d}]: {}", e.message).into();
            }
            e
        }
    };
    let (firsts, _) = first_faces(draws)?;
    let mut shaders = try_with_capacity(draws.len(), "the shaders")?;
    for (d, draw) in draws.iter().enumerate() {
        validate(draw, options.shading).map_err(named(d))?;
        let placed = RenderOptions {
            model: match draw.placement {
                Placement::Model => draw.model,
                Placement::Vertices => DMat4::IDENTITY,
            },
            cull: draw.cull,
            ..*options
        };
        let shader = Shader::new(draw.scene, camera, &placed, draw.mesh.textured.is_some())
            .map_err(named(d))?;
        // A call on no vertices checks the options against the scene before any work is done.
        let no_colors = draw.mesh.colors.map(|c| VertexColors {
            data: &c.data[..0],
            width: c.width,
        });
        shader
            .shade::<T>(&[], &[], no_colors, &mut [], stop)
            .map_err(named(d))?;
        shaders.push(shader);
    }
    let placed = draws
        .iter()
        .map(|draw| match draw.placement {
            Placement::Model => Ok(None),
            Placement::Vertices => {
                place(draw.mesh.vertices, draw.mesh.normals, draw.model, stop).map(Some)
            }
        })
        .collect::<Result<Vec<_>, _>>()?;
    let placed_draws = draws
        .iter()
        .zip(&placed)
        .map(|(draw, placed)| match placed {
            None => *draw,
            Some(p) => Draw {
                mesh: Mesh {
                    vertices: &p.vertices,
                    normals: p.normals.as_deref(),
                    ..draw.mesh
                },
                model: DMat4::IDENTITY,
                placement: Placement::Model,
                ..*draw
            },
        });
    let draws = try_collect(placed_draws, "the placed draws")?;
    let draws = &draws[..];
    let viewport = options.viewport;
    let triangles = setup(draws, &firsts, camera, viewport, stop)?;
    // Zeroed: a large buffer is mapped, not written; visibility clears it band by band.
    let mut ids = Zeroed::<u32>::new(viewport.width * viewport.height, "the triangle ids")?;
    visibility(&triangles, viewport, &mut ids, depth, stop)?;
    let computed = draws
        .iter()
        .map(|draw| normals_of(&draw.mesh, options.shading, stop))
        .collect::<Result<Vec<_>, _>>()?;
    let layers = draws.iter().zip(shaders).zip(&computed).zip(firsts).map(
        |(((draw, shader), computed), first_face)| Layer {
            shader,
            mesh: &draw.mesh,
            normals: draw.mesh.normals.or(computed.as_deref()).unwrap_or(&[]),
            first_face,
        },
    );
    let layers = try_collect(layers, "the layers")?;
    let pass = Pass {
        layers: &layers,
        frame: Frame::new(viewport, &triangles, &ids)?,
        background: options.background,
        transfer: options.transfer,
        clamp: options.clamp == ColorClamp::On,
    };
    match options.shading {
        Shading::Flat => pass.flat(options.provoking, image, stop),
        Shading::Gouraud => pass.gouraud(image, stop),
        Shading::Phong => pass.phong(image, stop),
    }
}

/// Renders `draws` once for each camera of `cameras`, as [`render_draws`] renders one view,
/// into consecutive frames of `images` (k × height × width × 4) and `depths` (k × height ×
/// width): what does not depend on the view, the normals a mesh placed by its model matrix
/// lacks, is computed once. Each view's pixels are those [`render_draws`] gives it alone.
///
/// # Errors
/// Those of [`render_draws`]; a value error when `images` and `depths` do not hold one frame
/// a camera.
pub fn render_views<T: Real, M: RenderModel>(
    draws: &[Draw<'_, T, M>],
    cameras: &[Camera],
    options: &RenderOptions,
    images: &mut [T],
    depths: &mut [T],
    stop: &Stop,
) -> Result<(), Error> {
    options.viewport.validate()?;
    let Viewport { width, height } = options.viewport;
    let area = count(&[width, height], "the image")?;
    let views = cameras.len();
    if views == 0
        || Some(images.len()) != area.checked_mul(4 * views)
        || depths.len() != area * views
    {
        return Err(Error::value(format!(
            "the images must hold {views} x {height} x {width} x 4 values and the depths \
             {views} x {height} x {width}, for at least one camera, got {} and {}",
            images.len(),
            depths.len()
        )));
    }
    for draw in draws {
        check_faces(draw.mesh.faces, draw.mesh.vertices.len())?;
    }
    let computed = draws
        .iter()
        .map(|draw| match draw.placement {
            Placement::Model => normals_of(&draw.mesh, options.shading, stop),
            // Placed per vertex first: their normals come from the placed vertices.
            Placement::Vertices => Ok(None),
        })
        .collect::<Result<Vec<_>, _>>()?;
    let shared = draws.iter().zip(&computed).map(|(draw, computed)| Draw {
        mesh: Mesh {
            normals: draw.mesh.normals.or(computed.as_deref()),
            ..draw.mesh
        },
        ..*draw
    });
    let shared = try_collect(shared, "the draws")?;
    let frames = images.chunks_mut(area * 4).zip(depths.chunks_mut(area));
    for (camera, (image, depth)) in cameras.iter().zip(frames) {
        render_draws(&shared, camera, options, image, depth, stop)?;
    }
    Ok(())
}

/// The normals `mesh` lacks for `shading`: its face normals for flat shading, its
/// angle-weighted vertex normals otherwise; `None` when it has its own.
///
/// # Errors
/// A memory error for the normals, or [`Error::interrupted`].
fn normals_of<T: Real>(
    mesh: &Mesh<'_, T>,
    shading: Shading,
    stop: &Stop,
) -> Result<Option<Zeroed<[T; 3]>>, Error> {
    if mesh.normals.is_some() {
        return Ok(None);
    }
    if shading == Shading::Flat {
        let mut n = Zeroed::<[T; 3]>::new(mesh.faces.len(), "the face normals")?;
        face_normals(mesh.vertices, mesh.faces, &mut n, stop)?;
        Ok(Some(n))
    } else {
        let mut n = Zeroed::<[T; 3]>::new(mesh.vertices.len(), "the vertex normals")?;
        vertex_normals(mesh.vertices, mesh.faces, Weighting::Angle, &mut n, stop)?;
        Ok(Some(n))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gl::material::Material;
    use crate::gl::scene::Scene;
    use crate::render::options::Provoking;
    use crate::render::raster::Cull;

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
        let camera = Camera {
            view: DMat4::IDENTITY,
            projection: DMat4::IDENTITY,
        };
        let scene = emission_scene().validated().unwrap();
        let quad = quad();
        let draws = [Draw {
            mesh: quad,
            scene: &scene,
            model: DMat4::IDENTITY,
            cull: Cull::None,
            placement: Placement::Model,
        }];
        let triangles = setup(&draws, &[0], &camera, viewport, &stop).unwrap();
        let mut ids = vec![0; 35];
        let mut depth = vec![0.0_f64; 35];
        visibility(&triangles, viewport, &mut ids, &mut depth, &stop).unwrap();
        stop.request();
        let interrupted = |e: Error| e.kind == crate::errors::error::ErrorKind::Interrupted;
        assert!(interrupted(
            setup(&draws, &[0], &camera, viewport, &stop).unwrap_err()
        ));
        let err = visibility(&triangles, viewport, &mut ids, &mut depth, &stop).unwrap_err();
        assert!(interrupted(err));
        let mut image = vec![0.0; 35 * 4];
        // One normal per vertex, or per face for flat shading.
        for normals in [&[[0.0, 0.0, 1.0]; 4][..], &[[0.0, 0.0, 1.0]; 2]] {
            let layers = [Layer {
                shader: Shader::new(&scene, &camera, &RenderOptions::default(), false).unwrap(),
                mesh: &quad,
                normals,
                first_face: 0,
            }];
            let pass = Pass {
                layers: &layers,
                frame: Frame::new(viewport, &triangles, &ids).unwrap(),
                background: [0.0; 4],
                transfer: crate::render::transfer::Transfer::Linear,
                clamp: true,
            };
            let err = if normals.len() == 2 {
                pass.flat(Provoking::Last, &mut image, &stop).unwrap_err()
            } else {
                assert!(interrupted(pass.gouraud(&mut image, &stop).unwrap_err()));
                pass.phong(&mut image, &stop).unwrap_err()
            };
            assert!(interrupted(err));
        }
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

    /// `draws` rendered at 61 x 47, with `shading`.
    fn draw_all(
        draws: &[Draw<'_, f64, crate::gl::scene::ValidScene>],
        shading: Shading,
    ) -> Result<(Vec<f64>, Vec<f64>), Error> {
        let options = RenderOptions {
            viewport: Viewport {
                width: 61,
                height: 47,
            },
            shading,
            ..RenderOptions::default()
        };
        let mut image = vec![0.0; 61 * 47 * 4];
        let mut depth = vec![0.0; 61 * 47];
        let camera = Camera::default();
        render_draws(
            draws,
            &camera,
            &options,
            &mut image,
            &mut depth,
            &Stop::new(),
        )?;
        Ok((image, depth))
    }

    /// A fan of triangles around the z axis, tilted, at depth offset `z`.
    fn fan(z: f64) -> (Vec<[f64; 3]>, Vec<[i64; 3]>) {
        let mut vertices = vec![[0.1, -0.05, z]];
        vertices.extend((0..13).map(|i| {
            let t = f64::from(i) * 0.5;
            [0.8 * t.cos(), 0.7 * t.sin(), z + 0.3 * t.sin()]
        }));
        let faces = (1..13).map(|i| [0, i, i + 1]).collect();
        (vertices, faces)
    }

    /// GL's default scene with one directional light, validated.
    fn one_light() -> crate::gl::scene::ValidScene {
        Scene {
            lights: vec![crate::gl::light::Light {
                position: [0.3, 0.5, 1.0, 0.0],
                ..crate::gl::light::Light::default()
            }],
            ..Scene::default()
        }
        .validated()
        .unwrap()
    }

    #[test]
    fn several_draws_render_as_their_meshes_merged() {
        let scene = one_light();
        let (a, fa) = fan(0.1);
        let (b, fb) = fan(-0.2);
        let shifted: Vec<[f64; 3]> = b.iter().map(|v| [v[0] + 0.3, v[1] - 0.2, v[2]]).collect();
        let mesh = |vertices, faces| Mesh {
            vertices,
            faces,
            normals: None,
            colors: None,
            textured: None,
        };
        let model = DMat4::from_translation(glam::DVec3::new(0.3, -0.2, 0.0));
        let draws = [
            Draw {
                mesh: mesh(&a, &fa),
                scene: &scene,
                model: DMat4::IDENTITY,
                cull: Cull::None,
                placement: Placement::Model,
            },
            Draw {
                mesh: mesh(&b, &fb),
                scene: &scene,
                model,
                cull: Cull::None,
                placement: Placement::Model,
            },
        ];
        let mut merged = a.clone();
        merged.extend(&shifted);
        let offset = i64::try_from(a.len()).unwrap();
        let mut faces = fa.clone();
        faces.extend(fb.iter().map(|f| f.map(|i| i + offset)));
        let lone = [Draw {
            mesh: mesh(&merged, &faces),
            ..draws[0]
        }];
        for shading in [Shading::Flat, Shading::Gouraud, Shading::Phong] {
            let (image, depth) = draw_all(&draws, shading).unwrap();
            let (expected_image, expected_depth) = draw_all(&lone, shading).unwrap();
            assert!(
                depth.iter().filter(|&&z| z < 1.0).count() > 300,
                "{shading:?}"
            );
            // The model matrix moves the second fan in clip space rather than in its
            // vertices: depths and colours agree to rounding.
            for (x, y) in depth.iter().zip(&expected_depth) {
                assert!((x - y).abs() < 1e-12, "{shading:?}: {x} {y}");
            }
            for (x, y) in image.iter().zip(&expected_image) {
                assert!((x - y).abs() < 1e-12, "{shading:?}: {x} {y}");
            }
        }
    }

    #[test]
    fn views_render_as_their_cameras_alone() {
        let scene = one_light();
        let (vertices, faces) = fan(0.1);
        let draws = [Draw {
            mesh: Mesh {
                vertices: &vertices,
                faces: &faces,
                normals: None,
                colors: None,
                textured: None,
            },
            scene: &scene,
            model: DMat4::IDENTITY,
            cull: Cull::None,
            placement: Placement::Model,
        }];
        let cameras: Vec<Camera> = [0.0, 0.7, 2.1]
            .iter()
            .map(|&turn| Camera {
                view: DMat4::from_rotation_y(turn) * DMat4::from_rotation_x(0.4 * turn),
                ..Camera::default()
            })
            .collect();
        for shading in [Shading::Flat, Shading::Gouraud, Shading::Phong] {
            let options = RenderOptions {
                viewport: Viewport {
                    width: 61,
                    height: 47,
                },
                shading,
                ..RenderOptions::default()
            };
            let (area, stop) = (61 * 47, Stop::new());
            let mut images = vec![0.0; 3 * area * 4];
            let mut depths = vec![0.0; 3 * area];
            render_views(&draws, &cameras, &options, &mut images, &mut depths, &stop).unwrap();
            for (k, camera) in cameras.iter().enumerate() {
                let (mut image, mut depth) = (vec![0.0; area * 4], vec![0.0; area]);
                render_draws(&draws, camera, &options, &mut image, &mut depth, &stop).unwrap();
                assert!(depth.iter().filter(|&&z| z < 1.0).count() > 100);
                assert_eq!(
                    image,
                    images[k * area * 4..(k + 1) * area * 4],
                    "{shading:?}"
                );
                assert_eq!(depth, depths[k * area..(k + 1) * area], "{shading:?}");
            }
            let mut short = vec![0.0; 2 * area * 4];
            let error = render_views(&draws, &cameras, &options, &mut short, &mut depths, &stop);
            assert!(error.unwrap_err().message.contains("3 x 47 x 61 x 4"));
        }
    }

    #[test]
    fn each_draw_is_lit_by_its_own_scene_and_the_first_drawn_wins_a_tie() {
        let red = Scene {
            material: Material {
                emission: [1.0, 0.0, 0.0, 1.0],
                ..emission_scene().material
            },
            ..emission_scene()
        }
        .validated()
        .unwrap();
        let blue = Scene {
            material: Material {
                emission: [0.0, 0.0, 1.0, 1.0],
                ..emission_scene().material
            },
            ..emission_scene()
        }
        .validated()
        .unwrap();
        let quad = quad();
        // The default camera's identity projection: a larger z is deeper.
        let (front, back) = (
            DMat4::IDENTITY,
            DMat4::from_translation(glam::DVec3::Z * 0.1),
        );
        let at = |scene, model, cull| Draw {
            mesh: quad,
            scene,
            model,
            cull,
            placement: Placement::Model,
        };
        for shading in [Shading::Flat, Shading::Gouraud, Shading::Phong] {
            let tie = draw_all(
                &[at(&red, front, Cull::None), at(&blue, front, Cull::None)],
                shading,
            );
            assert!(tie.unwrap().0.chunks(4).all(|p| p == [1.0, 0.0, 0.0, 1.0]));
            let nearer = draw_all(
                &[at(&red, back, Cull::None), at(&blue, front, Cull::None)],
                shading,
            );
            assert!(nearer
                .unwrap()
                .0
                .chunks(4)
                .all(|p| p == [0.0, 0.0, 1.0, 1.0]));
            // The nearer quad culled by its own rule: the other shows.
            let culled = draw_all(
                &[at(&red, back, Cull::None), at(&blue, front, Cull::Front)],
                shading,
            );
            assert!(culled
                .unwrap()
                .0
                .chunks(4)
                .all(|p| p == [1.0, 0.0, 0.0, 1.0]));
        }
    }

    #[test]
    fn a_bad_draw_is_named_by_its_index() {
        let scene = emission_scene().validated().unwrap();
        let quad = quad();
        let faces = [[0, 1, 9]];
        let good = Draw {
            mesh: quad,
            scene: &scene,
            model: DMat4::IDENTITY,
            cull: Cull::None,
            placement: Placement::Model,
        };
        let bad = Draw {
            mesh: Mesh {
                faces: &faces,
                ..quad
            },
            ..good
        };
        let err = draw_all(&[good, bad], Shading::Phong).unwrap_err();
        assert!(err.message.starts_with("draws[1]: "), "{}", err.message);
        let singular = Draw {
            model: DMat4::ZERO,
            ..good
        };
        let err = draw_all(&[singular], Shading::Phong).unwrap_err();
        assert!(err.message.starts_with("model"), "{}", err.message);
    }
}
