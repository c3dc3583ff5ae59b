//! GL's model: the lighting equation of GL state ([`ValidScene`]) over arrays of vertices, as
//! a [`Model`]. A call prepares the scene once ([`Prepared`]), decides what it needs computed
//! ([`Plan`]), and runs the kernel compiled for the scene's shape ([`on_shape`]) in the
//! arithmetic `options.accuracy` asks for: [`Accuracy::Fast`] computes in `T`,
//! [`Accuracy::Exact`] in `f64` whatever `T` is.

use std::marker::PhantomData;
use std::mem::MaybeUninit;

use crate::errors::error::Error;
use crate::errors::stop::Stop;
use crate::gl::scene::ValidScene;
use crate::gl::vertex_colors::VertexColors;
use crate::lighting::accuracy::Accuracy;
use crate::lighting::clamp::ColorClamp;
use crate::lighting::driver::{run_shader, Inputs};
use crate::lighting::fixed_function::kernel::Kernel;
use crate::lighting::fixed_function::options::ShadeOptions;
use crate::lighting::fixed_function::plan::Plan;
use crate::lighting::fixed_function::prepare::Prepared;
use crate::lighting::fixed_function::shape::{on_shape, OnShape, Shape};
use crate::lighting::model::Model;
use crate::lighting::widen::in_float64;
use crate::numbers::real::{block_lanes, Real};
use crate::simd::dispatch::Isa;

/// Checks that vertex colours come with a `color_material` mode, and the mode with colours.
fn check_color_material<T: Real>(
    colors: Option<VertexColors<'_, T>>,
    options: &ShadeOptions,
) -> Result<(), Error> {
    match (colors.is_some(), options.color_material.is_some()) {
        (true, false) => Err(Error::value("colors need a color_material mode, got None")),
        (false, true) => Err(Error::value("color_material needs colors, got None")),
        _ => Ok(()),
    }
}

/// GL's model: `out` holds the planes of [`crate::gl::scene::Scene::output_names`], each
/// clamped to [0, 1] unless `options.clamp` is off; positions are read only when a light is
/// positional or the viewer local, so only then does a non-finite position make a NaN row.
impl Model for ValidScene {
    type Options = ShadeOptions;

    fn outputs(&self) -> usize {
        self.output_count()
    }

    fn light_count(&self) -> usize {
        self.lights.len()
    }

    fn shade_rows<T: Real>(
        &self,
        inputs: Inputs<'_, T>,
        options: &ShadeOptions,
        out: &mut [MaybeUninit<T>],
        stop: &Stop,
    ) -> Result<(), Error> {
        check_color_material(inputs.colors, options)?;
        if !options.accuracy.widens::<T>() {
            let prepared = Prepared::<T>::new(self, options)?;
            let plan = Plan::new(&prepared);
            return run(&prepared, &plan, Isa::detect(), inputs, out, stop);
        }
        let prepared = Prepared::<f64>::new(self, options)?;
        let plan = Plan::new(&prepared);
        in_float64(inputs, plan.positions, out, stop, |wide, dst, stop| {
            run(&prepared, &plan, Isa::detect(), wide, dst, stop)
        })
    }

    /// The accuracy, the arithmetic, the instruction set, the shape of kernel, the lanes per
    /// block and the plan, with grey sums, float32's path and an unclamped range named.
    fn describe<T: Real>(&self, options: &ShadeOptions) -> Result<String, Error> {
        let scene = self;
        let isa = Isa::detect();
        let exact = options.accuracy == Accuracy::Exact;
        let (bytes, (shape, lanes, grey_sums), plan) = if exact || std::mem::size_of::<T>() == 8 {
            let prepared = Prepared::<f64>::new(scene, options)?;
            let plan = Plan::new(&prepared);
            (8, shape_of(&plan, &prepared, isa), plan)
        } else {
            let prepared = Prepared::<T>::new(scene, options)?;
            let plan = Plan::new(&prepared);
            (4, shape_of(&plan, &prepared, isa), plan)
        };
        let mode = options.accuracy.name();
        let range = if options.clamp == ColorClamp::Off {
            "; unclamped (high dynamic range)"
        } else {
            ""
        };
        let grey = if grey_sums && !plan.lights.is_empty() {
            "; grey lights: one channel summed"
        } else {
            ""
        };
        // The plan's terms are those of both paths; float32 says which runs first.
        let path = match (bytes, plan.lean) {
            (4, true) => {
                "; lean float32 blocks (the careful path where a vertex needs a safeguard)"
            }
            (4, false) => {
                "; the careful path (a shininess above 128 or a constant attenuation below 2^-60)"
            }
            _ => "",
        };
        Ok(format!(
            "{mode}: float{} arithmetic, {}, {shape} kernel, {lanes} vertices per block; \
             {plan}{grey}{path}{range}",
            bytes * 8,
            isa.name(),
        ))
    }
}

/// Runs the kernel of `prepared` and `plan`, compiled for the call's shape of scene, over every
/// row with instruction set `isa`, skipping the tasks that start after `stop` is requested.
///
/// # Errors
/// A memory error for the task list, or [`Error::interrupted`].
pub(crate) fn run<T: Real>(
    prepared: &Prepared<T>,
    plan: &Plan,
    isa: Isa,
    inputs: Inputs<'_, T>,
    out: &mut [MaybeUninit<T>],
    stop: &Stop,
) -> Result<(), Error> {
    struct Run<'a, 'b, T: Real> {
        prepared: &'a Prepared<T>,
        plan: &'a Plan,
        isa: Isa,
        inputs: Inputs<'a, T>,
        out: &'b mut [MaybeUninit<T>],
        stop: &'a Stop,
    }
    impl<T: Real> OnShape for Run<'_, '_, T> {
        type Output = Result<(), Error>;
        fn call<S: Shape>(self) -> Self::Output {
            let kernel = Kernel::<T, S>::new(self.prepared, self.plan);
            run_shader(&kernel, self.isa, self.inputs, self.out, self.stop)
        }
    }
    let work = Run {
        prepared,
        plan,
        isa,
        inputs,
        out,
        stop,
    };
    on_shape(plan, prepared, isa, work)
}

/// The name of the shape whose kernel runs `plan`, its lanes per block with `isa`, and whether
/// it sums the light sums in one channel ([`Kernel::sums_grey`]).
fn shape_of<T: Real>(plan: &Plan, prepared: &Prepared<T>, isa: Isa) -> (&'static str, usize, bool) {
    struct Name<'p, T>(Isa, &'p Plan, PhantomData<T>);
    impl<T: Real> OnShape for Name<'_, T> {
        type Output = (&'static str, usize, bool);
        fn call<S: Shape>(self) -> Self::Output {
            let grey = Kernel::<T, S>::sums_grey(self.1);
            (S::NAME, block_lanes::<T>(self.0), grey)
        }
    }
    on_shape(plan, prepared, isa, Name::<T>(isa, plan, PhantomData))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gl::light::Light;
    use crate::gl::material::{ColorMaterial, Material};
    use crate::gl::scene::Scene;
    use crate::lighting::model::shade;
    use crate::simd::float::Float;

    fn shade_one<T: Real>(scene: &Scene, p: [T; 3], n: [T; 3], options: &ShadeOptions) -> Vec<T> {
        let mut out = vec![T::ZERO; scene.output_count() * 4];
        let scene = scene.clone().validated().unwrap();
        shade(&scene, &[p], &[n], None, options, &mut out, &Stop::new()).unwrap();
        out
    }

    fn close(a: &[f64], b: &[f64]) -> bool {
        a.len() == b.len() && a.iter().zip(b).all(|(x, y)| (x - y).abs() < 1e-12)
    }

    fn headlight_scene() -> Scene {
        Scene {
            lights: vec![Light::default()],
            ..Scene::default()
        }
    }

    #[test]
    fn without_the_clamp_the_sums_exceed_one_in_both_types() {
        // Three headlights facing the normal: 0.04 + 3 · 0.8 in each channel, alpha 1.
        let scene = Scene {
            lights: vec![Light::default(); 3],
            ..Scene::default()
        };
        let off = ShadeOptions {
            clamp: ColorClamp::Off,
            ..ShadeOptions::default()
        };
        let wide = shade_one::<f64>(&scene, [0.0; 3], [0.0, 0.0, 1.0], &off);
        assert!(close(&wide, &[2.44, 2.44, 2.44, 1.0]), "{wide:?}");
        let narrow = shade_one::<f32>(&scene, [0.0; 3], [0.0, 0.0, 1.0], &off);
        assert!(narrow
            .iter()
            .zip(&wide)
            .all(|(x, y)| (f64::from(*x) - y).abs() < 1e-6));
        let clamped = shade_one::<f64>(&scene, [0.0; 3], [0.0, 0.0, 1.0], &ShadeOptions::default());
        assert_eq!(clamped, [1.0; 4]);
    }

    #[test]
    fn headlight_on_a_facing_normal() {
        // e + a·a_cs + a·a_cl + 1·d·d_cl = 0 + 0.04 + 0 + 0.8; specular colour is 0.
        let out = shade_one::<f64>(
            &headlight_scene(),
            [0.0; 3],
            [0.0, 0.0, 1.0],
            &ShadeOptions::default(),
        );
        assert!(close(&out, &[0.84, 0.84, 0.84, 1.0]), "{out:?}");
        let out32 = shade_one::<f32>(
            &headlight_scene(),
            [0.0; 3],
            [0.0, 0.0, 1.0],
            &ShadeOptions::default(),
        );
        assert!((out32[0] - 0.84).abs() < 1e-6);
    }

    #[test]
    fn back_facing_keeps_ambient_only_and_two_side_lights_the_back() {
        let mut scene = headlight_scene();
        scene.material.specular = [1.0, 1.0, 1.0, 1.0];
        let out = shade_one::<f64>(&scene, [0.0; 3], [0.0, 0.0, -1.0], &ShadeOptions::default());
        assert!(close(&out, &[0.04, 0.04, 0.04, 1.0]), "{out:?}");
        scene.two_side = true;
        scene.back_material.diffuse = [0.5, 0.25, 0.0, 0.5];
        let out = shade_one::<f64>(&scene, [0.0; 3], [0.0, 0.0, -1.0], &ShadeOptions::default());
        // Back: 0.04 + 1·back diffuse + 0^0 specular (shininess 0) with back specular (0, 0, 0).
        assert!(
            close(&out, &[0.04, 0.04, 0.04, 1.0, 0.54, 0.29, 0.04, 0.5]),
            "{out:?}"
        );
    }

    #[test]
    fn shininess_zero_gives_the_full_specular_when_lit() {
        let mut scene = headlight_scene();
        scene.material.specular = [0.1, 0.2, 0.3, 1.0];
        scene.separate_specular = true;
        let n = [0.0, 0.6, 0.8];
        let out = shade_one::<f64>(&scene, [0.0; 3], n, &ShadeOptions::default());
        assert!(close(&out[4..], &[0.1, 0.2, 0.3, 1.0]), "{out:?}");
    }

    #[test]
    fn attenuation_follows_eq_2_4() {
        let light = Light {
            position: [0.0, 0.0, 2.0, 1.0],
            constant_attenuation: 1.0,
            linear_attenuation: 0.5,
            quadratic_attenuation: 0.25,
            ..Light::default()
        };
        let scene = Scene {
            lights: vec![light],
            global_ambient: [0.0; 4],
            ..Scene::default()
        };
        let out = shade_one::<f64>(&scene, [0.0; 3], [0.0, 0.0, 1.0], &ShadeOptions::default());
        assert!((out[0] - 0.8 / (1.0 + 1.0 + 1.0)).abs() < 1e-15);
    }

    #[test]
    fn light_at_the_vertex_is_finite() {
        let light = Light {
            position: [1.0, 2.0, 3.0, 1.0],
            constant_attenuation: 0.0,
            quadratic_attenuation: 1.0,
            ambient: [0.0, 0.5, -1.0, 1.0],
            ..Light::default()
        };
        let scene = Scene {
            lights: vec![light],
            global_ambient: [0.0; 4],
            ..Scene::default()
        };
        let out = shade_one::<f32>(
            &scene,
            [1.0, 2.0, 3.0],
            [0.0, 0.0, 1.0],
            &ShadeOptions::default(),
        );
        assert_eq!(out, vec![0.0, 1.0, 0.0, 1.0]);
    }

    fn shade_rows(scene: &Scene, positions: &[[f32; 3]], normals: &[[f32; 3]]) -> Vec<f32> {
        let mut out = vec![0.0_f32; positions.len() * 4];
        let options = ShadeOptions::default();
        let scene = scene.clone().validated().unwrap();
        shade(
            &scene,
            positions,
            normals,
            None,
            &options,
            &mut out,
            &Stop::new(),
        )
        .unwrap();
        out
    }

    #[test]
    fn nan_stays_in_its_row() {
        let mut scene = headlight_scene();
        let positions = [[0.0_f32; 3], [f32::NAN, 0.0, 0.0], [0.0; 3], [0.0; 3]];
        let normals = [
            [0.0, 0.0, 1.0],
            [0.0, 0.0, 1.0],
            [f32::INFINITY, 0.0, 1.0],
            [0.0; 3],
        ];
        let out = shade_rows(&scene, &positions, &normals);
        // A directional light under an infinite viewer never reads positions.
        assert!(out[..8].iter().chain(&out[12..]).all(|x| x.is_finite()));
        assert!(out[8..12].iter().all(|x| x.is_nan()));
        scene.viewer = [0.0, 0.0, 0.0, 1.0];
        let out = shade_rows(&scene, &positions, &normals);
        assert!(out[4..12].iter().all(|x| x.is_nan()));
        assert!(out[..4].iter().chain(&out[12..]).all(|x| x.is_finite()));
    }

    #[test]
    fn color_material_replaces_the_tracked_parameters() {
        let scene = headlight_scene().validated().unwrap();
        let options = ShadeOptions {
            color_material: Some(ColorMaterial::parse("diffuse", "front_and_back").unwrap()),
            ..ShadeOptions::default()
        };
        let colors = VertexColors {
            data: &[0.5, 0.25, 1.0, 0.5][..],
            width: 4,
        };
        let mut out = vec![0.0; 4];
        shade::<f64, _>(
            &scene,
            &[[0.0; 3]],
            &[[0.0, 0.0, 1.0]],
            Some(colors),
            &options,
            &mut out,
            &Stop::new(),
        )
        .unwrap();
        assert!(close(&out, &[0.54, 0.29, 1.0, 0.5]), "{out:?}");
    }

    #[test]
    fn mismatched_lengths_are_rejected() {
        let mut out = vec![0.0; 8];
        let err = shade::<f64, _>(
            &headlight_scene().validated().unwrap(),
            &[[0.0; 3]; 2],
            &[[0.0; 3]],
            None,
            &ShadeOptions::default(),
            &mut out,
            &Stop::new(),
        )
        .unwrap_err();
        assert!(err.message.starts_with("normals"));
    }

    /// One light of diffuse 0.9 and 999 of 2.9e-8 (each below half an ulp of 0.9), facing a
    /// unit normal: the sum in `f32`, in this order and reversed.
    fn bright_and_dim(reversed: bool, count: usize, accuracy: Accuracy) -> (f32, f64) {
        let light = |d: f64| Light {
            position: [0.0, 0.0, 1.0, 0.0],
            diffuse: [d, d, d, 1.0],
            specular: [0.0; 4],
            ..Light::default()
        };
        let mut lights: Vec<Light> = std::iter::once(0.9)
            .chain(std::iter::repeat_n(2.9e-8, count - 1))
            .map(light)
            .collect();
        if reversed {
            lights.reverse();
        }
        let scene = Scene {
            lights,
            material: Material {
                ambient: [0.0; 4],
                diffuse: [1.0; 4],
                ..Material::default()
            },
            global_ambient: [0.0; 4],
            ..Scene::default()
        };
        let options = ShadeOptions {
            accuracy,
            ..ShadeOptions::default()
        };
        let out = shade_one::<f32>(&scene, [0.0; 3], [0.0, 0.0, 1.0], &options);
        // The terms as the kernel forms them (colours rounded to f32), summed exactly enough.
        let exact = f64::from(0.9_f32) + (count - 1) as f64 * f64::from(2.9e-8_f32);
        (out[0], exact)
    }

    #[test]
    fn light_sums_do_not_depend_on_the_order_of_the_lights() {
        // "fast" sums blocks of 8 lights in f32 and adds the blocks' sums with their rounding
        // errors kept apart: within SUM_BLOCK ulp of Σ|terms| in any order (a plain f32 sum
        // from the bright light on loses all 999 dim terms, 28 ulp). "exact" sums in f64:
        // within 1 ulp of the correctly rounded total.
        for count in [9, 1000] {
            for (accuracy, ulps) in [(Accuracy::Fast, f32::SUM_BLOCK), (Accuracy::Exact, 1)] {
                let (forward, exact) = bright_and_dim(false, count, accuracy);
                let (backward, _) = bright_and_dim(true, count, accuracy);
                let rounded = exact as f32;
                let ulp = f32::from_bits(rounded.to_bits() + 1) - rounded;
                for got in [forward, backward] {
                    assert!(
                        (got - rounded).abs() <= ulps as f32 * ulp,
                        "{count}, {accuracy:?}: {got} vs {rounded}"
                    );
                }
            }
        }
    }

    #[test]
    fn results_do_not_depend_on_the_thread_count() {
        let scene = Scene {
            lights: (0..5)
                .map(|i| Light {
                    position: [f64::from(i), 1.0, 2.0, 1.0],
                    spot_cutoff: 60.0,
                    spot_exponent: 3.0,
                    linear_attenuation: 0.3,
                    ..Light::default()
                })
                .collect(),
            material: Material {
                specular: [1.0; 4],
                shininess: 40.0,
                ..Material::default()
            },
            viewer: [0.0, 0.0, 0.0, 1.0],
            ..Scene::default()
        }
        .validated()
        .unwrap();
        let n = 5000;
        let positions: Vec<[f32; 3]> = (0..n)
            .map(|i| {
                let t = i as f32 * 0.01;
                [t.sin(), t.cos(), -1.0 - t.sin() * t]
            })
            .collect();
        let normals: Vec<[f32; 3]> = (0..n)
            .map(|i| {
                let t = i as f32 * 0.37;
                [t.cos(), t.sin(), 0.5]
            })
            .collect();
        let run = |threads: usize| {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap();
            let mut out = vec![0.0_f32; n * 4];
            pool.install(|| {
                shade(
                    &scene,
                    &positions,
                    &normals,
                    None,
                    &ShadeOptions::default(),
                    &mut out,
                    &Stop::new(),
                )
                .unwrap();
            });
            out.iter().map(|x| x.to_bits()).collect::<Vec<_>>()
        };
        assert_eq!(run(1), run(3));
    }
}
