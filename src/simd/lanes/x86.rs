//! [`Lanes`] in the registers of x86-64: SSE2 (4 `f32` or 2 `f64`), AVX2 (8 or 4) and AVX-512
//! (16 or 8), so the kernel's values stay in registers instead of passing through the stack.
//!
//! Every operation is one intrinsic, or a few for the row transposes, with the semantics of the
//! portable [`super::Pack`]: IEEE basic operations, ordered quiet comparisons, `min`/`max` that
//! keep a NaN of `self`. The fused multiply-add is one instruction with AVX2 and AVX-512; SSE2
//! computes its bits in `f64` ([`super::sse2_fma`]) for `f32`, and lane by lane through the
//! software `fma` for `f64`.
//!
//! SAFETY (for the whole module): the intrinsics of AVX2 and AVX-512 may only run on a CPU that
//! has them. The register types are `pub(crate)` and reach the kernel only through
//! [`crate::simd::dispatch::Isa::run`], which checks the CPU first and calls the kernel inside a
//! function compiled with those features. Loads and stores check their slice lengths.
#![allow(unsafe_code, clippy::cast_possible_wrap)]

use std::arch::x86_64::{
    __m128, __m128d, __m128i, __m256, __m256d, __m256i, __m512, __m512d, __m512i, _mm256_add_epi32,
    _mm256_add_epi64, _mm256_add_pd, _mm256_add_ps, _mm256_and_pd, _mm256_and_ps, _mm256_and_si256,
    _mm256_blend_ps, _mm256_blendv_pd, _mm256_blendv_ps, _mm256_castpd_ps, _mm256_castpd_si256,
    _mm256_castps_pd, _mm256_castps_si256, _mm256_castsi256_pd, _mm256_castsi256_ps, _mm256_cmp_pd,
    _mm256_cmp_ps, _mm256_div_pd, _mm256_div_ps, _mm256_fmadd_pd, _mm256_fmadd_ps, _mm256_fmsub_pd,
    _mm256_fmsub_ps, _mm256_loadu_pd, _mm256_loadu_ps, _mm256_max_pd, _mm256_max_ps, _mm256_min_pd,
    _mm256_min_ps, _mm256_movemask_pd, _mm256_movemask_ps, _mm256_mul_pd, _mm256_mul_ps,
    _mm256_or_pd, _mm256_or_ps, _mm256_or_si256, _mm256_permute2f128_ps, _mm256_permutevar8x32_ps,
    _mm256_set1_epi32, _mm256_set1_epi64x, _mm256_set1_pd, _mm256_set1_ps, _mm256_sll_epi32,
    _mm256_sll_epi64, _mm256_sqrt_pd, _mm256_sqrt_ps, _mm256_srl_epi32, _mm256_srl_epi64,
    _mm256_storeu_pd, _mm256_storeu_ps, _mm256_sub_epi32, _mm256_sub_epi64, _mm256_sub_pd,
    _mm256_sub_ps, _mm256_unpackhi_pd, _mm256_unpackhi_ps, _mm256_unpacklo_pd, _mm256_unpacklo_ps,
    _mm256_xor_pd, _mm256_xor_ps, _mm512_add_epi32, _mm512_add_epi64, _mm512_add_pd, _mm512_add_ps,
    _mm512_and_si512, _mm512_castpd_ps, _mm512_castpd_si512, _mm512_castps_pd, _mm512_castps_si512,
    _mm512_castsi512_pd, _mm512_castsi512_ps, _mm512_cmp_pd_mask, _mm512_cmp_ps_mask,
    _mm512_div_pd, _mm512_div_ps, _mm512_fmadd_pd, _mm512_fmadd_ps, _mm512_fmsub_pd,
    _mm512_fmsub_ps, _mm512_loadu_pd, _mm512_loadu_ps, _mm512_mask_blend_pd, _mm512_mask_blend_ps,
    _mm512_max_pd, _mm512_max_ps, _mm512_min_pd, _mm512_min_ps, _mm512_mul_pd, _mm512_mul_ps,
    _mm512_or_si512, _mm512_permutex2var_pd, _mm512_permutex2var_ps, _mm512_set1_epi32,
    _mm512_set1_epi64, _mm512_set1_pd, _mm512_set1_ps, _mm512_shuffle_f32x4, _mm512_shuffle_f64x2,
    _mm512_sll_epi32, _mm512_sll_epi64, _mm512_sqrt_pd, _mm512_sqrt_ps, _mm512_srl_epi32,
    _mm512_srl_epi64, _mm512_storeu_pd, _mm512_storeu_ps, _mm512_sub_epi32, _mm512_sub_epi64,
    _mm512_sub_pd, _mm512_sub_ps, _mm512_unpackhi_pd, _mm512_unpackhi_ps, _mm512_unpacklo_pd,
    _mm512_unpacklo_ps, _mm512_xor_si512, _mm_add_epi32, _mm_add_epi64, _mm_add_pd, _mm_add_ps,
    _mm_and_pd, _mm_and_ps, _mm_and_si128, _mm_andnot_pd, _mm_andnot_ps, _mm_castpd_si128,
    _mm_castps_si128, _mm_castsi128_pd, _mm_castsi128_ps, _mm_cmpeq_pd, _mm_cmpeq_ps, _mm_cmple_pd,
    _mm_cmple_ps, _mm_cmplt_pd, _mm_cmplt_ps, _mm_cvtsi32_si128, _mm_div_pd, _mm_div_ps,
    _mm_loadu_pd, _mm_loadu_ps, _mm_max_pd, _mm_max_ps, _mm_min_pd, _mm_min_ps, _mm_movemask_pd,
    _mm_movemask_ps, _mm_mul_pd, _mm_mul_ps, _mm_or_pd, _mm_or_ps, _mm_or_si128, _mm_set1_epi32,
    _mm_set1_epi64x, _mm_set1_pd, _mm_set1_ps, _mm_sll_epi32, _mm_sll_epi64, _mm_sqrt_pd,
    _mm_sqrt_ps, _mm_srl_epi32, _mm_srl_epi64, _mm_storeu_pd, _mm_storeu_ps, _mm_sub_epi32,
    _mm_sub_epi64, _mm_sub_pd, _mm_sub_ps, _mm_xor_pd, _mm_xor_ps, _CMP_EQ_OQ, _CMP_LE_OQ,
    _CMP_LT_OQ,
};
use std::mem::MaybeUninit;
use std::ops::{Add, BitAnd, BitOr, Div, Mul, Neg, Not, Sub};

use super::sse2_fma::fma_f32x4;
use super::{LaneBits, LaneMask, Lanes, V3};

/// The binary operators of a register type, one intrinsic each.
macro_rules! binary {
    ($type:ident, $($trait:ident, $method:ident, $intrinsic:ident;)*) => {$(
        impl $trait for $type {
            type Output = Self;
            #[inline(always)]
            #[allow(unused_unsafe)]
            fn $method(self, o: Self) -> Self {
                Self(unsafe { $intrinsic(self.0, o.0) })
            }
        }
    )*};
}

/// A comparison mask held in a vector register (SSE2, AVX2): all ones or all zeros per lane.
macro_rules! vector_mask {
    ($mask:ident, $reg:ty, $and:ident, $or:ident, $xor:ident, $movemask:ident, $ones:expr,
     $lanes:expr) => {
        #[doc = concat!("A comparison mask of ", stringify!($lanes), " lanes.")]
        #[derive(Clone, Copy, Debug)]
        pub(crate) struct $mask($reg);

        binary!($mask, BitAnd, bitand, $and; BitOr, bitor, $or;);

        impl Not for $mask {
            type Output = Self;
            #[inline(always)]
            #[allow(unused_unsafe)]
            fn not(self) -> Self {
                Self(unsafe { $xor(self.0, $ones) })
            }
        }

        impl LaneMask for $mask {
            const N: usize = $lanes;

            #[inline(always)]
            #[allow(unused_unsafe)]
            fn splat(b: bool) -> Self {
                let ones = unsafe { $ones };
                Self(if b { ones } else { unsafe { $xor(ones, ones) } })
            }
            #[inline(always)]
            #[allow(unused_unsafe, clippy::cast_sign_loss)]
            fn bitmask(self) -> u64 {
                u64::from(unsafe { $movemask(self.0) } as u32)
            }
            #[inline(always)]
            fn all(self) -> bool {
                self.bitmask() == (1 << $lanes) - 1
            }
        }
    };
}

/// A comparison mask held in an AVX-512 mask register.
macro_rules! k_mask {
    ($mask:ident, $int:ty, $lanes:expr) => {
        #[doc = concat!("A comparison mask of ", stringify!($lanes), " lanes.")]
        #[derive(Clone, Copy, Debug)]
        pub(crate) struct $mask($int);

        impl BitAnd for $mask {
            type Output = Self;
            #[inline(always)]
            fn bitand(self, o: Self) -> Self {
                Self(self.0 & o.0)
            }
        }

        impl BitOr for $mask {
            type Output = Self;
            #[inline(always)]
            fn bitor(self, o: Self) -> Self {
                Self(self.0 | o.0)
            }
        }

        impl Not for $mask {
            type Output = Self;
            #[inline(always)]
            fn not(self) -> Self {
                Self(!self.0)
            }
        }

        impl LaneMask for $mask {
            const N: usize = $lanes;

            #[inline(always)]
            fn splat(b: bool) -> Self {
                Self(if b { <$int>::MAX } else { 0 })
            }
            #[inline(always)]
            fn bitmask(self) -> u64 {
                u64::from(self.0)
            }
            #[inline(always)]
            fn all(self) -> bool {
                self.0 == <$int>::MAX
            }
        }
    };
}

/// Unsigned integer lanes in a vector register.
macro_rules! bits {
    ($bits:ident, $reg:ty, $add:ident, $sub:ident, $and:ident, $or:ident, $sll:ident,
     $srl:ident, $set1:ident, $int:ty) => {
        /// The bits of a register of floats.
        #[derive(Clone, Copy, Debug)]
        pub(crate) struct $bits($reg);

        binary!($bits, Add, add, $add; Sub, sub, $sub; BitAnd, bitand, $and; BitOr, bitor, $or;);

        impl LaneBits for $bits {
            #[inline(always)]
            #[allow(unused_unsafe, clippy::cast_possible_truncation)]
            fn splat(x: u64) -> Self {
                Self(unsafe { $set1(x as $int) })
            }
            #[inline(always)]
            #[allow(unused_unsafe)]
            fn shl(self, k: u32) -> Self {
                Self(unsafe { $sll(self.0, _mm_cvtsi32_si128(k as i32)) })
            }
            #[inline(always)]
            #[allow(unused_unsafe)]
            fn shr(self, k: u32) -> Self {
                Self(unsafe { $srl(self.0, _mm_cvtsi32_si128(k as i32)) })
            }
        }
    };
}

/// A register of floats: arithmetic, comparisons, bits. The operations where the instruction
/// sets differ are given as expressions in named registers (`|x| ...`), expanded in place: a
/// closure might stay out of line, compiled without the target features.
macro_rules! float_lanes {
    (
        $name:ident, $t:ty, $reg:ty, $lanes:expr, $mask:ident, $bits:ident,
        set1 $set1:ident, load $load:ident, store $store:ident,
        add $add:ident, sub $sub:ident, mul $mul:ident, div $div:ident, sqrt $sqrt:ident,
        min $min:ident, max $max:ident, to_bits $to_bits:ident, from_bits $from_bits:ident,
        neg |$nx:ident| $neg:expr,
        cmp |$ca:ident, $cb:ident, $op:ident| $cmp:expr,
        select |$sm:ident, $sa:ident, $sb:ident| $select:expr,
        square_error $square_error:tt, mul_add $mul_add:tt, rows $rows:tt
    ) => {
        #[doc = concat!(stringify!($lanes), " lanes of `", stringify!($t), "` in one register.")]
        #[derive(Clone, Copy, Debug)]
        pub(crate) struct $name($reg);

        binary!($name, Add, add, $add; Sub, sub, $sub; Mul, mul, $mul; Div, div, $div;);

        impl Neg for $name {
            type Output = Self;
            #[inline(always)]
            #[allow(unused_unsafe)]
            fn neg(self) -> Self {
                let $nx = self.0;
                Self(unsafe { $neg })
            }
        }

        impl Lanes for $name {
            type T = $t;
            type Mask = $mask;
            type Bits = $bits;
            const N: usize = $lanes;

            #[inline(always)]
            #[allow(unused_unsafe)]
            fn splat(x: $t) -> Self {
                Self(unsafe { $set1(x) })
            }
            #[inline(always)]
            #[allow(unused_unsafe)]
            fn load(src: &[$t]) -> Self {
                let src = &src[..$lanes];
                // SAFETY: `src` holds the `$lanes` values read.
                Self(unsafe { $load(src.as_ptr()) })
            }
            #[inline(always)]
            #[allow(unused_unsafe)]
            fn store(self, dst: &mut [$t]) {
                let dst = &mut dst[..$lanes];
                // SAFETY: `dst` holds the `$lanes` values written.
                unsafe { $store(dst.as_mut_ptr(), self.0) }
            }
            #[inline(always)]
            #[allow(unused_unsafe)]
            fn sqrt(self) -> Self {
                Self(unsafe { $sqrt(self.0) })
            }
            #[inline(always)]
            #[allow(unused_unsafe)]
            fn min(self, o: Self) -> Self {
                // minps(a, b) is `a < b ? a : b`: `o` where o < self, else self (NaN included).
                Self(unsafe { $min(o.0, self.0) })
            }
            #[inline(always)]
            #[allow(unused_unsafe)]
            fn max(self, o: Self) -> Self {
                Self(unsafe { $max(o.0, self.0) })
            }
            #[inline(always)]
            #[allow(unused_unsafe)]
            fn lt(self, o: Self) -> $mask {
                let ($ca, $cb, $op) = (self.0, o.0, _CMP_LT_OQ);
                $mask(unsafe { $cmp })
            }
            #[inline(always)]
            #[allow(unused_unsafe)]
            fn le(self, o: Self) -> $mask {
                let ($ca, $cb, $op) = (self.0, o.0, _CMP_LE_OQ);
                $mask(unsafe { $cmp })
            }
            #[inline(always)]
            #[allow(unused_unsafe)]
            fn eq(self, o: Self) -> $mask {
                let ($ca, $cb, $op) = (self.0, o.0, _CMP_EQ_OQ);
                $mask(unsafe { $cmp })
            }
            #[inline(always)]
            #[allow(unused_unsafe)]
            fn select(mask: $mask, a: Self, b: Self) -> Self {
                let ($sm, $sa, $sb) = (mask.0, a.0, b.0);
                Self(unsafe { $select })
            }
            #[inline(always)]
            #[allow(unused_unsafe)]
            fn to_bits(self) -> $bits {
                $bits(unsafe { $to_bits(self.0) })
            }
            #[inline(always)]
            #[allow(unused_unsafe)]
            fn from_bits(b: $bits) -> Self {
                Self(unsafe { $from_bits(b.0) })
            }
            float_lanes!(@square_error $square_error);
            float_lanes!(@mul_add $mul_add);
            float_lanes!(@rows $rows);
        }
    };
    (@square_error default) => {};
    (@square_error (|$sx:ident, $ss:ident| $e:expr)) => {
        #[inline(always)]
        fn square_error(self, square: Self) -> Self {
            let ($sx, $ss) = (self.0, square.0);
            Self(unsafe { $e })
        }
    };
    (@mul_add default) => {};
    (@mul_add (|$ma:ident, $mb:ident, $mc:ident| $e:expr)) => {
        #[inline(always)]
        #[allow(unused_unsafe)]
        fn mul_add(self, a: Self, b: Self) -> Self {
            let ($ma, $mb, $mc) = (self.0, a.0, b.0);
            Self(unsafe { $e })
        }
    };
    (@rows default) => {};
    (@rows ($load3:expr, $store4:expr)) => {
        #[inline(always)]
        fn load_rows3(rows: &[[Self::T; 3]]) -> V3<Self> {
            let flat = rows[..Self::N].as_flattened();
            let [x, y, z] = unsafe { $load3(flat) };
            V3 {
                x: Self(x),
                y: Self(y),
                z: Self(z),
            }
        }
        #[inline(always)]
        fn store_rows4(rgba: [Self; 4], rows: &mut [[MaybeUninit<Self::T>; 4]]) {
            let flat = rows[..Self::N].as_flattened_mut();
            unsafe { $store4([rgba[0].0, rgba[1].0, rgba[2].0, rgba[3].0], flat) }
        }
    };
}

// SSE2: the x86-64 baseline.
vector_mask!(
    MaskF32x4,
    __m128,
    _mm_and_ps,
    _mm_or_ps,
    _mm_xor_ps,
    _mm_movemask_ps,
    _mm_castsi128_ps(_mm_set1_epi32(-1)),
    4
);
vector_mask!(
    MaskF64x2,
    __m128d,
    _mm_and_pd,
    _mm_or_pd,
    _mm_xor_pd,
    _mm_movemask_pd,
    _mm_castsi128_pd(_mm_set1_epi32(-1)),
    2
);
bits!(
    BitsU32x4,
    __m128i,
    _mm_add_epi32,
    _mm_sub_epi32,
    _mm_and_si128,
    _mm_or_si128,
    _mm_sll_epi32,
    _mm_srl_epi32,
    _mm_set1_epi32,
    i32
);
bits!(
    BitsU64x2,
    __m128i,
    _mm_add_epi64,
    _mm_sub_epi64,
    _mm_and_si128,
    _mm_or_si128,
    _mm_sll_epi64,
    _mm_srl_epi64,
    _mm_set1_epi64x,
    i64
);

float_lanes!(
    F32x4, f32, __m128, 4, MaskF32x4, BitsU32x4,
    set1 _mm_set1_ps, load _mm_loadu_ps, store _mm_storeu_ps,
    add _mm_add_ps, sub _mm_sub_ps, mul _mm_mul_ps, div _mm_div_ps, sqrt _mm_sqrt_ps,
    min _mm_min_ps, max _mm_max_ps, to_bits _mm_castps_si128, from_bits _mm_castsi128_ps,
    neg |x| _mm_xor_ps(x, _mm_set1_ps(-0.0)),
    cmp |a, b, op| match op {
        _CMP_LT_OQ => _mm_cmplt_ps(a, b),
        _CMP_LE_OQ => _mm_cmple_ps(a, b),
        _ => _mm_cmpeq_ps(a, b),
    },
    select |m, a, b| _mm_or_ps(_mm_and_ps(m, a), _mm_andnot_ps(m, b)),
    square_error default,
    mul_add (|a, b, c| fma_f32x4(a, b, c)),
    rows default
);

float_lanes!(
    F64x2, f64, __m128d, 2, MaskF64x2, BitsU64x2,
    set1 _mm_set1_pd, load _mm_loadu_pd, store _mm_storeu_pd,
    add _mm_add_pd, sub _mm_sub_pd, mul _mm_mul_pd, div _mm_div_pd, sqrt _mm_sqrt_pd,
    min _mm_min_pd, max _mm_max_pd, to_bits _mm_castpd_si128, from_bits _mm_castsi128_pd,
    neg |x| _mm_xor_pd(x, _mm_set1_pd(-0.0)),
    cmp |a, b, op| match op {
        _CMP_LT_OQ => _mm_cmplt_pd(a, b),
        _CMP_LE_OQ => _mm_cmple_pd(a, b),
        _ => _mm_cmpeq_pd(a, b),
    },
    select |m, a, b| _mm_or_pd(_mm_and_pd(m, a), _mm_andnot_pd(m, b)),
    square_error default,
    mul_add default,
    rows default
);

// AVX2 (with FMA).
vector_mask!(
    MaskF32x8,
    __m256,
    _mm256_and_ps,
    _mm256_or_ps,
    _mm256_xor_ps,
    _mm256_movemask_ps,
    _mm256_castsi256_ps(_mm256_set1_epi32(-1)),
    8
);
vector_mask!(
    MaskF64x4,
    __m256d,
    _mm256_and_pd,
    _mm256_or_pd,
    _mm256_xor_pd,
    _mm256_movemask_pd,
    _mm256_castsi256_pd(_mm256_set1_epi32(-1)),
    4
);
bits!(
    BitsU32x8,
    __m256i,
    _mm256_add_epi32,
    _mm256_sub_epi32,
    _mm256_and_si256,
    _mm256_or_si256,
    _mm256_sll_epi32,
    _mm256_srl_epi32,
    _mm256_set1_epi32,
    i32
);
bits!(
    BitsU64x4,
    __m256i,
    _mm256_add_epi64,
    _mm256_sub_epi64,
    _mm256_and_si256,
    _mm256_or_si256,
    _mm256_sll_epi64,
    _mm256_srl_epi64,
    _mm256_set1_epi64x,
    i64
);

float_lanes!(
    F32x8, f32, __m256, 8, MaskF32x8, BitsU32x8,
    set1 _mm256_set1_ps, load _mm256_loadu_ps, store _mm256_storeu_ps,
    add _mm256_add_ps, sub _mm256_sub_ps, mul _mm256_mul_ps, div _mm256_div_ps,
    sqrt _mm256_sqrt_ps, min _mm256_min_ps, max _mm256_max_ps,
    to_bits _mm256_castps_si256, from_bits _mm256_castsi256_ps,
    neg |x| _mm256_xor_ps(x, _mm256_set1_ps(-0.0)),
    cmp |a, b, op| match op {
        _CMP_LT_OQ => _mm256_cmp_ps::<_CMP_LT_OQ>(a, b),
        _CMP_LE_OQ => _mm256_cmp_ps::<_CMP_LE_OQ>(a, b),
        _ => _mm256_cmp_ps::<_CMP_EQ_OQ>(a, b),
    },
    select |m, a, b| _mm256_blendv_ps(b, a, m),
    square_error (|x, square| _mm256_fmsub_ps(x, x, square)),
    mul_add (|a, b, c| _mm256_fmadd_ps(a, b, c)),
    rows (load3_f32x8, store4_f32x8)
);

float_lanes!(
    F64x4, f64, __m256d, 4, MaskF64x4, BitsU64x4,
    set1 _mm256_set1_pd, load _mm256_loadu_pd, store _mm256_storeu_pd,
    add _mm256_add_pd, sub _mm256_sub_pd, mul _mm256_mul_pd, div _mm256_div_pd,
    sqrt _mm256_sqrt_pd, min _mm256_min_pd, max _mm256_max_pd,
    to_bits _mm256_castpd_si256, from_bits _mm256_castsi256_pd,
    neg |x| _mm256_xor_pd(x, _mm256_set1_pd(-0.0)),
    cmp |a, b, op| match op {
        _CMP_LT_OQ => _mm256_cmp_pd::<_CMP_LT_OQ>(a, b),
        _CMP_LE_OQ => _mm256_cmp_pd::<_CMP_LE_OQ>(a, b),
        _ => _mm256_cmp_pd::<_CMP_EQ_OQ>(a, b),
    },
    select |m, a, b| _mm256_blendv_pd(b, a, m),
    square_error (|x, square| _mm256_fmsub_pd(x, x, square)),
    mul_add (|a, b, c| _mm256_fmadd_pd(a, b, c)),
    rows default
);

// AVX-512 (F, BW, DQ, VL).
k_mask!(Mask16, u16, 16);
k_mask!(Mask8, u8, 8);
bits!(
    BitsU32x16,
    __m512i,
    _mm512_add_epi32,
    _mm512_sub_epi32,
    _mm512_and_si512,
    _mm512_or_si512,
    _mm512_sll_epi32,
    _mm512_srl_epi32,
    _mm512_set1_epi32,
    i32
);
bits!(
    BitsU64x8,
    __m512i,
    _mm512_add_epi64,
    _mm512_sub_epi64,
    _mm512_and_si512,
    _mm512_or_si512,
    _mm512_sll_epi64,
    _mm512_srl_epi64,
    _mm512_set1_epi64,
    i64
);

/// 8 rows of `[x, y, z]` (24 values) as x, y and z registers: each component sits in three
/// disjoint positions of the three loaded registers, so two blends gather it and one permute
/// orders it.
#[inline(always)]
unsafe fn load3_f32x8(flat: &[f32]) -> [__m256; 3] {
    let flat = &flat[..24];
    let p = flat.as_ptr();
    let (a, b, c) = (
        _mm256_loadu_ps(p),
        _mm256_loadu_ps(p.add(8)),
        _mm256_loadu_ps(p.add(16)),
    );
    let order = |i: [i32; 8]| std::mem::transmute::<[i32; 8], __m256i>(i);
    let x = _mm256_blend_ps::<0b0010_0100>(_mm256_blend_ps::<0b1001_0010>(a, b), c);
    let y = _mm256_blend_ps::<0b0100_1001>(_mm256_blend_ps::<0b0010_0100>(a, b), c);
    let z = _mm256_blend_ps::<0b1001_0010>(_mm256_blend_ps::<0b0100_1001>(a, b), c);
    [
        _mm256_permutevar8x32_ps(x, order([0, 3, 6, 1, 4, 7, 2, 5])),
        _mm256_permutevar8x32_ps(y, order([1, 4, 7, 2, 5, 0, 3, 6])),
        _mm256_permutevar8x32_ps(z, order([2, 5, 0, 3, 6, 1, 4, 7])),
    ]
}

/// r, g, b and a registers as 8 rows of `[r, g, b, a]` (32 values): a 4×4 transpose within
/// each 128-bit half, then the halves exchanged.
#[inline(always)]
unsafe fn store4_f32x8([r, g, b, a]: [__m256; 4], flat: &mut [MaybeUninit<f32>]) {
    let flat = &mut flat[..32];
    let (rg_lo, rg_hi) = (_mm256_unpacklo_ps(r, g), _mm256_unpackhi_ps(r, g));
    let (ba_lo, ba_hi) = (_mm256_unpacklo_ps(b, a), _mm256_unpackhi_ps(b, a));
    let (pd, ps) = (_mm256_castps_pd, _mm256_castpd_ps);
    // Half j of row_k holds row 4j + k.
    let row0 = ps(_mm256_unpacklo_pd(pd(rg_lo), pd(ba_lo)));
    let row1 = ps(_mm256_unpackhi_pd(pd(rg_lo), pd(ba_lo)));
    let row2 = ps(_mm256_unpacklo_pd(pd(rg_hi), pd(ba_hi)));
    let row3 = ps(_mm256_unpackhi_pd(pd(rg_hi), pd(ba_hi)));
    let p = flat.as_mut_ptr().cast::<f32>();
    _mm256_storeu_ps(p, _mm256_permute2f128_ps::<0x20>(row0, row1));
    _mm256_storeu_ps(p.add(8), _mm256_permute2f128_ps::<0x20>(row2, row3));
    _mm256_storeu_ps(p.add(16), _mm256_permute2f128_ps::<0x31>(row0, row1));
    _mm256_storeu_ps(p.add(24), _mm256_permute2f128_ps::<0x31>(row2, row3));
}

/// The permutation indices that gather component `k` of `W` rows of 3 from three registers of
/// `W`: from the first two (the first 2W values), then from that result and the third.
const fn gather3<const W: usize>(k: usize) -> [[i64; W]; 2] {
    let (mut first, mut second) = ([0; W], [0; W]);
    let mut i = 0;
    while i < W {
        let e = 3 * i + k;
        if e < 2 * W {
            first[i] = e as i64;
            second[i] = i as i64;
        } else {
            second[i] = (W + e - 2 * W) as i64;
        }
        i += 1;
    }
    [first, second]
}

/// [`gather3`] for 16 lanes of 32 bits, as registers.
const GATHER_F32: [[__m512i; 2]; 3] = {
    const fn narrow(v: [i64; 16]) -> __m512i {
        let mut out = [0_i32; 16];
        let mut i = 0;
        while i < 16 {
            out[i] = v[i] as i32;
            i += 1;
        }
        // SAFETY: 16 × i32 and __m512i have the same size, and any bits are a valid __m512i.
        unsafe { std::mem::transmute::<[i32; 16], __m512i>(out) }
    }
    let [x, y, z] = [gather3::<16>(0), gather3::<16>(1), gather3::<16>(2)];
    [
        [narrow(x[0]), narrow(x[1])],
        [narrow(y[0]), narrow(y[1])],
        [narrow(z[0]), narrow(z[1])],
    ]
};

/// [`gather3`] for 8 lanes of 64 bits, as registers.
const GATHER_F64: [[__m512i; 2]; 3] = {
    const fn wide(v: [i64; 8]) -> __m512i {
        // SAFETY: 8 × i64 and __m512i have the same size, and any bits are a valid __m512i.
        unsafe { std::mem::transmute::<[i64; 8], __m512i>(v) }
    }
    let [x, y, z] = [gather3::<8>(0), gather3::<8>(1), gather3::<8>(2)];
    [
        [wide(x[0]), wide(x[1])],
        [wide(y[0]), wide(y[1])],
        [wide(z[0]), wide(z[1])],
    ]
};

/// 16 rows of `[x, y, z]` (48 values) as x, y and z registers: three loads, six permutes.
#[inline(always)]
unsafe fn load3_f32x16(flat: &[f32]) -> [__m512; 3] {
    let flat = &flat[..48];
    let p = flat.as_ptr();
    let (a, b, c) = (
        _mm512_loadu_ps(p),
        _mm512_loadu_ps(p.add(16)),
        _mm512_loadu_ps(p.add(32)),
    );
    let [x, y, z] = GATHER_F32;
    [
        _mm512_permutex2var_ps(_mm512_permutex2var_ps(a, x[0], b), x[1], c),
        _mm512_permutex2var_ps(_mm512_permutex2var_ps(a, y[0], b), y[1], c),
        _mm512_permutex2var_ps(_mm512_permutex2var_ps(a, z[0], b), z[1], c),
    ]
}

/// r, g, b and a registers as 16 rows of `[r, g, b, a]` (64 values): a 4×4 transpose within
/// each 128-bit quarter, then one of the quarters.
#[inline(always)]
unsafe fn store4_f32x16([r, g, b, a]: [__m512; 4], flat: &mut [MaybeUninit<f32>]) {
    let flat = &mut flat[..64];
    let (rg_lo, rg_hi) = (_mm512_unpacklo_ps(r, g), _mm512_unpackhi_ps(r, g));
    let (ba_lo, ba_hi) = (_mm512_unpacklo_ps(b, a), _mm512_unpackhi_ps(b, a));
    let pd = _mm512_castps_pd;
    // Quarter j of row_k holds row 4j + k.
    let row0 = _mm512_unpacklo_pd(pd(rg_lo), pd(ba_lo));
    let row1 = _mm512_unpackhi_pd(pd(rg_lo), pd(ba_lo));
    let row2 = _mm512_unpacklo_pd(pd(rg_hi), pd(ba_hi));
    let row3 = _mm512_unpackhi_pd(pd(rg_hi), pd(ba_hi));
    let ps = _mm512_castpd_ps;
    let v0 = _mm512_shuffle_f32x4::<0x44>(ps(row0), ps(row1));
    let v1 = _mm512_shuffle_f32x4::<0x44>(ps(row2), ps(row3));
    let v2 = _mm512_shuffle_f32x4::<0xEE>(ps(row0), ps(row1));
    let v3 = _mm512_shuffle_f32x4::<0xEE>(ps(row2), ps(row3));
    let p = flat.as_mut_ptr().cast::<f32>();
    _mm512_storeu_ps(p, _mm512_shuffle_f32x4::<0x88>(v0, v1));
    _mm512_storeu_ps(p.add(16), _mm512_shuffle_f32x4::<0xDD>(v0, v1));
    _mm512_storeu_ps(p.add(32), _mm512_shuffle_f32x4::<0x88>(v2, v3));
    _mm512_storeu_ps(p.add(48), _mm512_shuffle_f32x4::<0xDD>(v2, v3));
}

/// 8 rows of `[x, y, z]` (24 values) as x, y and z registers.
#[inline(always)]
unsafe fn load3_f64x8(flat: &[f64]) -> [__m512d; 3] {
    let flat = &flat[..24];
    let p = flat.as_ptr();
    let (a, b, c) = (
        _mm512_loadu_pd(p),
        _mm512_loadu_pd(p.add(8)),
        _mm512_loadu_pd(p.add(16)),
    );
    let [x, y, z] = GATHER_F64;
    [
        _mm512_permutex2var_pd(_mm512_permutex2var_pd(a, x[0], b), x[1], c),
        _mm512_permutex2var_pd(_mm512_permutex2var_pd(a, y[0], b), y[1], c),
        _mm512_permutex2var_pd(_mm512_permutex2var_pd(a, z[0], b), z[1], c),
    ]
}

/// r, g, b and a registers as 8 rows of `[r, g, b, a]` (32 values).
#[inline(always)]
unsafe fn store4_f64x8([r, g, b, a]: [__m512d; 4], flat: &mut [MaybeUninit<f64>]) {
    let flat = &mut flat[..32];
    // Quarter j of rg_even holds (r, g) of row 2j, of rg_odd of row 2j + 1; ba likewise.
    let (rg_even, rg_odd) = (_mm512_unpacklo_pd(r, g), _mm512_unpackhi_pd(r, g));
    let (ba_even, ba_odd) = (_mm512_unpacklo_pd(b, a), _mm512_unpackhi_pd(b, a));
    // [rg 0, rg 4, ba 0, ba 4] and [rg 1, rg 5, ba 1, ba 5]; then 2, 6 and 3, 7.
    let e04 = _mm512_shuffle_f64x2::<0x88>(rg_even, ba_even);
    let o15 = _mm512_shuffle_f64x2::<0x88>(rg_odd, ba_odd);
    let e26 = _mm512_shuffle_f64x2::<0xDD>(rg_even, ba_even);
    let o37 = _mm512_shuffle_f64x2::<0xDD>(rg_odd, ba_odd);
    let p = flat.as_mut_ptr().cast::<f64>();
    _mm512_storeu_pd(p, _mm512_shuffle_f64x2::<0x88>(e04, o15));
    _mm512_storeu_pd(p.add(8), _mm512_shuffle_f64x2::<0x88>(e26, o37));
    _mm512_storeu_pd(p.add(16), _mm512_shuffle_f64x2::<0xDD>(e04, o15));
    _mm512_storeu_pd(p.add(24), _mm512_shuffle_f64x2::<0xDD>(e26, o37));
}

float_lanes!(
    F32x16, f32, __m512, 16, Mask16, BitsU32x16,
    set1 _mm512_set1_ps, load _mm512_loadu_ps, store _mm512_storeu_ps,
    add _mm512_add_ps, sub _mm512_sub_ps, mul _mm512_mul_ps, div _mm512_div_ps,
    sqrt _mm512_sqrt_ps, min _mm512_min_ps, max _mm512_max_ps,
    to_bits _mm512_castps_si512, from_bits _mm512_castsi512_ps,
    neg |x| _mm512_castsi512_ps(_mm512_xor_si512(
        _mm512_castps_si512(x),
        _mm512_set1_epi32(i32::MIN),
    )),
    cmp |a, b, op| match op {
        _CMP_LT_OQ => _mm512_cmp_ps_mask::<_CMP_LT_OQ>(a, b),
        _CMP_LE_OQ => _mm512_cmp_ps_mask::<_CMP_LE_OQ>(a, b),
        _ => _mm512_cmp_ps_mask::<_CMP_EQ_OQ>(a, b),
    },
    select |m, a, b| _mm512_mask_blend_ps(m, b, a),
    square_error (|x, square| _mm512_fmsub_ps(x, x, square)),
    mul_add (|a, b, c| _mm512_fmadd_ps(a, b, c)),
    rows (load3_f32x16, store4_f32x16)
);

float_lanes!(
    F64x8, f64, __m512d, 8, Mask8, BitsU64x8,
    set1 _mm512_set1_pd, load _mm512_loadu_pd, store _mm512_storeu_pd,
    add _mm512_add_pd, sub _mm512_sub_pd, mul _mm512_mul_pd, div _mm512_div_pd,
    sqrt _mm512_sqrt_pd, min _mm512_min_pd, max _mm512_max_pd,
    to_bits _mm512_castpd_si512, from_bits _mm512_castsi512_pd,
    neg |x| _mm512_castsi512_pd(_mm512_xor_si512(
        _mm512_castpd_si512(x),
        _mm512_set1_epi64(i64::MIN),
    )),
    cmp |a, b, op| match op {
        _CMP_LT_OQ => _mm512_cmp_pd_mask::<_CMP_LT_OQ>(a, b),
        _CMP_LE_OQ => _mm512_cmp_pd_mask::<_CMP_LE_OQ>(a, b),
        _ => _mm512_cmp_pd_mask::<_CMP_EQ_OQ>(a, b),
    },
    select |m, a, b| _mm512_mask_blend_pd(m, b, a),
    square_error (|x, square| _mm512_fmsub_pd(x, x, square)),
    mul_add (|a, b, c| _mm512_fmadd_pd(a, b, c)),
    rows (load3_f64x8, store4_f64x8)
);
