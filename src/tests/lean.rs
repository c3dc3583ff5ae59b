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

/// Blocks of 16 and of 32 lanes, with AVX2's registers.
#[cfg(target_arch = "x86_64")]
mod widths {
    use super::*;
    use crate::lighting::driver::load_block;
    use crate::lighting::fixed_function::kernel::Kernel;
    use crate::lighting::fixed_function::shape::{fits, Mixed, Shape};
    use crate::numbers::real::BlockLanes;
    use crate::simd::dispatch::LaneWork;
    use crate::simd::lanes::{InstructionSet, Lanes, Pair, MAX_LANES};

    /// The front colours (RGBA rows, as bits) of `inputs` shaded in blocks of `V` by the mixed
    /// shape's kernel (one narrow kernel: two more copies of the general one would double the
    /// test build), loaded as the driver loads them.
    #[inline(always)]
    fn in_blocks<V: Lanes<T = f32>>(
        prepared: &Prepared<f32>,
        plan: &Plan,
        inputs: Inputs<'_, f32>,
    ) -> Vec<u32> {
        let kernel = Kernel::<f32, Mixed>::new(prepared, plan);
        let count = inputs.normals.len();
        let mut out = Vec::with_capacity(4 * count);
        for first in (0..count).step_by(V::N) {
            let valid = V::N.min(count - first);
            let block = load_block::<V>(inputs, kernel.reads_positions(), first, valid);
            let mut rgba = [[0.0_f32; MAX_LANES]; 4];
            for (plane, c) in rgba.iter_mut().zip(kernel.block(&block, 0)[0]) {
                c.store(plane);
            }
            for j in 0..valid {
                out.extend(rgba.iter().map(|c| c[j].to_bits()));
            }
        }
        out
    }

    /// One feature subset shaded in AVX2 blocks of 16 and of 32, and in blocks of 16 on the
    /// careful path alone.
    struct Widths<'a> {
        prepared: &'a Prepared<f32>,
        plan: &'a Plan,
        inputs: Inputs<'a, f32>,
        out: &'a mut [Vec<u32>; 3],
    }

    impl LaneWork for Widths<'_> {
        #[inline(always)]
        fn run<S: InstructionSet>(self) {
            let (prepared, plan, inputs) = (self.prepared, self.plan, self.inputs);
            let careful = Plan {
                lean: false,
                ..plan.clone()
            };
            *self.out = [
                in_blocks::<BlockLanes<f32, S>>(prepared, plan, inputs),
                in_blocks::<Pair<BlockLanes<f32, S>>>(prepared, plan, inputs),
                in_blocks::<BlockLanes<f32, S>>(prepared, &careful, inputs),
            ];
        }
    }

    #[test]
    fn blocks_of_16_and_of_32_give_the_same_bits() {
        // The lean path decides each group of 16 vertices alone, so AVX-512's blocks of 32 keep the
        // colours of SSE2's and AVX2's blocks of 16 where one half needs the careful path and the
        // other does not. The awkward rows of `vertices` (3 to 8) lie in the first group; the later
        // rows have unit normals, so their groups can run lean. 181 rows end in a block of 21 rows,
        // whose second group (rows 176 to 180) is padded with its own first row, not with row 160,
        // which has a zero normal and would send it to the careful path. AVX2's registers in both
        // widths (16 and 32 lanes), compiled for that set alone; the subsets of the mixed shape
        // (positional lights, spots and directional lights, ambient terms or not, a local viewer).
        if !Isa::Avx2.supported() {
            eprintln!("no AVX2 here: the blocks of 16 and of 32 are not compared");
            return;
        }
        let (mut positions, mut normals, mut colors) = vertices::<f32>();
        positions.extend_from_within(16..32);
        normals.extend_from_within(16..32);
        colors.extend_from_within(64..128);
        for n in &mut normals[16..] {
            let length = n.iter().map(|c| c * c).sum::<f32>().sqrt();
            *n = n.map(|c| c / length);
        }
        normals[160] = [0.0; 3];
        let (mut lean_groups, mut careful_groups) = (0, 0);
        for bits in 0..1 << FEATURES {
            let (scene, options) = scene_of(bits);
            let scene = scene.validated().unwrap();
            let prepared = Prepared::<f32>::new(&scene, &options).unwrap();
            let plan = Plan::new(&prepared);
            if !fits(&Mixed::KNOWN, &plan, &prepared) {
                continue;
            }
            let inputs = Inputs {
                positions: &positions,
                normals: &normals,
                colors: options.color_material.map(|_| VertexColors {
                    data: &colors[..],
                    width: 4,
                }),
            };
            let mut out = [Vec::new(), Vec::new(), Vec::new()];
            Isa::run_avx2(Widths {
                prepared: &prepared,
                plan: &plan,
                inputs,
                out: &mut out,
            });
            let [narrow, wide, careful] = out;
            assert_eq!(narrow.len(), 4 * 181);
            assert!(narrow == wide, "features {bits:#016b}");
            // Which path rows 176 to 180 took: the careful path's bits or others.
            let tail = 4 * 176..4 * 181;
            if narrow[tail.clone()] == careful[tail] {
                careful_groups += 1;
            } else {
                lean_groups += 1;
            }
        }
        // The padded group ran lean where the shape's subsets have lights (the careful path's
        // bits where they have none: the same arithmetic then), so the comparison can fail.
        assert!(
            lean_groups >= 2,
            "{lean_groups} lean, {careful_groups} careful"
        );
    }
}
