"""What `render` and `shade_mesh` use when no camera or scene is given: a camera that frames the
mesh's bounds wherever it is, and a default scene of a key light, a dim fill and a material."""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ._camera import Camera
from ._scene import Light, Material, Scene
from ._typing import Float64Array

# The direction from the mesh's centre to the default camera: in front (+z, GL's and trimesh's
# viewing axis), a little to the right and above, the three-quarter view of a product shot.
VIEW_DIRECTION = np.array([0.45, 0.35, 1.0]) / np.linalg.norm([0.45, 0.35, 1.0])
UP = (0.0, 1.0, 0.0)
# The key light comes from the upper left of that view, the fill from the lower right; both
# directional, so the lighting does not depend on the mesh's size or place.
KEY_DIRECTION = (-0.5, 0.8, 0.6)
FILL_DIRECTION = (0.8, -0.3, 0.4)
# The vertical field of view, and how much of the half-angle the bounding sphere takes.
FOVY = 35.0
FILL = 0.95


def bounding_sphere(points: NDArray[Any]) -> tuple[Float64Array, float]:
    """The centre of the finite points' bounding box and the distance from it to the farthest
    point: a sphere holding every point. (0, 0, 0) and 1 when no point is finite; a radius of 0
    (one point) becomes the centre's size / 1000, or 1 at the origin."""
    p = np.asarray(points, np.float64).reshape(-1, 3)
    p = p[np.isfinite(p).all(axis=1)]
    if len(p) == 0:
        return np.zeros(3), 1.0
    centre = 0.5 * (p.min(axis=0) + p.max(axis=0))
    radius = float(np.sqrt(((p - centre) ** 2).sum(axis=1).max()))
    if not radius > 0:
        size = float(np.abs(centre).max())
        radius = size * 1e-3 if size > 0 else 1.0
    return centre, radius


def frame(points: NDArray[Any], aspect: float) -> tuple[Float64Array, Camera]:
    """The default camera for `points` (world coordinates) seen in an image of `aspect` (width
    / height), and its eye: a perspective look_at along `VIEW_DIRECTION` at the bounding
    sphere's centre, from the distance where the sphere fills `FILL` of the narrower half-angle
    of view; near and far planes just outside the sphere."""
    centre, radius = bounding_sphere(points)
    half = math.radians(FOVY) / 2
    half = min(half, math.atan(aspect * math.tan(half)))
    distance = radius / math.sin(FILL * half)
    eye = centre + distance * VIEW_DIRECTION
    near = max(distance - 1.01 * radius, 1e-3 * distance)
    far = distance + 1.01 * radius
    camera = Camera.look_at(eye, centre, UP, fovy=FOVY, near=near, far=far)
    return eye, camera


def default_scene(viewer: tuple[float, float, float, float] = (0.0, 0.0, 0.0, 1.0)) -> Scene:
    """The scene of `render` and `shade_mesh` without one, in world coordinates: a white key
    light from `KEY_DIRECTION`, a dim cool fill from `FILL_DIRECTION` (so the side away from
    the key is not black), a light grey material with a soft highlight, GL's global ambient;
    `viewer` as given (GL's local viewer at the eye by default)."""
    key = Light(
        position=(*KEY_DIRECTION, 0.0), diffuse=(0.85, 0.85, 0.85), specular=(0.35, 0.35, 0.35)
    )
    fill = Light(position=(*FILL_DIRECTION, 0.0), diffuse=(0.2, 0.22, 0.27), specular=(0, 0, 0))
    material = Material(
        ambient=(0.8, 0.8, 0.8), diffuse=(0.8, 0.8, 0.8), specular=(1, 1, 1), shininess=40
    )
    return Scene(
        lights=[key, fill], material=material, global_ambient=(0.2, 0.2, 0.2), viewer=viewer
    )
