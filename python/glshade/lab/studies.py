"""Numerical studies behind the documentation's numbers (the Area lights and Meshes and
rendering pages, docs/pages/guide/area-lights.md and rendering.md); `gs.report` runs two of them.

Each study is one self-contained function returning rows of plain numbers.
"""

from __future__ import annotations

import functools
from collections.abc import Iterable, Sequence
from typing import Any

import numpy as np

import glshade as gs

from ..meshes import icosphere
from .timing import time_rounds

__all__ = ["area_light_closed_form", "area_light_convergence", "gouraud_vs_phong"]


def _area_light_scene(k: int) -> gs.Scene:
    """A 1 x 0.5 Lambertian panel 0.6 above a floor, facing it, with 1/d^2 attenuation; a glossy
    floor material and a local viewer, so the highlight makes the integrand sharp."""
    panel = gs.rectangle_light(
        center=(0.0, 0.6, 0.0),
        u=(1.0, 0.0, 0.0),
        v=(0.0, 0.0, 0.5),  # u x v points down, at the floor
        k=k,
        diffuse=(0.2, 0.2, 0.16),
        specular=(0.12, 0.12, 0.12),
        constant_attenuation=0.0,
        quadratic_attenuation=1.0,
        emission="lambertian",
    )
    floor = gs.Material(
        ambient=(0.0, 0.0, 0.0), diffuse=(0.8, 0.7, 0.6), specular=(0.5, 0.5, 0.5), shininess=24
    )
    return gs.Scene(lights=panel, material=floor, global_ambient=(0, 0, 0), viewer=(0, 2, 3, 1))


def area_light_convergence(
    ks: Sequence[int] = (1, 4, 16, 64, 256, 1024),
    reference_k: int = 16384,
    *,
    grid: int = 64,
    repeat: int = 5,
) -> list[dict[str, float]]:
    """Error and cost of a rectangle light sampled by k point lights, against a large k.

    The scene: a 1 x 0.5 Lambertian panel 0.6 above a floor of ``grid x grid`` vertices on
    [-1.5, 1.5]^2, inverse-square attenuation, Blinn specular with shininess 24, a local viewer;
    shaded in float64. The reference is the same light with `reference_k` points.

    Parameters
    ----------
    ks : sequence of int
        The sample counts to measure.
    reference_k : int
        The sample count of the converged answer.
    grid : int
        Vertices per side of the floor.
    repeat : int
        Timed rounds (`timing.time_rounds`, all k in each round); the median is reported.

    Returns
    -------
    list of dict
        One row per k: ``k``, ``max_error`` and ``mean_error`` (over the RGB channels of every
        vertex, against the reference), ``ms`` (the median time of one `shade` call) and
        ``ms_low``, ``ms_high`` (the fastest and slowest round).
    """
    if grid < 1 or repeat < 1 or reference_k < 1:
        raise ValueError(
            f"grid, repeat and reference_k must be >= 1, got {grid}, {repeat}, {reference_k}"
        )
    side = np.linspace(-1.5, 1.5, grid)
    x, z = np.meshgrid(side, side)
    positions = np.stack([x.ravel(), np.zeros(x.size), z.ravel()], axis=1)
    normals = np.tile([0.0, 1.0, 0.0], (len(positions), 1))
    reference = gs.shade(positions, normals, _area_light_scene(reference_k))[:, :3]
    outs = {k: np.zeros((len(positions), 4)) for k in ks}
    calls = {
        str(k): functools.partial(gs.shade, positions, normals, _area_light_scene(k), out=outs[k])
        for k in ks
    }
    timings = time_rounds(calls, repeat)  # the warm-up call fills `outs`
    rows: list[dict[str, float]] = []
    for k in ks:
        error = np.abs(outs[k][:, :3] - reference)
        t = timings[str(k)]
        rows.append(
            {
                "k": k,
                "max_error": float(error.max()),
                "mean_error": float(error.mean()),
                "ms": t.median * 1e3,
                "ms_low": t.low * 1e3,
                "ms_high": t.high * 1e3,
            }
        )
    return rows


def _on_axis(lights: gs.Lights, h: float) -> float:
    """The diffuse of a white, unit-normal vertex h below `lights` (at y = 0), facing them."""
    white = gs.Material(ambient=(0, 0, 0), diffuse=(1, 1, 1), specular=(0, 0, 0))
    scene = gs.Scene(lights=lights, material=white, global_ambient=(0, 0, 0))
    return float(gs.shade([[0.0, -h, 0.0]], [[0.0, 1.0, 0.0]], scene)[0, 0])


def area_light_closed_form(
    ks: Sequence[int] = (64, 89, 144, 987, 1024, 4096, 4181),
) -> list[dict[str, float]]:
    """Relative error of sampled area lights against the closed-form irradiance.

    Isotropic points of total colour 1 with ``1/d^2`` attenuation light a vertex on the axis,
    h = 0.7 below, facing them: the exact answer is the light's solid angle over its area,
    ``4 atan(ab / (h sqrt(a^2 + b^2 + h^2))) / (4ab)`` for a 1 x 0.5 rectangle (a = 0.5,
    b = 0.25) and ``2 pi (1 - h / sqrt(R^2 + h^2)) / (pi R^2)`` for a disc of radius R = 0.6.
    The colour is 0.25 so that nothing clamps.

    Parameters
    ----------
    ks : sequence of int
        The numbers of point lights to sample each light with.

    Returns
    -------
    list of dict
        One row per k: ``k``, ``rectangle`` and ``disc`` (signed relative errors).
    """
    h, a, b, radius, c = 0.7, 0.5, 0.25, 0.6, 0.25
    light: dict[str, Any] = {
        "diffuse": (c, c, c),
        "constant_attenuation": 0.0,
        "quadratic_attenuation": 1.0,
    }
    exact_rectangle = c * np.arctan(a * b / (h * np.sqrt(a**2 + b**2 + h**2))) / (a * b)
    exact_disc = c * 2.0 * (1.0 - h / np.hypot(radius, h)) / radius**2
    rows: list[dict[str, float]] = []
    for k in ks:
        rectangle = gs.rectangle_light((0, 0, 0), (2 * a, 0, 0), (0, 0, 2 * b), k, **light)
        disc = gs.disc_light((0, 0, 0), (0, -1, 0), radius, k, **light)
        rows.append(
            {
                "k": k,
                "rectangle": _on_axis(rectangle, h) / exact_rectangle - 1.0,
                "disc": _on_axis(disc, h) / exact_disc - 1.0,
            }
        )
    return rows


def _levels8(c: Any) -> Any:
    """The 8-bit values of colours in [0, 1], as a PNG stores them."""
    return np.round(np.clip(c, 0, 1) * 255)


def gouraud_vs_phong(
    subdivisions: Iterable[int] = (1, 2, 3, 4, 5), size: int = 512, repeat: int = 5
) -> list[dict[str, Any]]:
    """Gouraud against Phong shading of a unit icosphere, one row per tessellation level.

    The sphere (exact normals: the unit positions) is lit by a white directional light with a
    highlight of shininess 64 (material diffuse 0.7, specular 1) and rendered at `size` x `size`
    in float32 with both shadings, each timed as the median of `repeat` rounds (every render
    once per round, `timing.time_rounds`). Gouraud's error follows s * delta^2 / 8 for a
    highlight across an edge whose normals differ by delta (cos^s has curvature s at its peak):
    it falls fourfold with each subdivision, halving delta.

    Parameters
    ----------
    subdivisions : iterable of int
        Icosphere levels: 20 * 4**k triangles.
    size : int
        Image width and height in pixels.
    repeat : int
        Timed rounds.

    Returns
    -------
    list of dict
        Per level: ``triangles``; ``edge_degrees``, the largest angle between the normals at
        the ends of an edge; ``max_error`` and ``mean_error``, of |Gouraud - Phong| over the
        RGB channels of the pixels both draw; ``levels8_wrong``, the fraction of those channels
        whose 8-bit value differs; ``gouraud_ms`` and ``phong_ms``, the median render times.
    """
    scene = gs.Scene(
        lights=[gs.Light(position=(1.0, 1.5, 2.0, 0.0))],
        material=gs.Material(diffuse=(0.7, 0.7, 0.7), specular=(1, 1, 1), shininess=64),
        global_ambient=(0.1, 0.1, 0.1),
    )
    camera = gs.Camera.look_at((0.0, 0.0, 3.2), fovy=45, near=1, far=10)
    levels = list(subdivisions)
    calls, facts = {}, {}
    for level in levels:
        v, f = icosphere(level)
        edges = np.concatenate([f[:, [0, 1]], f[:, [1, 2]], f[:, [2, 0]]])
        cosines = np.einsum("ij,ij->i", v[edges[:, 0]], v[edges[:, 1]])
        facts[level] = (len(f), float(np.degrees(np.arccos(np.clip(cosines.min(), -1, 1)))))
        v32 = v.astype(np.float32)
        for shading in ("gouraud", "phong"):
            calls[f"{level} {shading}"] = functools.partial(
                gs.render,
                v32,
                f,
                scene,
                camera,
                width=size,
                height=size,
                shading=shading,
                normals=v32,
                depth=True,
            )
    times = time_rounds(calls, repeat)
    rows = []
    for level in levels:
        (gouraud, gouraud_depth), (phong, phong_depth) = (
            calls[f"{level} {shading}"]() for shading in ("gouraud", "phong")
        )
        both = (gouraud_depth < 1) & (phong_depth < 1)
        g, p = np.asarray(gouraud)[both][:, :3], np.asarray(phong)[both][:, :3]
        error = np.abs(g.astype(np.float64) - p)
        triangles, edge_degrees = facts[level]
        rows.append(
            {
                "triangles": triangles,
                "edge_degrees": edge_degrees,
                "max_error": float(error.max()),
                "mean_error": float(error.mean()),
                "levels8_wrong": float((_levels8(g) != _levels8(p)).mean()),
                "gouraud_ms": times[f"{level} gouraud"].median * 1e3,
                "phong_ms": times[f"{level} phong"].median * 1e3,
            }
        )
    return rows
