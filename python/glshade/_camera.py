"""`Camera`: GL's view and projection matrices, explicit or built like gluLookAt, gluPerspective
and glOrtho."""

from __future__ import annotations

from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from . import _glshade
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

    __slots__ = ("_lens", "_view")
    _lens: tuple[Any, ...]

    def __init__(self, view: ArrayLike | None = None, projection: ArrayLike | None = None) -> None:
        self._view = transform(view, "view")
        self._lens = ("projection", transform(projection, "projection"))

    @classmethod
    def _built(cls, view: Float64Array, lens: tuple[Any, ...]) -> Camera:
        """A camera of `view` and `lens`: ("projection", matrix), ("perspective", fovy, aspect,
        near, far) or ("orthographic", height, aspect, near, far), aspect None for the image's."""
        camera = cls(view)
        if lens[0] == "projection":  # read-only again after a pickle's round trip
            lens = ("projection", transform(lens[1], "projection"))
        camera._lens = lens
        camera.projection_matrix(1, 1)  # checks the parameters now rather than at the first render
        return camera

    def __reduce__(self) -> tuple[Any, ...]:
        return (Camera._built, (self._view, self._lens))

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
        view = _glshade.look_at(_point(eye, "eye"), _point(target, "target"), _point(up, "up"))
        f, n, z = number(fovy, "fovy"), number(near, "near"), number(far, "far")
        return cls._built(view, ("perspective", f, _aspect(aspect), n, z))

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
        view = _glshade.look_at(_point(eye, "eye"), _point(target, "target"), _point(up, "up"))
        h, n, z = number(height, "height"), number(near, "near"), number(far, "far")
        if not 0 < h < np.inf:
            raise ValueError(f"height must be finite and > 0, got {h:g}")
        return cls._built(view, ("orthographic", h, _aspect(aspect), n, z))

    @property
    def view(self) -> Float64Array:
        """(4, 4) float64: world to eye coordinates."""
        return self._view

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
        size, aspect, near, far = parameters
        a = w / h if aspect is None else aspect
        if kind == "perspective":
            return _glshade.perspective(size, a, near, far)
        half_width = 0.5 * size * a
        return _glshade.orthographic(-half_width, half_width, -0.5 * size, 0.5 * size, near, far)

    def __repr__(self) -> str:
        kind, *parameters = self._lens
        if kind == "projection":
            lens = "projection=..."
        else:
            size, aspect, near, far = parameters
            name = "fovy" if kind == "perspective" else "height"
            method = "look_at" if kind == "perspective" else "look_at_orthographic"
            lens = f"{method}({name}={size:g}, aspect={aspect}, near={near:g}, far={far:g})"
        return f"Camera({lens}, view={self._view.tolist()})"
