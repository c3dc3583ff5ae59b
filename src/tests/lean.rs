//! The lean arithmetic of float32's fast mode against float64 and against the careful path.
//!
//! Every feature subset of [`specialisation`](super::specialisation) is shaded in float32 with
//! the lean arithmetic and without it (the careful path alone), and in float64: the lean
//! colours stay within the fast mode's bound, 2·10⁻⁶·max(1, Σ|terms|) + 4u·s·Σ|terms| (u =
//! 2⁻²⁴; the subsets' terms are all nonnegative, so Σ|terms| is the unclamped float64 colour),
//! or, in the lanes that run the careful path, are its bits; a non-finite input gives NaN in
//! the same rows; and the lean arithmetic does run.

use crate::errors::stop::Stop;
use crate::gl::vertex_colors::VertexColors;
use crate::lighting::clamp::ColorClamp;
use crate::lighting::driver::Inputs;
use crate::lighting::fixed_function::model::run;
use crate::lighting::fixed_function::options::ShadeOptions;
use crate::lighting::fixed_function::plan::Plan;
use crate::lighting::fixed_function::prepare::Prepared;
use crate::memory::uninit::as_uninit;
use crate::numbers::real::Real;
use crate::simd::dispatch::Isa;
use crate::tests::specialisation::{scene_of, FEATURES};
use crate::tests::support::vertices;

/// The outputs of feature subset `bits` in `T`, with `options` changed by `adjust` and the
/// plan's lean arithmetic on or off.
fn outputs<T: Real>(bits: u32, lean: bool, adjust: fn(&mut ShadeOptions)) -> Vec<f64> {
    let (scene, mut options) = scene_of(bits);
    adjust(&mut options);
    let scene = scene.validated().unwrap();
    let (positions, normals, colors) = vertices::<T>();
    let prepared = Prepared::<T>::new(&scene, &options).unwrap();
    let plan = Plan {
        lean,
        ..Plan::new(&prepared)
    };
    let colors = options.color_material.map(|_| VertexColors {
        data: &colors[..],
        width: 4,
    });
    let mut out = vec![T::ZERO; scene.output_count() * 4 * normals.len()];
    let inputs = Inputs {
        positions: &positions,
        normals: &normals,
        colors,
    };
    let (isa, stop) = (Isa::detect(), Stop::new());
    run(&prepared, &plan, isa, inputs, as_uninit(&mut out), &stop).unwrap();
    out.iter().map(|x| x.to_f64()).collect()
}

/// The vertex of `vertices` whose VP and VP_e are opposite: its ĥ is the rounding of zero in
/// either arithmetic, so no bound holds there (the Accuracy page's 1/min(1, |h|)).
const OPPOSITE: usize = 8;

#[test]
fn lean_colours_stay_within_the_fast_bound() {
    let u = 2f64.powi(-24);
    let mut differ = 0;
    for bits in 0..1 << FEATURES {
        let lean = outputs::<f32>(bits, true, |_| {});
        let careful = outputs::<f32>(bits, false, |_| {});
        let exact = outputs::<f64>(bits, false, |_| {});
        let terms = outputs::<f64>(bits, false, |o| o.clamp = ColorClamp::Off);
        let s = scene_of(bits).0.material.shininess;
        let rows = vertices::<f32>().1.len();
        differ += usize::from(lean != careful);
        for (i, (&got, &want)) in lean.iter().zip(&exact).enumerate() {
            assert_eq!(got.is_nan(), careful[i].is_nan(), "{bits:#b}, value {i}");
            // The outputs are planes of (rows, 4): the vertex is the row within its plane.
            if got.is_nan() || i % (4 * rows) / 4 == OPPOSITE || got == careful[i] {
                continue;
            }
            let sum = terms[i].abs();
            let bound = 2e-6 * sum.max(1.0) + 4.0 * u * s * sum;
            assert!(
                (got - want).abs() <= bound,
                "features {bits:#016b}, value {i}: lean {got}, exact {want}, bound {bound:.3e}"
            );
        }
    }
    // Each subset has lights or a specular term in three of four cases: the lean arithmetic
    // changes some bits in most of them.
    assert!(
        differ > (1 << FEATURES) / 2,
        "lean differs in {differ} subsets"
    );
}

#[test]
fn a_light_at_a_vertex_sends_its_block_to_the_careful_path() {
    // Vertex 5 lies on the subsets' first point light (without a modelview, which moves it
    // off), where the lean arithmetic would divide by d = 0: the careful path's bits.
    let mut checked = 0;
    for bits in (0..1 << FEATURES).filter(|b| b & 0b10 != 0 && b & 1 << 10 == 0) {
        let lean = outputs::<f32>(bits, true, |_| {});
        let careful = outputs::<f32>(bits, false, |_| {});
        let rows = vertices::<f32>().1.len();
        // Row 5 of every output plane (each plane is (rows, 4)).
        let row5 = |i: &usize| i % (4 * rows) / 4 == 5;
        for i in (0..lean.len()).filter(row5) {
            assert!(lean[i].is_finite(), "{bits:#016b}");
            assert_eq!(lean[i].to_bits(), careful[i].to_bits(), "{bits:#016b}");
        }
        checked += 1;
    }
    assert!(checked > 0);
}
