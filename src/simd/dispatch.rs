//! The instruction set the kernels run with, chosen at run time so one build uses AVX-512 or
//! AVX2 where the CPU has them and SSE2 (or the target's baseline) elsewhere.
//!
//! The kernels are written once over [`Lanes`](crate::simd::lanes::Lanes); an [`InstructionSet`]
//! (in [`crate::simd::lanes`], with the register types) names the register types they are
//! instantiated with (a block is two registers, `BlockLanes`: 16 `f32` or 8 `f64` lanes each with
//! AVX-512, 8 or 4 with AVX2, 4 or 2 with SSE2), and the work runs inside a function compiled with
//! that set's target features. Every lane runs the same IEEE operations, so every instruction set
//! gives the same bits (a test checks it).
//!
//! `unsafe` appears here and in `lanes::x86` and `lanes::sse2_fma` (calling a
//! `#[target_feature]` function is sound only on a CPU with those features, which
//! [`Isa::supported`] has checked), and in functions that hand memory to be written, not read,
//! to `shade` (`memory::uninit::as_uninit`, and the binding's two new numpy arrays).
#![allow(unsafe_code)]

#[cfg(not(feature = "single-kernel"))]
use std::sync::OnceLock;

use crate::simd::lanes::InstructionSet;
#[cfg(not(target_arch = "x86_64"))]
use crate::simd::lanes::Portable;
#[cfg(target_arch = "x86_64")]
use crate::simd::lanes::{Avx2, Avx512, Sse2};

/// The baseline set of the target.
#[cfg(target_arch = "x86_64")]
pub type Baseline = Sse2;
/// The baseline set of the target.
#[cfg(not(target_arch = "x86_64"))]
pub type Baseline = Portable;

/// A work item that runs with the register types of an instruction set; `run` must be
/// `#[inline(always)]` so that its whole body is compiled with the caller's target features.
pub trait LaneWork {
    /// Does the work with the registers of `S`.
    fn run<S: InstructionSet>(self);
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

    /// True when this CPU can run the level (with the `single-kernel` feature, only the level
    /// the kernels were compiled for).
    pub fn supported(self) -> bool {
        #[cfg(feature = "single-kernel")]
        if self != single::ISA {
            return false;
        }
        match self {
            Isa::Baseline => true,
            #[cfg(target_arch = "x86_64")]
            Isa::Avx2 => avx2_detected(),
            #[cfg(target_arch = "x86_64")]
            Isa::Avx512 => avx512_detected(),
            #[cfg(not(target_arch = "x86_64"))]
            _ => false,
        }
    }

    /// The best level this CPU supports, capped by the environment variable `GLSHADE_ISA`
    /// (`baseline`, `avx2` or `avx512`) when it is set; detected once per process. With the
    /// `single-kernel` feature, the level compiled for, whatever `GLSHADE_ISA` says.
    pub fn detect() -> Isa {
        #[cfg(feature = "single-kernel")]
        {
            single::ISA
        }
        #[cfg(not(feature = "single-kernel"))]
        {
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
    }

    /// Runs `work` with the registers of this level.
    ///
    /// # Panics
    /// If the CPU does not support the level (callers pass [`Isa::detect`] or a level whose
    /// [`Isa::supported`] they checked).
    pub fn run<W: LaneWork>(self, work: W) {
        #[cfg(feature = "single-kernel")]
        {
            assert_eq!(self, single::ISA, "a single-kernel build runs one level");
            work.run::<single::Set>();
        }
        #[cfg(not(feature = "single-kernel"))]
        if self == Isa::Baseline {
            work.run::<Baseline>();
        } else {
            self.run_wide(work);
        }
    }

    /// Runs `work` with the registers of this level, which must be AVX2 or AVX-512: `work` is
    /// compiled for those two only (the shapes' kernels, which the baseline runs as the general
    /// kernel), so the baseline's registers never instantiate it.
    ///
    /// # Panics
    /// If the CPU does not support the level, or the level is the baseline.
    pub fn run_wide<W: LaneWork>(self, work: W) {
        assert!(self.supported(), "{} is not supported here", self.name());
        match self {
            #[cfg(target_arch = "x86_64")]
            Isa::Avx512 => unsafe { avx512(work) },
            #[cfg(target_arch = "x86_64")]
            Isa::Avx2 => unsafe { avx2(work) },
            _ => panic!("run_wide needs AVX2 or AVX-512, got {}", self.name()),
        }
    }
}

/// With the `single-kernel` feature (the inner loop of kernel work), the one level the kernels
/// are compiled for: the best of the features the whole crate is compiled with, so this
/// machine's best with `RUSTFLAGS="-C target-cpu=native"`, else the baseline. Those features
/// are on everywhere, so the work runs as it is, without a `#[target_feature]` function.
#[cfg(feature = "single-kernel")]
mod single {
    #[cfg(all(
        target_arch = "x86_64",
        target_feature = "avx512f",
        target_feature = "avx512bw",
        target_feature = "avx512dq",
        target_feature = "avx512vl",
        target_feature = "fma"
    ))]
    pub(super) use {super::Isa::Avx512 as ISA, crate::simd::lanes::Avx512 as Set};

    #[cfg(all(
        target_arch = "x86_64",
        target_feature = "avx2",
        target_feature = "fma",
        not(all(
            target_feature = "avx512f",
            target_feature = "avx512bw",
            target_feature = "avx512dq",
            target_feature = "avx512vl"
        ))
    ))]
    pub(super) use {super::Isa::Avx2 as ISA, crate::simd::lanes::Avx2 as Set};

    #[cfg(not(all(
        target_arch = "x86_64",
        target_feature = "avx2",
        target_feature = "fma"
    )))]
    pub(super) use {super::Baseline as Set, super::Isa::Baseline as ISA};
}

/// Defines, from one list of target features, the function that runs a [`LaneWork`] compiled
/// with them and the check that this CPU has every one of them: a feature enabled but not
/// checked would let the compiler emit an instruction the CPU may lack.
#[cfg(target_arch = "x86_64")]
macro_rules! feature_set {
    ($run:ident, $detected:ident, $set:ty, [$($feature:tt),+ $(,)?]) => {
        /// True when the CPU has every feature the function below is compiled with.
        fn $detected() -> bool {
            $(is_x86_feature_detected!($feature))&&+
        }

        // SAFETY: only called from `Isa::run`, after `Isa::supported` confirmed the features.
        $(#[target_feature(enable = $feature)])+
        fn $run<W: LaneWork>(work: W) {
            work.run::<$set>();
        }
    };
}

#[cfg(target_arch = "x86_64")]
feature_set!(
    avx512,
    avx512_detected,
    Avx512,
    [
        "avx512f", "avx512bw", "avx512dq", "avx512vl", "avx2", "avx", "fma", "bmi1", "bmi2",
        "lzcnt"
    ]
);

#[cfg(target_arch = "x86_64")]
feature_set!(
    avx2,
    avx2_detected,
    Avx2,
    ["avx2", "avx", "fma", "bmi1", "bmi2", "lzcnt"]
);
