"""Area lights as the lecture (document 004) builds them: the sum of many point lights.

A rectangle or a disc is sampled by k point lights at deterministic, stratified points, and the
light's colours are split evenly among them, so the k lights together carry the colour given.
"""

from __future__ import annotations

import operator
from typing import Literal

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ._intake import colors_checked, one_of
from ._params import rgb, scalar, vector3, warn_bytes
from ._scene import Lights
from ._typing import Float64Array

__all__ = ["disc_light", "rectangle_light"]

Emission = Literal["uniform", "lambertian"]

# 1/φ: the Kronecker step with the lowest discrepancy in one dimension (the Fibonacci lattice).
_GOLDEN = (np.sqrt(5.0) - 1.0) / 2.0


def _count(k: int) -> int:
    if isinstance(k, (bool, np.bool_)):
        raise TypeError(f"k must be an integer >= 1, got {k!r}")
    try:
        count = operator.index(k)
    except TypeError:
        raise TypeError(f"k must be an integer >= 1, got {k!r}") from None
    if count < 1:
        raise ValueError(f"k must be an integer >= 1, got {count}")
    return count


def lattice(k: int) -> Float64Array:
    """(k, 2) points of the unit square: ``((i + 1/2)/k, frac(1/2 + i/φ))``, a Fibonacci lattice.

    Stratified in x (one point per column of width 1/k), well spread in y for every k, and
    ``(1/2, 1/2)`` for k = 1, so one sample is the centre.
    """
    i = np.arange(k, dtype=np.float64)
    return np.stack([(i + 0.5) / k, np.mod(0.5 + i * _GOLDEN, 1.0)], axis=1)


def concentric_disc(square: Float64Array) -> Float64Array:
    """Shirley and Chiu's concentric map of [0, 1]^2 onto the unit disc: area-preserving, so
    equal weights stay right, and the square's centre maps to the disc's centre."""
    a = 2.0 * square[:, 0] - 1.0
    b = 2.0 * square[:, 1] - 1.0
    wide = np.abs(a) > np.abs(b)
    r = np.where(wide, a, b)
    with np.errstate(divide="ignore", invalid="ignore"):
        phi = np.where(wide, (np.pi / 4) * (b / a), np.pi / 2 - (np.pi / 4) * (a / b))
    phi = np.where(r == 0.0, 0.0, phi)
    return np.stack([r * np.cos(phi), r * np.sin(phi)], axis=1)


def _lights(
    points: NDArray[np.float64],
    normal: NDArray[np.float64],
    colours: tuple[ArrayLike, ArrayLike, ArrayLike],
    attenuation: tuple[float, float, float],
    emission: object,
    owner: str,
) -> Lights:
    """k point lights at `points` sharing the (ambient, diffuse, specular) `colours` evenly, with
    GL's (k0, k1, k2) `attenuation`; `owner` (the function called) is named by the warning for
    colours that look like 0-255 bytes."""
    mode = one_of(emission, "emission", ("uniform", "lambertian"))
    k = len(points)
    given = {
        name: rgb(value, name, alpha=True)
        for name, value in zip(("ambient", "diffuse", "specular"), colours, strict=True)
    }
    share = []
    for c in given.values():
        part = c.copy()
        part[:3] /= k  # alpha is not a power: GL ignores a light's alpha
        share.append(part)
    k0, k1, k2 = (
        scalar(a, name, 0.0)
        for a, name in zip(
            attenuation,
            ("constant_attenuation", "linear_attenuation", "quadratic_attenuation"),
            strict=True,
        )
    )
    # GL's spot factor with a 90° cutoff and exponent 1 is max(cos θ, 0) from the normal.
    lambertian = mode == "lambertian"
    # The k lights each carry 1/k of the colour: they warn about the whole light's, below.
    with colors_checked():
        lights = Lights(
            position=np.c_[points, np.ones(k)],
            ambient=share[0],
            diffuse=share[1],
            specular=share[2],
            constant_attenuation=k0,
            linear_attenuation=k1,
            quadratic_attenuation=k2,
            spot_direction=normal if lambertian else (0.0, 0.0, -1.0),
            spot_cutoff=90.0 if lambertian else 180.0,
            spot_exponent=1.0 if lambertian else 0.0,
        )
    # As `Lights` decides: an attenuated light's colour is an intensity, not bytes.
    if (k0, k1, k2) == (1.0, 0.0, 0.0):
        warn_bytes(given, owner)
    return lights


def rectangle_light(
    center: ArrayLike,
    u: ArrayLike,
    v: ArrayLike,
    k: int,
    *,
    diffuse: ArrayLike = (1.0, 1.0, 1.0),
    specular: ArrayLike = (1.0, 1.0, 1.0),
    ambient: ArrayLike = (0.0, 0.0, 0.0),
    constant_attenuation: float = 1.0,
    linear_attenuation: float = 0.0,
    quadratic_attenuation: float = 0.0,
    emission: Emission = "uniform",
) -> Lights:
    """A rectangular area light sampled by `k` point lights.

    Parameters
    ----------
    center : (3,) float
        The rectangle's centre, eye coordinates.
    u, v : (3,) float
        Its two edges: the rectangle is ``center + s u + t v`` for s, t in [-1/2, 1/2]. They
        need not be orthogonal (a parallelogram), only independent.
    k : int
        The number of point lights, >= 1; they sit at the Fibonacci lattice
        ``s = (i + 1/2)/k - 1/2``, ``t = frac(1/2 + i/φ) - 1/2`` (k = 1: the centre).
    diffuse : (3,) or (4,) float
        The whole light's diffuse colour, numbers in [0, 1] (uint8 is divided by 255; a name
        such as ``"white"`` is refused); each point light gets 1/k of the RGB.
    specular : (3,) or (4,) float
        The whole light's specular colour, shared the same way.
    ambient : (3,) or (4,) float
        The whole light's ambient colour, shared the same way.
    constant_attenuation : float
        Each point light's k0 (GL's attenuation ``1 / (k0 + k1 d + k2 d^2)``, from that point).
    linear_attenuation : float
        Each point light's k1.
    quadratic_attenuation : float
        Each point light's k2.
    emission : {"uniform", "lambertian"}
        ``"uniform"``: each point shines equally in all directions (the lecture's sum of point
        lights). ``"lambertian"``: each is weighted by ``max(cos θ, 0)`` from the normal
        ``cross(u, v)`` (GL's spot factor with a 90° cutoff and exponent 1): a one-sided panel.
        Either name in any case (``"Lambertian"``).

    Returns
    -------
    Lights
        k positional lights, built from arrays.

    Raises
    ------
    ValueError, TypeError
        For a bad shape, ``u`` parallel to ``v``, k < 1, or a bad colour or attenuation,
        naming the argument; a colour given by name (the message gives its numbers).

    Warns
    -----
    ColorRangeWarning
        For a colour of an unattenuated light (the default attenuation) that looks like 0-255
        bytes: every value a whole number in [0, 255], the largest 16 or more.
    """
    count = _count(k)
    c = vector3(center, "center")
    eu = vector3(u, "u", nonzero=True)
    ev = vector3(v, "v", nonzero=True)
    normal = np.cross(eu, ev)
    if not np.any(normal):
        raise ValueError(f"u and v must not be parallel, got u={u!r}, v={v!r}")
    st = lattice(count) - 0.5
    points = c + st[:, :1] * eu + st[:, 1:] * ev
    attenuation = (constant_attenuation, linear_attenuation, quadratic_attenuation)
    return _lights(
        points, normal, (ambient, diffuse, specular), attenuation, emission, "rectangle_light"
    )


def disc_light(
    center: ArrayLike,
    normal: ArrayLike,
    radius: float,
    k: int,
    *,
    diffuse: ArrayLike = (1.0, 1.0, 1.0),
    specular: ArrayLike = (1.0, 1.0, 1.0),
    ambient: ArrayLike = (0.0, 0.0, 0.0),
    constant_attenuation: float = 1.0,
    linear_attenuation: float = 0.0,
    quadratic_attenuation: float = 0.0,
    emission: Emission = "uniform",
) -> Lights:
    """A disc-shaped area light sampled by `k` point lights.

    Parameters
    ----------
    center : (3,) float
        The disc's centre, eye coordinates.
    normal : (3,) float
        The disc's normal (any nonzero length); the disc lies in the plane it defines.
    radius : float
        > 0.
    k : int
        The number of point lights, >= 1: the Fibonacci lattice of `rectangle_light` carried
        onto the disc by Shirley and Chiu's area-preserving concentric map (k = 1: the centre).
    diffuse : (3,) or (4,) float
        As in `rectangle_light`.
    specular : (3,) or (4,) float
        As in `rectangle_light`.
    ambient : (3,) or (4,) float
        As in `rectangle_light`.
    constant_attenuation : float
        As in `rectangle_light`.
    linear_attenuation : float
        As in `rectangle_light`.
    quadratic_attenuation : float
        As in `rectangle_light`.
    emission : {"uniform", "lambertian"}
        As in `rectangle_light`, with `normal` as the direction the panel faces.

    Returns
    -------
    Lights
        k positional lights, built from arrays.

    Raises
    ------
    ValueError, TypeError
        As `rectangle_light`, and for a zero `normal` or a `radius` <= 0.

    Warns
    -----
    ColorRangeWarning
        As `rectangle_light`.
    """
    count = _count(k)
    c = vector3(center, "center")
    n = vector3(normal, "normal", nonzero=True)
    r = scalar(radius, "radius")
    if r <= 0:
        raise ValueError(f"radius must be > 0, got {r:g}")
    n_hat = n / np.linalg.norm(n)
    # Any unit vector across n̂: the cross product with the axis least aligned with it.
    e1 = np.cross(n_hat, np.eye(3)[int(np.argmin(np.abs(n_hat)))])
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(n_hat, e1)
    xy = concentric_disc(lattice(count)) * r
    points = c + xy[:, :1] * e1 + xy[:, 1:] * e2
    attenuation = (constant_attenuation, linear_attenuation, quadratic_attenuation)
    return _lights(points, n, (ambient, diffuse, specular), attenuation, emission, "disc_light")
