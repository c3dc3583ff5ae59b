//! The robustness of the entry points: a requested [`Stop`] ends every one of them early, an
//! unrequested one changes no bit, and sizes beyond memory are errors, not aborts.

use std::time::{Duration, Instant};

use glam::{DMat4, DVec3};

use crate::*;

/// FNV-1a over the bits of every output value.
struct Fnv(u64);

impl Fnv {
    fn new() -> Self {
        Self(0xcbf2_9ce4_8422_2325)
    }

    fn add(&mut self, bits: u64) {
        for b in bits.to_le_bytes() {
            self.0 = (self.0 ^ u64::from(b)).wrapping_mul(0x100_0000_01b3);
        }
    }
}

/// Two-sided, separate specular, a local viewer and three kinds of light: most of the kernel.
fn scene() -> ValidScene {
    Scene {
        lights: vec![
            Light {
                position: [1.0, 2.0, 3.0, 1.0],
                spot_cutoff: 60.0,
                spot_exponent: 3.0,
                linear_attenuation: 0.3,
                specular: [1.0; 4],
                ..Light::default()
            },
            Light {
                position: [-1.0, 0.5, 1.0, 0.0],
                diffuse: [0.3, 0.6, 0.9, 1.0],
                ..Light::default()
            },
            Light {
                position: [0.0, -2.0, -1.0, 1.0],
                quadratic_attenuation: 0.2,
                ambient: [0.1, 0.1, 0.1, 1.0],
                ..Light::default()
            },
        ],
        material: Material {
            specular: [0.8; 4],
            shininess: 20.0,
            ..Material::default()
        },
        two_side: true,
        separate_specular: true,
        viewer: [0.0, 0.0, 0.0, 1.0],
        ..Scene::default()
    }
    .validated()
    .unwrap()
}

/// `n` positions and normals on smooth curves.
fn rows(n: usize) -> (Vec<[f64; 3]>, Vec<[f64; 3]>) {
    let p = (0..n)
        .map(|i| {
            let t = i as f64 * 0.013;
            [t.sin() * 2.0, t.cos(), -2.0 - (t * 0.3).sin()]
        })
        .collect();
    let q = (0..n)
        .map(|i| {
            let t = i as f64 * 0.37;
            [t.cos(), t.sin(), 0.5 - (t * 0.11).cos()]
        })
        .collect();
    (p, q)
}

/// `n` vertices and `m` scrambled faces over them.
fn mesh(n: u32, m: i64) -> (Vec<[f64; 3]>, Vec<[i64; 3]>) {
    let v = (0..n)
        .map(|i| {
            let t = f64::from(i);
            [t.sin(), (t * 0.7).cos(), (t * 0.13).sin() - 0.2]
        })
        .collect();
    let nn = i64::from(n);
    let f = (0..m)
        .map(|i| [i % nn, (i * 7 + 1) % nn, (i * 13 + 2) % nn])
        .collect();
    (v, f)
}

fn shade_options(accuracy: Accuracy) -> ShadeOptions {
    ShadeOptions {
        modelview: Some(DMat4::from_rotation_y(0.3) * DMat4::from_scale(DVec3::new(1.0, 2.0, 0.5))),
        normalize: true,
        accuracy,
        ..ShadeOptions::default()
    }
}

fn render_options(shading: Shading) -> RenderOptions {
    RenderOptions {
        viewport: Viewport {
            width: 70,
            height: 50,
        },
        shading,
        model: DMat4::from_translation(DVec3::new(0.0, 0.0, -0.5)),
        color_material: Some(
            ColorMaterial::parse("ambient_and_diffuse", "front_and_back").unwrap(),
        ),
        ..RenderOptions::default()
    }
}

/// Renders `v` and `f` with colours into fresh buffers.
fn draw(
    v: &[[f64; 3]],
    f: &[[i64; 3]],
    shading: Shading,
    stop: &Stop,
) -> Result<(Vec<f64>, Vec<f64>), Error> {
    let colors: Vec<f64> = (0..v.len() * 3).map(|i| (i % 7) as f64 / 7.0).collect();
    let mesh = Mesh {
        vertices: v,
        faces: f,
        normals: None,
        colors: Some(VertexColors {
            data: &colors,
            width: 3,
        }),
        textured: None,
    };
    let options = render_options(shading);
    let Viewport { width, height } = options.viewport;
    let mut image = vec![0.0; width * height * 4];
    let mut depth = vec![0.0; width * height];
    render(
        &scene(),
        &mesh,
        &Camera::default(),
        &options,
        &mut image,
        &mut depth,
        stop,
    )?;
    Ok((image, depth))
}

#[test]
fn an_unrequested_stop_changes_no_bit() {
    // The fingerprints of the same calls before `Stop` existed (commit ff857ae; the render one
    // after the exact clip crossings and the Gouraud clamp of 7545a77), the shading and render
    // ones taken again at the squared integer powers, the fused multiply-adds, the even
    // powers formed without ĥ and float32's lean arithmetic, which changed the kernel's bits
    // (Stop's code was untouched there).
    let stop = Stop::new();
    let scene = scene();
    let (p, q) = rows(20_000);
    let mut h = Fnv::new();
    for accuracy in [Accuracy::Fast, Accuracy::Exact] {
        let options = shade_options(accuracy);
        let p32: Vec<[f32; 3]> = p.iter().map(|r| r.map(|x| x as f32)).collect();
        let q32: Vec<[f32; 3]> = q.iter().map(|r| r.map(|x| x as f32)).collect();
        let mut out = vec![0.0_f32; 4 * 4 * p.len()];
        shade(&scene, &p32, &q32, None, &options, &mut out, &stop).unwrap();
        for x in &out {
            h.add(u64::from(x.to_bits()));
        }
        let mut out = vec![0.0_f64; 4 * 4 * p.len()];
        shade(&scene, &p, &q, None, &options, &mut out, &stop).unwrap();
        for x in &out {
            h.add(x.to_bits());
        }
    }
    assert_eq!(h.0, SHADE_FINGERPRINT, "shade");

    let (v, f) = mesh(9_000, 30_000);
    let mut h = Fnv::new();
    let mut out = vec![[0.0; 3]; f.len()];
    face_normals(&v, &f, &mut out, &stop).unwrap();
    out.as_flattened().iter().for_each(|x| h.add(x.to_bits()));
    for w in [Weighting::Angle, Weighting::Area, Weighting::Uniform] {
        let mut out = vec![[0.0; 3]; v.len()];
        vertex_normals(&v, &f, w, &mut out, &stop).unwrap();
        out.as_flattened().iter().for_each(|x| h.add(x.to_bits()));
    }
    assert_eq!(h.0, NORMALS_FINGERPRINT, "normals");

    let (v, f) = mesh(300, 600);
    let mut h = Fnv::new();
    for shading in [Shading::Flat, Shading::Gouraud, Shading::Phong] {
        let (image, depth) = draw(&v, &f, shading, &stop).unwrap();
        assert!(depth.iter().any(|&z| z < 1.0), "{shading:?} draws nothing");
        image.iter().chain(&depth).for_each(|x| h.add(x.to_bits()));
    }
    assert_eq!(h.0, RENDER_FINGERPRINT, "render");
}

const SHADE_FINGERPRINT: u64 = 0x0831_518d_ee33_cea4;
const NORMALS_FINGERPRINT: u64 = 0x7c18_53ee_fc8a_7b11;
const RENDER_FINGERPRINT: u64 = 0x75ce_c2e3_ba3b_9962;

fn requested() -> Stop {
    let stop = Stop::new();
    stop.request();
    stop
}

fn assert_interrupted<R: std::fmt::Debug>(result: Result<R, Error>, what: &str) {
    let err = result.unwrap_err();
    assert_eq!(err.kind, ErrorKind::Interrupted, "{what}: {}", err.message);
    assert_eq!(err.message, "interrupted");
}

#[test]
fn a_requested_stop_interrupts_every_entry_point() {
    let stop = requested();
    let scene = scene();
    // Several tasks of every kind: shade's 8192 rows, the normals' 4096 faces.
    let (p, q) = rows(40_000);
    for accuracy in [Accuracy::Fast, Accuracy::Exact] {
        let options = shade_options(accuracy);
        let mut out = vec![0.0_f64; 4 * 4 * p.len()];
        assert_interrupted(
            shade(&scene, &p, &q, None, &options, &mut out, &stop),
            "f64",
        );
        let p32: Vec<[f32; 3]> = p.iter().map(|r| r.map(|x| x as f32)).collect();
        let mut out = vec![std::mem::MaybeUninit::uninit(); 4 * 4 * p.len()];
        let result = shade_uninit(&scene, &p32, &p32, None, &options, &mut out, &stop);
        assert_interrupted(result, "f32");
    }
    let (v, f) = mesh(9_000, 30_000);
    let mut out = vec![[0.0; 3]; f.len()];
    assert_interrupted(face_normals(&v, &f, &mut out, &stop), "face normals");
    for w in [Weighting::Angle, Weighting::Area, Weighting::Uniform] {
        let mut out = vec![[0.0; 3]; v.len()];
        assert_interrupted(vertex_normals(&v, &f, w, &mut out, &stop), "vertex normals");
    }
    for shading in [Shading::Flat, Shading::Gouraud, Shading::Phong] {
        assert_interrupted(draw(&v, &f, shading, &stop), "render");
    }
}

#[test]
fn a_stop_from_another_thread_ends_a_long_shade_soon() {
    let scene = Scene {
        lights: (0..8)
            .map(|i| Light {
                position: [f64::from(i), 1.0, 2.0, 1.0],
                spot_cutoff: 60.0,
                spot_exponent: 3.0,
                linear_attenuation: 0.3,
                specular: [1.0; 4],
                ..Light::default()
            })
            .collect(),
        viewer: [0.0, 0.0, 0.0, 1.0],
        ..Scene::default()
    }
    .validated()
    .unwrap();
    let n = 4_000_000;
    let (p, q) = rows(n);
    let p: Vec<[f32; 3]> = p.iter().map(|r| r.map(|x| x as f32)).collect();
    let q: Vec<[f32; 3]> = q.iter().map(|r| r.map(|x| x as f32)).collect();
    let mut out = vec![0.0_f32; 4 * n];
    let stop = Stop::new();
    let options = ShadeOptions::default();
    let (err, latency) = std::thread::scope(|s| {
        let requester = s.spawn(|| {
            std::thread::sleep(Duration::from_millis(20));
            stop.request();
            Instant::now()
        });
        // Calls are repeated until one sees the stop, whatever this machine's speed.
        let err = (0..10_000)
            .find_map(|_| shade(&scene, &p, &q, None, &options, &mut out, &stop).err())
            .unwrap();
        let returned = Instant::now();
        (err, returned - requester.join().unwrap())
    });
    assert_eq!(err.kind, ErrorKind::Interrupted);
    // The target is 0.1 s; the bound leaves room for a loaded test machine.
    assert!(latency < Duration::from_secs(2), "{latency:?}");
}

#[test]
fn sizes_beyond_memory_are_memory_errors() {
    let err =
        crate::memory::alloc::try_filled(usize::MAX / 16, [0.0_f64; 3], "the rows").unwrap_err();
    assert_eq!(err.kind, ErrorKind::Memory);
    assert!(
        err.message.starts_with("cannot allocate "),
        "{}",
        err.message
    );
    let err = crate::memory::pages::Zeroed::<[f64; 4]>::new(1 << 56, "the face terms")
        .err()
        .unwrap();
    assert_eq!(err.kind, ErrorKind::Memory);
}
