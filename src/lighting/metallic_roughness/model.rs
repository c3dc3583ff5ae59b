//! The metallic-roughness model as a [`WorldModel`]: glTF state ([`ValidScene`]) lit by the
//! kernel of [`crate::lighting::metallic_roughness::kernel`], one linear RGBA colour per vertex.
//!
//! Normals are normalised; a vertex colour (RGB or RGBA) multiplies the result, alpha
//! included, as pyrender's `color_multiplier` does, or with [`ColorRole::BaseColor`] the base
//! colour. A vertex whose normal or colour is not finite, or whose position is not finite
//! when some light shines, gets NaN. `f32` arrays are computed in `f32` with fast accuracy,
//! whose error grows where the model is ill-conditioned (|n·v| near its 0.001 floor, the
//! highlight of roughness 0.04; the Accuracy page states the bound), in `f64` with exact
//! accuracy.

use crate::gltf::scene::ValidScene;
use crate::lighting::accuracy::Accuracy;
use crate::lighting::clamp::ColorClamp;
use crate::lighting::metallic_roughness::kernel::Kernel;
#[cfg(doc)]
use crate::lighting::metallic_roughness::options::ColorRole;
use crate::lighting::metallic_roughness::options::Options;
use crate::lighting::world::WorldModel;
use crate::numbers::real::Real;

impl WorldModel for ValidScene {
    const NAME: &'static str = "metallic-roughness (pyrender's mesh.frag)";
    type Options = Options;
    type Kernel<T: Real> = Kernel<T>;
    fn light_count(&self) -> usize {
        self.lights.len()
    }
    fn options(clamp: ColorClamp, accuracy: Accuracy) -> Options {
        Options {
            clamp,
            accuracy,
            ..Options::default()
        }
    }
    fn accuracy(options: &Options) -> Accuracy {
        options.accuracy
    }
}
