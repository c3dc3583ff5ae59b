//! The instruction set the kernels run with, chosen at run time so one build uses AVX-512 or
//! AVX2 where the CPU has them and SSE2 (or the target's baseline) elsewhere.
//!
//! The kernels are written once over lane arrays (`crate::lanes`); here the same code is
//! compiled three times, inside functions with different `#[target_feature]`s. Every lane runs
//! the same IEEE operations, so every instruction set gives the same bits (a test checks it).
//!
//! Blocks are [`LANES`] = 16 vertices for both `f32` and `f64` and every instruction set, also
//! where that is two or four vector registers: with 8 lanes LLVM fully unrolls the lane loops
//! of the elementary functions before its loop vectoriser runs, and the straight-line code that
//! remains stays scalar in a kernel this size (measured: `exp` and `ln` scalar in the 8-lane
//! `f64` and AVX2 `f32` kernels, vector with 16 lanes).
//!
//! This is the crate's only `unsafe`: calling a `#[target_feature]` function is sound only on a
//! CPU with those features, which [`Isa::detect`] has checked.
#![allow(unsafe_code)]

use std::sync::OnceLock;

/// Vertices per block.
pub const LANES: usize = 16;

/// A work item that runs with `N` lanes; `run` must be `#[inline(always)]` so that its whole
/// body is compiled with the caller's target features.
pub trait LaneWork {
    /// Does the work, `N` vertices at a time.
    fn run<const N: usize>(self);
}

/// An instruction-set level of x86-64 (or the baseline of any other target).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Isa {
    /// The target's baseline (SSE2 on x86-64).
    Baseline,
    /// AVX2 (x86-64-v3).
    Avx2,
    /// AVX-512 F/BW/DQ/VL (x86-64-v4).
    Avx512,
}

impl Isa {
    /// Every level, lowest first.
    pub const ALL: [Isa; 3] = [Isa::Baseline, Isa::Avx2, Isa::Avx512];

    /// The name used in `GLSHADE_ISA` and in plans: `"baseline"`, `"avx2"` or `"avx512"`.
    pub fn name(self) -> &'static str {
        match self {
            Isa::Baseline => "baseline",
            Isa::Avx2 => "avx2",
            Isa::Avx512 => "avx512",
        }
    }

    /// True when this CPU can run the level.
    pub fn supported(self) -> bool {
        match self {
            Isa::Baseline => true,
            #[cfg(target_arch = "x86_64")]
            Isa::Avx2 => is_x86_feature_detected!("avx2"),
            #[cfg(target_arch = "x86_64")]
            Isa::Avx512 => {
                is_x86_feature_detected!("avx512f")
                    && is_x86_feature_detected!("avx512bw")
                    && is_x86_feature_detected!("avx512dq")
                    && is_x86_feature_detected!("avx512vl")
            }
            #[cfg(not(target_arch = "x86_64"))]
            _ => false,
        }
    }

    /// The best level this CPU supports, capped by the environment variable `GLSHADE_ISA`
    /// (`baseline`, `avx2` or `avx512`) when it is set; detected once per process.
    pub fn detect() -> Isa {
        static CHOSEN: OnceLock<Isa> = OnceLock::new();
        *CHOSEN.get_or_init(|| {
            let cap = std::env::var("GLSHADE_ISA")
                .ok()
                .and_then(|name| Isa::ALL.into_iter().find(|isa| isa.name() == name))
                .unwrap_or(Isa::Avx512);
            Isa::ALL
                .into_iter()
                .rev()
                .find(|isa| *isa <= cap && isa.supported())
                .unwrap_or(Isa::Baseline)
        })
    }

    /// Runs `work` with [`LANES`] lanes, compiled for this level.
    ///
    /// # Panics
    /// If the CPU does not support the level (callers pass [`Isa::detect`] or a level whose
    /// [`Isa::supported`] they checked).
    pub fn run<W: LaneWork>(self, work: W) {
        assert!(self.supported(), "{} is not supported here", self.name());
        match self {
            #[cfg(target_arch = "x86_64")]
            Isa::Avx512 => unsafe { avx512::<W, LANES>(work) },
            #[cfg(target_arch = "x86_64")]
            Isa::Avx2 => unsafe { avx2::<W, LANES>(work) },
            _ => work.run::<LANES>(),
        }
    }
}

// SAFETY (for both): only called from `Isa::run`, after `Isa::supported` confirmed the features.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx512f,avx512bw,avx512dq,avx512vl,avx2,avx,fma,bmi1,bmi2,lzcnt")]
fn avx512<W: LaneWork, const N: usize>(work: W) {
    work.run::<N>();
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,avx,fma,bmi1,bmi2,lzcnt")]
fn avx2<W: LaneWork, const N: usize>(work: W) {
    work.run::<N>();
}
