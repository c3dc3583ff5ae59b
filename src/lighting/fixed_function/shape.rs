//! Kernels compiled for one shape of scene: the same kernel ([`crate::lighting::fixed_function::kernel`]) with some
//! of the plan's flags fixed when it is compiled, so the compiler drops the terms the shape cannot
//! have and the branches around the others, and more of a block's values stay in registers.
//!
//! A flag the shape leaves open (`None`) is read from the plan once per block, as in the
//! general kernel. A call runs a shape's kernel only when its plan and scene have every fixed
//! flag ([`fits`]), so the same operations run and the bits are those of the general kernel
//! (`tests::shape` checks it).

use crate::gl::scene::Specular;
use crate::lighting::fixed_function::plan::{LightKind, LightPlan, Plan};
use crate::lighting::fixed_function::prepare::{Prepared, Viewer};
use crate::numbers::real::Real;
use crate::simd::dispatch::{Isa, LaneWork};

/// The plan's flags a kernel is compiled with: `Some` is a constant, `None` is read from the
/// plan per block.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Known {
    /// Every light is of this kind.
    pub light_kind: Option<LightKind>,
    /// Every light has (`true`) or no light has (`false`) the attenuation quotient.
    pub attenuated: Option<bool>,
    /// Every light has (`true`) or no light has (`false`) an ambient term.
    pub light_ambient: Option<bool>,
    /// Every light has a diffuse and a specular term, and the front side a specular power.
    pub lit: Option<bool>,
    /// Positions are read.
    pub positions: Option<bool>,
    /// A modelview is applied.
    pub transform: Option<bool>,
    /// Vertex colours are read (`GL_COLOR_MATERIAL`).
    pub colors: Option<bool>,
    /// The viewer is local.
    pub local_viewer: Option<bool>,
    /// Sides lit: 1, or 2 with two-sided lighting.
    pub sides: Option<usize>,
    /// Blinn or Phong.
    pub specular: Option<Specular>,
    /// The f_i gate of eq. 2.2.
    pub gate: Option<bool>,
    /// `GL_SEPARATE_SPECULAR_COLOR`.
    pub separate_specular: Option<bool>,
    /// At most [`crate::simd::float::Float::SUM_BLOCK`] lights, summed in the kernel's type.
    pub few_lights: Option<bool>,
    /// Some light has a range or a soft spot edge (learnopengl's, Luna's: not GL's).
    pub edges: Option<bool>,
}

impl Known {
    /// Nothing fixed: the general kernel.
    pub const NOTHING: Known = Known {
        light_kind: None,
        attenuated: None,
        light_ambient: None,
        lit: None,
        positions: None,
        transform: None,
        colors: None,
        local_viewer: None,
        sides: None,
        specular: None,
        gate: None,
        separate_specular: None,
        few_lights: None,
        edges: None,
    };

    /// GL's common case: one side, no modelview, no vertex colours, Blinn-Phong with the
    /// gate, one colour, a few lights that each light diffusely and specularly and add no
    /// ambient term (the lights' kinds and the viewer left open).
    const PLAIN: Known = Known {
        lit: Some(true),
        transform: Some(false),
        colors: Some(false),
        sides: Some(1),
        specular: Some(Specular::Blinn),
        gate: Some(true),
        separate_specular: Some(false),
        edges: Some(false),
        ..Known::NOTHING
    };
}

/// A flag: the shape's constant, or the plan's value.
#[inline(always)]
pub fn flag<X: Copy>(known: Option<X>, actual: X) -> X {
    match known {
        Some(x) => x,
        None => actual,
    }
}

/// True when the plan and scene of a call have every flag `known` fixes.
pub fn fits<T: Real>(known: &Known, plan: &Plan, prepared: &Prepared<T>) -> bool {
    let same = |k: Option<bool>, actual: bool| k.is_none_or(|k| k == actual);
    let every = |k: Option<bool>, each: &dyn Fn(usize) -> bool| {
        k.is_none_or(|k| (0..plan.lights.len()).all(|i| each(i) == k))
    };
    let lit = |i: usize| {
        let light = &plan.lights[i];
        light.diffuse && light.specular && plan.sides[0].specular && plan.sides[0].power
    };
    known
        .light_kind
        .is_none_or(|kind| plan.lights.iter().all(|l| l.kind == kind))
        && every(known.attenuated, &|i| plan.lights[i].attenuated)
        && every(known.light_ambient, &|i| plan.lights[i].ambient)
        && every(known.lit, &lit)
        && same(known.positions, plan.positions)
        && same(known.transform, prepared.transform.is_some())
        && same(known.colors, prepared.color_material.is_some())
        && same(
            known.local_viewer,
            matches!(prepared.viewer, Viewer::Local(_)),
        )
        && known.sides.is_none_or(|s| s == prepared.sides)
        && known.specular.is_none_or(|s| s == prepared.specular)
        && same(known.gate, prepared.specular_gate)
        && same(known.separate_specular, prepared.separate_specular)
        && same(known.few_lights, prepared.lights.len() <= T::SUM_BLOCK)
        && same(
            known.edges,
            plan.lights.iter().copied().any(LightPlan::edges),
        )
}

/// A shape of scene: the flags it fixes, and the instruction sets its kernel is compiled for.
pub trait Shape: Sync + 'static {
    /// The name `Scene.plan` prints.
    const NAME: &'static str;
    /// The flags fixed.
    const KNOWN: Known;
    /// The kernel has a second copy of its light loop that sums one channel, for scenes of
    /// grey lights ([`Plan::grey`]; float32 only): the narrow shapes, not the general kernel,
    /// whose copies on every instruction set would cost the build more than they save.
    const GREY_SUMS: bool;
    /// Runs `work` (this shape's kernel) with the registers of `isa`, one the shape is
    /// compiled for.
    fn run<W: LaneWork>(isa: Isa, work: W);
}

/// Any scene, on every instruction set.
pub struct General;

impl Shape for General {
    const NAME: &'static str = "general";
    const KNOWN: Known = Known::NOTHING;
    const GREY_SUMS: bool = false;
    #[inline(always)]
    fn run<W: LaneWork>(isa: Isa, work: W) {
        isa.run(work);
    }
}

/// Defines the narrower shapes, each a unit type with its flags, compiled for AVX2 and
/// AVX-512 only: the baseline, a fallback for old CPUs, runs the general kernel.
macro_rules! shapes {
    ($($(#[$doc:meta])* $name:ident($label:literal) = $known:expr;)*) => {$(
        $(#[$doc])*
        pub struct $name;

        impl Shape for $name {
            const NAME: &'static str = $label;
            const KNOWN: Known = $known;
            const GREY_SUMS: bool = true;
            #[inline(always)]
            fn run<W: LaneWork>(isa: Isa, work: W) {
                isa.run_wide(work);
            }
        }
    )*};
}

shapes! {
    /// [`Known::PLAIN`] with directional lights (ĥ constant) and an infinite viewer: the
    /// normals are the only per-vertex input.
    Directional("directional") = Known {
        light_kind: Some(LightKind::Directional { constant_halfway: true }),
        positions: Some(false),
        local_viewer: Some(false),
        ..Known::PLAIN
    };
    /// [`Known::PLAIN`] with point lights (no cone) and a local viewer.
    Point("point") = Known {
        light_kind: Some(LightKind::Positional { spot: false }),
        positions: Some(true),
        local_viewer: Some(true),
        ..Known::PLAIN
    };
    /// [`Known::PLAIN`] with lights of any kind, ambient terms or not, and a local viewer.
    Mixed("mixed") = Known {
        light_ambient: None,
        positions: Some(true),
        local_viewer: Some(true),
        ..Known::PLAIN
    };
}

/// Work done with the kernel of one shape.
pub trait OnShape {
    /// What the work returns.
    type Output;
    /// Does the work with shape `S`.
    fn call<S: Shape>(self) -> Self::Output;
}

/// Does `work` with the first shape whose flags the call has ([`Directional`], [`Point`],
/// [`Mixed`]) and whose kernel `isa` runs, or with [`General`].
pub fn on_shape<T: Real, W: OnShape>(
    plan: &Plan,
    prepared: &Prepared<T>,
    isa: Isa,
    work: W,
) -> W::Output {
    // The inner loop of kernel work compiles the general kernel alone.
    #[cfg(feature = "single-kernel")]
    {
        let _ = (plan, prepared, isa);
        work.call::<General>()
    }
    #[cfg(not(feature = "single-kernel"))]
    if isa == Isa::Baseline {
        work.call::<General>()
    } else if fits(&Directional::KNOWN, plan, prepared) {
        work.call::<Directional>()
    } else if fits(&Point::KNOWN, plan, prepared) {
        work.call::<Point>()
    } else if fits(&Mixed::KNOWN, plan, prepared) {
        work.call::<Mixed>()
    } else {
        work.call::<General>()
    }
}
