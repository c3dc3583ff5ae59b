//! The kernels' arithmetic types tied to their lanes: a [`Real`] is a [`Float`] with the
//! elementary functions over its lanes ([`Elementary`]) and the register type of its lanes in
//! each instruction set, so one kernel written over `T: Real` runs with any of them.
//!
//! Also the scale-safe vector normalisation that the whole equation relies on: glam's
//! `normalize` computes `sqrt(dot(v, v))`, which under- or overflows for |v| outside roughly
//! [1e-19, 1e19] in f32; [`normalize_and_length`] prescales such vectors by an exact power of two
//! (it is the one-lane case of [`crate::simd::lanes::normalize_and_length`]).

use std::cell::Cell;
use std::marker::PhantomData;

use crate::numbers::elementary::Elementary;
use crate::simd::dispatch::{Isa, LaneWork};
use crate::simd::float::{Float, Vector3};
use crate::simd::lanes::{InstructionSet, Lanes, Scalar, V3};

/// A floating-point type the kernels compute in, `f32` or `f64`, with its lanes.
pub trait Real: Float + Elementary {
    /// The lanes of this type in one register of instruction set `S`.
    type Vector<S: InstructionSet>: Lanes<T = Self>;
}

/// The vertices float32's lean path decides together: a block of SSE2 and AVX2 (16 float32
/// lanes), so AVX-512's blocks of 32 decide each group of 16 alone and every instruction set
/// gives the same bits.
pub const LEAN_GROUP: usize = 16;

/// The lanes of one block of `T` under instruction set `S` ([`InstructionSet::Block`]): two
/// registers with AVX-512 and AVX2, four with SSE2. Measured, one thread: on Zen 4, 2026-12-02,
/// with AVX-512 two ran 1.2 to 1.4 times as fast as one in the shapes' kernels and as fast as
/// four in the general one, in half the code. AVX2 runs where AVX-512 is missing: on Zen 2,
/// 2026-12-05, two ran the seven bench scenes 0.99 to 1.44 times as fast as four in float32 and
/// float64 (four spilled most values to the stack: 16 registers of 8 lanes hold little of a
/// 32-lane block) and 1.2 to 1.4 times as fast as one; Zen 4's AVX2 path, which that machine
/// does not run, had four 10 to 15% ahead on 8 lights.
pub type BlockLanes<T, S> = <S as InstructionSet>::Block<<T as Real>::Vector<S>>;

impl Real for f32 {
    type Vector<S: InstructionSet> = S::F32;
}

impl Real for f64 {
    type Vector<S: InstructionSet> = S::F64;
}

/// The unit vector in the direction of `v` and the length of `v`; `(0, 0)` for the zero vector.
///
/// Exact for every finite `v`: when |v|² is subnormal or overflows, `v` is first scaled by an
/// exact power of two ([`Float::UPSCALE`] or [`Float::DOWNSCALE`]), which changes no direction bit.
/// The length itself may round to infinity for |v| beyond the type's range.
#[inline]
pub fn normalize_and_length<T: Real>(v: T::Vec3) -> (T::Vec3, T) {
    let (unit, length) =
        crate::simd::lanes::normalize_and_length(V3::<T::Vector<Scalar>>::splat(v.to_array()));
    (T::Vec3::from_array(unit.lane(0)), length.lane(0))
}

/// The unit vector in the direction of `v`, or zero for the zero vector (see
/// [`normalize_and_length`]).
#[inline]
pub fn normalize_or_zero<T: Real>(v: T::Vec3) -> T::Vec3 {
    normalize_and_length::<T>(v).0
}

/// The lanes per block of `T` with instruction set `isa` ([`BlockLanes`]), asked of the register
/// type.
///
/// # Panics
/// As [`Isa::run`].
pub fn block_lanes<T: Real>(isa: Isa) -> usize {
    struct Count<'a, T>(&'a Cell<usize>, PhantomData<T>);
    impl<T: Real> LaneWork for Count<'_, T> {
        #[inline(always)]
        fn run<S: InstructionSet>(self) {
            self.0.set(<BlockLanes<T, S> as Lanes>::N);
        }
    }
    let lanes = Cell::new(0);
    isa.run(Count::<T>(&lanes, PhantomData));
    lanes.get()
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::{DVec3, Vec3};

    fn unit_error(v: Vec3) -> f32 {
        (normalize_or_zero::<f32>(v).dot(normalize_or_zero::<f32>(v)) - 1.0).abs()
    }

    #[test]
    fn zero_vector_normalises_to_zero() {
        assert_eq!(normalize_and_length::<f32>(Vec3::ZERO), (Vec3::ZERO, 0.0));
        assert_eq!(normalize_and_length::<f64>(DVec3::ZERO), (DVec3::ZERO, 0.0));
    }

    #[test]
    fn tiny_and_huge_vectors_keep_their_direction() {
        for scale in [1e-45_f32, 1e-40, 1e-25, 1e-20, 1.0, 1e20, 1e30, 3e38] {
            let v = Vec3::new(3.0, 4.0, 0.0) * (scale / 5.0);
            if v == Vec3::ZERO {
                continue;
            }
            assert!(unit_error(v) < 4e-7, "scale {scale}");
        }
        let tiny = 1e-40_f32; // subnormal
        let (u, len) = normalize_and_length::<f32>(Vec3::new(tiny, 0.0, tiny));
        assert!((u.x - std::f32::consts::FRAC_1_SQRT_2).abs() < 1e-7);
        // The length itself is subnormal: its ulp, 2^-149, is 1e-5 of it.
        assert!((f64::from(len) - f64::from(tiny) * 2f64.sqrt()).abs() <= 1.5e-45);
        let (u, len) = normalize_and_length::<f64>(DVec3::new(0.0, 1e-320, 0.0));
        assert_eq!(u, DVec3::Y);
        assert!((len - 1e-320).abs() <= 1e-323);
        let (u, _) = normalize_and_length::<f64>(DVec3::new(1e300, 1e300, 0.0));
        assert!((u.x - std::f64::consts::FRAC_1_SQRT_2).abs() <= 2.0 * f64::EPSILON);
    }
}
