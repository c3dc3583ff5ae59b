"""`render`'s depth and coverage against pyrender's (Mesa llvmpipe through EGL).

pyrender always renders with 4x MSAA and reads depth back from sample 0, which lies off the
pixel centre: at (-1/8, -3/8) pixel in GL window coordinates (y up; (-1/8, +3/8)
in image rows). glshade samples pixel centres, so its projection is shifted by the opposite
offset to look through the same points. pyrender culls back faces, so glshade does too. Its
depth buffer has 24 bits and comes back
linearised with the perspective formula (for every camera); the test undoes that formula and
compares window depths.
"""

from __future__ import annotations

import functools
from typing import Any

import numpy as np
import pytest
from conftest import require

import glshade as gs
from glshade.meshes import icosphere, torus
from support import glpeers  # first: it sets PYOPENGL_PLATFORM=egl before OpenGL is imported

pytestmark = pytest.mark.gl

# Where pyrender's depth sample lies, in pixels from the pixel centre, GL window coordinates.
SAMPLE_0 = (-0.125, -0.375)
# Window depth: 24-bit quantisation (6e-8) and pyrender's float32 linearisation round trip.
ATOL_DEPTH = 1e-6
# On the silhouette, where a depth slope is steep (up to 0.05 per pixel here), the two
# rasterisers' sub-pixel vertex positions (snapped to 1/256 pixel from float32 in llvmpipe,
# from float64 in glshade) make up to 1/512 pixel of difference.
ATOL_DEPTH_EDGE = 1e-4
# Pixels may differ only where an edge passes between the centre and sample 0.
MAX_COVERAGE_DIFFERENCE = 0.005


def pyrender_module() -> Any:
    return require("pyrender")


@functools.cache
def offscreen_renderer(width: int, height: int) -> Any:
    """One pyrender renderer per size for the session, never deleted: pyrender's delete()
    calls eglTerminate on the EGL display it shares with moderngl's context."""
    pyrender = pyrender_module()
    return glpeers.gl_resource(
        "pyrender OffscreenRenderer (EGL)", lambda: pyrender.OffscreenRenderer(width, height)
    )


def pyrender_depth(
    mesh: tuple[np.ndarray, np.ndarray], camera: Any, pose: np.ndarray, size: tuple[int, int]
) -> np.ndarray:
    pyrender = pyrender_module()
    trimesh = require("trimesh")
    scene = pyrender.Scene()
    scene.add(pyrender.Mesh.from_trimesh(trimesh.Trimesh(*mesh, process=False), smooth=False))
    scene.add(camera, pose=pose)
    depth: np.ndarray = offscreen_renderer(*size).render(
        scene, flags=pyrender.RenderFlags.DEPTH_ONLY
    )
    return depth


def window_depth(linear: np.ndarray, near: float, far: float) -> np.ndarray:
    """Undoes pyrender's linearisation, d = 2fn / (f + n - z_ndc (f - n))."""
    z_ndc = (far + near - 2 * far * near / linear) / (far - near)
    return (z_ndc + 1) / 2


def silhouette(covered: np.ndarray) -> np.ndarray:
    """Pixels with a differently covered neighbour (8-connected): where edges pass."""
    padded = np.pad(covered, 1, mode="edge")
    h, w = covered.shape
    around = [
        padded[1 + dy : 1 + dy + h, 1 + dx : 1 + dx + w] for dy in (-1, 0, 1) for dx in (-1, 0, 1)
    ]
    result: np.ndarray = np.any([a != covered for a in around], axis=0)
    return result


CASES = {
    "torus, perspective": ("perspective", torus(48, 32), (0.3, -2.4, 1.9), (0, 0, 1)),
    "icosphere, orthographic": ("orthographic", icosphere(3), (1.5, 2.0, 2.5), (0, 1, 0)),
    "torus through the near plane": (
        "perspective",
        torus(64, 24, 1.0, 0.5),
        (0.0, -1.05, 0.2),
        (0, 0, 1),
    ),
}


@pytest.mark.parametrize("case", list(CASES))
def test_depth_and_coverage_match_pyrender(case: str) -> None:
    pyrender = pyrender_module()
    kind, mesh, eye, up = CASES[case]
    width, height, near, far = 160, 120, 0.5, 10.0
    view = gs.Camera.look_at(eye, (0, 0, 0), up).view
    if kind == "perspective":
        camera = pyrender.PerspectiveCamera(np.radians(50), near, far, aspectRatio=width / height)
    else:
        camera = pyrender.OrthographicCamera(xmag=1.6, ymag=1.2, znear=near, zfar=far)
    theirs = pyrender_depth(mesh, camera, np.linalg.inv(view), (width, height))
    shift = np.eye(4)
    shift[:2, 3] = -2 * np.array(SAMPLE_0) / (width, height)
    projection = shift @ camera.get_projection_matrix(width, height)
    camera = gs.Camera(view, projection)
    args: dict[str, Any] = {"width": width, "height": height, "cull": "back", "depth": True}
    _, ours = gs.render(*mesh, gs.Scene(), camera, **args)

    covered, their_covered = ours < 1, theirs > 0
    assert 0.05 < covered.mean() < 0.95
    differ = covered != their_covered
    assert differ.mean() < MAX_COVERAGE_DIFFERENCE
    assert not (differ & ~silhouette(covered)).any(), "coverage differs away from the edges"
    both = covered & their_covered
    difference = np.abs(ours[both] - window_depth(theirs[both], near, far))
    inner = ~silhouette(covered)[both]
    assert difference[inner].max() < ATOL_DEPTH
    assert difference.max() < ATOL_DEPTH_EDGE


@pytest.mark.parametrize("kind", ["perspective", "orthographic", "intrinsics", "infinite"])
def test_a_pyrender_camera_sees_what_pyrender_sees(kind: str) -> None:
    """`Camera.from_pyrender` of each pyrender camera class at a pose: pyrender's own
    projection matrix at the render's size, the pose's inverse as the view, and pyrender's
    depth and coverage through them (its sample 0 allowed for, as above)."""
    pyrender = pyrender_module()
    width, height, near, far = 160, 120, 0.5, 10.0
    pose = np.linalg.inv(gs.Camera.look_at((0.4, -2.2, 2.0), (0.1, 0, 0), (0, 0, 1)).view)
    camera = {
        "perspective": lambda: pyrender.PerspectiveCamera(np.radians(50), near, far),
        "orthographic": lambda: pyrender.OrthographicCamera(xmag=1.6, ymag=1.2, znear=near,
                                                            zfar=far),
        "intrinsics": lambda: pyrender.IntrinsicsCamera(150.0, 140.0, 70.0, 66.0, near, far),
        "infinite": lambda: pyrender.PerspectiveCamera(np.radians(50), near, None),
    }[kind]()  # fmt: skip
    ours = gs.Camera.from_pyrender(camera, pose)
    np.testing.assert_allclose(ours.view, np.linalg.inv(pose), atol=1e-12)
    projection = ours.projection_matrix(width, height)
    np.testing.assert_allclose(projection, camera.get_projection_matrix(width, height), atol=1e-12)
    node = pyrender.Node(camera=camera, matrix=pose)
    np.testing.assert_allclose(gs.Camera.from_pyrender(node).view, ours.view, atol=1e-12)
    mesh = torus(48, 32)
    theirs = pyrender_depth(mesh, camera, pose, (width, height))
    shift = np.eye(4)
    shift[:2, 3] = -2 * np.array(SAMPLE_0) / (width, height)
    sampled = gs.Camera(ours.view, shift @ projection)
    args: dict[str, Any] = {"width": width, "height": height, "cull": "back", "depth": True}
    _, depth = gs.render(*mesh, gs.Scene(), sampled, **args)
    covered, their_covered = depth < 1, theirs > 0
    assert 0.05 < covered.mean() < 0.95
    differ = covered != their_covered
    assert differ.mean() < MAX_COVERAGE_DIFFERENCE
    assert not (differ & ~silhouette(covered)).any(), "coverage differs away from the edges"
