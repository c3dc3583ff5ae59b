"""`Camera`: GL's view and projection matrices, explicit or built like gluLookAt, gluPerspective
and glOrtho."""

from __future__ import annotations

from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from . import _glshade
from ._camera_conventions import (
    infinite_perspective,
    intrinsics_projection,
    opencv_lens,
    opencv_view,
    pose_view,
    pyrender_lens,
    trimesh_lens,
)
from ._intake import integer, number, real, transform
from ._typing import Float64Array

__all__ = ["Camera"]


def _point(value: ArrayLike, name: str) -> tuple[float, float, float]:
    p = real(value, name)
    if p.shape != (3,):
        raise ValueError(f"{name} must have shape (3,), got shape {p.shape}")
    x, y, z = p.tolist()
    return (x, y, z)


def _aspect(value: float | None) -> float | None:
    """None, or a finite aspect ratio > 0."""
    if value is None:
        return None
    a = number(value, "aspect")
    if not 0 < a < np.inf:
        raise ValueError(f"aspect must be finite and > 0, got {a:g}")
    return a


def is_camera_list(value: object) -> bool:
    """A non-empty list or tuple of `Camera` (the views of one `render` call)."""
    return (
        isinstance(value, (list, tuple))
        and bool(value)
        and all(isinstance(c, Camera) for c in value)
    )


class Camera:
    """Where the mesh is seen from and how it is projected: GL's view and projection matrices.

    Matrices are row-major (4, 4) arrays, as numpy prints them (the transpose of what
    ``glLoadMatrixd`` reads). A point p of the mesh reaches clip coordinates as
    ``projection @ view @ model @ (p, 1)``. The view takes world to eye coordinates, where the
    camera sits at the origin looking down -z with +y up, and where a `Scene`'s lights and viewer
    are given (as for `shade`).

    Parameters
    ----------
    view : (4, 4) float, optional
        World to eye coordinates; affine (last row (0, 0, 0, 1)) and invertible. Default: the
        identity (GL's initial modelview).
    projection : (4, 4) float, optional
        Eye to clip coordinates. Default: the identity (GL's initial projection: the cube
        [-1, 1]^3 of eye coordinates, seen orthographically along -z).

    Examples
    --------
    >>> import glshade as gs
    >>> camera = gs.Camera.look_at(eye=(0, 0, 5), target=(0, 0, 0), fovy=30)
    >>> camera.projection_matrix(640, 480).shape
    (4, 4)
    """

    __slots__ = ("_lens", "_target", "_view")
    _lens: tuple[Any, ...]

    def __init__(self, view: ArrayLike | None = None, projection: ArrayLike | None = None) -> None:
        self._view = transform(view, "view")
        self._lens = ("projection", transform(projection, "projection"))
        self._target: Float64Array | None = None

    @classmethod
    def _built(
        cls, view: Float64Array, lens: tuple[Any, ...], target: ArrayLike | None = None
    ) -> Camera:
        """A camera of `view` and `lens`: ("projection", matrix), ("perspective", fovy, aspect,
        near, far) (far inf: none), ("orthographic", height, aspect, near, far) or
        ("intrinsics", fx, fy, cx, cy, near, far) (pyrender's, for the image's size), aspect
        None for the image's; `target`, the point it was aimed at, where it was."""
        camera = cls(view)
        if lens[0] == "projection":  # read-only again after a pickle's round trip
            lens = ("projection", transform(lens[1], "projection"))
        camera._lens = lens
        camera._target = None if target is None else np.array(target, dtype=np.float64)
        camera.projection_matrix(1, 1)  # checks the parameters now rather than at the first render
        return camera

    def __reduce__(self) -> tuple[Any, ...]:
        return (Camera._built, (self._view, self._lens, self._target))

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Camera):
            return NotImplemented
        same = (
            np.array_equal(a, b) if isinstance(a, np.ndarray) else a == b
            for a, b in zip(self._lens, other._lens, strict=False)
        )
        return (
            np.array_equal(self._view, other._view)
            and len(self._lens) == len(other._lens)
            and all(same)
        )

    __hash__ = None  # type: ignore[assignment]

    @classmethod
    def look_at(
        cls,
        eye: ArrayLike,
        target: ArrayLike = (0.0, 0.0, 0.0),
        up: ArrayLike = (0.0, 1.0, 0.0),
        *,
        fovy: float = 45.0,
        aspect: float | None = None,
        near: float = 0.1,
        far: float = 100.0,
    ) -> Camera:
        """A perspective camera at `eye` looking at `target` (gluLookAt + gluPerspective).

        Parameters
        ----------
        eye : (3,) float
            The camera's position, in world coordinates.
        target : (3,) float
            The point it looks at, in world coordinates.
        up : (3,) float
            The world direction that appears upwards (any length, not parallel to the view).
        fovy : float
            The vertical field of view in degrees, in (0, 180).
        aspect : float, optional
            Width / height of the view; None (the default) takes the image's at render time.
        near : float
            The distance to the near clip plane, 0 < near < far.
        far : float
            The distance to the far clip plane.

        Returns
        -------
        Camera

        Raises
        ------
        ValueError
            For ``eye == target``, `up` parallel to the view, or out-of-range parameters.
        """
        aim = _point(target, "target")
        view = _glshade.look_at(_point(eye, "eye"), aim, _point(up, "up"))
        f, n, z = number(fovy, "fovy"), number(near, "near"), number(far, "far")
        return cls._built(view, ("perspective", f, _aspect(aspect), n, z), aim)

    @classmethod
    def look_at_orthographic(
        cls,
        eye: ArrayLike,
        target: ArrayLike = (0.0, 0.0, 0.0),
        up: ArrayLike = (0.0, 1.0, 0.0),
        *,
        height: float = 2.0,
        aspect: float | None = None,
        near: float = 0.1,
        far: float = 100.0,
    ) -> Camera:
        """An orthographic camera at `eye` looking at `target` (gluLookAt + glOrtho).

        Parameters
        ----------
        eye : (3,) float
            As for `look_at`.
        target : (3,) float
            As for `look_at`.
        up : (3,) float
            As for `look_at`.
        height : float
            The height of the visible box in world units; its width is ``height * aspect``,
            centred on the view axis.
        aspect : float, optional
            Width / height of the view; None (the default) takes the image's at render time.
        near : float
            The distance along the view direction to the near clip plane (``near != far``;
            negative values are behind the eye, as in glOrtho).
        far : float
            The distance along the view direction to the far clip plane.

        Returns
        -------
        Camera
        """
        aim = _point(target, "target")
        view = _glshade.look_at(_point(eye, "eye"), aim, _point(up, "up"))
        h, n, z = number(height, "height"), number(near, "near"), number(far, "far")
        if not 0 < h < np.inf:
            raise ValueError(f"height must be finite and > 0, got {h:g}")
        return cls._built(view, ("orthographic", h, _aspect(aspect), n, z), aim)

    @classmethod
    def from_pose(
        cls,
        pose: ArrayLike,
        *,
        fovy: float,
        aspect: float | None = None,
        near: float = 0.1,
        far: float | None = 100.0,
    ) -> Camera:
        """A perspective camera placed by a camera-to-world `pose`, looking down the pose's -z
        axis with its +y axis up: OpenGL's and pyrender's convention (a pyrender camera
        node's pose).

        Parameters
        ----------
        pose : (4, 4) float
            Camera to world: its last column is the eye, its columns 0 to 2 the camera's x
            (right), y (up) and z (backwards) axes in the world. Affine and invertible.
        fovy : float
            The vertical field of view in degrees, in (0, 180) (pyrender's ``yfov`` is in
            radians: ``fovy=np.degrees(yfov)``).
        aspect : float, optional
            Width / height; None (the default) takes the image's at render time.
        near : float
            The near clip plane's distance, > 0.
        far : float or None
            The far clip plane's distance, > near; None: none (an infinite far plane, as
            pyrender's ``zfar=None``).

        Returns
        -------
        Camera

        Raises
        ------
        ValueError
            For a pose that is not 4 x 4, finite, affine and invertible, or lens parameters
            out of range.
        """
        view = pose_view(pose)
        z = np.inf if far is None else number(far, "far")
        lens = ("perspective", number(fovy, "fovy"), _aspect(aspect), number(near, "near"), z)
        return cls._built(view, lens)

    @classmethod
    def from_opencv(
        cls,
        K: ArrayLike,
        R: ArrayLike,
        t: ArrayLike,
        width: int,
        height: int,
        *,
        near: float = 0.1,
        far: float | None = 100.0,
    ) -> Camera:
        """A camera of OpenCV's intrinsics and extrinsics: a point x of the world is at
        ``R @ x + t`` in the camera's coordinates (x right, y down, z forward) and at pixel
        ``(u, v) = (fx X / Z + cx, fy Y / Z + cy)``, pixel centres at whole numbers
        from the top left, as ``cv2.projectPoints`` puts it. Render it at `width` x `height`
        (the size K belongs to): the point lands on the centre of pixel (u, v) of the image.

        Parameters
        ----------
        K : (3, 3) float
            ``[[fx, 0, cx], [0, fy, cy], [0, 0, 1]]``, in pixels; fx, fy > 0 (no skew, as
            OpenCV's model has none). Lens distortion is not modelled: undistort first.
        R : (3, 3) float
            World to camera rotation (``cv2.Rodrigues(rvec)[0]``), determinant +1.
        t : (3,) or (3, 1) float
            World to camera translation (``tvec``).
        width, height : int
            The image's size in pixels, K's.
        near : float
            The near clip plane's distance along the optical axis, > 0.
        far : float or None
            The far clip plane's, > near; None: none.

        Returns
        -------
        Camera
            With a fixed projection: a render at another size of the same aspect sees the same
            view, scaled.

        Raises
        ------
        ValueError
            For a K that is not an upper-triangular camera matrix with positive focal lengths,
            an R that is not a rotation, or out-of-range sizes and planes.
        """
        w = integer(width, "width", 1, _glshade.MAX_SIZE)
        h = integer(height, "height", 1, _glshade.MAX_SIZE)
        return cls._built(opencv_view(R, t), opencv_lens(K, w, h, near, far))

    @classmethod
    def from_pyrender(cls, camera: Any, pose: ArrayLike | None = None) -> Camera:
        """A pyrender camera as pyrender renders it: ``PerspectiveCamera``,
        ``OrthographicCamera`` or ``IntrinsicsCamera`` (whose fx, fy, cx, cy pyrender measures
        from the image's corner, half a pixel from OpenCV's centres), with its node's pose.

        Parameters
        ----------
        camera : pyrender camera or pyrender.Node
            The camera, or a node holding one (its pose is then the node's matrix).
        pose : (4, 4) float, optional
            Camera to world, as ``scene.add(camera, pose=pose)`` takes it; required for a
            camera, not given with a node.

        Returns
        -------
        Camera

        Raises
        ------
        TypeError
            For another object, or a camera without a pose.
        """
        if hasattr(camera, "camera") and hasattr(camera, "matrix"):  # a pyrender.Node
            if pose is not None:
                raise TypeError("a pyrender.Node carries its own pose: give no pose with it")
            camera, pose = camera.camera, camera.matrix
        lens = pyrender_lens(camera)
        if pose is None:
            raise TypeError("a pyrender camera needs its pose (camera to world, 4 x 4)")
        return cls._built(pose_view(pose), lens)

    @classmethod
    def from_trimesh(cls, scene: Any) -> Camera:
        """A ``trimesh.Scene``'s camera (``scene.camera``, placed by
        ``scene.camera_transform``), as trimesh's viewer and ``scene.camera_rays()`` see: the
        rays through the centres of its ``camera.resolution`` pixels pass through the same
        pixel centres of a render at that size.

        Parameters
        ----------
        scene : trimesh.Scene

        Returns
        -------
        Camera
        """
        if not (hasattr(scene, "camera") and hasattr(scene, "camera_transform")):
            raise TypeError(f"scene must be a trimesh.Scene, got {type(scene)!r}")
        return cls._built(pose_view(scene.camera_transform), trimesh_lens(scene.camera))

    @classmethod
    def orbit(
        cls,
        views: int,
        *,
        target: ArrayLike = (0.0, 0.0, 0.0),
        distance: float = 3.0,
        elevation: float = 20.0,
        up: ArrayLike = (0.0, 1.0, 0.0),
        fovy: float = 45.0,
        aspect: float | None = None,
        near: float = 0.1,
        far: float = 100.0,
    ) -> list[Camera]:
        """`views` perspective cameras on a circle around `target`, for a turntable: view i at
        azimuth 360 i / views degrees (0 on the +z side, turning counter-clockwise about `up`
        seen from above), `elevation` degrees above the plane through `target` normal to `up`,
        at `distance`, each looking at `target` with `up` up.

        Parameters
        ----------
        views : int
            How many cameras, 1 to 65536.
        target : (3,) float, default: (0.0, 0.0, 0.0)
            The point they circle and look at.
        distance : float, default: 3.0
            From `target` to each eye, > 0.
        elevation : float, default: 20.0
            Degrees above the plane normal to `up`, in (-90, 90).
        up : (3,) float, default: (0.0, 1.0, 0.0)
            The turntable's axis, and the direction each camera has up; nonzero.
        fovy : float, default: 45.0
            As for `look_at`.
        aspect : float, optional
            As for `look_at`.
        near : float, default: 0.1
            As for `look_at`.
        far : float, default: 100.0
            As for `look_at`.

        Returns
        -------
        list of Camera
            ``len(views)`` cameras; `render` takes the list and returns (views, H, W, 4).
        """
        k = integer(views, "views", 1, 1 << 16)
        centre, axis = _point(target, "target"), real(up, "up")
        if axis.shape != (3,) or not np.isfinite(axis).all() or not axis.any():
            raise ValueError(f"up must be a nonzero finite (3,) vector, got {axis.tolist()}")
        axis = axis / np.linalg.norm(axis)
        # Azimuth 0 lies towards +z (or +x when up is along z), projected off the axis.
        ahead = np.array([0.0, 0.0, 1.0]) if abs(axis[2]) < 0.9 else np.array([1.0, 0.0, 0.0])
        ahead = ahead - axis * (ahead @ axis)
        ahead /= np.linalg.norm(ahead)
        side = np.cross(axis, ahead)
        d, lift = number(distance, "distance"), np.radians(number(elevation, "elevation"))
        if not 0 < d < np.inf or not abs(lift) < np.pi / 2:
            raise ValueError(f"distance must be > 0 and |elevation| < 90, got {d:g}, {elevation}")
        cameras = []
        for i in range(k):
            turn = 2 * np.pi * i / k
            way = np.cos(lift) * (np.cos(turn) * ahead + np.sin(turn) * side) + np.sin(lift) * axis
            eye = centre + d * way
            camera = cls.look_at(eye, centre, axis, fovy=fovy, aspect=aspect, near=near, far=far)
            cameras.append(camera)
        return cameras

    @property
    def view(self) -> Float64Array:
        """(4, 4) float64: world to eye coordinates."""
        return self._view

    @property
    def pose(self) -> Float64Array:
        """(4, 4) float64: camera to world, the inverse of `view` (OpenGL's and pyrender's camera
        pose: the eye in the last column, the camera's right, up and backward axes before)."""
        pose = np.linalg.inv(self._view).astype(np.float64)
        pose[3] = (0.0, 0.0, 0.0, 1.0)
        return pose

    @property
    def eye(self) -> Float64Array:
        """(3,) float64: where the camera is, in world coordinates."""
        eye: Float64Array = self.pose[:3, 3]
        return eye

    @property
    def target(self) -> Float64Array:
        """(3,) float64: the point the camera was aimed at (`look_at`'s `target`), or for a
        camera made otherwise the point one unit ahead of the eye along the view axis."""
        if self._target is not None:
            return self._target.copy()
        pose = self.pose
        ahead: Float64Array = pose[:3, 3] - pose[:3, 2]
        return ahead

    @property
    def up(self) -> Float64Array:
        """(3,) float64: the camera's up axis in world coordinates (unit length for a rigid
        view; `look_at`'s `up` made orthogonal to the view axis)."""
        up: Float64Array = self.pose[:3, 1]
        return up

    @property
    def fovy(self) -> float | None:
        """The vertical field of view in degrees, top to bottom of the image (for an off-centre
        projection, OpenCV's say, the sum of its two halves); None for an orthographic camera
        and for pyrender's ``IntrinsicsCamera``, whose field the image's height decides."""
        kind, *parameters = self._lens
        if kind == "perspective":
            return float(parameters[0])
        if kind != "projection" or parameters[0][3, 2] == 0:
            return None
        p = parameters[0]
        top, bottom = (1 + p[1, 2]) / p[1, 1], (1 - p[1, 2]) / p[1, 1]
        return float(np.degrees(np.arctan(top) + np.arctan(bottom)))

    @property
    def projection(self) -> Float64Array | None:
        """(4, 4) float64: the projection, when it does not depend on the image's size (a
        camera of its own matrix, an aspect, or OpenCV's K); None when it takes the image's
        aspect: then `projection_matrix(width, height)`."""
        kind, *parameters = self._lens
        if kind == "projection" or (kind in ("perspective", "orthographic") and parameters[1]):
            return self.projection_matrix(1, 1)
        return None

    def projection_matrix(self, width: int, height: int) -> Float64Array:
        """The (4, 4) float64 projection for an image of `width` x `height` pixels (which sets
        the aspect ratio of a camera built without one).

        Parameters
        ----------
        width : int
            The image's width in pixels.
        height : int
            The image's height in pixels.

        Returns
        -------
        (4, 4) float64 ndarray
            The camera's own matrix for a camera built from one; otherwise gluPerspective's or
            glOrtho's, with the aspect ratio ``width / height`` unless the camera has its own.

        Raises
        ------
        TypeError, ValueError
            For a width or height that is not an integer from 1 to 16384.
        """
        w = integer(width, "width", 1, _glshade.MAX_SIZE)
        h = integer(height, "height", 1, _glshade.MAX_SIZE)
        kind, *parameters = self._lens
        if kind == "projection":
            fixed: Float64Array = parameters[0]
            return fixed
        if kind == "intrinsics":
            return intrinsics_projection(self._lens, w, h)
        size, aspect, near, far = parameters
        a = w / h if aspect is None else aspect
        if kind == "perspective":
            if far == np.inf:
                return infinite_perspective(size, a, near)
            return _glshade.perspective(size, a, near, far)
        half_width = 0.5 * size * a
        return _glshade.orthographic(-half_width, half_width, -0.5 * size, 0.5 * size, near, far)

    def __repr__(self) -> str:
        kind, *parameters = self._lens
        if kind == "projection":
            lens = "projection=..."
        elif kind == "intrinsics":
            fx, fy, cx, cy, near, far = parameters
            lens = f"from_pyrender(fx={fx:g}, fy={fy:g}, cx={cx:g}, cy={cy:g}, near={near:g}, "
            lens += f"far={far})"
        else:
            size, aspect, near, far = parameters
            name = "fovy" if kind == "perspective" else "height"
            method = "look_at" if kind == "perspective" else "look_at_orthographic"
            lens = f"{method}({name}={size:g}, aspect={aspect}, near={near:g}, far={far:g})"
        return f"Camera({lens}, view={self._view.tolist()})"
