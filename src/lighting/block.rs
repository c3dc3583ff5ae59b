//! The block vocabulary every model's kernel speaks: a block's inputs in lanes ([`Block`]),
//! the colours a side writes ([`SideColors`]) and how an output colour is emitted ([`emit`]:
//! clamped or not, NaN where an input was not finite).

use crate::simd::float::Float;
use crate::simd::lanes::{Lanes, V3};

/// One block's inputs, already loaded into lanes.
#[derive(Clone, Copy)]
pub struct Block<V: Lanes> {
    /// Positions (model coordinates), or zeros when the plan does not read them.
    pub positions: V3<V>,
    /// Normals (model coordinates).
    pub normals: V3<V>,
    /// RGBA vertex colours for `GL_COLOR_MATERIAL`.
    pub colors: Option<[V; 4]>,
}

/// The primary and secondary RGBA colours of one side of a block, after the clamp (the
/// secondary is unused without separate specular).
pub type SideColors<V> = [[V; 4]; 2];

/// `x` clamped to [0, 1] where `finite`, NaN elsewhere; + 0 turns −0 into +0, and the clamp
/// keeps NaN, which `finite` then decides.
#[inline(always)]
fn clamp01<V: Lanes>(x: V, finite: V::Mask) -> V {
    let zero = V::splat(V::T::ZERO);
    V::select(
        finite,
        (x + zero).clamp(V::T::ZERO, V::T::ONE),
        V::splat(V::T::NAN),
    )
}

/// `x` as it is where `finite` (high dynamic range), NaN elsewhere; + 0 turns −0 into +0.
#[inline(always)]
fn unclamped<V: Lanes>(x: V, finite: V::Mask) -> V {
    V::select(finite, x + V::splat(V::T::ZERO), V::splat(V::T::NAN))
}

/// An output colour: `rgb` and `alpha`, clamped unless `clamp` is off (one branch per block).
#[inline(always)]
pub fn emit<V: Lanes>(rgb: V3<V>, alpha: V, finite: V::Mask, clamp: bool) -> [V; 4] {
    if clamp {
        [
            clamp01(rgb.x, finite),
            clamp01(rgb.y, finite),
            clamp01(rgb.z, finite),
            clamp01(alpha, finite),
        ]
    } else {
        [
            unclamped(rgb.x, finite),
            unclamped(rgb.y, finite),
            unclamped(rgb.z, finite),
            unclamped(alpha, finite),
        ]
    }
}
