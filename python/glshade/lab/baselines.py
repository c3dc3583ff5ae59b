"""The GL equation transcribed once in numpy, in any float dtype, and compiled by numba: the
baselines of ``python -m glshade bench shade`` and, evaluated in long double with a stable
power, the reference of the report.

The baselines are what a user writes today: the GL equation (Blinn, GL's specular gate, one
side) with a new RGBA array per call, numpy vectorised over vertices with a Python loop over
lights, and numba compiled with ``parallel=True`` (a ``prange`` over vertices, all cores). Both
read the scene through one light table (`light_table`, its columns named below) and normalise
directional lights once, as glshade does; the tests check that both agree with `gs.shade`.

The conventions are glshade's where GL says "undefined" (the documentation's Conventions page,
docs/pages/guide/conventions.md): a light at the vertex gives
VP = 0, a zero halfway vector no specular (0^0 = 1 for shininess 0), cos 90 deg = 0 exactly, an
infinite weight times a zero colour nothing, and a non-finite input that is read makes its row
NaN.
"""

from __future__ import annotations

import os
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray

import glshade as gs

__all__ = [
    "Evaluation",
    "constants",
    "equation",
    "light_table",
    "naive_power",
    "numba_shade",
    "numpy_shade",
    "stable_power",
]

F32 = NDArray[np.float32]
Power = Callable[[NDArray[Any], NDArray[Any], Any], NDArray[Any]]

# The columns of `light_table`, one row per light; numba reads the same integers.
W = 3  # position x, y, z in 0..2 (unit for directional lights, divided by w otherwise), w
AMBIENT, DIFFUSE, SPECULAR = 4, 7, 10  # a_cm·a_cl, d_cm·d_cl, s_cm·s_cl (RGB each)
SPOT = 13  # the unit spot direction (3)
SPOT_EXPONENT, COS_CUTOFF = 16, 17  # cos cutoff: -2 for no cone (180), exactly 0 for 90
K0, K1, K2 = 18, 19, 20  # constant, linear, quadratic attenuation
# The columns of `constants`.
BASE, ALPHA, SHININESS, VIEWER = 0, 3, 4, 5  # e_cm + a_cm·a_cs (RGB), alpha, s, viewer (xyzw)


def light_table(scene: gs.Scene, dtype: Any = np.float32) -> NDArray[Any]:
    """The scene's lights, one row per light, computed in `dtype` (columns: the constants above)."""
    lights, m = scene.lights, scene.material

    def col(a: Any) -> NDArray[Any]:
        return np.asarray(a).astype(dtype)

    position = col(lights.position)
    directional = position[:, 3] == 0
    xyz = position[:, :3]
    xyz[directional] /= np.sqrt((xyz[directional] ** 2).sum(axis=1, keepdims=True))
    xyz[~directional] /= position[~directional, 3:]
    spot = col(lights.spot_direction)
    spot /= np.sqrt((spot**2).sum(axis=1, keepdims=True))
    cutoff = np.asarray(lights.spot_cutoff)
    cos_cutoff = np.where(cutoff == 180.0, -2.0, np.cos(np.radians(cutoff)))
    cos_cutoff = np.where(cutoff == 90.0, 0.0, cos_cutoff)  # exactly, as the spec's cos 90
    return np.column_stack(
        [
            position,
            col(lights.ambient)[:, :3] * col(m.ambient)[:3],
            col(lights.diffuse)[:, :3] * col(m.diffuse)[:3],
            col(lights.specular)[:, :3] * col(m.specular)[:3],
            spot,
            col(lights.spot_exponent),
            col(cos_cutoff),
            col(lights.constant_attenuation),
            col(lights.linear_attenuation),
            col(lights.quadratic_attenuation),
        ]
    )


def constants(scene: gs.Scene, dtype: Any = np.float32) -> NDArray[Any]:
    """e_cm + a_cm·a_cs (RGB), the diffuse alpha, the shininess, the viewer (xyzw), in `dtype`."""
    m = scene.material
    e, a, g = (
        np.asarray(c).astype(dtype)[:3] for c in (m.emission, m.ambient, scene.global_ambient)
    )
    rest = np.asarray([m.diffuse[3], m.shininess, *scene.viewer]).astype(dtype)
    return np.concatenate([e + a * g, rest])


def naive_power(normals: NDArray[Any], h: NDArray[Any], s: Any) -> NDArray[Any]:
    """max(n . h, 0)^s, as a shader writes it."""
    power: NDArray[Any] = np.maximum(np.einsum("ij,ij->i", normals, h), 0)[:, None] ** s
    return power


def stable_power(normals: NDArray[Any], h: NDArray[Any], s: Any) -> NDArray[Any]:
    """(n . h)^s = |n|^s (1 - x)^s with x = |n^ - h|^2 / 2, which has no cancellation near the
    highlight: exp(s (log1p(-x) + log |n|)), 0 where n . h <= 0."""
    length = np.sqrt(np.einsum("ij,ij->i", normals, normals))[:, None]
    d = normals / length - h
    x = np.einsum("ij,ij->i", d, d)[:, None] / 2
    with np.errstate(divide="ignore"):  # x = 1: log 0, then masked
        power = np.exp(s * (np.log1p(-np.minimum(x, 1)) + np.log(length)))
    out: NDArray[Any] = np.where(x < 1, power, 0)
    return out


@dataclass(frozen=True)
class Evaluation:
    """What `equation` computes per vertex: ``rgb``, the unclamped (n, 3) colour; with
    ``account``, per channel ``magnitude`` (the sum of |terms|) and ``sensitivity`` (the sum of
    (s tan theta / min(1, |VP + V|) + e tan phi) |term|, the condition numbers of the specular
    and spot powers times their terms), and per vertex ``edge``, the distance to the nearest
    discontinuity (|n^ . VP| where the specular gate has something to switch, |cos - cos
    cutoff| at a cone's edge), inf where there is none."""

    rgb: NDArray[Any]
    magnitude: NDArray[Any] | None = None
    sensitivity: NDArray[Any] | None = None
    edge: NDArray[Any] | None = None


def _unit(v: NDArray[Any]) -> tuple[NDArray[Any], NDArray[Any]]:
    """v / |v| per row (0 where |v| = 0) and |v| as a column."""
    length = np.sqrt(np.einsum("ij,ij->i", v, v))[:, None]
    return np.divide(v, length, out=np.zeros_like(v), where=length > 0), length


def _times(weight: Any, colour: NDArray[Any]) -> NDArray[Any]:
    """weight · colour per channel, 0 where the colour is 0 (never inf · 0)."""
    if (colour != 0).all():
        out: NDArray[Any] = weight * colour
        return out
    return np.where(colour != 0, weight * colour, 0)


def equation(
    positions: NDArray[Any],
    normals: NDArray[Any],
    scene: gs.Scene,
    power: Power = naive_power,
    *,
    account: bool = False,
) -> Evaluation:
    """The GL equation (eqs. 2.2-2.5: Blinn, GL's specular gate, one side, no clamp) in the
    dtype of `positions`, with `power(n, h^, s)` the specular power for s > 0.

    Parameters
    ----------
    positions, normals : (n, 3) arrays of one float dtype
        Eye-space vertices, normals as given (not normalised).
    scene : Scene
        Its lights, material, global ambient and viewer (other settings are not read).
    power : callable
        ``power(normals, unit_halfway, shininess)`` -> (n, 1).
    account : bool
        Also the magnitudes, sensitivities and distances to a discontinuity (`Evaluation`).
    """
    dtype = positions.dtype
    table, k = light_table(scene, dtype), constants(scene, dtype)
    eye = k[VIEWER : VIEWER + 4]
    view = _unit(eye[:3] / eye[3] - positions)[0] if eye[3] != 0 else _unit(eye[None, :3])[0]
    rgb = np.broadcast_to(k[BASE : BASE + 3], positions.shape).copy()
    shininess = k[SHININESS]
    if account:
        magnitude, sensitivity = np.abs(rgb), np.zeros_like(rgb)
        edge, n_hat = np.full((len(positions), 1), np.inf, dtype), _unit(normals)[0]
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        for row in table:
            weight: Any = dtype.type(1.0)
            spot_condition: Any = 0
            if row[W] == 0:
                vp = np.broadcast_to(row[:3], positions.shape)
            else:
                vp, d = _unit(row[:3] - positions)
                weight = 1 / (row[K0] + row[K1] * d + row[K2] * d * d)
            if row[COS_CUTOFF] > -2:  # a cone, on directional lights too
                c = np.maximum(-(vp @ row[SPOT : SPOT + 3]), 0)[:, None]
                inside = c >= row[COS_CUTOFF]
                weight = weight * np.where(inside, c ** row[SPOT_EXPONENT], 0)
                if account:
                    tan = np.sqrt(np.maximum(1 - c * c, 0)) / c
                    spot_condition = np.where((c > 0) & (c < 1), row[SPOT_EXPONENT] * tan, 0)
                    if row[COS_CUTOFF] ** row[SPOT_EXPONENT] != 0:  # the cone's edge jumps
                        edge = np.minimum(edge, np.abs(c - row[COS_CUTOFF]))
            ambient = _times(weight, row[AMBIENT : AMBIENT + 3])
            n_dot_vp = np.einsum("ij,ij->i", normals, vp)[:, None]
            lit = n_dot_vp > 0
            diffuse = np.where(lit, _times(weight * n_dot_vp, row[DIFFUSE : DIFFUSE + 3]), 0)
            h_hat, h_length = _unit(vp + view)
            specular_colour = row[SPECULAR : SPECULAR + 3]
            if shininess == 0:  # 0^0 = 1, also for a zero halfway vector
                spec_power: Any = np.ones_like(n_dot_vp)
            else:
                spec_power = np.where(h_length > 0, power(normals, h_hat, shininess), 0)
            specular = np.where(lit, _times(weight * spec_power, specular_colour), 0)
            rgb += ambient + diffuse + specular
            if account:
                terms = np.abs(ambient) + np.abs(diffuse) + np.abs(specular)
                magnitude += terms
                cos = np.clip(np.einsum("ij,ij->i", n_hat, h_hat)[:, None], 1e-300, 1)
                # ĥ's direction is as uncertain as u / |VP + V|: L + V near 0 amplifies it.
                tan_theta = np.sqrt(1 - cos * cos) / cos / np.minimum(h_length, 1)
                powered = np.where(specular != 0, shininess * tan_theta * np.abs(specular), 0)
                sensitivity += powered + spot_condition * terms
                if (specular_colour != 0).any():  # the gate has something to switch
                    gate = np.abs(np.einsum("ij,ij->i", n_hat, vp))[:, None]
                    edge = np.minimum(edge, np.where(spec_power * weight > 0, gate, np.inf))
    unread = ~np.isfinite(normals).all(axis=1)
    if eye[3] != 0 or (table[:, W] != 0).any():
        unread |= ~np.isfinite(positions).all(axis=1)
    rgb[unread] = np.nan  # a non-finite input makes its row NaN, and no other row
    if not account:
        return Evaluation(rgb)
    return Evaluation(rgb, magnitude, sensitivity, edge[:, 0])


def numpy_shade(
    positions: NDArray[Any],
    normals: NDArray[Any],
    scene: gs.Scene,
    power: Power = naive_power,
) -> NDArray[Any]:
    """`equation` clamped, as `gs.shade` returns it: (n, 4) in the dtype of `positions`."""
    rgb = equation(positions, normals, scene, power).rgb
    out = np.zeros((len(positions), 4), positions.dtype)
    out[:, :3] = np.clip(rgb, 0, 1)
    out[:, 3] = np.clip(constants(scene, positions.dtype)[ALPHA], 0, 1)
    return out


def numba_shade() -> Callable[[F32, F32, gs.Scene], F32] | str:
    """The same equation as `numpy_shade`, compiled by numba with ``parallel=True``, float32
    throughout; or why numba is not available."""
    # numba's OpenMP threads spin after each parallel loop unless told to sleep, and on a
    # machine with few cores they would take them from whichever method runs next.
    os.environ.setdefault("OMP_WAIT_POLICY", "PASSIVE")
    try:
        import numba
    except ImportError:
        return "numba is not installed (pip install numba): no numba baseline"

    @numba.njit(parallel=True, fastmath=False, cache=False)
    def kernel(p: F32, n: F32, table: F32, k: F32, out: F32) -> None:  # pragma: no cover
        zero, one = np.float32(0.0), np.float32(1.0)
        for i in numba.prange(len(p)):
            px, py, pz = p[i, 0], p[i, 1], p[i, 2]
            nx, ny, nz = n[i, 0], n[i, 1], n[i, 2]
            vx, vy, vz = k[VIEWER], k[VIEWER + 1], k[VIEWER + 2]
            if k[VIEWER + 3] != zero:
                w = k[VIEWER + 3]
                vx, vy, vz = vx / w - px, vy / w - py, vz / w - pz
            length = np.sqrt(vx * vx + vy * vy + vz * vz)
            vx, vy, vz = vx / length, vy / length, vz / length
            r, g, b = k[BASE], k[BASE + 1], k[BASE + 2]
            for j in range(len(table)):
                row = table[j]
                lx, ly, lz = row[0], row[1], row[2]
                weight = one
                if row[W] != zero:
                    lx, ly, lz = lx - px, ly - py, lz - pz
                    d = np.sqrt(lx * lx + ly * ly + lz * lz)
                    lx, ly, lz = lx / d, ly / d, lz / d
                    weight = one / (row[K0] + row[K1] * d + row[K2] * d * d)
                if row[COS_CUTOFF] > np.float32(-2.0):
                    c = -(lx * row[SPOT] + ly * row[SPOT + 1] + lz * row[SPOT + 2])
                    c = max(c, zero)
                    weight = weight * (c ** row[SPOT_EXPONENT] if c >= row[COS_CUTOFF] else zero)
                r += weight * row[AMBIENT]
                g += weight * row[AMBIENT + 1]
                b += weight * row[AMBIENT + 2]
                n_dot_vp = nx * lx + ny * ly + nz * lz
                if n_dot_vp > zero:
                    diffuse = weight * n_dot_vp
                    r += diffuse * row[DIFFUSE]
                    g += diffuse * row[DIFFUSE + 1]
                    b += diffuse * row[DIFFUSE + 2]
                    hx, hy, hz = lx + vx, ly + vy, lz + vz
                    length = np.sqrt(hx * hx + hy * hy + hz * hz)
                    n_dot_h = max((nx * hx + ny * hy + nz * hz) / length, zero)
                    power = n_dot_h ** k[SHININESS] if k[SHININESS] != zero else one
                    specular = weight * power
                    r += specular * row[SPECULAR]
                    g += specular * row[SPECULAR + 1]
                    b += specular * row[SPECULAR + 2]
            out[i, 0] = min(max(r, zero), one)
            out[i, 1] = min(max(g, zero), one)
            out[i, 2] = min(max(b, zero), one)
            out[i, 3] = min(max(k[ALPHA], zero), one)

    def shade(positions: F32, normals: F32, scene: gs.Scene) -> F32:
        out = np.zeros((len(positions), 4), np.float32)
        kernel(positions, normals, light_table(scene), constants(scene), out)
        return out

    return shade
