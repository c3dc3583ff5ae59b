//! Normals of any finite magnitude, under any normal matrix the modelview gives: finite
//! input gives finite output in [0, 1] in both dtypes, however |n| or N·n compare with the
//! type's range, on every instruction set; a non-finite input normal still gives NaN.

use glam::{DMat4, DVec3};

use crate::errors::stop::Stop;
use crate::gl::light::Light;
use crate::gl::material::Material;
use crate::gl::scene::{Scene, Specular};
use crate::lighting::driver::Inputs;
use crate::lighting::fixed_function::model::run;
use crate::lighting::fixed_function::options::ShadeOptions;
use crate::lighting::fixed_function::plan::Plan;
use crate::lighting::fixed_function::prepare::Prepared;
use crate::memory::uninit::as_uninit;
use crate::numbers::real::Real;
use crate::simd::dispatch::Isa;
use crate::tests::support::Numbers;

/// The positional spot light with attenuation of the report, or a directional light.
fn scene(spot: bool, specular: Specular, two_side: bool) -> Scene {
    let light = if spot {
        Light {
            position: [1.0, 2.0, 3.0, 1.0],
            linear_attenuation: 0.3,
            spot_cutoff: 40.0,
            spot_exponent: 2.0,
            ..Light::default()
        }
    } else {
        Light {
            position: [0.3, -0.5, 1.0, 0.0],
            ..Light::default()
        }
    };
    let material = Material {
        specular: [0.8; 4],
        shininess: 20.0,
        ..Material::default()
    };
    Scene {
        lights: vec![light],
        material,
        back_material: material,
        two_side,
        specular,
        ..Scene::default()
    }
}

/// The index of the row whose normal is NaN, and of the one whose normal is infinite.
const NAN_ROW: usize = 5;
const INF_ROW: usize = 40;

/// Positions near the origin and normals of magnitude 0.5·MAX, 0.9·MAX and MAX per
/// component with every sign pattern, random directions at those magnitudes, some with zero
/// components, a few ordinary normals, one NaN and one infinite normal: 83 rows, a full
/// block of the widest registers and a short one.
fn rows<T: Real>() -> (Vec<[T; 3]>, Vec<[T; 3]>) {
    let mut numbers = Numbers(11);
    let max = T::MAX.to_f64();
    let mut normals = Vec::new();
    for fraction in [0.5, 0.9, 1.0] {
        let m = fraction * max;
        for signs in 0..8 {
            let sign = |k: u32| if signs >> k & 1 == 1 { -m } else { m };
            normals.push([sign(0), sign(1), sign(2)]);
        }
        for _ in 0..12 {
            normals.push([0; 3].map(|_| numbers.next() * m));
        }
        normals.push([m, 0.0, -m]);
        normals.push([0.0, -m, 0.0]);
    }
    normals.extend([
        [0.0, 0.0, 1.0],
        [0.6, -0.8, 0.0],
        [0.0; 3],
        [3.0, 1.0, -2.0],
    ]);
    normals[NAN_ROW] = [f64::NAN, 1.0, 0.0];
    normals[INF_ROW] = [0.0, f64::INFINITY, 1.0];
    let positions = normals
        .iter()
        .map(|_| [0; 3].map(|_| numbers.next() * 0.5))
        .collect::<Vec<_>>();
    let cast = |rows: Vec<[f64; 3]>| {
        rows.into_iter()
            .map(|r| r.map(T::from_f64))
            .collect::<Vec<_>>()
    };
    (cast(positions), cast(normals))
}

/// 10^k as an `f64`.
fn pow10(k: i32) -> f64 {
    format!("1e{k}").parse().unwrap()
}

/// Shades the rows under every combination with every modelview of `modelviews` (skipping
/// the ones `T` rejects) on every instruction set, and checks every output.
fn check<T: Real>(modelviews: &[Option<DMat4>]) {
    let (positions, normals) = rows::<T>();
    let isas: Vec<Isa> = Isa::ALL.into_iter().filter(|i| i.supported()).collect();
    for spot in [true, false] {
        for specular in [Specular::Blinn, Specular::Phong] {
            for two_side in [false, true] {
                let scene = scene(spot, specular, two_side).validated().unwrap();
                for &modelview in modelviews {
                    for (normalize, rescale_normal) in
                        [(false, false), (true, false), (false, true), (true, true)]
                    {
                        let options = ShadeOptions {
                            modelview,
                            normalize,
                            rescale_normal,
                            ..ShadeOptions::default()
                        };
                        let Ok(prepared) = Prepared::<T>::new(&scene, &options) else {
                            continue;
                        };
                        let plan = Plan::new(&prepared);
                        for &isa in &isas {
                            let n = normals.len();
                            let mut out = vec![T::ZERO; scene.output_count() * 4 * n];
                            run(
                                &prepared,
                                &plan,
                                isa,
                                Inputs {
                                    positions: &positions,
                                    normals: &normals,
                                    colors: None,
                                },
                                as_uninit(&mut out),
                                &Stop::new(),
                            )
                            .unwrap();
                            for (i, value) in out.iter().enumerate() {
                                let (row, x) = (i / 4 % n, value.to_f64());
                                let what = || {
                                    format!(
                                        "{}: spot {spot}, {specular:?}, two-sided {two_side}, \
                                         normalize {normalize}, rescale {rescale_normal}, \
                                         modelview {modelview:?}, {}: row {row} (normal {:?}) \
                                         gives {x}",
                                        std::any::type_name::<T>(),
                                        isa.name(),
                                        normals[row],
                                    )
                                };
                                let ok = if row == NAN_ROW || row == INF_ROW {
                                    x.is_nan()
                                } else {
                                    (0.0..=1.0).contains(&x)
                                };
                                assert!(ok, "{}", what());
                            }
                        }
                    }
                }
            }
        }
    }
}

/// No modelview, the identity, and diag(10^k, 10^k, 10^k, 1) for every k whose 10^k is a
/// finite, nonzero `f64`, with the diagonals diag(10^k, 1, 10^−k) and diag(−10^k, 10^k, 1).
fn modelviews(ks: std::ops::RangeInclusive<i32>) -> Vec<Option<DMat4>> {
    let mut all = vec![None, Some(DMat4::IDENTITY)];
    for k in ks {
        let (s, r) = (pow10(k), pow10(-k));
        for d in [
            DVec3::splat(s),
            DVec3::new(s, 1.0, r),
            DVec3::new(-s, s, 1.0),
        ] {
            if d.is_finite() && d.abs().min_element() != 0.0 {
                all.push(Some(DMat4::from_scale(d)));
            }
        }
    }
    all
}

#[test]
fn normals_of_any_magnitude_light_within_the_unit_interval_f32() {
    check::<f32>(&modelviews(-60..=60));
}

#[test]
fn normals_of_any_magnitude_light_within_the_unit_interval_f64() {
    check::<f64>(&modelviews(-320..=320));
}

/// The outputs of `scene` and `options` for `normals` at the origin, the same bits on every
/// instruction set.
fn shade_all<T: Real>(scene: &Scene, normals: &[[T; 3]], options: &ShadeOptions) -> Vec<f64> {
    let scene = scene.clone().validated().unwrap();
    let prepared = Prepared::<T>::new(&scene, options).unwrap();
    let plan = Plan::new(&prepared);
    let positions = vec![[T::ZERO; 3]; normals.len()];
    let mut outputs = Isa::ALL.into_iter().filter(|i| i.supported()).map(|isa| {
        let mut out = vec![T::ZERO; scene.output_count() * 4 * normals.len()];
        run(
            &prepared,
            &plan,
            isa,
            Inputs {
                positions: &positions,
                normals,
                colors: None,
            },
            as_uninit(&mut out),
            &Stop::new(),
        )
        .unwrap();
        out.iter().map(|x| x.to_f64()).collect::<Vec<_>>()
    });
    let first = outputs.next().unwrap();
    for other in outputs {
        assert!(
            other
                .iter()
                .zip(&first)
                .all(|(a, b)| a.to_bits() == b.to_bits()),
            "instruction sets differ"
        );
    }
    first
}

/// `count` normals with components in [-1, 1], scaled by `scale`.
fn directions<T: Real>(count: usize, scale: f64) -> Vec<[T; 3]> {
    let mut numbers = Numbers(5);
    (0..count)
        .map(|_| [0; 3].map(|_| T::from_f64(numbers.next() * scale)))
        .collect()
}

/// With `normalize`, a normal beyond the kernel's range, or one that a saturated normal matrix
/// sends there, lights as its direction does: the saturation keeps the direction.
fn saturation_keeps_the_direction<T: Real>(tiny: f64, tol: f64) {
    let max = T::MAX.to_f64();
    let units = directions::<T>(70, 1.0);
    for spot in [true, false] {
        for specular in [Specular::Blinn, Specular::Phong] {
            let scene = scene(spot, specular, true);
            let normalized = |modelview| ShadeOptions {
                modelview,
                normalize: true,
                ..ShadeOptions::default()
            };
            let expected = shade_all(&scene, &units, &normalized(None));
            let huge = directions::<T>(70, 0.9 * max);
            let small = Some(DMat4::from_scale(DVec3::splat(tiny)));
            for got in [
                shade_all(&scene, &huge, &normalized(None)),
                shade_all(&scene, &units, &normalized(small)),
                shade_all(&scene, &huge, &normalized(small)),
            ] {
                let worst = got
                    .iter()
                    .zip(&expected)
                    .map(|(a, b)| (a - b).abs())
                    .fold(0.0, f64::max);
                assert!(worst <= tol, "{specular:?}, spot {spot}: off by {worst}");
            }
        }
    }
}

#[test]
fn saturation_keeps_the_direction_f32() {
    saturation_keeps_the_direction::<f32>(1e-50, 2e-5);
}

#[test]
fn saturation_keeps_the_direction_f64() {
    saturation_keeps_the_direction::<f64>(1e-310, 1e-12);
}

/// Without `normalize` a normal of magnitude beyond the range lights as the limit |n| → ∞ of
/// the equation: the diffuse term saturates where n·VP > 0 (the clamp gives 1) and is absent
/// elsewhere, on both sides, whether the input normal, the normal matrix or both are huge
/// (N·n overflows then).
fn huge_normals_light_as_the_limit<T: Real>(tiny: f64) {
    let max = T::MAX.to_f64();
    let scene = Scene {
        lights: vec![Light::default()],
        two_side: true,
        ..Scene::default()
    };
    let plain = |modelview| ShadeOptions {
        modelview,
        ..ShadeOptions::default()
    };
    let unlit = shade_all::<T>(&scene, &[[T::ZERO, T::ZERO, -T::ONE]], &plain(None))[0];
    assert!((unlit - 0.04).abs() < 1e-6, "the ambient term: {unlit}");
    let units = directions::<T>(70, 1.0);
    let small = Some(DMat4::from_scale(DVec3::splat(tiny)));
    for (normals, options) in [
        (directions::<T>(70, max), plain(None)),
        (units.clone(), plain(small)),
        (directions::<T>(70, 0.5 * max), plain(small)),
    ] {
        let out = shade_all(&scene, &normals, &options);
        let n = normals.len();
        for (row, u) in units.iter().enumerate() {
            let z = u[2].to_f64();
            if z == 0.0 {
                continue;
            }
            let (front, back) = (
                &out[4 * row..4 * row + 3],
                &out[4 * (n + row)..4 * (n + row) + 3],
            );
            let (lit, dark) = if z > 0.0 {
                (front, back)
            } else {
                (back, front)
            };
            assert!(lit.iter().all(|&c| c == 1.0), "row {row}: {lit:?}");
            assert!(dark.iter().all(|&c| c == unlit), "row {row}: {dark:?}");
        }
    }
}

#[test]
fn huge_normals_light_as_the_limit_f32() {
    huge_normals_light_as_the_limit::<f32>(1e-60);
}

#[test]
fn huge_normals_light_as_the_limit_f64() {
    huge_normals_light_as_the_limit::<f64>(1e-300);
}
