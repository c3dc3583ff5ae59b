//! What every world model does alike, checked on each through the one entry point
//! ([`crate::lighting::model::shade`]): a light at the vertex lights it finitely, clamped or
//! not, and a scene that no light shines on reads no positions (a NaN position leaves the row
//! alone) and emits its emission at the material's opacity; in `f64`, in `f32` (fast) and in
//! `f32` arrays widened (exact).

use crate::errors::stop::Stop;
use crate::gltf::light::{Light as GltfLight, Punctual};
use crate::gltf::material::Material;
use crate::gltf::scene::{Scene as GltfScene, ValidScene as GltfState};
use crate::lighting::accuracy::Accuracy;
use crate::lighting::clamp::ColorClamp;
use crate::lighting::model::{shade, Model};
use crate::lighting::world::WorldModel;
use crate::numbers::real::Real;
use crate::threejs::light::{Kind, Light as ThreejsLight};
use crate::threejs::material::MeshPhongMaterial;
use crate::threejs::scene::{Scene as ThreejsScene, ValidScene as ThreejsState, Viewer};

/// A world model's scenes for the checks.
trait Cases: WorldModel + Model<Options = <Self as WorldModel>::Options> + Sized {
    /// A scene lit by one point light at `at`.
    fn point_light_at(at: [f64; 3]) -> Self;
    /// A scene whose one light shines on nothing, with an emission of (0.25, 0, 0) and an
    /// opacity of 0.5.
    fn unlit() -> Self;
}

impl Cases for GltfState {
    fn point_light_at(at: [f64; 3]) -> Self {
        let light = GltfLight {
            punctual: Punctual::Point { position: at },
            color: [1.0, 0.5, 0.25],
            intensity: 3.0,
        };
        let material = Material {
            base_color: [0.8, 0.6, 0.4, 0.5],
            metallic: 0.3,
            roughness: 0.0,
            emissive: [0.0; 3],
        };
        GltfScene {
            lights: vec![light],
            material,
            ambient_light: [0.0; 3],
            camera_position: [0.0, 0.0, 5.0],
        }
        .validated()
        .unwrap()
    }

    fn unlit() -> Self {
        let mut scene = (*Self::point_light_at([0.0, 0.0, 1.0])).clone();
        scene.lights[0].intensity = 0.0;
        scene.material.emissive = [0.25, 0.0, 0.0];
        scene.validated().unwrap()
    }
}

impl Cases for ThreejsState {
    fn point_light_at(at: [f64; 3]) -> Self {
        let point = Kind::Point {
            position: at,
            distance: 0.0,
            decay: 2.0,
        };
        ThreejsScene {
            lights: vec![ThreejsLight {
                kind: point,
                color: [1.0, 0.5, 0.25],
                intensity: 3.0,
            }],
            material: MeshPhongMaterial {
                color: [0.8, 0.6, 0.4],
                opacity: 0.5,
                ..MeshPhongMaterial::default()
            },
            viewer: Viewer::Position([0.0, 0.0, 5.0]),
            physically_correct_lights: true,
        }
        .validated()
        .unwrap()
    }

    fn unlit() -> Self {
        let mut scene = (*Self::point_light_at([0.0, 0.0, 1.0])).clone();
        scene.lights[0].color = [0.0; 3];
        scene.material.emissive = [0.25, 0.0, 0.0];
        scene.validated().unwrap()
    }
}

/// The RGBA of one vertex at `p` with normal `n`, the front side, in arrays of `T` with
/// `accuracy`.
fn one_vertex<M: Cases, T: Real>(
    scene: &M,
    p: [f64; 3],
    n: [f64; 3],
    clamp: ColorClamp,
    accuracy: Accuracy,
) -> [f64; 4] {
    let mut out = vec![T::ZERO; 4 * Model::outputs(scene)];
    let options = M::options(clamp, accuracy);
    let (p, n) = (p.map(T::from_f64), n.map(T::from_f64));
    shade(scene, &[p], &[n], None, &options, &mut out, &Stop::new()).unwrap();
    [0, 1, 2, 3].map(|k| out[k].to_f64())
}

/// `one_vertex` in each arithmetic: `f64`, `f32` and `f32` widened to `f64`.
fn every_arithmetic<M: Cases>(
    scene: &M,
    p: [f64; 3],
    n: [f64; 3],
    clamp: ColorClamp,
) -> [[f64; 4]; 3] {
    [
        one_vertex::<M, f64>(scene, p, n, clamp, Accuracy::Fast),
        one_vertex::<M, f32>(scene, p, n, clamp, Accuracy::Fast),
        one_vertex::<M, f32>(scene, p, n, clamp, Accuracy::Exact),
    ]
}

fn a_light_at_the_vertex_lights_finitely<M: Cases>() {
    let at = [0.5, -0.25, 1.0];
    let scene = M::point_light_at(at);
    for clamp in [ColorClamp::On, ColorClamp::Off] {
        for c in every_arithmetic(&scene, at, [0.0, 0.0, 1.0], clamp) {
            assert!(c.iter().all(|x| x.is_finite()), "{}: {c:?}", M::NAME);
        }
    }
}

fn unlit_scenes_read_no_positions<M: Cases>() {
    let n = [0.0, 0.0, 1.0];
    for c in every_arithmetic(&M::unlit(), [f64::NAN; 3], n, ColorClamp::Off) {
        assert_eq!(c, [0.25, 0.0, 0.0, 0.5], "{}", M::NAME);
    }
}

#[test]
fn every_world_model_lights_a_light_at_the_vertex_finitely() {
    a_light_at_the_vertex_lights_finitely::<GltfState>();
    a_light_at_the_vertex_lights_finitely::<ThreejsState>();
}

#[test]
fn every_world_model_reads_no_positions_where_no_light_shines() {
    unlit_scenes_read_no_positions::<GltfState>();
    unlit_scenes_read_no_positions::<ThreejsState>();
}
