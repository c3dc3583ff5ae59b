//! The kernels compiled for a shape of scene ([`crate::lighting::fixed_function::shape`]) against the general
//! kernel, bit for bit, on scenes of each shape, the instruction sets they are compiled for (AVX2,
//! AVX-512) and both types; the baseline choosing the general kernel; and [`fits`]
//! refusing every feature a shape fixes otherwise; and which plans are grey.

use glam::DMat4;

use crate::errors::stop::Stop;
use crate::gl::light::Light;
use crate::gl::material::{ColorMaterial, ColorMaterialMode, Face, Material};
use crate::gl::scene::{Scene, Specular};
use crate::lighting::driver::{run_shader, Inputs};
use crate::lighting::fixed_function::kernel::Kernel;
use crate::lighting::fixed_function::options::ShadeOptions;
use crate::lighting::fixed_function::plan::Plan;
use crate::lighting::fixed_function::prepare::Prepared;
use crate::lighting::fixed_function::shape::{
    fits, on_shape, Directional, General, Known, Mixed, OnShape, Point, Shape,
};
use crate::lighting::model::describe;
use crate::memory::uninit::as_uninit;
use crate::numbers::real::Real;
use crate::simd::dispatch::Isa;
use crate::tests::support::vertices;

/// Lights of every kind the mixed shape takes: directional, attenuated point, spot, one with
/// an ambient term (the benchmark's eight, in short).
fn mixed_lights() -> Vec<Light> {
    vec![
        Light {
            position: [0.3, 0.5, 1.0, 0.0],
            ..Light::default()
        },
        Light {
            position: [1.0, 2.0, 1.0, 1.0],
            linear_attenuation: 0.3,
            ..Light::default()
        },
        Light {
            position: [0.25, -0.5, 1.5, 0.5],
            spot_cutoff: 60.0,
            spot_direction: [-0.5, -1.0, -0.5],
            spot_exponent: 3.0,
            quadratic_attenuation: 0.2,
            ambient: [0.1, 0.05, 0.2, 1.0],
            ..Light::default()
        },
    ]
}

/// [`mixed_lights`] with a grey ambient term: every light's colours grey.
fn grey_mixed_lights() -> Vec<Light> {
    let mut lights = mixed_lights();
    lights[2].ambient = [0.1, 0.1, 0.1, 1.0];
    lights
}

/// A scene of each shape: (the shape's name, its flags, the scene).
fn shaped_scenes() -> Vec<(&'static str, Known, Scene)> {
    let material = Material {
        specular: [0.6, 0.5, 0.4, 1.0],
        shininess: 20.0,
        emission: [0.05, 0.0, 0.1, 1.0],
        ..Material::default()
    };
    let scene = |lights: Vec<Light>, viewer: [f64; 4]| Scene {
        lights,
        material,
        viewer,
        ..Scene::default()
    };
    let directional = vec![
        Light {
            position: [0.3, 0.5, 1.0, 0.0],
            ..Light::default()
        },
        Light {
            position: [-1.0, 0.2, 0.4, 0.0],
            spot_cutoff: 80.0,
            diffuse: [0.5, 0.3, 0.2, 1.0],
            ambient: [0.1, 0.1, 0.05, 1.0],
            ..Light::default()
        },
    ];
    let point = vec![
        Light {
            position: [1.0, 2.0, 1.0, 1.0],
            ..Light::default()
        },
        Light {
            position: [0.25, -0.5, 1.5, 0.5],
            constant_attenuation: 0.5,
            linear_attenuation: 0.3,
            quadratic_attenuation: 0.2,
            ..Light::default()
        },
    ];
    let local = [0.5, 0.0, 2.0, 1.0];
    vec![
        (
            "directional",
            Directional::KNOWN,
            scene(directional.clone(), [0.0, 0.0, 1.0, 0.0]),
        ),
        // More lights than one sum block: the blocks' compensated sum.
        (
            "directional",
            Directional::KNOWN,
            scene(directional.repeat(5), [0.0, 0.0, 1.0, 0.0]),
        ),
        ("point", Point::KNOWN, scene(point.repeat(6), local)),
        (
            "mixed",
            Mixed::KNOWN,
            scene(mixed_lights().repeat(4), local),
        ),
        ("point", Point::KNOWN, scene(point.clone(), local)),
        // One light and three: a kernel runs one or two lights as straight code, more in a loop.
        (
            "directional",
            Directional::KNOWN,
            scene(directional[..1].to_vec(), [0.0, 0.0, 1.0, 0.0]),
        ),
        ("point", Point::KNOWN, scene(point[..1].to_vec(), local)),
        (
            "point",
            Point::KNOWN,
            scene(point.iter().cycle().take(3).copied().collect(), local),
        ),
        // Grey lights (`Plan::grey`): the narrow shapes sum one channel; twelve lights take
        // the blocks' compensated sum, three the loop.
        (
            "mixed",
            Mixed::KNOWN,
            scene(grey_mixed_lights().repeat(4), local),
        ),
        ("mixed", Mixed::KNOWN, scene(grey_mixed_lights(), local)),
        // Last: the base of `a_shape_fits_only_scenes_with_every_flag_it_fixes`.
        ("mixed", Mixed::KNOWN, scene(mixed_lights(), local)),
    ]
}

/// The output bits of the kernel of shape `S` on `scene` with `isa`.
fn bits<T: Real, S: Shape>(scene: &Scene, options: &ShadeOptions, isa: Isa) -> Vec<u64> {
    let scene = scene.clone().validated().unwrap();
    let (positions, normals, _) = vertices::<T>();
    let prepared = Prepared::<T>::new(&scene, options).unwrap();
    let plan = Plan::new(&prepared);
    let inputs = Inputs {
        positions: &positions,
        normals: &normals,
        colors: None,
    };
    let mut out = vec![T::ZERO; 4 * normals.len()];
    let kernel = Kernel::<T, S>::new(&prepared, &plan);
    run_shader(&kernel, isa, inputs, as_uninit(&mut out), &Stop::new()).unwrap();
    out.iter().map(|x| x.to_f64().to_bits()).collect()
}

/// Each shape's scene, with and without `normalize`, fits its shape and gives the general
/// kernel's bits on every instruction set the shape is compiled for, in type `T`.
fn check<T: Real>() {
    for (name, known, scene) in shaped_scenes() {
        for normalize in [false, true] {
            let options = ShadeOptions {
                normalize,
                ..ShadeOptions::default()
            };
            let prepared =
                Prepared::<T>::new(&scene.clone().validated().unwrap(), &options).unwrap();
            assert!(
                fits(&known, &Plan::new(&prepared), &prepared),
                "{name} fits"
            );
            // The shapes are compiled for AVX2 and AVX-512; the baseline runs the general kernel.
            for isa in Isa::ALL
                .into_iter()
                .filter(|i| i.supported() && *i != Isa::Baseline)
            {
                let general = bits::<T, General>(&scene, &options, isa);
                let shaped = match name {
                    "directional" => bits::<T, Directional>(&scene, &options, isa),
                    "point" => bits::<T, Point>(&scene, &options, isa),
                    _ => bits::<T, Mixed>(&scene, &options, isa),
                };
                assert!(
                    shaped == general,
                    "{name}, normalize {normalize}, {}",
                    isa.name()
                );
            }
        }
    }
}

#[test]
fn shaped_kernels_match_the_general_one_bit_for_bit() {
    check::<f32>();
    check::<f64>();
}

#[test]
fn a_shape_fits_only_scenes_with_every_flag_it_fixes() {
    let (_, _, base) = shaped_scenes().pop().unwrap();
    let fits_mixed = |scene: &Scene, options: &ShadeOptions| {
        let prepared = Prepared::<f32>::new(&scene.clone().validated().unwrap(), options).unwrap();
        fits(&Mixed::KNOWN, &Plan::new(&prepared), &prepared)
    };
    let plain = ShadeOptions::default();
    assert!(fits_mixed(&base, &plain));
    let changed: Vec<(&str, Scene, ShadeOptions)> = vec![
        (
            "two-sided",
            Scene {
                two_side: true,
                ..base.clone()
            },
            plain,
        ),
        (
            "Phong",
            Scene {
                specular: Specular::Phong,
                ..base.clone()
            },
            plain,
        ),
        (
            "a range",
            Scene {
                lights: vec![Light {
                    position: [1.0, 2.0, 1.0, 1.0],
                    range: 3.0,
                    ..Light::default()
                }],
                ..base.clone()
            },
            plain,
        ),
        (
            "a soft spot edge",
            Scene {
                lights: vec![Light {
                    position: [1.0, 2.0, 1.0, 1.0],
                    spot_cutoff: 40.0,
                    spot_inner_cutoff: 30.0,
                    ..Light::default()
                }],
                ..base.clone()
            },
            plain,
        ),
        (
            "no gate",
            Scene {
                specular_gate: false,
                ..base.clone()
            },
            plain,
        ),
        (
            "separate specular",
            Scene {
                separate_specular: true,
                ..base.clone()
            },
            plain,
        ),
        (
            "infinite viewer",
            Scene {
                viewer: [0.0, 0.0, 1.0, 0.0],
                ..base.clone()
            },
            plain,
        ),
        (
            "no shininess",
            Scene {
                material: Material {
                    shininess: 0.0,
                    ..base.material
                },
                ..base.clone()
            },
            plain,
        ),
        (
            "a light without specular",
            Scene {
                lights: vec![Light {
                    specular: [0.0; 4],
                    ..Light::default()
                }],
                ..base.clone()
            },
            plain,
        ),
        (
            "modelview",
            base.clone(),
            ShadeOptions {
                modelview: Some(DMat4::from_scale(glam::DVec3::splat(2.0))),
                ..plain
            },
        ),
        (
            "colour material",
            base.clone(),
            ShadeOptions {
                color_material: Some(ColorMaterial {
                    mode: ColorMaterialMode::Diffuse,
                    face: Face::FrontAndBack,
                }),
                ..plain
            },
        ),
    ];
    for (what, scene, options) in changed {
        assert!(!fits_mixed(&scene, &options), "{what}");
    }
    // The narrower shapes refuse what they do not take.
    let (_, _, directional) = shaped_scenes().remove(0);
    let prepared = Prepared::<f32>::new(&base.validated().unwrap(), &plain).unwrap();
    assert!(!fits(&Directional::KNOWN, &Plan::new(&prepared), &prepared));
    assert!(!fits(&Point::KNOWN, &Plan::new(&prepared), &prepared));
    // A local viewer is not the directional shape's, whatever its lights.
    let local = Scene {
        viewer: [0.0, 0.0, 0.0, 1.0],
        ..directional
    };
    let prepared = Prepared::<f32>::new(&local.validated().unwrap(), &plain).unwrap();
    assert!(!fits(&Directional::KNOWN, &Plan::new(&prepared), &prepared));
}

#[test]
fn the_baseline_runs_the_general_kernel() {
    struct Name;
    impl OnShape for Name {
        type Output = &'static str;
        fn call<S: Shape>(self) -> Self::Output {
            S::NAME
        }
    }
    let options = ShadeOptions::default();
    for (name, _, scene) in shaped_scenes() {
        let prepared = Prepared::<f32>::new(&scene.validated().unwrap(), &options).unwrap();
        let plan = Plan::new(&prepared);
        assert_eq!(on_shape(&plan, &prepared, Isa::Baseline, Name), "general");
        for isa in [Isa::Avx2, Isa::Avx512] {
            assert_eq!(on_shape(&plan, &prepared, isa, Name), name);
        }
    }
}

#[test]
fn a_plan_is_grey_only_when_every_light_colour_is() {
    let plan = |lights: Vec<Light>| {
        let scene = Scene {
            lights,
            ..Scene::default()
        };
        let options = ShadeOptions::default();
        Plan::new(&Prepared::<f32>::new(&scene.validated().unwrap(), &options).unwrap())
    };
    assert!(plan(grey_mixed_lights()).grey);
    assert!(!plan(mixed_lights()).grey, "a coloured ambient term");
    let mut coloured = grey_mixed_lights();
    coloured[1].diffuse = [1.0, 1.0, 0.999, 1.0];
    assert!(!plan(coloured).grey, "a coloured diffuse term");
    let mut coloured = grey_mixed_lights();
    coloured[0].specular = [0.3, 0.2, 0.2, 1.0];
    assert!(!plan(coloured).grey, "a coloured specular term");
}

#[test]
fn the_plan_line_names_grey_sums_only_where_a_kernel_sums_one_channel() {
    let line = |lights: Vec<Light>, wide: bool| {
        // A specular term and a local viewer: the mixed kernel's scene.
        let scene = Scene {
            lights,
            material: Material {
                specular: [0.6, 0.5, 0.4, 1.0],
                shininess: 20.0,
                ..Material::default()
            },
            viewer: [0.0, 0.0, 0.0, 1.0],
            ..Scene::default()
        };
        let (scene, options) = (scene.validated().unwrap(), ShadeOptions::default());
        if wide {
            describe::<f64, _>(&scene, &options).unwrap()
        } else {
            describe::<f32, _>(&scene, &options).unwrap()
        }
    };
    let named = "grey lights: one channel summed";
    assert!(line(grey_mixed_lights(), false).contains("mixed kernel"));
    assert!(line(grey_mixed_lights(), false).contains(named));
    assert!(!line(grey_mixed_lights(), true).contains(named), "float64");
    assert!(!line(mixed_lights(), false).contains(named), "coloured");
    assert!(!line(Vec::new(), false).contains(named), "no lights");
}
