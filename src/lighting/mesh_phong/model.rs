//! `MeshPhongMaterial` as a [`WorldModel`]: three.js state ([`ValidScene`]) lit by the kernel
//! of [`crate::lighting::mesh_phong::kernel`], one linear RGBA colour per vertex and side (a
//! double-sided material writes the front's rows, then the back's).
//!
//! Normals are normalised; a vertex colour (RGB or RGBA) multiplies the material's `color`,
//! and its alpha the opacity. A vertex whose normal or colour is not finite, or whose
//! position is not finite when it is read, gets NaN. `f32` arrays are computed in `f32` with
//! fast accuracy (the Accuracy page states the bound), in `f64` with exact accuracy.

use crate::lighting::accuracy::Accuracy;
use crate::lighting::clamp::ColorClamp;
use crate::lighting::mesh_phong::kernel::Kernel;
use crate::lighting::mesh_phong::options::Options;
use crate::lighting::world::WorldModel;
use crate::numbers::real::Real;
use crate::threejs::scene::ValidScene;

impl WorldModel for ValidScene {
    const NAME: &'static str = "MeshPhongMaterial (three.js r111's meshphong_frag)";
    type Options = Options;
    type Kernel<T: Real> = Kernel<T>;
    /// 2 for a double-sided material (front, back), else 1.
    fn outputs(&self) -> usize {
        self.material.side.count()
    }
    fn light_count(&self) -> usize {
        self.lights.len()
    }
    fn options(clamp: ColorClamp, accuracy: Accuracy) -> Options {
        Options {
            model: None,
            clamp,
            accuracy,
        }
    }
    fn accuracy(options: &Options) -> Accuracy {
        options.accuracy
    }
}
