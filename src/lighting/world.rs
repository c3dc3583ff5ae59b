//! The world models: glTF's metallic-roughness model and three.js' `MeshPhongMaterial`, whose
//! scenes are in world coordinates and whose kernels are built per call. One path runs them
//! all ([`WorldModel`] makes a [`Model`]): the kernel built from the scene and the options,
//! run by the driver in the arrays' type with fast accuracy, or in `f64` with exact accuracy
//! (`f32` arrays widened and the result rounded once), and one line of description.

use std::fmt;
use std::mem::MaybeUninit;

use glam::DMat4;

use crate::errors::error::Error;
use crate::errors::stop::Stop;
use crate::lighting::accuracy::Accuracy;
use crate::lighting::block::{emit, Block, SideColors};
use crate::lighting::clamp::ColorClamp;
use crate::lighting::driver::{run_shader, BlockShader, Inputs};
use crate::lighting::model::Model;
use crate::lighting::round::cast_saturating;
use crate::lighting::transform::Transform;
use crate::lighting::widen::in_float64;
use crate::numbers::real::{block_lanes, normalize_or_zero, Real};
use crate::simd::dispatch::Isa;
use crate::simd::lanes::{Lanes, V3};

/// A model in world coordinates whose kernel is built per call.
pub trait WorldModel: Sync + Sized {
    /// The model's name, which its description starts with.
    const NAME: &'static str;
    /// The options of a call: the model matrix, the clamp, what vertex colours are.
    type Options: Sync;
    /// The kernel for arrays of `T`.
    type Kernel<T: Real>: WorldKernel<T, Scene = Self, Options = Self::Options>;
    /// The colour planes a call writes per vertex.
    fn outputs(&self) -> usize {
        1
    }
    /// The lights summed per vertex.
    fn light_count(&self) -> usize;
    /// The options of a call on arrays in world coordinates, clamped or not, in `accuracy`.
    fn options(clamp: ColorClamp, accuracy: Accuracy) -> Self::Options;
    /// The accuracy of a call with `options`.
    fn accuracy(options: &Self::Options) -> Accuracy;
}

/// A world model's kernel for arrays of `T`: built from the scene and the options of a call,
/// it lights a block of vertices in world coordinates, framed by a [`Frame`]; the driver runs
/// it as a [`BlockShader`].
pub trait WorldKernel<T: Real>: Sync + Sized {
    /// The model's scene.
    type Scene;
    /// The options of a call.
    type Options;
    /// Prepares `scene` for arrays of `T` with `options`.
    ///
    /// # Errors
    /// A value error for a model matrix that is not finite, affine and invertible, or whose
    /// entries exceed `T`'s range.
    fn new(scene: &Self::Scene, options: &Self::Options) -> Result<Self, Error>;
    /// What the driver and the description read of the kernel: its frame (the model matrix,
    /// the finite test, the clamp) and its plan (which lights and terms run).
    fn parts(&self) -> (&Frame<T>, &dyn fmt::Display);
    /// Sides written: 1, or 2 for a double-sided material.
    fn sides(&self) -> usize {
        1
    }
    /// The colours of one side of a block; must be `#[inline(always)]`.
    fn block<V: Lanes<T = T>>(&self, input: &Block<V>, side: usize) -> SideColors<V>;
}

/// A world kernel as the driver runs it.
struct Shader<K>(K);

impl<T: Real, K: WorldKernel<T>> BlockShader<T> for Shader<K> {
    #[inline(always)]
    fn reads_positions(&self) -> bool {
        self.0.parts().0.positions
    }
    #[inline(always)]
    fn sides(&self) -> usize {
        self.0.sides()
    }
    #[inline(always)]
    fn block<V: Lanes<T = T>>(&self, input: &Block<V>, side: usize) -> SideColors<V> {
        self.0.block(input, side)
    }
}

impl<W: WorldModel> Model for W {
    type Options = W::Options;

    fn outputs(&self) -> usize {
        WorldModel::outputs(self)
    }

    fn light_count(&self) -> usize {
        WorldModel::light_count(self)
    }

    fn shade_rows<T: Real>(
        &self,
        inputs: Inputs<'_, T>,
        options: &W::Options,
        out: &mut [MaybeUninit<T>],
        stop: &Stop,
    ) -> Result<(), Error> {
        if !W::accuracy(options).widens::<T>() {
            let kernel = Shader(W::Kernel::<T>::new(self, options)?);
            return run_shader(&kernel, Isa::detect(), inputs, out, stop);
        }
        let kernel = Shader(W::Kernel::<f64>::new(self, options)?);
        in_float64(
            inputs,
            kernel.reads_positions(),
            out,
            stop,
            |wide, dst, stop| run_shader(&kernel, Isa::detect(), wide, dst, stop),
        )
    }

    /// The model's name, the accuracy, the arithmetic, the instruction set, the lanes per
    /// block and the plan.
    fn describe<T: Real>(&self, options: &W::Options) -> Result<String, Error> {
        let accuracy = W::accuracy(options);
        let (bits, lanes, plan) = if accuracy.widens::<T>() || std::mem::size_of::<T>() == 8 {
            let kernel = W::Kernel::<f64>::new(self, options)?;
            (
                64,
                block_lanes::<f64>(Isa::detect()),
                kernel.parts().1.to_string(),
            )
        } else {
            let kernel = W::Kernel::<T>::new(self, options)?;
            (
                32,
                block_lanes::<T>(Isa::detect()),
                kernel.parts().1.to_string(),
            )
        };
        let arrays = if accuracy.widens::<T>() {
            " (float32 arrays widened)"
        } else {
            ""
        };
        Ok(format!(
            "{}: {}, float{bits} arithmetic{arrays}, {}, {lanes} vertices per block; {plan}",
            W::NAME,
            accuracy.name(),
            Isa::detect().name(),
        ))
    }
}

/// A direct light's kind, as a world kernel evaluates it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PunctualKind {
    /// The direction to the light is a per-call constant; no falloff.
    Directional,
    /// The direction and the distance falloff per vertex.
    Point,
    /// The direction, the falloff and the cone per vertex.
    Spot,
}

impl PunctualKind {
    /// What a light of this kind forms per vertex, as a plan's line says it: `falloff` and
    /// `cone` name the model's distance falloff and cone.
    pub fn terms(self, falloff: &str, cone: &str) -> String {
        match self {
            Self::Directional => "directional (l constant)".to_owned(),
            Self::Point => format!("point (l, {falloff})"),
            Self::Spot => format!("spot (l, {falloff}, {cone})"),
        }
    }
}

/// What every world kernel does around its model: the model matrix's transform of a block's
/// positions and normals into world coordinates, the test of which lanes are finite, and the
/// clamp of the colours emitted.
pub struct Frame<T: Real> {
    /// Model to world coordinates (`None`: the identity).
    transform: Option<Transform<T>>,
    /// Positions are read.
    positions: bool,
    /// The colours are clamped to [0, 1].
    clamp: bool,
}

impl<T: Real> Frame<T> {
    /// The frame of a call with the `model` matrix (`None`: the arrays are in world
    /// coordinates) and `clamp`, which reads positions or not.
    ///
    /// # Errors
    /// A value error for a model that is not finite, affine and invertible, or whose entries
    /// exceed `T`'s range.
    pub fn new(model: Option<&DMat4>, clamp: ColorClamp, positions: bool) -> Result<Self, Error> {
        let transform = model
            .map(|model| Transform::for_shading(model, false, true, positions))
            .transpose()?;
        Ok(Self {
            transform,
            positions,
            clamp: clamp == ColorClamp::On,
        })
    }

    /// The world-space positions and normals of a block (positions only when read: zeros
    /// otherwise), and the lanes whose inputs are all finite (positions only when read).
    #[inline(always)]
    pub fn inputs<V: Lanes<T = T>>(&self, input: &Block<V>) -> (V3<V>, V3<V>, V::Mask) {
        let (mut p, mut n) = (input.positions, input.normals);
        if let Some(t) = &self.transform {
            n = t.normal(n);
            if self.positions {
                p = t.point(p);
            }
        }
        let mut finite = n.is_finite();
        if self.positions {
            finite = finite & p.is_finite();
        }
        if let Some(c) = &input.colors {
            finite = finite & c[0].is_finite() & c[1].is_finite();
            finite = finite & c[2].is_finite() & c[3].is_finite();
        }
        (p, n, finite)
    }

    /// A side's colours: `rgb` and `alpha`, clamped unless the call is unclamped, NaN where
    /// not `finite` (a world model writes no secondary colour).
    #[inline(always)]
    pub fn emit<V: Lanes<T = T>>(&self, rgb: V3<V>, alpha: V, finite: V::Mask) -> SideColors<V> {
        let zero = V::splat(T::ZERO);
        [emit(rgb, alpha, finite, self.clamp), [zero; 4]]
    }
}

/// A unit vector in `T` from a nonzero `f64` direction (a light's, the view's).
pub fn unit<T: Real>(d: [f64; 3]) -> [T; 3] {
    let u = normalize_or_zero::<f64>(glam::DVec3::from_array(d));
    u.to_array().map(T::from_f64)
}

/// The lights of a scene that a plan keeps (`kept`: their indices and kinds), in its order.
pub fn kept<'a, L>(
    kept: &'a [(usize, PunctualKind)],
    lights: &'a [L],
) -> impl Iterator<Item = &'a L> + 'a {
    kept.iter().map(|&(i, _)| &lights[i])
}

/// A positional light's position (saturated) and a spot light's unit axis, in `T`.
pub fn placed<T: Real>(position: [f64; 3], direction: [f64; 3]) -> ([T; 3], [T; 3]) {
    (cast_saturating(position.into()), unit(direction))
}

/// The RGB of RGBA lanes (a vertex colour's).
#[inline(always)]
pub fn rgb_of<V: Lanes>(c: &[V; 4]) -> V3<V> {
    V3 {
        x: c[0],
        y: c[1],
        z: c[2],
    }
}
