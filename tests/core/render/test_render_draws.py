"""The native `render_draws` (several meshes in one frame, as `render(pyrender_scene)` uses
it): one draw renders as `render` does, and every bad draw is named by its index."""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest

import glshade as gs
from glshade import _glshade

V, F = gs.meshes.icosphere(2)
N = V.copy()
CAMERA = gs.Camera.look_at((0.4, 0.3, 3.5), (0, 0, 0), (0, 1, 0))
SCENE = gs.gltf.Scene(
    [gs.gltf.DirectionalLight((1, 1, 1), 2.0, (-0.3, -0.4, -1))],
    gs.gltf.Material((0.8, 0.5, 0.3, 1), 0.2, 0.5),
)


def draw(**given: Any) -> tuple[Any, ...]:
    """A draw tuple of the sphere, with `given` in place of its fields."""
    fields = {
        "vertices": V, "faces": F, "scene": SCENE._native, "model": np.eye(4), "cull": "none",
        "normals": N, "colors": None, "texture": None, "uv": None, "filter": "linear",
        "wrap": ("repeat", "repeat"),
    }  # fmt: skip
    fields.update(given)
    return tuple(fields.values())


def render_draws(draws: list[tuple[Any, ...]], **options: Any) -> tuple[Any, Any]:
    kwargs = {
        "view": CAMERA.view, "projection": CAMERA.projection_matrix(40, 30), "width": 40,
        "height": 30, "shading": "phong", "provoking_vertex": "last", "background": np.zeros(4),
        "transfer": "linear", "clamp": True,
    }  # fmt: skip
    kwargs.update(options)
    return _glshade.render_draws(draws, **kwargs)  # type: ignore[arg-type]


def test_one_draw_is_a_render() -> None:
    image, depth = render_draws([draw()])
    expected, expected_depth = gs.render(V, F, SCENE, CAMERA, width=40, height=30, normals=N,
                                         depth=True)  # fmt: skip
    np.testing.assert_array_equal(image, expected)
    np.testing.assert_array_equal(depth, expected_depth)


def test_placing_the_vertices_is_placing_them_by_hand() -> None:
    """The "vertices" placement moves positions and normals per vertex as a vertex shader:
    the same picture as the mesh moved beforehand in numpy."""
    model = np.eye(4)
    model[:3, :3] = (
        np.diag([1.5, 0.7, 1.0]) @ gs.Camera.look_at((1, 2, 3), (0, 0, 0), (0, 1, 0)).view[:3, :3]
    )
    model[:3, 3] = (0.2, -0.1, -0.3)
    placed, placed_depth = render_draws([draw(model=model)], placement="vertices")
    world = V @ model[:3, :3].T + model[:3, 3]
    normals = N @ np.linalg.inv(model[:3, :3])
    normals /= np.linalg.norm(normals, axis=1, keepdims=True)
    by_hand, depth = render_draws([draw(vertices=world, normals=normals)])
    assert (depth < 1).sum() > 200
    np.testing.assert_allclose(placed_depth, depth, atol=1e-12)
    np.testing.assert_allclose(placed, by_hand, atol=1e-12)
    # In the model's evaluation instead, non-uniform scale: the normals interpolate otherwise.
    in_model, _ = render_draws([draw(model=model)])
    assert np.abs(in_model - placed).max() > 1e-6


@pytest.mark.parametrize(
    ("draws", "options", "error", "message"),
    [
        ([], {}, ValueError, "draws must hold at least one mesh"),
        ([draw(), draw(scene=gs.Scene()._native)], {}, TypeError, "draws[1].scene must be"),
        ([draw(), draw(vertices=V.astype(np.float32))], {}, TypeError, "draws[1].vertices"),
        ([draw(), draw(faces=F + len(V))], {}, IndexError, "draws[1]: "),
        ([draw(), draw(normals=N[:5])], {}, ValueError, "draws[1]: normals must have"),
        ([draw(), draw(model=np.zeros((4, 4)))], {}, ValueError, "draws[1]: model must be affine"),
        ([draw(model=np.zeros((3, 4)))], {}, ValueError, "draws[0].model"),
        ([draw(cull="sides")], {}, ValueError, "cull must be"),
        ([draw()], {"placement": "world"}, ValueError, "placement must be"),
        ([draw()], {"transfer": "sRGB"}, ValueError, "transfer must be"),
        ([draw(texture=np.zeros((2, 2, 4), np.int8), uv=V[:, :2])], {}, TypeError,
         "texture must be a (height, width, channels) array"),
    ],
)  # fmt: skip
def test_bad_draws_are_named(
    draws: list[tuple[Any, ...]], options: dict[str, Any], error: type, message: str
) -> None:
    with pytest.raises(error) as raised:
        render_draws(draws, **options)
    assert message in str(raised.value)
