"""gs.compare's depth tolerance follows the depth's slope: on a plane it is exactly
``depth_tolerance + depth_shift * (|gx| + |gy|)``, a shift of the geometry by up to
`depth_shift` pixels passes, another surface does not, and a camera moved by half a pixel
leaves only edge differences in depth and coverage (colours keep their rule: the shading moves
with the surface)."""

from __future__ import annotations

import numpy as np
import pytest

import glshade as gs
from glshade.meshes import icosphere, torus

GX, GY = 3e-4, -1e-4  # the plane's depth change per pixel along a row and down a column
TOLERANCE = 1e-5  # compare's default depth_tolerance


def _plane(shift_x: float = 0.0, shift_y: float = 0.0) -> np.ndarray:
    """Window depths of a plane over 20 x 24 pixels, the plane moved by (shift_x, shift_y)."""
    rows, columns = np.mgrid[0:20, 0:24].astype(np.float64)
    depth: np.ndarray = 0.5 + GX * (columns + shift_x) + GY * (rows + shift_y)
    return depth


def _labels(
    depth: np.ndarray, reference_depth: np.ndarray, depth_shift: float = 1.0
) -> dict[str, int]:
    image = np.full((*depth.shape, 4), 0.5)
    result = gs.compare(
        image, image, depth=depth, reference_depth=reference_depth, depth_shift=depth_shift
    )
    return result.counts


@pytest.mark.parametrize("shift", [1.0, 0.5, 0.0])
def test_on_a_plane_the_tolerance_is_the_stated_one(shift: float) -> None:
    # Central differences along the row, column and diagonals: |gx|, |gy|, |gx +- gy|.
    allowed = TOLERANCE + shift * (abs(GX) + abs(GY))
    reference = _plane()
    below = _labels(reference + 0.999 * allowed, reference, depth_shift=shift)
    above = _labels(reference + 1.001 * allowed, reference, depth_shift=shift)
    assert below["depth, interior"] == below["depth, edge"] == 0
    assert above["depth, interior"] == 20 * 24  # every pixel; no silhouette anywhere


@pytest.mark.parametrize(("sx", "sy"), [(0.5, 0.5), (-0.5, 0.25), (0.999, -0.999), (-0.9, 0.0)])
def test_the_plane_moved_by_less_than_a_pixel_passes(sx: float, sy: float) -> None:
    assert _labels(_plane(sx, sy), _plane())["depth, interior"] == 0


def test_the_plane_moved_by_two_pixels_does_not() -> None:
    counts = _labels(_plane(2.0, -2.0), _plane())
    assert counts["depth, interior"] == 20 * 24


def test_another_surface_on_the_slope_is_still_a_depth_difference() -> None:
    reference = _plane()
    image = reference.copy()
    image[5, 5] += 1.5 * abs(GX) + 1.5 * abs(GY)  # one pixel of another surface
    image[10:13, 14:17] += 3 * (abs(GX) + abs(GY))  # a 3 x 3 patch of one
    counts = _labels(image, reference)
    assert counts["depth, interior"] == 1 + 9
    labels = gs.compare(np.zeros((20, 24, 3)), np.zeros((20, 24, 3)), depth=image).counts
    assert labels["depth, interior"] == 0  # one depth alone compares no depths


def _shifted_renders(
    mesh: tuple[np.ndarray, np.ndarray], camera: gs.Camera, scene: gs.Scene
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """The mesh rendered at 256 x 256, then with the projection moved by half a pixel right
    and half a pixel up (x and y in normalised device coordinates span 2 over the size)."""
    size = 256
    shift = np.eye(4)
    shift[0, 3] = shift[1, 3] = 2 * 0.5 / size
    moved = gs.Camera(camera.view, shift @ camera.projection_matrix(size, size))
    options = {"width": size, "height": size, "depth": True, "lights_in": "world"}
    a, da = gs.render(*mesh, scene, camera, **options)  # type: ignore[call-overload]
    b, db = gs.render(*mesh, scene, moved, **options)  # type: ignore[call-overload]
    return np.asarray(b, np.float64), db, np.asarray(a, np.float64), da


def _largest_step(image: np.ndarray) -> np.ndarray:
    """Per pixel, the largest colour change (largest channel) to an 8-neighbour."""
    h, w = image.shape[:2]
    padded = np.pad(image[..., :3], ((1, 1), (1, 1), (0, 0)), mode="edge")
    out = np.zeros((h, w))
    for a in (-1, 0, 1):
        for b in (-1, 0, 1):
            step = np.abs(padded[1 + a : 1 + a + h, 1 + b : 1 + b + w] - image[..., :3])
            out = np.maximum(out, step.max(axis=2))
    return out


MESHES = {"icosphere": icosphere(3), "torus": torus(48, 24)}
CAMERAS = {
    "perspective": gs.Camera.look_at(eye=(0, 1, 3)),
    "orthographic": gs.Camera.look_at_orthographic(eye=(0, 2, 3), height=3.2),
}
LIT = gs.Scene(
    lights=[gs.Light(position=(1, 2, 2, 0))],
    material=gs.Material(specular=(1, 1, 1), shininess=40),
)


@pytest.mark.parametrize("mesh", list(MESHES))
@pytest.mark.parametrize("camera", list(CAMERAS))
def test_a_camera_moved_by_half_a_pixel_gives_no_interior_depth_difference(
    mesh: str, camera: str
) -> None:
    image, depth, reference, reference_depth = _shifted_renders(MESHES[mesh], CAMERAS[camera], LIT)
    result = gs.compare(image, reference, depth=depth, reference_depth=reference_depth)
    assert result.counts["depth, interior"] == 0
    assert result.counts["coverage, interior"] == 0
    assert result.counts["coverage, edge"] > 100  # the silhouette moved
    # The fixed tolerance alone (the rule before) calls most of the surface another one.
    fixed = gs.compare(
        image, reference, depth=depth, reference_depth=reference_depth, depth_shift=0
    )
    assert fixed.counts["depth, interior"] > 0.3 * fixed.compared
    # Colours keep their rule: the shading moves with the surface, by at most the colour
    # change to a neighbouring pixel (in either image), which is what a half pixel can do.
    interior = result.labels == gs.Comparison.KINDS.index("color, interior")
    assert interior.sum() > 0.5 * result.compared
    error = np.abs(image - reference)[..., :3].max(axis=2)
    bound = np.maximum(_largest_step(image), _largest_step(reference))
    assert (error[interior] <= bound[interior]).all()


@pytest.mark.parametrize("mesh", list(MESHES))
def test_half_a_pixel_of_an_evenly_coloured_mesh_is_edge_only(mesh: str) -> None:
    unlit = gs.Scene(
        lights=[], material=gs.Material(emission=(0.3, 0.6, 0.9)), global_ambient=(0, 0, 0)
    )
    image, depth, reference, reference_depth = _shifted_renders(
        MESHES[mesh], CAMERAS["perspective"], unlit
    )
    result = gs.compare(image, reference, depth=depth, reference_depth=reference_depth)
    assert result.edge_only
    assert result.counts["coverage, edge"] > 100 and result.within_tolerance == 1.0


@pytest.mark.parametrize(
    ("option", "value", "message"),
    [
        ("depth_shift", -1, "depth_shift must be a finite number >= 0, got -1.0"),
        ("depth_tolerance", float("nan"), "depth_tolerance must be a finite number >= 0, got nan"),
        ("depth_jump", float("inf"), "depth_jump must be a finite number >= 0, got inf"),
    ],
)
def test_bad_depth_options_name_themselves(option: str, value: float, message: str) -> None:
    a = np.zeros((4, 4, 4))
    with pytest.raises(ValueError, match=message):
        gs.compare(a, a, **{option: value})  # type: ignore[arg-type]
    with pytest.raises(TypeError, match="depth_shift must be a number"):
        gs.compare(a, a, depth_shift="1")  # type: ignore[arg-type]
