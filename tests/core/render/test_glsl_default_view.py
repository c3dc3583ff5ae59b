"""``gs.glsl.render(mesh)`` without a scene or a camera draws what ``gs.render(mesh)`` draws: the
same framing camera for the image's size (landscape or portrait) and the mesh placed by
`model`, the same default lights, the same shading names in any case; OpenGL (Mesa's llvmpipe
through moderngl) against glshade's rasteriser, compared by `gs.compare` and by hand."""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest
from conftest import require

import glshade as gs
from support import glpeers

pytestmark = pytest.mark.gl

# The crosscheck's bar for llvmpipe against glshade: colours within 1e-4 where both cover.
ATOL_COLOUR = 1e-4


def _mesh() -> Any:
    """A trimesh sphere far from the origin, so a camera at the origin would miss it."""
    trimesh: Any = require("trimesh")
    mesh = trimesh.creation.icosphere(subdivisions=3, radius=2.0)
    mesh.apply_translation((30.0, -12.0, 55.0))
    return mesh


def _agree(
    theirs: tuple[np.ndarray, np.ndarray], ours: tuple[np.ndarray, np.ndarray]
) -> gs.Comparison:
    """`gs.compare` of GL's image with glshade's, checked against the images themselves."""
    (image, depth), (reference, reference_depth) = theirs, ours
    result = gs.compare(image, reference, depth=depth, reference_depth=reference_depth)
    # Coverage may differ only on silhouettes; colours agree where both cover.
    assert result.counts["coverage, interior"] == 0, str(result)
    assert result.counts["color, interior"] + result.counts["color, edge"] == 0, str(result)
    both = (image[..., 3] > 0) & (reference[..., 3] > 0)
    assert np.abs(image - reference)[both].max() <= ATOL_COLOUR
    # The mesh is framed and lit: between 10% and 90% of the image, and not black.
    coverage = float((reference[..., 3] > 0).mean())
    assert 0.1 <= coverage <= 0.9, coverage
    assert reference[both][:, :3].mean() > 0.2
    return result


@pytest.mark.parametrize(
    ("width", "height", "shading"),
    [(160, 120, "phong"), (120, 160, "Gouraud"), (160, 120, "FLAT")],
)
def test_glsl_render_of_a_bare_mesh_matches_render(width: int, height: int, shading: Any) -> None:
    context = glpeers.moderngl_context()
    mesh = _mesh()
    theirs = gs.glsl.render(
        mesh, width=width, height=height, shading=shading, depth=True, context=context
    )
    ours = gs.render(mesh, width=width, height=height, shading=shading, depth=True)
    assert theirs[0].shape == ours[0].shape == (height, width, 4)
    _agree(theirs, ours)


def test_glsl_render_frames_the_mesh_where_model_puts_it() -> None:
    context = glpeers.moderngl_context()
    mesh = _mesh()
    model = np.array(
        [[0.0, 0.0, 3.0, -40.0], [0.0, 3.0, 0.0, 7.0], [-3.0, 0.0, 0.0, 2.0], [0, 0, 0, 1]]
    )
    theirs = gs.glsl.render(mesh, width=160, height=120, model=model, depth=True, context=context)
    ours = gs.render(mesh, width=160, height=120, model=model, depth=True)
    _agree(theirs, ours)


def test_glsl_cull_and_transfer_names_in_any_case() -> None:
    context = glpeers.moderngl_context()
    mesh = _mesh()
    upper = gs.glsl.render(mesh, width=64, height=48, cull="FRONT", context=context)  # type: ignore[call-overload]
    lower = gs.glsl.render(mesh, width=64, height=48, cull="front", context=context)
    np.testing.assert_array_equal(upper, lower)
    # Front faces culled, a closed sphere shows its inside: still drawn, as gs.render does.
    ours = gs.render(mesh, width=64, height=48, cull="front")
    both = (upper[..., 3] > 0) & (ours[..., 3] > 0)
    assert both.mean() > 0.1 and np.abs(upper - ours)[both].max() <= ATOL_COLOUR
    linear = gs.glsl.render(mesh, width=64, height=48, context=context)
    encoded = gs.glsl.render(mesh, width=64, height=48, transfer="SRGB", context=context)  # type: ignore[call-overload]
    # IEC 61966-2-1, written here: 12.92 x up to 0.0031308, else 1.055 x^(1/2.4) - 0.055.
    x = linear[..., :3].astype(np.float64)
    expected = np.where(x <= 0.0031308, 12.92 * x, 1.055 * np.abs(x) ** (1 / 2.4) - 0.055)
    np.testing.assert_allclose(encoded[..., :3], expected, atol=1e-6)
    np.testing.assert_array_equal(encoded[..., 3], linear[..., 3])


def test_rasterize_reads_uint8_colours_as_normalised_bytes() -> None:
    """uint8 vertex colours are GL's normalised bytes in `gs.glsl.rasterize` too: the same
    targets as the colours divided by 255."""
    context = glpeers.moderngl_context()
    vertices, faces = gs.meshes.icosphere(2)
    positions = vertices + np.array([0.0, 0.0, -4.0])
    projection = gs.Camera.look_at((0, 0, 0), (0, 0, -1), fovy=40).projection_matrix(64, 48)
    scene = gs.Scene(lights=[gs.Light(position=(1, 1, 1, 0))])
    bytes8 = np.random.default_rng(5).integers(0, 256, (len(vertices), 4), dtype=np.uint8)
    drawn = [
        gs.glsl.rasterize(
            positions, vertices, faces, projection, 64, 48, scene, colors=c, context=context
        ).color
        for c in (bytes8, bytes8 / 255.0)
    ]
    assert (drawn[0][..., 3] > 0).mean() > 0.1
    np.testing.assert_array_equal(drawn[0], drawn[1])
