"""gs.compare against llvmpipe's renders of the render tests' scenes (glshade.glsl's shaders),
a sub-pixel shift (coverage differences, all on edges) and a light turned by 1 degree (interior
differences). Its synthetic cases are in tests/core/render/test_comparison.py."""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest

import glshade as gs
from support import glpeers
from support.render_cases import CASES, face_edges, named, on_edges, vertex_colours

pytestmark = pytest.mark.gl

WIDTH, HEIGHT = 240, 180


def both_renders(case: dict[str, Any], shading: str, dtype: Any, **changes: Any) -> Any:
    v, f = case["mesh"]
    colors = case.get("colors") and vertex_colours(len(v))
    kwargs = {"width": WIDTH, "height": HEIGHT, "shading": shading, "depth": True,
              "colors": colors, "color_material": case.get("colors")}  # fmt: skip
    ours = gs.render(v.astype(dtype), f, case["scene"], case["camera"], **kwargs)
    scene = changes.get("scene", case["scene"])
    camera = changes.get("camera", case["camera"])
    theirs = gs.glsl.render(v, f, scene, camera, context=glpeers.moderngl_context(), **kwargs)
    return ours, theirs


@pytest.mark.parametrize("dtype", [np.float32, np.float64])
@pytest.mark.parametrize("shading", ["phong", "gouraud", "flat"])
@pytest.mark.parametrize("name", list(CASES))
def test_glshade_against_llvmpipe_agrees_and_differs_only_on_edges(
    name: str, shading: str, dtype: Any
) -> None:
    (ours, depth), (theirs, their_depth) = both_renders(CASES[name], shading, dtype)
    result = gs.compare(ours, theirs, depth=depth, reference_depth=their_depth)
    assert result.compared > 0.05 * WIDTH * HEIGHT
    # Every colour difference off the silhouettes lies where two flat-shaded faces meet, and
    # the edges' are few.
    interior = result.labels == 1
    if shading != "flat":
        assert not interior.any(), str(result)
    else:
        error = np.abs(ours - theirs).max(axis=-1)
        assert not (interior & ~face_edges(ours)).any(), named(interior & ~face_edges(ours), error)
    assert result.within_tolerance >= 0.995, str(result)
    differ = (depth < 1) != (their_depth < 1)
    assert result.counts["coverage, edge"] == differ.sum()
    assert result.counts["coverage, interior"] == 0
    assert not (differ & ~on_edges(depth < 1)).any()


def test_a_subpixel_shift_is_all_edge_coverage() -> None:
    """An unlit mesh (emission only: one colour everywhere) drawn by llvmpipe a third of a pixel
    to the right: colours agree, coverage differs along the silhouette only."""
    case = CASES["torus, perspective, local viewer, spot"]
    flat = gs.Scene(
        lights=[], material=gs.Material(emission=(0.3, 0.6, 0.9)), global_ambient=(0, 0, 0)
    )
    camera: gs.Camera = case["camera"]
    projection = camera.projection_matrix(WIDTH, HEIGHT)
    shift = np.eye(4)
    shift[0, 3] = 2 * (1 / 3) / WIDTH  # NDC units per pixel: 2 / width
    moved = gs.Camera(camera.view, shift @ projection)
    v, f = case["mesh"]
    ours = gs.render(v, f, flat, camera, width=WIDTH, height=HEIGHT)
    theirs = gs.glsl.render(v, f, flat, moved, width=WIDTH, height=HEIGHT,
                            context=glpeers.moderngl_context())  # fmt: skip
    result = gs.compare(ours, theirs)  # coverage from alpha
    assert result.counts["coverage, edge"] > 50
    assert result.counts["coverage, interior"] == 0
    assert result.counts["color, interior"] == result.counts["color, edge"] == 0
    assert result.within_tolerance == 1.0 and result.edge_only
    assert result.largest[0]["kind"] == "coverage, edge"


def turned(scene: gs.Scene, degrees: float) -> gs.Scene:
    """The scene with every light turned about the eye's y axis."""
    a = np.radians(degrees)
    rotation = np.eye(4)
    rotation[[0, 0, 2, 2], [0, 2, 0, 2]] = np.cos(a), np.sin(a), -np.sin(a), np.cos(a)
    return scene.in_eye_space(rotation)


@pytest.mark.parametrize("shading", ["phong", "gouraud"])
def test_a_light_turned_by_one_degree_shows_as_interior_differences(shading: str) -> None:
    case = CASES["icosphere, vertex colours (COLOR_MATERIAL diffuse), shininess 100"]
    (ours, depth), (theirs, their_depth) = both_renders(
        case, shading, np.float64, scene=turned(case["scene"], 1.0)
    )
    result = gs.compare(ours, theirs, depth=depth, reference_depth=their_depth)
    assert result.within_tolerance < 0.9, str(result)
    assert result.counts["color, interior"] > 0.5 * result.compared
    assert not result.edge_only
    assert result.counts["coverage, interior"] == result.counts["coverage, edge"] == 0
    assert result.largest[0]["kind"] == "color, interior"
