//! Range tests: finite input gives finite output in [0, 1] in both dtypes, and uniform scales
//! of the modelview, of the parameters and of the geometry change nothing they should not.
//! Every call goes through the two helpers below.

use glam::{DMat4, DQuat, DVec3};

use crate::light::Light;
use crate::prepare::ShadeOptions;
use crate::real::Real;
use crate::scene::Scene;
use crate::shade::shade;

/// The colours `shade` computes for one vertex.
fn shade_one<T: Real>(
    scene: &Scene,
    p: [T; 3],
    n: [T; 3],
    options: &ShadeOptions,
) -> Result<Vec<f64>, crate::Error> {
    let mut out = vec![T::ZERO; scene.output_count() * 4];
    shade(scene, &[p], &[n], None, options, &mut out)?;
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
