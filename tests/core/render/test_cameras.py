"""Cameras as other libraries give them: OpenCV's K, R, t against ``cv2.projectPoints``, a
trimesh scene's camera against ``scene.camera_rays()``, a camera-to-world pose against
`look_at`; what a camera says of itself; many views in one call against single calls; files
rendered as their loaded meshes."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from conftest import require

import glshade as gs

RNG = np.random.default_rng(4)


def window(camera: gs.Camera, points: np.ndarray, width: int, height: int) -> np.ndarray:
    """GL's window coordinates (x right, y up, pixel centres at half integers) of `points`."""
    clip = np.c_[points, np.ones(len(points))] @ (camera.projection_matrix(width, height)
                                                   @ camera.view).T  # fmt: skip
    ndc = clip[:, :3] / clip[:, 3:]
    return np.c_[(ndc[:, 0] + 1) / 2 * width, (ndc[:, 1] + 1) / 2 * height]


def opencv_camera(width: int, height: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """An off-centre K with fx != fy, and a rotation and translation looking at the origin."""
    k = np.array([[0.9 * width, 0, 0.47 * width], [0, 1.1 * width, 0.55 * height], [0, 0, 1]])
    rvec = np.array([0.3, -0.5, 0.2])
    angle = np.linalg.norm(rvec)
    axis = rvec / angle
    cross = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    r = np.eye(3) + math.sin(angle) * cross + (1 - math.cos(angle)) * cross @ cross
    return k, r, np.array([0.1, -0.2, 4.0])


def test_opencv_cameras_project_where_projectpoints_does() -> None:
    cv2 = require("cv2")
    width, height = 640, 480
    k, r, t = opencv_camera(width, height)
    camera = gs.Camera.from_opencv(k, r, t, width, height)
    points = RNG.uniform(-1, 1, (500, 3))
    rvec, _ = cv2.Rodrigues(r)
    theirs, _ = cv2.projectPoints(points, rvec, t, k, None)
    x, y = window(camera, points, width, height).T
    ours = np.c_[x - 0.5, height - y - 0.5]  # OpenCV's pixel centres are whole numbers, v down
    np.testing.assert_allclose(ours, theirs.reshape(-1, 2), atol=1e-3)
    assert np.abs(ours - theirs.reshape(-1, 2)).max() < 1e-8


def test_a_point_opencv_puts_on_a_pixel_is_drawn_on_it() -> None:
    """A speck 0.4 pixels wide around a point OpenCV projects onto pixel (u, v) covers exactly
    that pixel of the render: row v from the top, column u."""
    width, height = 64, 48
    k, r, t = opencv_camera(width, height)
    camera = gs.Camera.from_opencv(k, r, t, width, height)
    for u, v in ((5, 7), (40, 30), (63, 0), (0, 47)):
        depth = 3.0
        cam_point = depth * np.array([(u - k[0, 2]) / k[0, 0], (v - k[1, 2]) / k[1, 1], 1.0])
        # A speck in the camera's plane, 0.2 pixels each way at that depth.
        du, dv = 0.2 * depth / k[0, 0], 0.2 * depth / k[1, 1]
        corners = cam_point + np.array([[-du, -dv, 0], [du, -dv, 0], [0, dv, 0]])
        world = (corners - t) @ r  # R^T (x - t)
        image = gs.render(world, [[0, 1, 2]], gs.Camera.from_opencv(k, r, t, width, height),
                          width=width, height=height)  # fmt: skip
        covered = np.argwhere(np.asarray(image)[..., 3] > 0)
        assert covered.tolist() == [[v, u]], (u, v, covered.tolist())
    assert camera.fovy == pytest.approx(
        math.degrees(math.atan((k[1, 2] + 0.5) / k[1, 1])
                     + math.atan((height - k[1, 2] - 0.5) / k[1, 1]))
    )  # fmt: skip


def test_a_trimesh_scene_s_camera_sees_along_its_rays() -> None:
    trimesh = require("trimesh")
    scene = trimesh.Scene(trimesh.creation.icosphere())
    scene.set_camera(angles=(0.4, 0.7, 0.1), distance=5.0, resolution=(96, 64), fov=(60, 45))
    origins, directions, pixels = scene.camera_rays()
    camera = gs.Camera.from_trimesh(scene)
    x, y = window(camera, origins + 2.5 * directions, 96, 64).T
    # trimesh numbers a ray's pixel from the bottom left: GL's window pixel.
    np.testing.assert_allclose(x, pixels[:, 0] + 0.5, atol=1e-9)
    np.testing.assert_allclose(y, pixels[:, 1] + 0.5, atol=1e-9)
    # render takes a trimesh scene's own camera.
    own = gs.render(scene, width=96, height=64)
    np.testing.assert_array_equal(own, gs.render(scene, camera, width=96, height=64))


def test_a_pose_is_the_inverse_of_the_view() -> None:
    look = gs.Camera.look_at((1, 2, 3), (0, 0.5, 0), (0, 1, 0), fovy=40)
    posed = gs.Camera.from_pose(look.pose, fovy=40)
    np.testing.assert_allclose(posed.view, look.view, atol=1e-12)
    np.testing.assert_array_equal(posed.projection_matrix(30, 20), look.projection_matrix(30, 20))
    np.testing.assert_allclose(look.eye, (1, 2, 3), atol=1e-12)
    np.testing.assert_array_equal(look.target, (0, 0.5, 0))
    forward = np.subtract((0, 0.5, 0), (1, 2, 3))
    assert abs(look.up @ forward) < 1e-12 and look.up[1] > 0
    assert look.fovy == 40 and look.projection is None
    assert gs.Camera.look_at((0, 0, 5), aspect=2.0).projection is not None
    assert gs.Camera.look_at_orthographic((0, 0, 5)).fovy is None
    np.testing.assert_allclose(posed.target, look.eye + forward / np.linalg.norm(forward))
    infinite = gs.Camera.from_pose(np.eye(4), fovy=60, far=None).projection_matrix(4, 4)
    assert infinite[2, 2] == -1 and infinite[2, 3] == -0.2


def test_bad_cameras_are_named() -> None:
    with pytest.raises(ValueError, match="pose must be finite and affine"):
        gs.Camera.from_pose(np.ones((4, 4)), fovy=45)
    with pytest.raises(ValueError, match="pose must be invertible"):
        gs.Camera.from_pose(np.diag([1.0, 0.0, 1.0, 1.0]), fovy=45)
    k, r, t = opencv_camera(64, 48)
    with pytest.raises(ValueError, match="R must be a rotation matrix"):
        gs.Camera.from_opencv(k, 2 * r, t, 64, 48)
    with pytest.raises(ValueError, match="determinant"):
        gs.Camera.from_opencv(k, -r, t, 64, 48)
    with pytest.raises(ValueError, match=r"K must be \[\[fx, 0, cx\]"):
        gs.Camera.from_opencv(k + np.eye(3)[::-1], r, t, 64, 48)
    with pytest.raises(ValueError, match="t must be 3 finite numbers"):
        gs.Camera.from_opencv(k, r, [1, 2], 64, 48)
    with pytest.raises(ValueError, match="width must be"):
        gs.Camera.from_opencv(k, r, t, 0, 48)
    with pytest.raises(TypeError, match=r"camera must be a glshade\.Camera, a list of them"):
        gs.render(gs.meshes.icosphere(1), gs.Scene(), np.eye(4))  # type: ignore[call-overload]
    with pytest.raises(TypeError, match=r"scene must be a trimesh\.Scene"):
        gs.Camera.from_trimesh(object())
    with pytest.raises(TypeError, match="pyrender PerspectiveCamera"):
        gs.Camera.from_pyrender(object(), np.eye(4))
    with pytest.raises(ValueError, match="views must be"):
        gs.Camera.orbit(0)


@pytest.mark.parametrize("lights_in", ["eye", "world"])
@pytest.mark.parametrize("shading", ["phong", "flat"])
def test_many_views_are_the_single_views(lights_in: str, shading: str) -> None:
    """A list of cameras renders each view as a call with that camera alone, bit for bit: with
    lights fixed to the eye (one native call) and in the world (a scene a view)."""
    mesh = gs.meshes.torus(24, 12, 1.0, 0.4)
    scene = gs.Scene(lights=[gs.Light(position=(1, 2, 3, 0))], material=gs.Material(),
                     viewer=(0, 0, 0, 1))  # fmt: skip
    cameras = gs.Camera.orbit(5, distance=4.0, elevation=30.0)
    options = {"width": 40, "height": 30, "shading": shading, "lights_in": lights_in}
    images, depths = gs.render(mesh, scene, cameras, depth=True, **options)
    assert images.shape == (5, 30, 40, 4) and depths.shape == (5, 30, 40)
    for k, camera in enumerate(cameras):
        image, depth = gs.render(mesh, scene, camera, depth=True, **options)
        np.testing.assert_array_equal(images[k], image)
        np.testing.assert_array_equal(depths[k], depth)
    default = gs.render(mesh, cameras, width=20, height=20)  # the default scene, in the world
    np.testing.assert_array_equal(default[3], gs.render(mesh, cameras[3], width=20, height=20))


def test_an_orbit_circles_its_target() -> None:
    cameras = gs.Camera.orbit(8, target=(1, 0, 0), distance=2.0, elevation=30.0)
    eyes = np.array([c.eye for c in cameras])
    np.testing.assert_allclose(np.linalg.norm(eyes - (1, 0, 0), axis=1), 2.0)
    np.testing.assert_allclose(eyes[:, 1], 2.0 * math.sin(math.radians(30)))
    np.testing.assert_allclose(eyes[0], (1, 1.0, 2.0 * math.cos(math.radians(30))), atol=1e-12)
    np.testing.assert_allclose(eyes[2, 0] - 1, 2.0 * math.cos(math.radians(30)), atol=1e-12)
    assert all(np.array_equal(c.target, (1, 0, 0)) for c in cameras)


@pytest.mark.parametrize("suffix", [".glb", ".obj", ".ply"])
def test_a_file_renders_as_its_loaded_mesh(tmp_path: Path, suffix: str) -> None:
    trimesh = require("trimesh")
    v, f = gs.meshes.torus(20, 10, 1.0, 0.35)
    colors = (RNG.uniform(0.2, 1.0, (len(v), 4)) * 255).astype(np.uint8)
    colors[:, 3] = 255
    path = tmp_path / f"torus{suffix}"
    trimesh.Trimesh(v, f, vertex_colors=colors, process=False).export(path)
    loaded = trimesh.load(path)
    camera = gs.Camera.look_at((2, 2, 3))
    ours = gs.render(str(path), camera, width=48, height=40)
    np.testing.assert_array_equal(ours, gs.render(loaded, camera, width=48, height=40))
    np.testing.assert_array_equal(ours, gs.render(path, camera, width=48, height=40))
    assert (np.asarray(ours)[..., 3] > 0).sum() > 200
    with pytest.raises(FileNotFoundError, match="does not exist"):
        gs.render(tmp_path / f"missing{suffix}", camera)


def test_a_file_of_points_is_refused_by_name(tmp_path: Path) -> None:
    trimesh = require("trimesh")
    path = tmp_path / "points.ply"
    trimesh.PointCloud(RNG.uniform(-1, 1, (50, 3))).export(path)
    with pytest.raises(TypeError, match=r"points\.ply' holds a PointCloud, not a triangle mesh"):
        gs.render(path)
