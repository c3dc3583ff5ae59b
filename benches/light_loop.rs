//! How fast a light loop can be on this CPU, whatever glshade's kernels do: point lights under a
//! local viewer (attenuated, Blinn-Phong, shininess 32) in loops of three structures, with no
//! exactness safeguard at all, as an upper bound for each structure.
//!
//! - `run-time`: one loop over the lights per block, the lights' numbers read from memory, as
//!   glshade's kernels (and any kernel compiled ahead of time) loop;
//! - `two-pass`: the same loop split in two, each light's weights first (nothing carried from
//!   one light to the next), then the sums;
//! - `straight`: every light's numbers compiled in as constants, the loop unrolled into one
//!   block of code, as Dr.Jit compiles a scene.
//!
//! Each in three arithmetics: `naive` (VP and ĥ normalised, 2 √ and 3 ÷ per light, the power by
//! plain squaring), `lean` (1 √ and 2 ÷ per light: the attenuation and 1/|d| from one division,
//! ĥ's power from ‖n × g‖²/‖g‖² squared on the complement, without the test n·ĥ > 0, which
//! these vertices never fail) and `approximate` (`lean` with the CPU's approximate reciprocals),
//! and in one or two AVX2 registers a value (8 or 16 vertices a block). Every kernel reads positions and normals as
//! planes (no transposes) and writes one grey channel (no ambient, no clamp): less than
//! `gs.shade` does, so a structure that cannot lead a peer here cannot lead it in glshade.
//! `benches/light_loop.py` times glshade and Dr.Jit on the same lights. Run both with one thread:
//!
//! ```text
//! cargo bench --bench light_loop -- 8 32
//! RAYON_NUM_THREADS=1 python benches/light_loop.py 8 32
//! ```
#![allow(unsafe_code)] // std::arch's intrinsics

/// A point light: its position, GL's three attenuation coefficients, its grey diffuse and
/// specular colours.
#[derive(Clone, Copy)]
struct PointLight {
    position: [f32; 3],
    attenuation: [f32; 3],
    diffuse: f32,
    specular: f32,
}

/// The most lights of a run.
const LIGHT_COUNT: usize = 32;

/// Light `i` of the example's 32, from integer arithmetic alone so that the constants of the
/// straight code and the Python script's lights are the same numbers.
const fn point_light(i: usize) -> PointLight {
    PointLight {
        position: [
            6.0 * fraction(i, 37, 61) - 3.0,
            6.0 * fraction(i, 53, 59) - 3.0,
            3.0 * fraction(i, 29, 31) - 1.0,
        ],
        attenuation: [1.0, 0.1 * (i % 3) as f32, 0.05 * (i % 2 + 1) as f32],
        diffuse: 0.1,
        specular: 0.1,
    }
}

/// ((a·i + 7) mod m)/m: a fraction in [0, 1) that walks through m values.
const fn fraction(i: usize, a: usize, m: usize) -> f32 {
    ((a * i + 7) % m) as f32 / m as f32
}

/// The example's lights.
const LIGHTS: [PointLight; LIGHT_COUNT] = {
    let mut lights = [point_light(0); LIGHT_COUNT];
    let mut i = 1;
    while i < LIGHT_COUNT {
        lights[i] = point_light(i);
        i += 1;
    }
    lights
};

/// The material's grey diffuse and specular colours.
const MATERIAL: [f32; 2] = [0.8, 0.5];

#[cfg(target_arch = "x86_64")]
mod avx2 {
    use super::{PointLight, LIGHTS, LIGHT_COUNT, MATERIAL};
    use std::arch::x86_64::{
        __m256, _mm256_add_ps, _mm256_and_ps, _mm256_cmp_ps, _mm256_div_ps, _mm256_fmadd_ps,
        _mm256_fmsub_ps, _mm256_fnmadd_ps, _mm256_loadu_ps, _mm256_max_ps, _mm256_mul_ps,
        _mm256_rcp_ps, _mm256_rsqrt_ps, _mm256_set1_ps, _mm256_setzero_ps, _mm256_sqrt_ps,
        _mm256_storeu_ps, _mm256_sub_ps, _CMP_GT_OQ,
    };

    /// A value of every vertex of a block: one register or two.
    pub trait Lanes: Copy {
        /// Vertices a block.
        const N: usize;
        /// `x` in every lane.
        fn splat(x: f32) -> Self;
        /// Lanes from `N` values at `p`.
        unsafe fn load(p: *const f32) -> Self;
        /// The lanes to `N` values at `p`.
        unsafe fn store(self, p: *mut f32);
        /// `self + b`.
        fn add(self, b: Self) -> Self;
        /// `self − b`.
        fn sub(self, b: Self) -> Self;
        /// `self · b`.
        fn mul(self, b: Self) -> Self;
        /// `self / b`.
        fn div(self, b: Self) -> Self;
        /// max(self, 0).
        fn max0(self) -> Self;
        /// `self · b + c`.
        fn mul_add(self, b: Self, c: Self) -> Self;
        /// `self · b − c`.
        fn mul_sub(self, b: Self, c: Self) -> Self;
        /// `c − self · b`.
        fn neg_mul_add(self, b: Self, c: Self) -> Self;
        /// √self.
        fn sqrt(self) -> Self;
        /// `self` where `gate` > 0, else 0.
        fn where_positive(self, gate: Self) -> Self;
        /// 1/√self from `vrsqrtps` and one Newton step.
        fn inverse_sqrt_newton(self) -> Self;
        /// 1/self from `vrcpps` and one Newton step.
        fn inverse_newton(self) -> Self;
    }

    // The intrinsics are safe to call here: `run` checks AVX2 and FMA, and every caller is
    // compiled for them (`#[target_feature]` on the kernels, which inline all of this; no
    // closure, which would be compiled without them).
    impl Lanes for __m256 {
        const N: usize = 8;
        #[inline(always)]
        fn splat(x: f32) -> Self {
            unsafe { _mm256_set1_ps(x) }
        }
        #[inline(always)]
        unsafe fn load(p: *const f32) -> Self {
            _mm256_loadu_ps(p)
        }
        #[inline(always)]
        unsafe fn store(self, p: *mut f32) {
            _mm256_storeu_ps(p, self);
        }
        #[inline(always)]
        fn add(self, b: Self) -> Self {
            unsafe { _mm256_add_ps(self, b) }
        }
        #[inline(always)]
        fn sub(self, b: Self) -> Self {
            unsafe { _mm256_sub_ps(self, b) }
        }
        #[inline(always)]
        fn mul(self, b: Self) -> Self {
            unsafe { _mm256_mul_ps(self, b) }
        }
        #[inline(always)]
        fn div(self, b: Self) -> Self {
            unsafe { _mm256_div_ps(self, b) }
        }
        #[inline(always)]
        fn max0(self) -> Self {
            unsafe { _mm256_max_ps(self, _mm256_setzero_ps()) }
        }
        #[inline(always)]
        fn mul_add(self, b: Self, c: Self) -> Self {
            unsafe { _mm256_fmadd_ps(self, b, c) }
        }
        #[inline(always)]
        fn mul_sub(self, b: Self, c: Self) -> Self {
            unsafe { _mm256_fmsub_ps(self, b, c) }
        }
        #[inline(always)]
        fn neg_mul_add(self, b: Self, c: Self) -> Self {
            unsafe { _mm256_fnmadd_ps(self, b, c) }
        }
        #[inline(always)]
        fn sqrt(self) -> Self {
            unsafe { _mm256_sqrt_ps(self) }
        }
        #[inline(always)]
        fn where_positive(self, gate: Self) -> Self {
            unsafe { _mm256_and_ps(_mm256_cmp_ps::<_CMP_GT_OQ>(gate, _mm256_setzero_ps()), self) }
        }
        #[inline(always)]
        fn inverse_sqrt_newton(self) -> Self {
            // y·(3 − x·y²)/2
            let y = unsafe { _mm256_rsqrt_ps(self) };
            let half_y = y.mul(Self::splat(0.5));
            self.mul(y).neg_mul_add(y, Self::splat(3.0)).mul(half_y)
        }
        #[inline(always)]
        fn inverse_newton(self) -> Self {
            // r·(2 − x·r)
            let r = unsafe { _mm256_rcp_ps(self) };
            self.neg_mul_add(r, Self::splat(2.0)).mul(r)
        }
    }

    /// Two registers a value.
    #[derive(Clone, Copy)]
    pub struct Pair(__m256, __m256);

    /// Pair's operations: the register's on each half.
    macro_rules! halves {
        ($($op:ident($($arg:ident),*)),+) => {$(
            #[inline(always)]
            fn $op(self, $($arg: Self),*) -> Self {
                Pair(self.0.$op($($arg.0),*), self.1.$op($($arg.1),*))
            }
        )+};
    }

    impl Lanes for Pair {
        const N: usize = 16;
        #[inline(always)]
        fn splat(x: f32) -> Self {
            Pair(__m256::splat(x), __m256::splat(x))
        }
        #[inline(always)]
        unsafe fn load(p: *const f32) -> Self {
            Pair(__m256::load(p), __m256::load(p.add(8)))
        }
        #[inline(always)]
        unsafe fn store(self, p: *mut f32) {
            self.0.store(p);
            self.1.store(p.add(8));
        }
        halves!(
            add(b),
            sub(b),
            mul(b),
            div(b),
            max0(),
            mul_add(b, c),
            mul_sub(b, c)
        );
        halves!(neg_mul_add(b, c), sqrt(), where_positive(gate));
        halves!(inverse_sqrt_newton(), inverse_newton());
    }

    #[inline(always)]
    fn dot<V: Lanes>(a: [V; 3], b: [V; 3]) -> V {
        a[0].mul_add(b[0], a[1].mul_add(b[1], a[2].mul(b[2])))
    }

    /// One block's inputs and what every light reads of them.
    #[derive(Clone, Copy)]
    struct Vertices<V> {
        p: [V; 3],
        n: [V; 3],
        /// VP_e, the unit vector to the viewer at the origin.
        view: [V; 3],
        /// |n|² − 1 (the lean power's).
        squared_minus_one: V,
    }

    impl<V: Lanes> Vertices<V> {
        #[inline(always)]
        unsafe fn load(planes: &[Vec<f32>; 6], i: usize) -> Self {
            let at = |k: usize| planes[k].as_ptr().add(i);
            let p = [V::load(at(0)), V::load(at(1)), V::load(at(2))];
            let n = [V::load(at(3)), V::load(at(4)), V::load(at(5))];
            let to_eye = V::splat(-1.0).div(dot(p, p).sqrt());
            Self {
                p,
                n,
                view: [p[0].mul(to_eye), p[1].mul(to_eye), p[2].mul(to_eye)],
                squared_minus_one: n[0]
                    .mul_add(n[0], n[1].mul_add(n[1], n[2].mul_sub(n[2], V::splat(1.0)))),
            }
        }
    }

    /// VP and ĥ normalised (2 √ and 3 ÷ a light), the power by plain squaring.
    const NAIVE: u8 = 0;
    /// 1 √ and 2 ÷ a light: the attenuation and 1/|d| from one division, ĥ's power from
    /// ‖n × g‖²/‖g‖² squared on the complement.
    const LEAN: u8 = 1;
    /// [`LEAN`]'s formula with no √ or ÷: the CPU's approximate 1/√x and 1/x and one Newton
    /// step each (about 2 ulp; their bits differ between CPU vendors).
    const APPROXIMATE: u8 = 2;

    /// att·(n·VP) and att·(n·ĥ)^32, gated by n·VP > 0, of one light at a block.
    #[inline(always)]
    fn weights<V: Lanes, const ARITHMETIC: u8>(light: &PointLight, v: &Vertices<V>) -> (V, V) {
        let [x, y, z] = light.position;
        let d = [
            V::splat(x).sub(v.p[0]),
            V::splat(y).sub(v.p[1]),
            V::splat(z).sub(v.p[2]),
        ];
        let [k0, k1, k2] = light.attenuation;
        let [k0, k1, k2] = [V::splat(k0), V::splat(k1), V::splat(k2)];
        let d2 = dot(d, d);
        let (n_dot_vp, attenuation, power) = if ARITHMETIC == NAIVE {
            let length = d2.sqrt();
            let inverse = V::splat(1.0).div(length);
            let vp = [d[0].mul(inverse), d[1].mul(inverse), d[2].mul(inverse)];
            let attenuation = V::splat(1.0).div(k2.mul_add(d2, k1.mul_add(length, k0)));
            let g = [
                vp[0].add(v.view[0]),
                vp[1].add(v.view[1]),
                vp[2].add(v.view[2]),
            ];
            let mut power = dot(v.n, g).div(dot(g, g).sqrt()).max0();
            for _ in 0..5 {
                power = power.mul(power);
            }
            (dot(v.n, vp), attenuation, power)
        } else {
            let (inverse_length, attenuation) = if ARITHMETIC == LEAN {
                let length = d2.sqrt();
                let den = k2.mul_add(d2, k1.mul_add(length, k0));
                let r = V::splat(1.0).div(length.mul(den));
                (den.mul(r), length.mul(r))
            } else {
                let inverse_length = d2.inverse_sqrt_newton();
                let length = d2.mul(inverse_length);
                let den = k2.mul_add(d2, k1.mul_add(length, k0));
                (inverse_length, den.inverse_newton())
            };
            let g = [
                d[0].mul_add(inverse_length, v.view[0]),
                d[1].mul_add(inverse_length, v.view[1]),
                d[2].mul_add(inverse_length, v.view[2]),
            ];
            let n = v.n;
            let cross = [
                n[1].mul_sub(g[2], n[2].mul(g[1])),
                n[2].mul_sub(g[0], n[0].mul(g[2])),
                n[0].mul_sub(g[1], n[1].mul(g[0])),
            ];
            // (n·ĥ)² = |n|² − ‖n × g‖²/‖g‖²; its complement squared 4 times: (n·ĥ)^32.
            let sine2 = if ARITHMETIC == LEAN {
                dot(cross, cross).div(dot(g, g))
            } else {
                dot(cross, cross).mul(dot(g, g).inverse_newton())
            };
            let mut y = sine2.sub(v.squared_minus_one);
            for _ in 0..4 {
                y = y.neg_mul_add(y, y.add(y));
            }
            (
                dot(v.n, d).mul(inverse_length),
                attenuation,
                V::splat(1.0).sub(y),
            )
        };
        (
            attenuation.mul(n_dot_vp.max0()),
            attenuation.mul(power).where_positive(n_dot_vp),
        )
    }

    /// The grey colour of a block from its light sums.
    #[inline(always)]
    fn colour<V: Lanes>(diffuse: V, specular: V) -> V {
        diffuse.mul_add(V::splat(MATERIAL[0]), specular.mul(V::splat(MATERIAL[1])))
    }

    /// One loop over `lights` per block.
    #[inline(always)]
    fn run_time<V: Lanes, const ARITHMETIC: u8>(
        planes: &[Vec<f32>; 6],
        lights: &[PointLight],
        out: &mut [f32],
    ) {
        for i in (0..out.len()).step_by(V::N) {
            let v = unsafe { Vertices::<V>::load(planes, i) };
            let (mut diffuse, mut specular) = (V::splat(0.0), V::splat(0.0));
            for light in lights {
                let (d, s) = weights::<V, ARITHMETIC>(light, &v);
                diffuse = d.mul_add(V::splat(light.diffuse), diffuse);
                specular = s.mul_add(V::splat(light.specular), specular);
            }
            unsafe { colour(diffuse, specular).store(out.as_mut_ptr().add(i)) };
        }
    }

    /// Each light's weights in one loop, the sums in a second.
    #[inline(always)]
    fn two_pass<V: Lanes, const ARITHMETIC: u8>(
        planes: &[Vec<f32>; 6],
        lights: &[PointLight],
        out: &mut [f32],
    ) {
        let lights = &lights[..lights.len().min(LIGHT_COUNT)];
        let mut weighed = [(V::splat(0.0), V::splat(0.0)); LIGHT_COUNT];
        for i in (0..out.len()).step_by(V::N) {
            let v = unsafe { Vertices::<V>::load(planes, i) };
            for (slot, light) in weighed.iter_mut().zip(lights) {
                *slot = weights::<V, ARITHMETIC>(light, &v);
            }
            let (mut diffuse, mut specular) = (V::splat(0.0), V::splat(0.0));
            for ((d, s), light) in weighed.iter().zip(lights) {
                diffuse = d.mul_add(V::splat(light.diffuse), diffuse);
                specular = s.mul_add(V::splat(light.specular), specular);
            }
            unsafe { colour(diffuse, specular).store(out.as_mut_ptr().add(i)) };
        }
    }

    /// Straight code for the first lights of `LIGHTS`, their numbers constants.
    macro_rules! straight {
        ($name:ident, $($i:literal)+) => {
            #[inline(always)]
            fn $name<V: Lanes, const ARITHMETIC: u8>(planes: &[Vec<f32>; 6], out: &mut [f32]) {
                for i in (0..out.len()).step_by(V::N) {
                    let v = unsafe { Vertices::<V>::load(planes, i) };
                    let (mut diffuse, mut specular) = (V::splat(0.0), V::splat(0.0));
                    $(
                        let (d, s) = weights::<V, ARITHMETIC>(&LIGHTS[$i], &v);
                        diffuse = d.mul_add(V::splat(LIGHTS[$i].diffuse), diffuse);
                        specular = s.mul_add(V::splat(LIGHTS[$i].specular), specular);
                    )+
                    unsafe { colour(diffuse, specular).store(out.as_mut_ptr().add(i)) };
                }
            }
        };
    }
    straight!(straight_8, 0 1 2 3 4 5 6 7);
    straight!(straight_32, 0 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17 18 19 20 21 22 23 24 25 26 27 28 29 30 31);

    /// A kernel of the comparison: its planes, its lights (the first `count` of `LIGHTS`) and
    /// its output.
    type Kernel = fn(&[Vec<f32>; 6], &[PointLight], &mut [f32]);

    /// Compiles `$body` for AVX2 and FMA as a [`Kernel`].
    macro_rules! kernel {
        (|$planes:ident, $lights:ident, $out:ident| $body:expr) => {{
            #[target_feature(enable = "avx2,fma")]
            unsafe fn compiled($planes: &[Vec<f32>; 6], $lights: &[PointLight], $out: &mut [f32]) {
                $body
            }
            (|p, l, o| unsafe { compiled(p, l, o) }) as Kernel
        }};
    }

    /// Every kernel, by name, for `count` lights (8 or 32).
    fn kernels(count: usize) -> Vec<(&'static str, Kernel)> {
        let mut all: Vec<(&'static str, Kernel)> = vec![
            (
                "run-time, naive, one register",
                kernel!(|p, l, o| run_time::<__m256, NAIVE>(p, l, o)),
            ),
            (
                "run-time, naive",
                kernel!(|p, l, o| run_time::<Pair, NAIVE>(p, l, o)),
            ),
            (
                "run-time, lean",
                kernel!(|p, l, o| run_time::<Pair, LEAN>(p, l, o)),
            ),
            (
                "run-time, approximate",
                kernel!(|p, l, o| run_time::<Pair, APPROXIMATE>(p, l, o)),
            ),
            (
                "two-pass, naive",
                kernel!(|p, l, o| two_pass::<Pair, NAIVE>(p, l, o)),
            ),
            (
                "two-pass, lean",
                kernel!(|p, l, o| two_pass::<Pair, LEAN>(p, l, o)),
            ),
        ];
        // The straight kernels' lights are constants, so each count is its own function.
        macro_rules! straight_kernels {
            ($straight:ident) => {
                [
                    (
                        "straight, naive",
                        kernel!(|p, _l, o| $straight::<Pair, NAIVE>(p, o)),
                    ),
                    (
                        "straight, lean",
                        kernel!(|p, _l, o| $straight::<Pair, LEAN>(p, o)),
                    ),
                    (
                        "straight, approximate",
                        kernel!(|p, _l, o| $straight::<Pair, APPROXIMATE>(p, o)),
                    ),
                ]
            };
        }
        if count == 8 {
            all.extend(straight_kernels!(straight_8));
        } else {
            all.extend(straight_kernels!(straight_32));
        }
        all
    }

    /// 2^20 vertices as planes: positions x, y in [−1, 1], z in [−4, −2]; unit normals towards
    /// +z (the Python script's distribution).
    fn vertices() -> [Vec<f32>; 6] {
        let count = 1 << 20;
        let mut state = 0x9e37_79b9_7f4a_7c15_u64;
        let mut uniform = move || {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            (state >> 40) as f32 / (1u64 << 24) as f32
        };
        let mut planes: [Vec<f32>; 6] = Default::default();
        for _ in 0..count {
            let p = [
                2.0 * uniform() - 1.0,
                2.0 * uniform() - 1.0,
                -2.0 - 2.0 * uniform(),
            ];
            let n = [uniform() - 0.5, uniform() - 0.5, uniform() + 0.01];
            let length = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
            for (plane, c) in planes.iter_mut().zip([
                p[0],
                p[1],
                p[2],
                n[0] / length,
                n[1] / length,
                n[2] / length,
            ]) {
                plane.push(c);
            }
        }
        planes
    }

    /// Times every kernel for each light count, interleaved over three rounds, and prints
    /// each one's median rate and its largest difference from the first kernel's output.
    pub fn run(counts: &[usize]) {
        let planes = vertices();
        let vertices = planes[0].len();
        // Through `black_box`, so the run-time loops cannot fold the lights in as constants.
        let lights = std::hint::black_box(LIGHTS.to_vec());
        for &count in counts {
            let kernels = kernels(count);
            let mut outputs = vec![vec![0.0_f32; vertices]; kernels.len()];
            let mut rates = vec![Vec::new(); kernels.len()];
            for _round in 0..3 {
                for ((_, kernel), (out, rate)) in
                    kernels.iter().zip(outputs.iter_mut().zip(&mut rates))
                {
                    let mut seconds: Vec<f64> = (0..7)
                        .map(|_| {
                            let start = std::time::Instant::now();
                            kernel(&planes, &lights[..count], out);
                            start.elapsed().as_secs_f64()
                        })
                        .collect();
                    seconds.sort_by(f64::total_cmp);
                    rate.push(vertices as f64 / seconds[3] / 1e6);
                }
            }
            println!("{count} point lights, {vertices} vertices, one thread: million vertices/s, rounds 1 to 3");
            for (((name, _), rate), out) in kernels.iter().zip(&rates).zip(&outputs) {
                let difference = out
                    .iter()
                    .zip(&outputs[0])
                    .map(|(a, b)| (a - b).abs())
                    .fold(0.0_f32, f32::max);
                let rounds: Vec<String> = rate.iter().map(|r| format!("{r:.1}")).collect();
                println!(
                    "  {name:32} {}   (max |Δ| from the first {difference:.1e})",
                    rounds.join("  ")
                );
            }
        }
    }
}

fn main() {
    let counts: Vec<usize> = std::env::args()
        .skip(1)
        .filter(|a| a != "--bench") // what `cargo bench` adds
        .map(|a| match a.parse() {
            Ok(n @ (8 | 32)) => n,
            _ => panic!("light counts are 8 or 32, not {a:?}"),
        })
        .collect();
    let counts = if counts.is_empty() {
        vec![8, 32]
    } else {
        counts
    };
    #[cfg(target_arch = "x86_64")]
    if is_x86_feature_detected!("avx2") && is_x86_feature_detected!("fma") {
        avx2::run(&counts);
        return;
    }
    eprintln!("this example needs an x86-64 CPU with AVX2 and FMA");
}
