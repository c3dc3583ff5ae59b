//! Properties of `shade` over random scenes and vertices (proptest): finite input gives finite
//! output in [0, 1]; a non-finite row gives NaN in that row only; scaling a scene without
//! attenuation by a power of two, or mirroring it, changes no bit.

use proptest::prelude::*;

use crate::errors::stop::Stop;
use crate::gl::light::Light;
use crate::gl::material::Material;
use crate::gl::scene::{Scene, Specular};
use crate::lighting::fixed_function::options::ShadeOptions;
use crate::lighting::model::shade;
fn colour() -> impl Strategy<Value = [f64; 4]> {
    (-1.0..2.0, -1.0..2.0, -1.0..2.0).prop_map(|(r, g, b)| [r, g, b, 1.0])
}

fn light() -> impl Strategy<Value = Light> {
    (
        prop::array::uniform3(-4.0..4.0_f64),
        prop::sample::select(vec![0.0, 1.0, 0.5]),
        (colour(), colour(), colour()),
        prop::sample::select(vec![180.0, 90.0, 30.0]),
        0.0..50.0_f64,
    )
        .prop_map(
            |(xyz, w, (ambient, diffuse, specular), cutoff, exponent)| Light {
                position: [xyz[0], xyz[1], xyz[2] + 0.25, w],
                ambient,
                diffuse,
                specular,
                spot_cutoff: cutoff,
                spot_exponent: exponent,
                ..Light::default()
            },
        )
}

fn scene() -> impl Strategy<Value = Scene> {
    (
        prop::collection::vec(light(), 0..10),
        (colour(), colour()),
        prop::sample::select(vec![0.0, 1.0, 64.0, 1e4, 1e6]),
        prop::sample::select(vec![[0.0, 0.0, 1.0, 0.0], [0.0, 0.0, 0.0, 1.0]]),
        any::<(bool, bool, bool)>(),
    )
        .prop_map(
            |(lights, (diffuse, specular), shininess, viewer, (two_side, separate, phong))| Scene {
                lights,
                material: Material {
                    diffuse,
                    specular,
                    shininess,
                    ..Material::default()
                },
                viewer,
                two_side,
                separate_specular: separate,
                specular: if phong {
                    Specular::Phong
                } else {
                    Specular::Blinn
                },
                ..Scene::default()
            },
        )
}

/// Values from the awkward ends of f32: zero, subnormal, huge, ordinary.
fn coordinate() -> impl Strategy<Value = f32> {
    prop_oneof![
        -8.0..8.0_f32,
        prop::sample::select(vec![0.0, -0.0, 1e-40, 1e-30, 1e30, -3e38, 1.0]),
    ]
}

fn rows(len: usize) -> impl Strategy<Value = Vec<[f32; 3]>> {
    prop::collection::vec(prop::array::uniform3(coordinate()), len)
}

fn run(scene: &Scene, p: &[[f32; 3]], n: &[[f32; 3]], normalize: bool) -> Vec<f32> {
    let mut out = vec![0.0; scene.output_count() * 4 * p.len()];
    let options = ShadeOptions {
        normalize,
        ..ShadeOptions::default()
    };
    let scene = scene.clone().validated().unwrap();
    shade(&scene, p, n, None, &options, &mut out, &Stop::new()).unwrap();
    out
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn finite_in_gives_finite_out_in_the_unit_interval(
        scene in scene(), p in rows(20), n in rows(20), normalize in any::<bool>(),
    ) {
        for x in run(&scene, &p, &n, normalize) {
            prop_assert!((0.0..=1.0).contains(&x), "{x}");
        }
    }

    #[test]
    fn a_nan_stays_in_its_row(
        scene in scene(), p in rows(20), n in rows(20), row in 0..20_usize, which in 0..2_usize,
    ) {
        let clean = run(&scene, &p, &n, false);
        let (mut p2, mut n2) = (p.clone(), n.clone());
        if which == 0 { p2[row][1] = f32::NAN } else { n2[row][0] = f32::NAN }
        let dirty = run(&scene, &p2, &n2, false);
        for (i, (a, b)) in clean.iter().zip(&dirty).enumerate() {
            if (i / 4) % p.len() == row {
                // An unread position (no positional light, infinite viewer) changes nothing.
                prop_assert!(b.is_nan() || a.to_bits() == b.to_bits());
            } else {
                prop_assert_eq!(a.to_bits(), b.to_bits());
            }
        }
    }

    #[test]
    fn power_of_two_scaling_and_mirroring_change_no_bit(
        scene in scene(), p in prop::collection::vec(prop::array::uniform3(-8.0..8.0_f32), 20),
        n in rows(20), k in -40..40_i32, axis in 0..3_usize,
    ) {
        let base = run(&scene, &p, &n, true);
        let scale = 2.0_f64.powi(k);
        let mut scaled = scene.clone();
        for light in &mut scaled.lights {
            if light.position[3] != 0.0 {
                for c in &mut light.position[..3] { *c *= scale }
            }
        }
        if scaled.viewer[3] != 0.0 {
            for c in &mut scaled.viewer[..3] { *c *= scale }
        }
        let p_scaled: Vec<[f32; 3]> = p.iter().map(|r| r.map(|c| c * scale as f32)).collect();
        let again = run(&scaled, &p_scaled, &n, true);
        prop_assert!(base.iter().zip(&again).all(|(a, b)| a.to_bits() == b.to_bits()));

        let mut mirrored = scene.clone();
        for light in &mut mirrored.lights {
            light.position[axis] = -light.position[axis];
            light.spot_direction[axis] = -light.spot_direction[axis];
        }
        mirrored.viewer[axis] = -mirrored.viewer[axis];
        let flip = |rows: &[[f32; 3]]| -> Vec<[f32; 3]> {
            rows.iter().map(|r| { let mut r = *r; r[axis] = -r[axis]; r }).collect()
        };
        let again = run(&mirrored, &flip(&p), &flip(&n), true);
        prop_assert!(base.iter().zip(&again).all(|(a, b)| a.to_bits() == b.to_bits()));
    }
}
