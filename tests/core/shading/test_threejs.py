"""three.js' ``MeshPhongMaterial`` against its transcription (`support.threejs_reference`,
release 111's shader chunks in float64), unclamped and clamped, on random scenes with every
light kind, both light conventions, every side, perspective and orthographic cameras, vertex
colours, penumbras from 0 to 1, finite and unlimited distances, integer and fractional decays.

The bounds: float64, and float32 with exact accuracy (computed in float64, rounded once),
within 1e-12 relative to max(1, |value|) plus half an ulp of the result; float32 with fast
accuracy (float32 arithmetic) within the Accuracy page's bound (`fast_bound`), off the jumps of
the model (`kinks`: a spot's edge without penumbra, n·h = 0 below shininess 1).
"""

from __future__ import annotations

import math
import pickle
import re
from typing import Any

import numpy as np
import pytest

import glshade as gs
from support.threejs_reference import fast_bound, kinks, meshphong_frag, random_scene

TOL = 1e-12
SEEDS = 48
VERTICES = 300
t = gs.threejs


def error(got: np.ndarray, want: np.ndarray) -> float:
    """The largest error relative to max(1, |want|), less half an ulp of `got`'s dtype (the
    result's own rounding)."""
    excess = np.abs(got.astype(np.float64) - want)
    rounding = np.abs(want) * float(np.finfo(got.dtype).epsneg)
    return float(np.max((excess - rounding) / np.maximum(1, np.abs(want))))


def fast_error(
    got: np.ndarray, want: np.ndarray, p: np.ndarray, n: np.ndarray, scene: t.Scene, colors: Any
) -> float:
    """float32 fast mode's largest error (RGB) as a share of `fast_bound`, off `kinks`, on
    each side `shade` wrote; alpha within its two roundings (the factor's and the product's)."""
    sides = [False, True] if scene.material.side == "double" else [False]
    worst = 0.0
    planes = zip(
        sides, got.reshape(-1, *got.shape[-2:]), want.reshape(-1, *want.shape[-2:]), strict=True
    )
    for back, g, w in planes:
        smooth = ~kinks(p, n, scene, back=back)
        excess = np.abs(g.astype(np.float64) - w)
        over = excess[smooth, :3] / fast_bound(p, n, scene, colors, back)[smooth]
        worst = max(worst, float(over.max(initial=0)))
        assert (excess[:, 3] <= np.abs(w[:, 3]) * 2.0**-23).all()
    return worst


def expected(p: np.ndarray, n: np.ndarray, scene: t.Scene, colors: np.ndarray | None) -> np.ndarray:
    """The transcription's colours in `shade`'s layout: (n, 4), or (2, n, 4) front and back."""
    front = meshphong_frag(p, n, scene, colors)
    if scene.material.side != "double":
        return front
    return np.stack([front, meshphong_frag(p, n, scene, colors, back=True)])


@pytest.mark.parametrize("dtype", [np.float64, np.float32])
@pytest.mark.parametrize("seed", range(SEEDS))
def test_agrees_with_meshphong_frag(seed: int, dtype: type) -> None:
    rng = np.random.default_rng(seed)
    scene = random_scene(rng, lights=int(rng.integers(1, 7)))
    p = rng.uniform(-3, 3, (VERTICES, 3)).astype(dtype)
    n = rng.normal(size=(VERTICES, 3)).astype(dtype)
    width = (3, 4, None)[seed % 3]
    colors = None if width is None else rng.uniform(0, 1, (VERTICES, width)).astype(dtype)
    want = expected(p, n, scene, colors)
    exact = gs.shade(p, n, scene, colors=colors, clamp=False, accuracy="exact")
    assert exact.dtype == dtype and exact.shape == want.shape
    assert error(exact, want) <= TOL, scene
    clamped = gs.shade(p, n, scene, colors=colors, accuracy="exact")
    assert error(clamped, np.clip(want, 0, 1)) <= TOL, scene
    got = gs.shade(p, n, scene, colors=colors, clamp=False)
    if dtype == np.float64:
        np.testing.assert_array_equal(got, exact)
        return
    assert fast_error(got, want, p, n, scene, colors) <= 1, scene
    clamped = gs.shade(p, n, scene, colors=colors)
    assert fast_error(clamped, np.clip(want, 0, 1), p, n, scene, colors) <= 1, scene


def test_the_random_scenes_cover_every_case() -> None:
    """The seeds above reach every light kind, convention, side, camera and edge case."""
    seen: set[str] = set()
    for seed in range(SEEDS):
        rng = np.random.default_rng(seed)
        scene = random_scene(rng, lights=int(rng.integers(1, 7)))
        seen.add(f"side {scene.material.side}")
        seen.add(f"physical {scene.physically_correct_lights}")
        seen.add(f"orthographic {scene.view_direction is not None}")
        seen.add(f"shininess 0 {scene.material.shininess == 0}")
        for light in scene.lights:
            seen.add(type(light).__name__)
            if isinstance(light, (t.PointLight, t.SpotLight)):
                seen.add(f"distance {light.distance > 0}")
                seen.add(f"decay {light.decay if light.decay in (0, 1, 2) else 'fractional'}")
            if isinstance(light, t.SpotLight):
                seen.add(f"penumbra {light.penumbra if light.penumbra in (0, 1) else 'between'}")
    kinds = {"AmbientLight", "HemisphereLight", "DirectionalLight", "PointLight", "SpotLight"}
    cases = {
        *kinds, "side front", "side back", "side double", "physical True", "physical False",
        "orthographic True", "orthographic False", "shininess 0 True", "distance True",
        "distance False", "decay 0.0", "decay 1.0", "decay 2.0", "decay fractional",
        "penumbra 0.0", "penumbra 1.0", "penumbra between",
    }  # fmt: skip
    assert cases <= seen, cases - seen


def test_one_light_by_hand() -> None:
    """A directional light along the normal and the view: Lambert 2·0.8/π plus the specular
    2·F·(30/2 + 1)/(4π) with F = 0.0667 + 0.9333·2^-12.53789, written out."""
    scene = t.Scene(
        [t.DirectionalLight(intensity=2.0, position=(0, 0, 1))],
        t.MeshPhongMaterial(color=(0.8, 0.2, 0.2)),
        camera_position=(0, 0, 5),
    )
    f = 17 / 255 + (1 - 17 / 255) * 2 ** (-5.55473 - 6.98316)
    specular = 2 * f * 16 / (4 * math.pi)
    want = [2 * c / math.pi + specular for c in (0.8, 0.2, 0.2)] + [1.0]
    got = gs.shade(np.zeros((1, 3)), np.array([[0, 0, 1.0]]), scene)
    np.testing.assert_allclose(got[0], want, rtol=1e-15)


def test_legacy_lights_multiply_by_pi_and_decay_only_within_a_distance() -> None:
    """r111's default lights: the diffuse term is colour times intensity (π/π), and a point light
    without a distance does not fall off; physically correct lights divide by d^decay."""
    p, n = np.array([[0, 0, 0.0]]), np.array([[0, 0, 1.0]])
    light = t.PointLight(intensity=1.0, decay=2.0, position=(0, 0, 2))
    black = t.MeshPhongMaterial(color=(1, 1, 1), specular=(0, 0, 0), shininess=0)
    legacy = t.Scene([light], black, camera_position=(5, 0, 0), physically_correct_lights=False)
    physical = t.Scene([light], black, camera_position=(5, 0, 0))
    diffuse = gs.shade(p, n, legacy, clamp=False)[0, 0]
    assert diffuse > 1.0  # 1 plus a specular Fresnel share
    got = gs.shade(p, n, physical, clamp=False)[0, 0]
    np.testing.assert_allclose(got, diffuse / (4 * math.pi), rtol=1e-14)


def test_a_light_at_the_vertex_is_finite() -> None:
    for physical in (True, False):
        scene = t.Scene(
            [t.PointLight(position=(1, 2, 3)), t.SpotLight(position=(1, 2, 3), target=(1, 2, 2))],
            physically_correct_lights=physical,
        )
        got = gs.shade(np.array([[1, 2, 3.0]]), np.array([[0, 0, 1.0]]), scene, clamp=False)
        assert np.isfinite(got).all()


def test_non_finite_inputs_give_nan_rows_only() -> None:
    scene = t.Scene([t.PointLight(position=(0, 0, 3))], camera_position=(0, 0, 5))
    p = np.array([[0, 0, 0], [np.nan, 0, 0], [0, 0, 0.0]])
    n = np.array([[0, 0, 1], [0, 0, 1], [np.inf, 0, 1.0]])
    got = gs.shade(p, n, scene)
    assert np.isfinite(got[0]).all() and np.isnan(got[1:]).all()


def test_plan_names_the_terms_that_run() -> None:
    scene = t.Scene(
        [
            t.DirectionalLight(),
            t.PointLight(intensity=0.0),
            t.HemisphereLight(),
            t.AmbientLight(),
            t.SpotLight(),
        ],
        t.MeshPhongMaterial(side="double", emissive=(0.1, 0, 0)),
    )
    plan = scene.plan()
    assert "fast, float32 arithmetic, " in plan
    assert "exact, float64 arithmetic (float32 arrays widened)" in scene.plan(accuracy="exact")
    # three.js' order: point, spot, then directional lights; the dark point light is skipped.
    assert re.search(r"light 4 spot.*light 0 directional", plan), plan
    assert "light 1" not in plan
    assert "light 2 hemisphere" in plan and "ambient" in plan
    assert "emission" in plan and "two sides" in plan
    unlit = t.Scene([t.HemisphereLight()], view_direction=(0, 0, 1))
    assert "normals only" in unlit.plan()
    orthographic = t.Scene([t.DirectionalLight()], view_direction=(0, 0, 1))
    assert "normals only" in orthographic.plan()
    assert "positions and normals" in t.Scene([t.DirectionalLight()]).plan()


@pytest.mark.parametrize(
    ("make", "message"),
    [
        (lambda: t.MeshPhongMaterial(side="both"), "side must be 'front', 'back' or 'double'"),
        (lambda: t.MeshPhongMaterial(shininess=-1), "shininess must be finite and >= 0"),
        (lambda: t.MeshPhongMaterial(opacity=2), r"opacity must be in \[0, 1\]"),
        (lambda: t.MeshPhongMaterial(color=(1, 0)), r"color must have shape \(3,\)"),
        (lambda: t.PointLight(decay=-1), "decay of light 0 must be finite and >= 0"),
        (lambda: t.PointLight(distance=math.inf), "distance of light 0 must be finite"),
        (lambda: t.SpotLight(angle=2.0), r"angle of light 0 must be in \(0, pi/2\]"),
        (lambda: t.SpotLight(penumbra=1.5), r"penumbra of light 0 must be in \[0, 1\]"),
        (lambda: t.DirectionalLight(position=(1, 2, 3), target=(1, 2, 3)), "position - target"),
        (lambda: t.HemisphereLight(position=(0, 0, 0)), "position of light 0 must be finite"),
        (lambda: t.AmbientLight(intensity=-1), "intensity of light 0 must be finite and >= 0"),
        (lambda: t.Scene(view_direction=(0, 0, 0)), "view_direction must be finite and nonzero"),
        (lambda: t.Scene([gs.gltf.PointLight()]), r"lights\[0\] must be a glshade.threejs"),
        (lambda: t.Scene(material=gs.gltf.Material()), "material must be a glshade.threejs"),
        (lambda: t.Scene(physically_correct_lights=1), "physically_correct_lights must be"),
    ],
)
def test_bad_values_name_themselves(make: object, message: str) -> None:
    with pytest.raises((ValueError, TypeError), match=message):
        make()  # type: ignore[operator]


def test_gl_options_are_refused() -> None:
    scene = t.Scene([t.DirectionalLight()])
    with pytest.raises(
        TypeError, match=r"normalize applies to the GL model .* glshade.threejs.Scene"
    ):
        gs.shade(np.zeros((1, 3)), (0, 0, 1), scene, normalize=True)


def test_scenes_compare_and_pickle() -> None:
    scene = random_scene(np.random.default_rng(3), lights=5)
    copy = pickle.loads(pickle.dumps(scene))
    assert copy == scene and repr(copy) == repr(scene)
    p = np.random.default_rng(4).normal(size=(50, 3))
    np.testing.assert_array_equal(gs.shade(p, p, copy), gs.shade(p, p, scene))
    assert scene != t.Scene(scene.lights, scene.material)


def test_render_matches_shade_at_the_vertices() -> None:
    """Gouraud shading interpolates `shade`'s colours: at a pixel on a vertex the render is
    the shaded vertex, with the camera's eye as the scene's camera position."""
    v, f = gs.meshes.icosphere(2)
    scene = t.Scene(
        [t.PointLight(intensity=8.0, position=(2, 2, 3)), t.HemisphereLight((0.2, 0.3, 0.9))],
        t.MeshPhongMaterial(color=(0.9, 0.5, 0.2), shininess=50),
    )
    camera = gs.Camera.look_at(eye=(0, 0, 4), target=(0, 0, 0), fovy=30)
    image = gs.render(v, f, scene, camera, width=64, height=64, shading="phong")
    centre = np.asarray(image)[32, 32]
    # The sphere's front point, seen head-on from the eye: n = (0, 0, 1) at p = (0, 0, ~1).
    placed = t.Scene(scene.lights, scene.material, camera_position=(0, 0, 4))
    want = gs.shade(np.array([[0, 0, 1.0]]), np.array([[0, 0, 1.0]]), placed)[0]
    np.testing.assert_allclose(centre, want, atol=0.02)


def test_render_culls_by_side_and_lights_the_back_of_double_sided_materials() -> None:
    """A square seen from behind: culled for side "front" (three.js' default), drawn lit by
    the negated normal for "double", as `shade`'s back colour."""
    v = np.array([[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0.0]])
    f = np.array([[0, 1, 2], [0, 2, 3]])
    camera = gs.Camera.look_at(eye=(0, 0, -3), target=(0, 0, 0), fovy=40)
    light = t.DirectionalLight(position=(0, 0, -1))
    front = t.Scene([light], t.MeshPhongMaterial(color=(1, 0, 0)))
    image = np.asarray(gs.render(v, f, front, camera, width=16, height=16))
    assert (image[..., 3] == 0).all()
    double = t.Scene([light], t.MeshPhongMaterial(color=(1, 0, 0), side="double"))
    image = np.asarray(gs.render(v, f, double, camera, width=17, height=17))
    placed = t.Scene(double.lights, double.material, camera_position=(0, 0, -3))
    back = gs.shade(np.array([[0, 0, 0.0]]), np.array([[0, 0, 1.0]]), placed)[1, 0]
    assert image[8, 8, 0] > 0.3
    # Pixel (8, 8) of 17 is the image's centre, the square's: the same point, within the
    # interpolation's rounding.
    np.testing.assert_allclose(image[8, 8, :3], back[:3], atol=1e-6)


def test_render_gives_an_orthographic_camera_one_view_direction() -> None:
    """Under a directional light, a flat square seen by an orthographic camera has one colour,
    `shade`'s with the camera's +z axis as `view_direction` (three.js' ``isOrthographic``); a
    perspective camera's highlight moves across it."""
    v = np.array([[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0.0]])
    f = np.array([[0, 1, 2], [0, 2, 3]])
    scene = t.Scene([t.DirectionalLight(position=(0.3, 0.2, 1))], t.MeshPhongMaterial(shininess=5))
    eye = np.array([0.5, 0.4, 3.0])
    camera = gs.Camera.look_at_orthographic(eye=eye, target=(0, 0, 0), height=1.5)
    image = np.asarray(gs.render(v, f, scene, camera, width=16, height=16))
    axis = t.Scene(scene.lights, scene.material, view_direction=eye)
    want = gs.shade(np.zeros((1, 3)), [[0, 0, 1.0]], axis)[0]
    np.testing.assert_allclose(image.reshape(-1, 4), np.broadcast_to(want, (256, 4)), atol=1e-12)
    perspective = gs.Camera.look_at(eye=eye, target=(0, 0, 0), fovy=30)
    image = np.asarray(gs.render(v, f, scene, perspective, width=16, height=16))
    assert np.ptp(image[..., 0]) > 1e-3
