"""Cameras as other libraries give them, as GL's view and projection: a camera-to-world pose
(OpenGL's and pyrender's, looking down -z), OpenCV's intrinsics and extrinsics (+z forward, y
down, pixel centres at whole coordinates), pyrender's camera classes and a trimesh scene's
camera. Each returns what `Camera._built` takes: a view matrix and a lens."""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from ._intake import matrix, number, real
from ._typing import Float64Array

__all__ = [
    "infinite_perspective",
    "intrinsics_projection",
    "opencv_lens",
    "opencv_view",
    "pose_view",
    "pyrender_lens",
    "trimesh_lens",
]

# OpenCV's camera axes (x right, y down, z forward) as GL's eye axes (x right, y up, z back).
_CV_TO_GL = np.diag([1.0, -1.0, -1.0, 1.0])


def pose_view(pose: ArrayLike, name: str = "pose") -> Float64Array:
    """The view (world to eye) of a camera-to-world `pose`: its inverse. The pose must be
    finite, affine (last row 0, 0, 0, 1) and invertible."""
    p = matrix(pose, name)
    if not np.isfinite(p).all() or not np.array_equal(p[3], [0.0, 0.0, 0.0, 1.0]):
        raise ValueError(f"{name} must be finite and affine (last row (0, 0, 0, 1)), got {p}")
    with np.errstate(all="ignore"):  # a huge pose overflows: refused below, not warned of
        det = np.linalg.det(p[:3, :3])
        view = np.linalg.inv(p) if np.isfinite(det) and abs(det) > 1e-12 else None
    if view is None or not np.isfinite(view).all():
        raise ValueError(f"{name} must be invertible, got a 3x3 part of determinant {det:g}: {p}")
    view[3] = (0.0, 0.0, 0.0, 1.0)
    result: Float64Array = view.astype(np.float64)
    return result


def opencv_view(rotation: ArrayLike, translation: ArrayLike) -> Float64Array:
    """GL's view of OpenCV's extrinsics: ``x_cam = R @ x_world + t`` with OpenCV's axes, turned
    into GL's eye axes (y and z negated). R must be a rotation (orthonormal within 1e-6,
    determinant +1)."""
    r = real(rotation, "R")
    if r.shape != (3, 3):
        raise ValueError(f"R must have shape (3, 3), got shape {r.shape}")
    if not np.isfinite(r).all() or not np.allclose(r @ r.T, np.eye(3), atol=1e-6):
        raise ValueError(f"R must be a rotation matrix (R @ R.T = I within 1e-6), got {r.tolist()}")
    if np.linalg.det(r) < 0:
        raise ValueError(f"R must be a rotation (determinant +1), got a reflection: {r.tolist()}")
    t = real(translation, "t").reshape(-1) if np.size(translation) == 3 else real(translation, "t")
    if t.shape != (3,) or not np.isfinite(t).all():
        raise ValueError(f"t must be 3 finite numbers, (3,) or (3, 1), got {np.shape(translation)}")
    extrinsics = np.eye(4)
    extrinsics[:3, :3], extrinsics[:3, 3] = r, t
    view: Float64Array = _CV_TO_GL @ extrinsics
    return view


def _clip_depth(near: float, far: float | None) -> tuple[float, float]:
    """GL's third row of a perspective projection, (P22, P23), for `near` and `far` (None or
    inf: an infinite far plane, as pyrender's ``zfar=None``)."""
    n = number(near, "near")
    if not 0 < n < math.inf:
        raise ValueError(f"near must be a finite number > 0, got {n}")
    f = math.inf if far is None else number(far, "far")
    if not f > n:
        raise ValueError(f"far must be greater than near ({n:g}), got {f}")
    if math.isinf(f):
        return -1.0, -2.0 * n
    return -(f + n) / (f - n), -2.0 * f * n / (f - n)


def opencv_lens(
    intrinsics: ArrayLike, width: int, height: int, near: float, far: float | None
) -> tuple[Any, ...]:
    """GL's projection of OpenCV's camera matrix K for an image of `width` x `height`: pixel
    (u, v) of OpenCV (centres at whole numbers, v down) is GL's window point (u + 1/2,
    height - v - 1/2), so a point projected by ``cv2.projectPoints`` lands on the same pixel
    centre. Independent of the image's size once made (a render at twice the size sees the
    same view)."""
    k = real(intrinsics, "K")
    if k.shape != (3, 3):
        raise ValueError(f"K must have shape (3, 3), got shape {k.shape}")
    fx, skew, cx = k[0]
    fy, cy = k[1, 1:]
    # OpenCV's pinhole model has no skew (projectPoints reads fx, fy, cx and cy alone).
    if not np.isfinite(k).all() or skew or k[1, 0] or tuple(k[2]) != (0.0, 0.0, 1.0):
        raise ValueError(f"K must be [[fx, 0, cx], [0, fy, cy], [0, 0, 1]], got {k.tolist()}")
    if not (fx > 0 and fy > 0):
        raise ValueError(f"K's focal lengths fx and fy must be > 0, got {fx:g} and {fy:g}")
    p22, p23 = _clip_depth(near, far)
    projection = np.array([
        [2 * fx / width, 0.0, 1 - 2 * (cx + 0.5) / width, 0.0],
        [0.0, 2 * fy / height, 2 * (cy + 0.5) / height - 1, 0.0],
        [0.0, 0.0, p22, p23],
        [0.0, 0.0, -1.0, 0.0],
    ])  # fmt: skip
    return ("projection", projection)


def pyrender_lens(camera: Any) -> tuple[Any, ...]:
    """The lens of a pyrender camera: ``PerspectiveCamera`` (yfov in radians, its aspect ratio
    or the image's), ``OrthographicCamera`` (xmag, ymag) or ``IntrinsicsCamera`` (fx, fy, cx,
    cy in pixels, measured from the image's corner, for the image size it is rendered at, as
    pyrender's ``get_projection_matrix`` has them)."""
    kind = type(camera).__name__
    if kind not in ("PerspectiveCamera", "OrthographicCamera", "IntrinsicsCamera"):
        raise TypeError(
            "camera must be a pyrender PerspectiveCamera, OrthographicCamera or "
            f"IntrinsicsCamera, or a pyrender.Node holding one, got {type(camera)!r}"
        )
    near, far = float(camera.znear), camera.zfar
    if kind == "PerspectiveCamera":
        aspect = None if camera.aspectRatio is None else float(camera.aspectRatio)
        far = math.inf if far is None else float(far)
        return ("perspective", math.degrees(camera.yfov), aspect, near, far)
    if kind == "OrthographicCamera":  # pyrender widens xmag to the image's aspect
        return ("orthographic", 2.0 * float(camera.ymag), None, near, float(far))
    far = math.inf if far is None else float(far)
    _clip_depth(near, far)
    return ("intrinsics", camera.fx, camera.fy, camera.cx, camera.cy, near, far)


def intrinsics_projection(lens: tuple[Any, ...], width: int, height: int) -> Float64Array:
    """pyrender's ``IntrinsicsCamera.get_projection_matrix(width, height)``."""
    _, fx, fy, cx, cy, near, far = lens
    p22, p23 = _clip_depth(near, far)
    return np.array([
        [2 * fx / width, 0.0, 1 - 2 * cx / width, 0.0],
        [0.0, 2 * fy / height, 2 * cy / height - 1, 0.0],
        [0.0, 0.0, p22, p23],
        [0.0, 0.0, -1.0, 0.0],
    ])  # fmt: skip


def trimesh_lens(camera: Any) -> tuple[Any, ...]:
    """The lens of a ``trimesh.scene.Camera``: its vertical field of view, and the aspect of
    its two fields of view (``tan(fovx / 2) / tan(fovy / 2)``, the frustum its rays span),
    near and far ``z_near`` and ``z_far``."""
    fov_x, fov_y = (math.radians(float(a)) for a in camera.fov)
    aspect = math.tan(fov_x / 2) / math.tan(fov_y / 2)
    return ("perspective", math.degrees(fov_y), aspect, float(camera.z_near), float(camera.z_far))


def infinite_perspective(fovy: float, aspect: float, near: float) -> Float64Array:
    """gluPerspective's matrix with the far plane at infinity (pyrender's ``zfar=None``)."""
    p22, p23 = _clip_depth(near, None)
    if not (0 < fovy < 180 and 0 < aspect < math.inf):
        raise ValueError(f"fovy must be in (0, 180) and aspect > 0, got {fovy:g} and {aspect:g}")
    f = 1.0 / math.tan(math.radians(fovy) / 2)
    return np.array([
        [f / aspect, 0.0, 0.0, 0.0], [0.0, f, 0.0, 0.0], [0.0, 0.0, p22, p23], [0.0, 0.0, -1.0, 0.0]
    ])  # fmt: skip
