"""gs.compare: against llvmpipe's renders of the render tests' scenes (glshade.glsl's shaders),
a sub-pixel shift (coverage differences, all on edges), a light turned by 1 degree (interior
differences), and synthetic images whose every difference is known."""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest
from test_render_vs_moderngl import CASES, on_edges, vertex_colours

import glpeers
import glshade as gs

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


def test_statistics_labels_and_largest_on_known_differences() -> None:
    reference = np.zeros((20, 30, 4))
    reference[4:16, 5:25] = (0.5, 0.25, 0.75, 1.0)
    image = reference.copy()
    image[10, 12, 1] += 0.01  # interior colour
    image[4, 10, 0] += 0.002  # colour on the silhouette's row
    image[16, 8] = (0.5, 0.25, 0.75, 1.0)  # one more pixel covered, below the edge
    depth = np.where(reference[..., 3] > 0, 0.5, 1.0)
    their_depth = depth.copy()
    depth[16, 8] = 0.5
    their_depth[8, 20] = 0.505  # another surface behind, closer than a silhouette step
    result = gs.compare(image, reference, depth=depth, reference_depth=their_depth)
    assert result.compared == 12 * 20
    assert result.counts == {
        "color, interior": 1,
        "color, edge": 1,
        "depth, interior": 1,
        "depth, edge": 0,
        "coverage, interior": 0,
        "coverage, edge": 1,
    }
    assert result.within_tolerance == (240 - 2) / 240
    np.testing.assert_allclose(result.max_error, [0.002, 0.01, 0, 0], atol=1e-15)
    np.testing.assert_allclose(result.mean_error, [0.002 / 240, 0.01 / 240, 0, 0], atol=1e-15)
    assert result.percentiles[50.0].tolist() == [0, 0, 0, 0]
    first, second = result.largest[:2]
    assert (first["row"], first["column"], first["kind"]) == (16, 8, "coverage, edge")
    assert (second["row"], second["column"], second["error"]) == (10, 12, pytest.approx(0.01))
    labels = result.labels
    assert gs.Comparison.KINDS[labels[8, 20]] == "depth, interior"
    assert isinstance(result.heatmap, gs.Image) and result.heatmap.shape == (20, 30, 4)
    assert result._repr_png_().startswith(b"\x89PNG")
    np.testing.assert_array_equal(result.heatmap[16, 8, :3], [1, 0, 1])  # magenta: edge coverage
    assert "coverage, edge" in str(result)


def test_uint8_and_premultiplied_images_compare_as_their_straight_colours() -> None:
    rng = np.random.default_rng(1)
    straight = rng.uniform(0, 1, (8, 9, 4))
    straight[..., 3] = rng.choice([0.0, 0.5, 1.0], (8, 9))
    straight[straight[..., 3] == 0, :3] = 0
    premultiplied = straight.copy()
    premultiplied[..., :3] *= straight[..., 3:]
    result = gs.compare(premultiplied, straight, alpha="premultiplied", reference_alpha="straight")
    assert result.max_error.max() < 1e-15 and result.within_tolerance == 1.0
    quantised = np.round(straight * 255).astype(np.uint8)
    result = gs.compare(quantised, straight, tolerance=0.5 / 255)
    assert result.within_tolerance == 1.0
    assert result.max_error.max() == pytest.approx(0.5 / 255, abs=2e-3 / 255)
    assert gs.compare(quantised, straight, tolerance=0.1 / 255).within_tolerance < 1.0


def test_bad_arguments_name_themselves() -> None:
    a = np.zeros((4, 4, 4))
    with pytest.raises(ValueError, match="image and reference must have one shape"):
        gs.compare(a, np.zeros((4, 5, 4)))
    with pytest.raises(ValueError, match=r"image must have shape \(height, width, 3\)"):
        gs.compare(np.zeros((4, 4)), a)
    with pytest.raises(ValueError, match="alpha must be 'straight' or 'premultiplied'"):
        gs.compare(a, a, alpha="linear")  # type: ignore[arg-type]
    with pytest.raises(ValueError, match=r"reference_depth must have shape \(4, 4\)"):
        gs.compare(a, a, depth=np.ones((4, 4)), reference_depth=np.ones((3, 4)))
    with pytest.raises(TypeError, match="tolerance must be a number"):
        gs.compare(a, a, tolerance="1e-4")  # type: ignore[arg-type]
    with pytest.raises(TypeError, match="image must be real numbers"):
        gs.compare(np.zeros((4, 4, 4), complex), a)
