//! Range tests: finite input gives finite output in [0, 1] in both dtypes, and uniform scales
//! of the modelview, of the parameters and of the geometry change nothing they should not.
//! Every call goes through the two helpers below.

use glam::{DMat4, DQuat, DVec3};

use crate::errors::stop::Stop;
use crate::gl::light::Light;
use crate::gl::scene::Scene;
use crate::lighting::fixed_function::options::ShadeOptions;
use crate::lighting::model::shade;
use crate::numbers::real::Real;

/// The colours `shade` computes for one vertex.
fn shade_one<T: Real>(
    scene: &Scene,
    p: [T; 3],
    n: [T; 3],
    options: &ShadeOptions,
) -> Result<Vec<f64>, crate::Error> {
    let mut out = vec![T::ZERO; scene.output_count() * 4];
    let scene = scene.clone().validated()?;
    shade(&scene, &[p], &[n], None, options, &mut out, &Stop::new())?;
    Ok(out.iter().map(|x| x.to_f64()).collect())
}

fn in_unit_interval(out: &[f64]) -> bool {
    out.iter().all(|c| (0.0..=1.0).contains(c))
}

fn headlight() -> Scene {
    Scene {
        lights: vec![Light::default()],
        ..Scene::default()
    }
}

fn options(modelview: DMat4, normalize: bool, rescale_normal: bool) -> ShadeOptions {
    ShadeOptions {
        modelview: Some(modelview),
        normalize,
        rescale_normal,
        ..ShadeOptions::default()
    }
}

/// 10^k as an `f64`, finite for k in [−323, 308].
fn pow10(k: i32) -> f64 {
    format!("1e{k}").parse().unwrap()
}

fn scaled_modelviews_light_as_the_unscaled_one<T: Real>(
    ks: std::ops::RangeInclusive<i32>,
    tol: f64,
) {
    let scene = headlight();
    let rotation = DMat4::from_quat(DQuat::from_axis_angle(
        DVec3::new(1.0, 2.0, 0.5).normalize(),
        0.4,
    ));
    let n = [0.3, -0.2, 0.9].map(T::from_f64);
    for (normalize, rescale) in [(true, false), (false, true), (true, true)] {
        for base in [DMat4::IDENTITY, rotation] {
            let expected =
                shade_one::<T>(&scene, [T::ZERO; 3], n, &options(base, normalize, rescale))
                    .unwrap();
            for k in ks.clone() {
                let s = pow10(k);
                let m = DMat4::from_scale(DVec3::splat(s)) * base;
                let got = shade_one::<T>(&scene, [T::ZERO; 3], n, &options(m, normalize, rescale))
                    .unwrap();
                let worst = got
                    .iter()
                    .zip(&expected)
                    .map(|(a, b)| (a - b).abs())
                    .fold(0.0, f64::max);
                assert!(
                    worst <= tol,
                    "k {k} normalize {normalize} rescale {rescale}: {got:?} vs {expected:?}"
                );
            }
        }
    }
}

#[test]
fn scaled_modelviews_light_as_the_unscaled_one_f64() {
    scaled_modelviews_light_as_the_unscaled_one::<f64>(-300..=300, 1e-12);
}

#[test]
fn scaled_modelviews_light_as_the_unscaled_one_f32() {
    // The modelview is f64 state: its normal matrix is formed there, so f32 reaches as far.
    scaled_modelviews_light_as_the_unscaled_one::<f32>(-300..=300, 1e-6);
}

#[test]
fn the_normal_of_the_brief_lights_to_0_84_at_any_scale() {
    let scene = headlight();
    for k in [-300, -110, -50, 0, 50, 110, 300] {
        let m = DMat4::from_scale(DVec3::splat(pow10(k)));
        for rescale in [false, true] {
            let o = options(m, !rescale, rescale);
            let out = shade_one::<f64>(&scene, [0.0; 3], [0.0, 0.0, 1.0], &o).unwrap();
            assert!((out[0] - 0.84).abs() < 1e-12, "k {k}: {out:?}");
            let out = shade_one::<f32>(&scene, [0.0; 3], [0.0, 0.0, 1.0], &o).unwrap();
            assert!((out[0] - 0.84).abs() < 1e-6, "k {k}: {out:?}");
        }
    }
}

#[test]
fn no_finite_modelview_gives_nan() {
    let mut scene = headlight();
    scene.material.specular = [1.0; 4];
    scene.material.shininess = 20.0;
    let mut ks: Vec<i32> = (-323..=308).step_by(7).collect();
    ks.extend([-323, -308, 308]);
    for k in ks {
        let s = pow10(k);
        for m in [
            DMat4::from_scale(DVec3::splat(s)),
            DMat4::from_scale(DVec3::new(s, 1.0, 1.0)),
            DMat4::from_scale(DVec3::new(1.0, 1.0, s)),
        ] {
            for (normalize, rescale) in [(false, false), (true, false), (false, true)] {
                let o = options(m, normalize, rescale);
                let out = shade_one::<f64>(&scene, [0.0; 3], [0.0, 0.6, 0.8], &o).unwrap();
                assert!(in_unit_interval(&out), "f64 k {k}: {out:?}");
                let out = shade_one::<f32>(&scene, [0.0; 3], [0.0, 0.6, 0.8], &o).unwrap();
                assert!(in_unit_interval(&out), "f32 k {k}: {out:?}");
            }
        }
    }
}

#[test]
fn float32_rejects_modelview_entries_it_would_overflow_in_positions() {
    let mut scene = headlight();
    scene.lights[0].position = [0.0, 0.0, 1.0, 1.0];
    let big = DMat4::from_scale(DVec3::splat(1e50));
    let err = shade_one::<f32>(
        &scene,
        [0.0; 3],
        [0.0, 0.0, 1.0],
        &options(big, true, false),
    )
    .unwrap_err();
    assert!(
        err.message
            .starts_with("modelview entries must be within float32's range")
            && err.message.contains("1e50"),
        "{}",
        err.message
    );
    let far = DMat4::from_translation(DVec3::new(1e39, 0.0, 0.0));
    assert!(shade_one::<f32>(
        &scene,
        [0.0; 3],
        [0.0, 0.0, 1.0],
        &options(far, true, false)
    )
    .is_err());
    // f64 computes them; a directional light never reads positions.
    assert!(shade_one::<f64>(
        &scene,
        [0.0; 3],
        [0.0, 0.0, 1.0],
        &options(big, true, false)
    )
    .is_ok());
    let out = shade_one::<f32>(
        &headlight(),
        [0.0; 3],
        [0.0, 0.0, 1.0],
        &options(far, true, false),
    )
    .unwrap();
    assert!((out[0] - 0.84).abs() < 1e-6);
    // Tiny entries are representable enough: the eye-space positions round towards 0.
    let tiny = DMat4::from_scale(DVec3::splat(1e-50));
    let out = shade_one::<f32>(
        &scene,
        [1.0, 1.0, 1.0],
        [0.0, 0.0, 1.0],
        &options(tiny, true, false),
    )
    .unwrap();
    assert!(in_unit_interval(&out));
}

/// A positional spot light straight above the vertex, with a specular material: every
/// parameter of eqs. 2.2–2.5 is in use.
fn spot_scene() -> Scene {
    Scene {
        lights: vec![Light {
            position: [0.0, 0.0, 2.0, 1.0],
            spot_direction: [0.0, 0.0, -1.0],
            spot_cutoff: 30.0,
            spot_exponent: 2.0,
            linear_attenuation: 0.5,
            ..Light::default()
        }],
        material: crate::gl::material::Material {
            specular: [1.0; 4],
            shininess: 10.0,
            ..crate::gl::material::Material::default()
        },
        viewer: [0.0, 0.0, 3.0, 1.0],
        ..Scene::default()
    }
}

/// Every scalar parameter of `spot_scene` set to `huge` in turn, lit at the vertex under the
/// light (cosines exactly 1, distance 2) and beside it (cosines below 1), with and without a
/// light at the vertex.
fn huge_parameters_light_finitely<T: Real>(huge: f64) {
    type Edit = fn(&mut Scene, f64);
    let edits: [(&str, Edit); 6] = [
        ("shininess", |s, x| s.material.shininess = x),
        ("spot_exponent", |s, x| s.lights[0].spot_exponent = x),
        ("constant_attenuation", |s, x| {
            s.lights[0].constant_attenuation = x;
        }),
        ("linear_attenuation", |s, x| {
            s.lights[0].linear_attenuation = x;
        }),
        ("quadratic_attenuation", |s, x| {
            s.lights[0].quadratic_attenuation = x;
        }),
        ("constant_attenuation = 0, quadratic", |s, x| {
            s.lights[0].constant_attenuation = 0.0;
            s.lights[0].quadratic_attenuation = x;
        }),
    ];
    let vertices = [[0.0, 0.0, 0.0], [0.3, 0.1, 0.0], [0.0, 0.0, 2.0]];
    for (name, edit) in edits {
        let mut scene = spot_scene();
        edit(&mut scene, huge);
        for p in vertices {
            for n in [[0.0, 0.0, 1.0], [0.1, 0.0, 0.9]] {
                let out = shade_one::<T>(
                    &scene,
                    p.map(T::from_f64),
                    n.map(T::from_f64),
                    &ShadeOptions::default(),
                )
                .unwrap();
                assert!(
                    in_unit_interval(&out),
                    "{name} = {huge:e} at {p:?}, {n:?}: {out:?}"
                );
            }
        }
    }
}

#[test]
fn huge_parameters_light_finitely_f32() {
    huge_parameters_light_finitely::<f32>(1e39);
    huge_parameters_light_finitely::<f32>(f64::MAX);
    // Saturated at f32::MAX, a huge exponent gives what f64 gives: 1^s = 1, x^s = 0 for x < 1.
    for n in [[0.0, 0.0, 1.0], [0.1, 0.0, 0.9]] {
        let mut scene = spot_scene();
        scene.material.shininess = 1e39;
        scene.lights[0].spot_exponent = 1e39;
        let wide = shade_one::<f64>(&scene, [0.0; 3], n, &ShadeOptions::default()).unwrap();
        let narrow = shade_one::<f32>(
            &scene,
            [0.0; 3],
            n.map(|x| x as f32),
            &ShadeOptions::default(),
        )
        .unwrap();
        for (a, b) in wide.iter().zip(&narrow) {
            assert!((a - b).abs() < 1e-6, "{wide:?} vs {narrow:?}");
        }
    }
}

#[test]
fn points_beyond_float32_are_rejected_by_name_directions_are_not() {
    let mut scene = spot_scene();
    scene.lights[0].position = [1e39, 0.0, 0.0, 1.0];
    let err =
        shade_one::<f32>(&scene, [0.0; 3], [0.0, 0.0, 1.0], &ShadeOptions::default()).unwrap_err();
    assert!(
        err.message
            .starts_with("position of light 0 must lie within float32's range"),
        "{}",
        err.message
    );
    let wide = shade_one::<f64>(&scene, [0.0; 3], [0.0, 0.0, 1.0], &ShadeOptions::default());
    assert!(in_unit_interval(&wide.unwrap()));
    let mut scene = spot_scene();
    scene.viewer = [0.0, 1e39, 0.0, 1.0];
    let err =
        shade_one::<f32>(&scene, [0.0; 3], [0.0, 0.0, 1.0], &ShadeOptions::default()).unwrap_err();
    assert!(
        err.message.starts_with("viewer must lie within"),
        "{}",
        err.message
    );
    // Directions are normalised in f64: any finite length is fine.
    let mut scene = spot_scene();
    scene.lights[0].spot_direction = [0.0, 0.0, -1e300];
    scene.lights.push(Light {
        position: [1e300, 0.0, 1e300, 0.0],
        ..Light::default()
    });
    scene.viewer = [0.0, 1e300, 1e300, 0.0];
    for huge_point in [[0.0, 0.0, 3e38, 1.0], [3e38, 3e38, 3e38, 1.0]] {
        scene.lights[0].position = huge_point;
        let out = shade_one::<f32>(&scene, [0.0; 3], [0.0, 0.0, 1.0], &ShadeOptions::default());
        assert!(in_unit_interval(&out.unwrap()), "{huge_point:?}");
    }
}

#[test]
fn huge_parameters_light_finitely_f64() {
    huge_parameters_light_finitely::<f64>(1e300);
    huge_parameters_light_finitely::<f64>(f64::MAX);
}

/// The image and depth of `vertices` (one face per three) rendered under the headlight with
/// `camera` into a `width` x `height` viewport.
fn draw<T: Real>(
    vertices: &[[T; 3]],
    scene: &Scene,
    camera: &crate::render::camera::Camera,
    shading: crate::render::options::Shading,
    (width, height): (usize, usize),
) -> (Vec<f64>, Vec<f64>) {
    let faces: Vec<[i64; 3]> = (0..i64::try_from(vertices.len() / 3).unwrap())
        .map(|f| [3 * f, 3 * f + 1, 3 * f + 2])
        .collect();
    let mesh = crate::render::mesh::Mesh {
        vertices,
        faces: &faces,
        normals: None,
        colors: None,
        textured: None,
    };
    let options = crate::render::options::RenderOptions {
        viewport: crate::render::raster::Viewport { width, height },
        shading,
        ..crate::render::options::RenderOptions::default()
    };
    let mut image = vec![T::ZERO; width * height * 4];
    let mut depth = vec![T::ZERO; width * height];
    let scene = scene.clone().validated().unwrap();
    crate::render::render(
        &scene,
        &mesh,
        camera,
        &options,
        &mut image,
        &mut depth,
        &Stop::new(),
    )
    .unwrap();
    let wide = |v: Vec<T>| v.into_iter().map(T::to_f64).collect::<Vec<_>>();
    (wide(image), wide(depth))
}

/// `corners` times `scale` in `T`.
fn scaled<T: Real>(corners: &[[f64; 3]], scale: f64) -> Vec<[T; 3]> {
    corners
        .iter()
        .map(|c| c.map(|x| T::from_f64(x * scale)))
        .collect()
}

fn huge_triangles_rasterise_as_small_ones<T: Real>(ks: std::ops::RangeInclusive<i32>, tol: f64) {
    use crate::render::options::Shading;
    let size = (17, 13);
    let ortho = crate::render::camera::Camera::default();
    // Enclosing the view; and with edges y = x/2 and x = 0.3·y... through it (lines through
    // the origin, so a uniform scale keeps them where they are on screen).
    let enclosing = [[-3.0, -3.0, 0.0], [3.0, -3.0, 0.0], [0.0, 3.0, 0.0]];
    let partial = [[-3.0, -1.5, 0.0], [3.0, 1.5, 0.0], [3.0, -3.0, 0.0]];
    for shading in [Shading::Flat, Shading::Gouraud, Shading::Phong] {
        for corners in [&enclosing, &partial] {
            let (small, small_depth) = draw(
                &scaled::<T>(corners, 1.0),
                &headlight(),
                &ortho,
                shading,
                size,
            );
            if corners == &enclosing {
                assert!(small_depth.iter().all(|&z| z < 1.0));
            } else {
                let drawn = small_depth.iter().filter(|&&z| z < 1.0).count();
                assert!(drawn > 20 && drawn < 17 * 13 - 20, "{drawn}");
            }
            for k in ks.clone() {
                let s = pow10(k);
                let (image, depth) = draw(
                    &scaled::<T>(corners, s),
                    &headlight(),
                    &ortho,
                    shading,
                    size,
                );
                let coverage = |d: &[f64]| d.iter().map(|&z| z < 1.0).collect::<Vec<_>>();
                assert_eq!(
                    coverage(&depth),
                    coverage(&small_depth),
                    "{shading:?} 1e{k}"
                );
                for (a, b) in image.iter().zip(&small) {
                    assert!((a - b).abs() <= tol, "{shading:?} 1e{k}: {a} vs {b}");
                }
                // A projection with w = s: the clip coordinates are the small triangle's
                // times s, so it is the same triangle on screen, at the same depth.
                let homogeneous = crate::render::camera::Camera {
                    projection: DMat4::from_diagonal(glam::DVec4::new(1.0, 1.0, 1.0, s)),
                    ..ortho
                };
                let (image, depth) = draw(
                    &scaled::<T>(corners, s),
                    &headlight(),
                    &homogeneous,
                    shading,
                    size,
                );
                assert_eq!(
                    coverage(&depth),
                    coverage(&small_depth),
                    "{shading:?} w 1e{k}"
                );
                for (a, b) in image.iter().zip(&small) {
                    assert!((a - b).abs() <= tol, "{shading:?} w 1e{k}: {a} vs {b}");
                }
            }
        }
    }
}

#[test]
fn huge_triangles_rasterise_as_small_ones_f64() {
    huge_triangles_rasterise_as_small_ones::<f64>(0..=300, 1e-12);
}

#[test]
fn huge_triangles_rasterise_as_small_ones_f32() {
    huge_triangles_rasterise_as_small_ones::<f32>(0..=30, 1e-6);
}

fn huge_triangles_under_point_lights_stay_finite<T: Real>(ks: &[i32]) {
    use crate::render::options::Shading;
    let mut scene = spot_scene();
    scene.lights[0].quadratic_attenuation = 1.0;
    let enclosing = [[-3.0, -3.0, 0.0], [3.0, -3.0, 0.0], [0.0, 3.0, 0.0]];
    let ortho = crate::render::camera::Camera::default();
    for &k in ks {
        for shading in [Shading::Flat, Shading::Gouraud, Shading::Phong] {
            let (image, _) = draw(
                &scaled::<T>(&enclosing, pow10(k)),
                &scene,
                &ortho,
                shading,
                (9, 7),
            );
            assert!(in_unit_interval(&image), "{shading:?} 1e{k}");
        }
    }
}

#[test]
fn huge_triangles_under_point_lights_stay_finite_f64() {
    huge_triangles_under_point_lights_stay_finite::<f64>(&[20, 100, 200, 300]);
}

#[test]
fn huge_triangles_under_point_lights_stay_finite_f32() {
    huge_triangles_under_point_lights_stay_finite::<f32>(&[10, 20, 30]);
}
