"""Lights fixed in the world (`lights_in="world"`, `Scene.in_eye_space`): a sphere seen from three
cameras has its highlight where rays cast in world space put it, and GL's order of calls."""

from __future__ import annotations

import numpy as np
import pytest

import glshade as gs
from glshade.meshes import icosphere

SIZE = 96
LIGHT = np.array([1.0, 2.0, 1.5]) / np.linalg.norm([1.0, 2.0, 1.5])  # towards the light, world
SHININESS = 400.0
CAMERAS = [(0.5, 1.5, 4.0), (4.0, 1.0, 0.5), (-1.0, 4.0, 2.0)]


def world_scene() -> gs.Scene:
    """Specular only (the highlight is the brightest pixel), a viewer at the eye."""
    material = gs.Material(ambient=(0, 0, 0), diffuse=(0, 0, 0), specular=(1, 1, 1),
                           shininess=SHININESS)  # fmt: skip
    light = gs.Light(position=(*LIGHT, 0.0))
    return gs.Scene(lights=[light], material=material, global_ambient=(0, 0, 0),
                    viewer=(0, 0, 0, 1))  # fmt: skip


def ray_traced_highlight(camera: gs.Camera, eye: np.ndarray) -> tuple[int, int]:
    """The pixel whose centre's ray hits the unit sphere where the world-space Blinn term
    (n . h)^s is largest: rays through the pixel centres, hits and normals in world space."""
    rows, cols = np.mgrid[0:SIZE, 0:SIZE]
    ndc = np.stack([(cols + 0.5) / SIZE * 2 - 1, 1 - (rows + 0.5) / SIZE * 2], -1)
    inverse = np.linalg.inv(camera.projection_matrix(SIZE, SIZE) @ camera.view)
    far = np.concatenate([ndc, np.ones((SIZE, SIZE, 2))], -1) @ inverse.T
    direction = far[..., :3] / far[..., 3:] - eye
    direction /= np.linalg.norm(direction, axis=-1, keepdims=True)
    b = direction @ eye
    disc = b * b - (eye @ eye - 1.0)
    t = -b - np.sqrt(np.maximum(disc, 0.0))
    hit = eye + t[..., None] * direction
    to_eye = eye - hit
    h = LIGHT + to_eye / np.linalg.norm(to_eye, axis=-1, keepdims=True)
    h /= np.linalg.norm(h, axis=-1, keepdims=True)
    spec = np.where(disc > 0, np.maximum(np.sum(hit * h, -1), 0) ** SHININESS, -1.0)
    r, c = np.unravel_index(np.argmax(spec), spec.shape)
    return int(r), int(c)


@pytest.mark.parametrize("eye", CAMERAS)
def test_the_highlight_stays_where_world_space_rays_put_it(eye: tuple[float, ...]) -> None:
    v, f = icosphere(5)
    camera = gs.Camera.look_at(eye, fovy=35, near=1, far=10)
    image = gs.render(v, f, world_scene(), camera, width=SIZE, height=SIZE, lights_in="world")
    brightest = np.unravel_index(np.argmax(image[..., 0]), image.shape[:2])
    expected = ray_traced_highlight(camera, np.asarray(eye, np.float64))
    assert image[..., 0].max() > 0.9  # a highlight, seen (pixel centres miss its peak)
    assert np.hypot(*np.subtract(brightest, expected)) <= 1.5, (brightest, expected)
    # Lights given in eye space (the default) move with the camera: the same numbers as a
    # light at the world's LIGHT seen from the eye would not put the highlight there.
    carried = gs.render(v, f, world_scene(), camera, width=SIZE, height=SIZE)
    moved = np.unravel_index(np.argmax(carried[..., 0]), carried.shape[:2])
    assert np.hypot(*np.subtract(moved, expected)) > 5


def test_in_eye_space_is_gl_order_of_calls() -> None:
    """glLoadMatrix(view) then glLight: positions by the view, spot directions by its 3x3, a
    world viewer moved, GL's eye-space viewers kept; rendering with lights_in="world" is
    rendering the moved scene."""
    view = gs.Camera.look_at((1.0, 2.0, 3.0), up=(0, 0, 1)).view
    lights = gs.Lights(
        position=[(1, 2, 3, 1), (0, 1, 0, 0)], spot_direction=[(0, 0, -1), (1, 0, 0)],
        spot_cutoff=[30, 180], linear_attenuation=[0.5, 0], diffuse=[(1, 0, 0), (0, 1, 0)],
    )  # fmt: skip
    scene = gs.Scene(lights=lights, viewer=(0, 0, 5, 1), two_side=True)
    moved = scene.in_eye_space(view)
    expected = [view @ (1, 2, 3, 1), view @ (0, 1, 0, 0)]
    np.testing.assert_allclose(moved.lights.position, expected, rtol=0, atol=1e-15)
    np.testing.assert_allclose(moved.lights.spot_direction[1], view[:3, :3] @ (1, 0, 0))
    np.testing.assert_allclose(moved.viewer, view @ (0, 0, 5, 1), rtol=0, atol=1e-15)
    assert moved.lights.linear_attenuation.tolist() == [0.5, 0]
    assert moved.two_side and moved.material == scene.material
    for gl_viewer in ((0, 0, 1, 0), (0, 0, 0, 1)):
        kept = gs.Scene(lights=lights, viewer=gl_viewer).in_eye_space(view)
        assert kept.viewer.tolist() == list(gl_viewer)
    assert len(gs.Scene().in_eye_space(view).lights) == 0
    v, f = icosphere(2)
    camera = gs.Camera.look_at((1.0, 2.0, 3.0), up=(0, 0, 1))
    a = gs.render(v, f, scene, camera, width=32, height=32, lights_in="world")
    b = gs.render(v, f, moved, camera, width=32, height=32)
    np.testing.assert_array_equal(a, b)
    with pytest.raises(ValueError, match="lights_in must be 'eye' or 'world', got 'model'"):
        gs.render(v, f, scene, camera, lights_in="model")  # type: ignore[arg-type]
    with pytest.raises(ValueError, match="view must be finite and affine"):
        scene.in_eye_space(np.ones((4, 4)))
