"""Point clouds rendered as GL points: lit at their vertices as `gs.shade` lights them (with
their normals), or drawn in their own colours; depth-tested; a trimesh.PointCloud as it comes;
many views; the errors of a bad call."""

from __future__ import annotations

import numpy as np
import pytest
from conftest import require

import glshade as gs

CAMERA = gs.Camera.look_at((0.5, 0.8, 4.0), fovy=40, near=1.0, far=8.0)
SCENE = gs.Scene(
    lights=[gs.Light(position=(1, 2, 3, 0)),
            gs.Light(position=(-1, 0, 2, 1), diffuse=(0.3, 0.4, 0.5))],
    material=gs.Material(diffuse=(0.8, 0.5, 0.3), specular=(0.5, 0.5, 0.5), shininess=20),
    viewer=(0, 0, 0, 1),
)  # fmt: skip


def window_pixels(points: np.ndarray, width: int, height: int) -> np.ndarray:
    """Each point's pixel, (row from the top, column), from the camera's matrices."""
    clip = np.c_[points, np.ones(len(points))] @ (CAMERA.projection_matrix(width, height)
                                                   @ CAMERA.view).T  # fmt: skip
    ndc = clip[:, :3] / clip[:, 3:]
    x, y = (ndc[:, 0] + 1) / 2 * width, (ndc[:, 1] + 1) / 2 * height
    return np.c_[height - 1 - np.floor(y), np.floor(x)].astype(int)


@pytest.mark.parametrize("dtype", [np.float32, np.float64])
def test_lit_points_are_shade_at_their_vertices(dtype: type) -> None:
    """One pixel a point (size 1), points far apart: each pixel is gs.shade of its point in
    eye coordinates with its normal, to the last bit."""
    rng = np.random.default_rng(2)
    grid = np.stack(np.meshgrid(np.linspace(-1, 1, 9), np.linspace(-1, 1, 9)), -1).reshape(-1, 2)
    points = np.c_[grid, rng.uniform(-0.3, 0.3, len(grid))].astype(dtype)
    normals = rng.normal(size=points.shape).astype(dtype)
    image = np.asarray(gs.render(points, None, SCENE, CAMERA, width=160, height=120,
                                 normals=normals))  # fmt: skip
    assert image.dtype == dtype
    lit = gs.shade(points, normals, SCENE, modelview=CAMERA.view, normalize=True)
    where = window_pixels(points.astype(np.float64), 160, 120)
    np.testing.assert_array_equal(image[where[:, 0], where[:, 1]], lit)
    assert (image[..., 3] > 0).sum() == len(points)


def test_nearer_points_hide_farther_ones_and_depth_is_window_depth() -> None:
    # Both on the view axis: the same window position, the first nearer.
    axis = CAMERA.target - CAMERA.eye
    near, far = list(CAMERA.eye + 0.6 * axis), list(CAMERA.eye + 0.9 * axis)
    colors = [[1, 0, 0], [0, 0, 1]]
    for order in ([near, far], [far, near]):
        picked = colors if order[0] == near else colors[::-1]
        image, depth = gs.render(np.array(order, float), None, None, CAMERA, width=40,
                                 height=30, colors=picked, point_size=4, depth=True)  # fmt: skip
        red = np.asarray(image)[..., 0] > 0.5
        assert red.sum() == 16 and not (np.asarray(image)[..., 2] > 0.5).any()
        assert 0 < depth[red].max() < 1 and (depth[~red] == 1).all()


def test_a_point_cloud_as_trimesh_holds_it() -> None:
    trimesh = require("trimesh")
    rng = np.random.default_rng(5)
    cloud = trimesh.PointCloud(rng.uniform(-1, 1, (200, 3)),
                               colors=rng.integers(0, 256, (200, 4)).astype(np.uint8))  # fmt: skip
    ours = gs.render(cloud, CAMERA, width=64, height=48, point_size=3)
    same = gs.render(np.asarray(cloud.vertices), None, None, CAMERA, width=64, height=48,
                     colors=np.asarray(cloud.colors), point_size=3)  # fmt: skip
    np.testing.assert_array_equal(ours, same)
    views = gs.render(cloud, gs.Camera.orbit(3, distance=4.0), width=32, height=24)
    assert views.shape == (3, 24, 32, 4)
    framed = gs.render(cloud, width=32, height=32, point_shape="round", point_size=5)
    assert (np.asarray(framed)[..., 3] > 0).mean() > 0.2  # framed without a camera


def test_bad_points_are_named() -> None:
    points = np.zeros((5, 3))
    with pytest.raises(TypeError, match="a scene lights them through their normals"):
        gs.render(points, None, SCENE, CAMERA)
    with pytest.raises(ValueError, match=r"point_size must be in \(0, 255\]"):
        gs.render(points, None, None, CAMERA, point_size=0)
    with pytest.raises(ValueError, match=r"point_shape must be .square. or .round., got .disc."):
        gs.render(points, None, None, CAMERA, point_shape="disc")
    with pytest.raises(ValueError, match="normals must have one row per point"):
        gs.render(points, None, SCENE, CAMERA, normals=np.ones((4, 3)))
    with pytest.raises(TypeError, match="points take no texture"):
        gs.render(points, texture=np.ones((2, 2, 3)), uv=np.zeros((5, 2)))
