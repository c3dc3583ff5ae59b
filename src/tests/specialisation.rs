//! The specialised kernels against the general one and across instruction sets, bit for bit.
//!
//! Every subset of the scene features that choose what the kernel computes (directional and
//! positional lights, attenuation, spot, local viewer, shininess, specular colour, two-sided
//! lighting, separate specular, colour material, modelview, `normalize`, Phong, light ambient)
//! is shaded with [`Plan::new`] and with [`Plan::general`] (every term of every light), with
//! every instruction set this CPU has; all outputs must have the same bits.

use glam::DMat4;

use crate::errors::stop::Stop;
use crate::gl::light::Light;
use crate::gl::material::{ColorMaterial, ColorMaterialMode, Face, Material};
use crate::gl::scene::{Scene, Specular};
use crate::gl::vertex_colors::VertexColors;
use crate::lighting::driver::Inputs;
use crate::lighting::fixed_function::model::run;
use crate::lighting::fixed_function::options::ShadeOptions;
use crate::lighting::fixed_function::plan::{LightPlan, Plan};
use crate::lighting::fixed_function::prepare::Prepared;
use crate::memory::uninit::as_uninit;
use crate::numbers::real::Real;
use crate::simd::dispatch::Isa;
use crate::tests::support::vertices;

pub(crate) const FEATURES: u32 = 14;

/// The scene and options of feature subset `bits` (bit k on = feature k present).
pub(crate) fn scene_of(bits: u32) -> (Scene, ShadeOptions) {
    let on = |k: u32| bits >> k & 1 == 1;
    let ambient = if on(13) {
        [0.1, 0.05, 0.2, 1.0]
    } else {
        [0.0, 0.0, 0.0, 1.0]
    };
    let mut lights = Vec::new();
    if on(0) {
        lights.push(Light {
            position: [0.3, 0.5, 1.0, 0.0],
            ambient,
            ..Light::default()
        });
        // With an infinite viewer ĥ is a constant; the spot of a directional light is too.
        lights.push(Light {
            position: [-1.0, 0.2, 0.4, 0.0],
            diffuse: [0.5, 0.3, 0.2, 1.0],
            specular: [0.0; 4],
            spot_cutoff: 80.0,
            ..Light::default()
        });
    }
    if on(1) {
        let (k, cutoff) = (
            if on(2) {
                [0.5, 0.3, 0.2]
            } else {
                [1.0, 0.0, 0.0]
            },
            if on(3) { 60.0 } else { 180.0 },
        );
        // The second light has learnopengl's soft edge and Luna's range where the spot and
        // the attenuation are on together (both cut vertices of `vertices`).
        let edges = on(2) && on(3);
        for (i, position) in [[1.0, 2.0, 1.0, 1.0], [0.25, -0.5, 1.5, 0.5]]
            .into_iter()
            .enumerate()
        {
            lights.push(Light {
                position,
                ambient,
                constant_attenuation: k[0],
                linear_attenuation: k[1],
                quadratic_attenuation: k[2],
                spot_cutoff: cutoff,
                spot_direction: [-0.5, -1.0, -0.5],
                spot_exponent: 3.0,
                spot_inner_cutoff: if edges && i == 1 { 30.0 } else { 180.0 },
                range: if edges && i == 1 { 4.0 } else { f64::INFINITY },
                ..Light::default()
            });
        }
    }
    let material = Material {
        specular: if on(6) {
            [0.6, 0.5, 0.4, 1.0]
        } else {
            [0.0, 0.0, 0.0, 1.0]
        },
        // An even exponent (a power with no ĥ) in some subsets, an odd one in others.
        shininess: match (on(5), bits / 3 % 2) {
            (false, _) => 0.0,
            (true, 0) => 20.0,
            (true, _) => 7.0,
        },
        emission: [0.05, 0.0, 0.1, 1.0],
        ..Material::default()
    };
    let scene = Scene {
        lights,
        material,
        back_material: Material {
            diffuse: [0.2, 0.8, 0.3, 0.5],
            ..material
        },
        viewer: if on(4) {
            [0.5, 0.0, 2.0, 1.0]
        } else {
            [0.0, 0.0, 1.0, 0.0]
        },
        two_side: on(7),
        separate_specular: on(8),
        specular: if on(12) {
            Specular::Phong
        } else {
            Specular::Blinn
        },
        specular_gate: bits.count_ones().is_multiple_of(2),
        ..Scene::default()
    };
    let modes = [
        ColorMaterialMode::AmbientAndDiffuse,
        ColorMaterialMode::Specular,
        ColorMaterialMode::Emission,
        ColorMaterialMode::Diffuse,
        ColorMaterialMode::Ambient,
    ];
    let options = ShadeOptions {
        modelview: on(10).then(|| {
            DMat4::from_cols_array(&[
                0.8, 0.1, -0.2, 0.0, -0.1, 1.3, 0.3, 0.0, 0.2, -0.2, 0.7, 0.0, 0.1, -0.3, -2.0, 1.0,
            ])
        }),
        normalize: on(11),
        color_material: on(9).then(|| ColorMaterial {
            mode: modes[(bits as usize / 7) % modes.len()],
            face: [Face::FrontAndBack, Face::Front, Face::Back][bits as usize % 3],
        }),
        ..ShadeOptions::default()
    };
    (scene, options)
}

/// The output bits of `plan` (new or general) on `isa` in mode `"fast"` (the kernel's own
/// arithmetic).
fn shade_bits<T: Real>(bits: u32, general: bool, isa: Isa) -> Vec<u64> {
    let (scene, options) = scene_of(bits);
    let scene = scene.validated().unwrap();
    let (positions, normals, colors) = vertices::<T>();
    let prepared = Prepared::<T>::new(&scene, &options).unwrap();
    let plan = if general {
        Plan::general(&prepared)
    } else {
        Plan::new(&prepared)
    };
    let colors = options.color_material.map(|_| VertexColors {
        data: &colors[..],
        width: 4,
    });
    let mut out = vec![T::ZERO; scene.output_count() * 4 * normals.len()];
    run(
        &prepared,
        &plan,
        isa,
        Inputs {
            positions: &positions,
            normals: &normals,
            colors,
        },
        as_uninit(&mut out),
        &Stop::new(),
    )
    .unwrap();
    out.iter().map(|x| x.to_f64().to_bits()).collect()
}

fn check_every_subset<T: Real>() {
    let isas: Vec<Isa> = Isa::ALL.into_iter().filter(|i| i.supported()).collect();
    for bits in 0..1 << FEATURES {
        let reference = shade_bits::<T>(bits, true, Isa::Baseline);
        for &isa in &isas {
            for general in [false, true] {
                assert!(
                    shade_bits::<T>(bits, general, isa) == reference,
                    "features {bits:#016b}: plan {} on {} differs from the general plan on \
                     baseline",
                    if general { "general" } else { "new" },
                    isa.name(),
                );
            }
        }
    }
}

#[test]
fn specialised_kernels_match_the_general_one_bit_for_bit_f32() {
    check_every_subset::<f32>();
}

#[test]
fn specialised_kernels_match_the_general_one_bit_for_bit_f64() {
    check_every_subset::<f64>();
}

#[test]
fn the_subsets_reach_every_plan_flag() {
    // The test is only as good as its scenes: each flag is both on and off somewhere.
    let plans: Vec<Plan> = (0..1 << FEATURES)
        .map(|bits| {
            let (scene, options) = scene_of(bits);
            Plan::new(&Prepared::<f32>::new(&scene.validated().unwrap(), &options).unwrap())
        })
        .collect();
    let both = |f: &dyn Fn(&Plan) -> bool| plans.iter().any(f) && !plans.iter().all(f);
    assert!(both(&|p| p.positions));
    assert!(both(&|p| p.lights.iter().copied().any(LightPlan::edges)));
    assert!(both(&|p| p.unit_normal));
    assert!(both(&|p| p.normal_length));
    assert!(both(&|p| p.view));
    assert!(both(&|p| p.sides[0].power));
    assert!(both(&|p| p.sides[1].specular));
    assert!(both(&|p| p.lights.iter().any(|l| l.ambient)));
    assert!(both(&|p| p.lights.iter().any(|l| l.attenuated)));
    assert!(both(&|p| p.lights.iter().any(|l| l.specular)));
}
