"""`glshade.threejs` against three.js itself: release 111 (Debian's ``libjs-three``) renders a
``MeshPhongMaterial`` plane into a float32 render target in headless Chromium (WebGL 2 on
SwiftShader, float32 shaders), and `glshade.shade` lights the world point and normal under
every pixel (`support.threejs_browser`). Random scenes of every light kind, both light
conventions, every side (seen from the front and, for "back" and "double", from behind),
perspective and orthographic cameras.

Bound, relative to max(1, |value|): 1e-5, the float32 bound of every renderer here, or
4·2⁻²⁴·shininess where that is larger: three.js computes in float32, and its n·h, good to about
3·2⁻²⁴, is raised to the shininess, which multiplies that relative error (seed 4, shininess 162,
errs 2.9e-5 at its highlight; 3·2⁻²⁴·162 = 2.9e-5). glshade's own error is 2⁻²⁴ at most.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from typing import Any

import numpy as np
import pytest
from conftest import unavailable

import glshade as gs
from support.chromium import chromium
from support.threejs_browser import ARGUMENTS, THREE, light_record, page, render
from support.threejs_reference import random_scene

pytestmark = [pytest.mark.gl, pytest.mark.subprocess]

BOUND = 1e-5
WIDTH, HEIGHT = 40, 32
Renderer = Callable[[dict[str, Any]], tuple[np.ndarray, np.ndarray]]


@pytest.fixture(scope="module")
def threejs(tmp_path_factory: pytest.TempPathFactory) -> Iterator[Renderer]:
    if not THREE.exists():
        unavailable(f"three.js r111 is not installed at {THREE} (apt-get install libjs-three)")
    url = page(tmp_path_factory.mktemp("threejs")).as_uri()
    with chromium(*ARGUMENTS) as driver:
        yield lambda config: render(driver, url, config)


def case(seed: int) -> tuple[dict[str, Any], gs.threejs.Scene, bool]:
    """The page's configuration, the same scene for glshade, and whether the camera sees the
    plane's front."""
    rng = np.random.default_rng(1000 + seed)
    scene = random_scene(rng, lights=int(rng.integers(2, 7)))
    side = ("front", "back", "double", "double")[seed % 4]
    front = side == "front" or (side == "double" and seed % 8 == 2)
    material = gs.threejs.MeshPhongMaterial(**{**vars(scene.material), "side": side})
    normal = rng.normal(size=3)
    normal[1] *= 0.3  # away from the cameras' up axis
    normal /= np.linalg.norm(normal)
    centre = rng.uniform(-0.5, 0.5, 3)
    sideways = np.cross(normal, rng.normal(size=3))
    towards = (normal if front else -normal) + 0.6 * sideways / np.linalg.norm(sideways)
    eye = centre + rng.uniform(4, 7) * towards / np.linalg.norm(towards)
    camera: dict[str, Any] = {
        "eye": eye.tolist(),
        "target": (centre + rng.uniform(-0.3, 0.3, 3)).tolist(),
        "up": [0.0, 1.0, 0.0],
        "near": 0.1,
        "far": 100.0,
    }
    if seed % 3 == 2:
        camera.update(kind="orthographic", half_width=3.0, half_height=3.0 * HEIGHT / WIDTH)
    else:
        camera.update(kind="perspective", fov=float(rng.uniform(35, 60)))
    config = {
        "width": WIDTH,
        "height": HEIGHT,
        "physical": scene.physically_correct_lights,
        "camera": camera,
        "plane": {"center": centre.tolist(), "normal": normal.tolist()},
        "material": {**vars(material)},
        "lights": [light_record(light) for light in scene.lights],
    }
    z = eye - np.asarray(camera["target"])
    placed = gs.threejs.Scene(
        scene.lights,
        material,
        camera_position=eye,
        view_direction=z if camera["kind"] == "orthographic" else None,
        physically_correct_lights=scene.physically_correct_lights,
    )
    return config, placed, front


SEEDS = range(24)


@pytest.mark.parametrize("seed", SEEDS)
def test_agrees_with_threejs_in_chromium(threejs: Renderer, seed: int) -> None:
    config, scene, front = case(seed)
    pixels, points = threejs(config)
    covered = np.isfinite(points).all(axis=1)
    assert covered.mean() > 0.9  # the plane fills the view
    pixels, points = pixels[covered], points[covered]
    normal = np.broadcast_to(config["plane"]["normal"], points.shape)
    got = gs.shade(points, normal, scene, clamp=False)
    if scene.material.side == "double":
        got = got[0 if front else 1]
    error = np.abs(got - pixels) / np.maximum(1, np.abs(pixels))
    bound = max(BOUND, 4 * 2.0**-24 * scene.material.shininess)
    assert error.max() <= bound, (seed, float(error.max()), scene)


def test_the_cases_cover_every_kind_side_camera_and_convention() -> None:
    seen: set[object] = set()
    for seed in SEEDS:
        config, scene, front = case(seed)
        seen |= {type(light).__name__ for light in scene.lights}
        seen |= {(scene.material.side, front), config["camera"]["kind"]}
        seen.add(("physical", scene.physically_correct_lights))
        spots = [x for x in scene.lights if isinstance(x, gs.threejs.SpotLight)]
        seen |= {("penumbra", 0 < x.penumbra < 1) for x in spots}
        seen |= {("distance", x.distance > 0) for x in spots}
    wanted = {
        "AmbientLight", "HemisphereLight", "DirectionalLight", "PointLight", "SpotLight",
        ("front", True), ("back", False), ("double", True), ("double", False), "perspective",
        "orthographic", ("physical", True), ("physical", False), ("penumbra", True),
        ("penumbra", False), ("distance", True), ("distance", False),
    }  # fmt: skip
    assert wanted <= seen, wanted - seen
