"""`render` against OpenGL itself: Mesa's llvmpipe through moderngl, rendering the same mesh
into float32 targets with glshade.glsl's shaders (`glpeers.rasterize`), per
vertex for Gouraud and flat shading and per fragment for Phong.

GL gets the mesh in eye coordinates (view applied here in float64, normals by the inverse
transpose); flat shading gets unshared vertices that carry their face's normal, so that the
provoking vertex lights the face with it. The targets hold GL's colour sum of the primary and
secondary colours, added and clamped as `render` does it.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest

import glshade as gs
from support import glpeers
from support.render_cases import CASES, face_edges, named, on_edges, vertex_colours

pytestmark = pytest.mark.gl

# The bar: the colour of every pixel both cover within 1e-4, but on the silhouettes (a pixel
# with a neighbour of other coverage in either image) and, with flat shading, where two faces
# meet (a pixel centre on their shared edge may go to either face); those edge pixels beyond
# it fewer than 0.5%, and named when they are not. Coverage different only on silhouettes and
# on fewer than 0.5% of the pixels, depth within 1e-6.
ATOL_COLOUR = 1e-4
MAX_EDGE_DIFFERENCE = 0.005
MAX_COVERAGE_DIFFERENCE = 0.005
ATOL_DEPTH = 1e-6
# Except on steep depth slopes (grazing silhouettes, the near-plane cut), where llvmpipe's
# float32 evaluation of the depth plane, z0 + dz/dx x + dz/dy y with x and y up to 240 pixels
# and |dz/dx| up to 0.1, rounds by up to u32 * 0.1 * 240 * a few = 5e-6 (glshade evaluates it
# in float64: test_render checks it against the projection formula to 1e-12).
MIN_DEPTH_AGREEING = 0.999
ATOL_DEPTH_STEEP = 1e-5


def gl_render(
    case: dict[str, Any], shading: str, width: int, height: int
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """GL's image (the colour sum), depth and coverage."""
    v, f = case["mesh"]
    camera: gs.Camera = case["camera"]
    view = camera.view
    normal_matrix = np.linalg.inv(view[:3, :3]).T
    eye = v @ view[:3, :3].T + view[:3, 3]
    colors = case.get("colors") and vertex_colours(len(v))
    if shading == "flat":
        normals = np.repeat(gs.face_normals(v, f) @ normal_matrix.T, 3, axis=0)
        eye, f = eye[f].reshape(-1, 3), np.arange(3 * len(f)).reshape(-1, 3)
        colors = None if colors is None else colors[case["mesh"][1]].reshape(-1, 4)
    else:
        normals = gs.vertex_normals(v, f) @ normal_matrix.T
    targets = glpeers.rasterize(
        eye,
        normals,
        f,
        camera.projection_matrix(width, height),
        width,
        height,
        case["scene"],
        shading=shading,  # type: ignore[arg-type]
        normalize=True,
        colors=colors,
        color_material=case.get("colors"),
    )
    return targets.color, targets.depth, targets.covered


@pytest.mark.parametrize("dtype", [np.float32, np.float64])
@pytest.mark.parametrize("shading", ["phong", "gouraud", "flat"])
@pytest.mark.parametrize("name", list(CASES))
def test_render_matches_llvmpipe(name: str, shading: str, dtype: Any) -> None:
    case = CASES[name]
    width, height = 240, 180
    theirs, their_depth, their_covered = gl_render(case, shading, width, height)
    v, f = case["mesh"]
    colors = case.get("colors") and vertex_colours(len(v)).astype(dtype)
    ours, depth = gs.render(
        v.astype(dtype),
        f,
        case["scene"],
        case["camera"],
        width=width,
        height=height,
        shading=shading,  # type: ignore[arg-type]
        colors=colors,
        color_material=case.get("colors"),
        depth=True,
    )
    covered = depth < 1
    assert 0.05 < covered.mean() < 0.98

    differ = covered != their_covered
    assert differ.mean() < MAX_COVERAGE_DIFFERENCE, f"coverage differs at {differ.sum()} pixels"
    assert not (differ & ~on_edges(covered)).any(), "coverage differs away from the edges"

    both = covered & their_covered
    error = np.abs(ours - theirs).max(axis=-1)
    edges = on_edges(covered) | on_edges(their_covered)
    if shading == "flat":
        edges |= face_edges(ours) | face_edges(theirs)
    beyond = both & (error > ATOL_COLOUR)
    assert not (beyond & ~edges).any(), f"off the edges, beyond {ATOL_COLOUR}: " + named(
        beyond & ~edges, error
    )
    assert beyond.sum() < MAX_EDGE_DIFFERENCE * both.sum(), "on edges: " + named(beyond, error)

    depth_error = np.abs(depth[both] - their_depth[both])
    assert (depth_error <= ATOL_DEPTH).mean() >= MIN_DEPTH_AGREEING
    assert depth_error.max() <= ATOL_DEPTH_STEEP, f"depth differs by up to {depth_error.max():.2e}"
