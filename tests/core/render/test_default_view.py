"""`gs.render(mesh)` and `gs.shade_mesh(mesh)` without a scene or a camera: the camera frames the
mesh wherever it is and whatever its size, the default key light lights it from the world."""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import pytest
from conftest import require

import glshade as gs

PLACES = [((0.0, 0.0, 0.0), 1.0), ((100.0, -50.0, 30.0), 1e-3), ((100.0, -50.0, 30.0), 1e3)]
# The documented framing: 35 degrees vertically, the bounding sphere filling 95% of the
# narrower half-angle, seen from the direction (0.45, 0.35, 1).
HALF = math.radians(35.0) / 2
DIRECTION = np.array([0.45, 0.35, 1.0]) / np.linalg.norm([0.45, 0.35, 1.0])


def _placed(mesh: Any, offset: tuple[float, float, float], scale: float) -> Any:
    moved = mesh.copy()
    moved.apply_scale(scale)
    moved.apply_translation(offset)
    return moved


def _ambient_only(mesh: Any, camera: gs.Camera, size: tuple[int, int]) -> float:
    """The brightest a pixel gets without lights: a white ambient material under GL's global
    ambient (0.2), the default scene's."""
    unlit = gs.Scene(lights=[], material=gs.Material(ambient=(1, 1, 1), diffuse=(1, 1, 1)))
    image = gs.render(mesh, unlit, camera, width=size[0], height=size[1])
    return float(np.asarray(image)[..., :3].max())


@pytest.mark.parametrize(("offset", "scale"), PLACES, ids=["origin", "far-small", "far-large"])
@pytest.mark.parametrize("shape", ["box", "icosphere", "annulus"])
def test_a_trimesh_mesh_anywhere_is_framed_and_lit(
    shape: str, offset: tuple[float, float, float], scale: float
) -> None:
    trimesh: Any = require("trimesh")
    made = {
        "box": lambda: trimesh.creation.box(),
        "icosphere": lambda: trimesh.creation.icosphere(3),
        "annulus": lambda: trimesh.creation.annulus(0.5, 1.0, 0.3),
    }
    mesh = _placed(made[shape](), offset, scale)
    image, depth = gs.render(mesh, width=96, height=64, depth=True)
    covered = depth < 1
    np.testing.assert_array_equal(covered, image[..., 3] > 0)
    assert 0.10 <= covered.mean() <= 0.90, covered.mean()
    # The whole mesh is in view: nothing touches the border.
    assert not (
        covered[0].any() or covered[-1].any() or covered[:, 0].any() or covered[:, -1].any()
    )
    rgb = np.asarray(image)[..., :3][covered]
    # The camera used: render(mesh) is render(mesh, camera=...) for the camera it built; the
    # brightest unlit pixel seen through the same framing is 0.2.
    level = _ambient_only(mesh, _framing_camera(mesh.vertices, 96 / 64), (96, 64))
    assert level == pytest.approx(0.2, abs=1e-9)
    assert rgb.mean() > 2 * level and rgb.max() > 0.6
    assert rgb.std() > 0.05  # shaded, not flat


def _framing_camera(points: np.ndarray, aspect: float) -> gs.Camera:
    """The documented default camera, transcribed: the bounding box's centre, the distance
    where the farthest vertex's sphere fills 95% of the narrower half-angle."""
    centre = (points.min(axis=0) + points.max(axis=0)) / 2
    radius = np.linalg.norm(points - centre, axis=1).max()
    half = min(HALF, math.atan(aspect * math.tan(HALF)))
    distance = radius / math.sin(0.95 * half)
    return gs.Camera.look_at(
        centre + distance * DIRECTION,
        centre,
        (0, 1, 0),
        fovy=35.0,
        near=distance - 1.01 * radius,
        far=distance + 1.01 * radius,
    )


@pytest.mark.parametrize(("width", "height"), [(64, 64), (96, 48), (48, 96)])
def test_a_sphere_fills_the_documented_share_of_the_view(width: int, height: int) -> None:
    v, f = gs.meshes.icosphere(5)
    _, depth = gs.render(v * 7 + (3, -4, 5), f, width=width, height=height, depth=True)
    covered = depth < 1
    # A sphere whose sine of angular radius is sin(0.95 half) appears with the radius
    # tan(asin(...)) / tan(half-angle) of the half-height (or half-width), in pixels.
    half = min(HALF, math.atan(width / height * math.tan(HALF)))
    across = math.tan(0.95 * half) / math.tan(half) * min(width, height)
    rows, cols = np.nonzero(covered)
    assert abs((rows.max() - rows.min() + 1) - across) <= 2.0
    assert abs((cols.max() - cols.min() + 1) - across) <= 2.0
    # Centred: the sphere's centre is the bounding box's.
    assert abs(rows.mean() + 0.5 - height / 2) < 0.5 and abs(cols.mean() + 0.5 - width / 2) < 0.5


def test_the_default_camera_is_the_documented_one() -> None:
    v, f = gs.meshes.torus(32, 16, 1.0, 0.4)
    placed = v * 0.01 + (5, 6, 7)
    default = gs.render(placed, f, width=80, height=60)
    framed = gs.render(placed, f, camera=_framing_camera(placed, 80 / 60), width=80, height=60)
    np.testing.assert_allclose(default, framed, atol=1e-12)


def test_the_default_lights_stay_in_the_world() -> None:
    v, f = gs.meshes.icosphere(4)
    front = gs.Camera.look_at((0, 0, 4), fovy=40, near=1, far=10)
    behind = gs.Camera.look_at((0, 0, -4), fovy=40, near=1, far=10)
    seen = [gs.render(v, f, camera=c, width=48, height=48, depth=True) for c in (front, behind)]
    means = [float(np.asarray(image)[..., :3][depth < 1].mean()) for image, depth in seen]
    # The key light comes from +z's side of the world: the far side, seen from behind, is
    # darker. Lights following the eye would light both views alike (the sphere is symmetric).
    assert means[1] < 0.75 * means[0]
    # Keyword or positional camera, and the mesh as a (vertices, faces) tuple: one picture.
    np.testing.assert_array_equal(seen[0][0], gs.render(v, f, front, width=48, height=48))
    np.testing.assert_array_equal(seen[0][0], gs.render((v, f), front, width=48, height=48))
    scene = gs.Scene(lights=[gs.Light()])
    np.testing.assert_array_equal(
        gs.render((v, f), scene, front, width=16, height=16),
        gs.render(v, f, scene, front, width=16, height=16),
    )


def test_shade_mesh_sees_a_mesh_at_the_origin_from_outside() -> None:
    v, f = gs.meshes.icosphere(3)
    colours = gs.shade_mesh(v, f)
    # The viewer is where the framing camera's eye is, a point outside the mesh's bounds: the
    # colours do not change when the mesh moves or grows, as a viewer at the origin's would.
    for offset, scale in PLACES[1:]:
        np.testing.assert_allclose(gs.shade_mesh(v * scale + offset, f), colours, atol=1e-9)
    # That viewer, transcribed from the documentation, with the default lights of render.
    from glshade._framing import default_scene

    radius = np.linalg.norm(v, axis=1).max()
    eye = radius / math.sin(0.95 * HALF) * DIRECTION
    assert np.linalg.norm(eye) > 3 * radius  # well outside the mesh
    expected = gs.shade(v, gs.vertex_normals(v, f), default_scene(viewer=(*eye, 1.0)))
    np.testing.assert_allclose(colours, expected, atol=1e-12)
    # The specular highlight faces that viewer: the brightest vertex looks towards the eye's
    # side (and the key's), not away from it.
    brightest = v[np.argmax(colours[:, :3].sum(axis=1))]
    assert brightest @ DIRECTION > 0
    flat = gs.shade_mesh((v, f), per="Face")  # a (vertices, faces) tuple; names any case
    assert flat.shape == (len(f), 4)


def test_the_framing_follows_the_model_matrix() -> None:
    v, f = gs.meshes.torus(24, 12, 1.0, 0.4)
    model = np.eye(4)
    model[:3, :3] *= 250.0
    model[:3, 3] = (-400.0, 90.0, 1e3)
    moved = v @ model[:3, :3].T + model[:3, 3]
    a = gs.render(v, f, model=model, width=40, height=30)
    b = gs.render(moved, f, width=40, height=30)
    assert 0.1 < (np.asarray(a)[..., 3] > 0).mean() < 0.9
    np.testing.assert_allclose(a, b, atol=1e-9)
    # shade_mesh's default viewer follows a modelview the same way (GL_NORMALIZE undoes the
    # scale the normal matrix gives the normals).
    np.testing.assert_allclose(
        gs.shade_mesh(v, f, modelview=model, normalize=True), gs.shade_mesh(moved, f), atol=1e-9
    )
