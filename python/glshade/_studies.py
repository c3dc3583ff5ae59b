"""Studies for the error-versus-run-time report: how far Gouraud shading is from per-pixel Phong
shading, and what each costs, as a sphere is tessellated more finely."""

from __future__ import annotations

import functools
from collections.abc import Iterable
from typing import Any

import numpy as np

import glshade as gs

from ._demo import median_seconds
from ._meshes import icosphere


def _levels8(c: Any) -> Any:
    """The 8-bit values of colours in [0, 1], as a PNG stores them."""
    return np.round(np.clip(c, 0, 1) * 255)


def gouraud_vs_phong(
    subdivisions: Iterable[int] = (1, 2, 3, 4, 5), size: int = 512, repeat: int = 5
) -> list[dict[str, Any]]:
    """Gouraud against Phong shading of a unit icosphere, one row per tessellation level.

    The sphere (exact normals: the unit positions) is lit by a white directional light with a
    highlight of shininess 64 (material diffuse 0.7, specular 1) and rendered at `size` x `size`
    in float32 with both shadings, each timed as the median of `repeat` renders. Gouraud's error
    follows s * delta^2 / 8 for a highlight across an edge whose normals differ by delta
    (notes/numerics.md section 5): it falls fourfold with each subdivision, which halves delta.

    Parameters
    ----------
    subdivisions : iterable of int
        Icosphere levels: 20 * 4**k triangles.
    size : int
        Image width and height in pixels.
    repeat : int
        Renders per timing.

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
    rows = []
    for level in subdivisions:
        v, f = icosphere(level)
        edges = np.concatenate([f[:, [0, 1]], f[:, [1, 2]], f[:, [2, 0]]])
        cosines = np.einsum("ij,ij->i", v[edges[:, 0]], v[edges[:, 1]])
        v32 = v.astype(np.float32)
        images = {}
        times = {}
        for shading in ("gouraud", "phong"):
            render = functools.partial(
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
            images[shading] = render()
            times[shading] = median_seconds(render, repeat) * 1e3
        (gouraud, gouraud_depth), (phong, phong_depth) = images["gouraud"], images["phong"]
        both = (gouraud_depth < 1) & (phong_depth < 1)
        g, p = np.asarray(gouraud)[both][:, :3], np.asarray(phong)[both][:, :3]
        error = np.abs(g.astype(np.float64) - p)
        rows.append(
            {
                "triangles": len(f),
                "edge_degrees": float(np.degrees(np.arccos(np.clip(cosines.min(), -1, 1)))),
                "max_error": float(error.max()),
                "mean_error": float(error.mean()),
                "levels8_wrong": float((_levels8(g) != _levels8(p)).mean()),
                "gouraud_ms": times["gouraud"],
                "phong_ms": times["phong"],
            }
        )
    return rows
