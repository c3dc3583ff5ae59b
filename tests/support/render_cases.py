"""The render cross-checks' scenes (tests/crosscheck/test_render_vs_moderngl.py and
test_compare.py): four meshes, lights, cameras and shadings that exercise every path of
`render`, the vertex colours of the coloured one, and the pixels on coverage edges."""

from __future__ import annotations

from typing import Any

import numpy as np

import glshade as gs
from glshade.meshes import icosphere, torus

LIGHTS = [
    gs.Light(position=(2.0, 3.0, 2.0, 1.0), linear_attenuation=0.1),
    gs.Light(position=(-1.0, 0.5, 1.0, 0.0), diffuse=(0.3, 0.4, 0.9), specular=(0.5, 0.5, 1)),
    gs.Light(
        position=(0.0, 2.0, 1.0, 1.0),
        spot_direction=(0.0, -1.0, -0.5),
        spot_cutoff=30.0,
        spot_exponent=4.0,
        diffuse=(0.9, 0.6, 0.2),
    ),
]
SHINY = gs.Material(specular=(1, 1, 1), shininess=30)
BACK = gs.Material(diffuse=(0.9, 0.2, 0.1), specular=(0.4, 0.4, 0.4), shininess=8)


def sheet(n: int = 40) -> tuple[np.ndarray, np.ndarray]:
    """A wavy open square: both of its sides can be seen."""
    x, y = np.meshgrid(np.linspace(-1, 1, n), np.linspace(-1, 1, n))
    v = np.stack([x, y, 0.25 * np.sin(3 * x) * np.cos(2 * y)], -1).reshape(-1, 3)
    i, j = np.meshgrid(np.arange(n - 1), np.arange(n - 1))
    a = (j * n + i).ravel()
    faces = np.concatenate([np.c_[a, a + 1, a + n + 1], np.c_[a, a + n + 1, a + n]])
    return v, faces


CASES: dict[str, dict[str, Any]] = {
    "torus, perspective, local viewer, spot": {
        "mesh": torus(40, 24),
        "scene": gs.Scene(lights=LIGHTS, material=SHINY, viewer=(0, 0, 0, 1)),
        "camera": gs.Camera.look_at((0.3, -2.4, 1.9), up=(0, 0, 1), fovy=50, near=0.5, far=10),
    },
    "sheet, both sides, two-sided, separate specular, orthographic": {
        "mesh": sheet(),
        "scene": gs.Scene(
            lights=LIGHTS,
            material=SHINY,
            back_material=BACK,
            two_side=True,
            separate_specular=True,
            specular="phong",
        ),
        "camera": gs.Camera.look_at_orthographic((2.5, -1.0, 0.6), height=2.6, near=0.5, far=8),
    },
    "icosphere, vertex colours (COLOR_MATERIAL diffuse), shininess 100": {
        "mesh": icosphere(2),
        "scene": gs.Scene(
            lights=LIGHTS[:2], material=gs.Material(specular=(1, 1, 1), shininess=100)
        ),
        "camera": gs.Camera.look_at((0.4, 0.5, 2.8), fovy=45, near=0.5, far=10),
        "colors": "diffuse",
    },
    "torus cut by the near plane, inside visible": {
        "mesh": torus(64, 24, 1.0, 0.5),
        "scene": gs.Scene(lights=LIGHTS, material=SHINY, back_material=BACK, two_side=True),
        "camera": gs.Camera.look_at((0.0, -1.05, 0.2), up=(0, 0, 1), fovy=70, near=0.5, far=10),
    },
}


def vertex_colours(n: int) -> np.ndarray:
    rng = np.random.default_rng(8)
    return np.c_[rng.uniform(0.1, 1.0, (n, 3)), np.ones(n)]


def face_edges(image: np.ndarray) -> np.ndarray:
    """Pixels of a flat-shaded image with an 8-neighbour of another colour (beyond 1e-6): where
    two faces meet, and a pixel centre on their shared edge may go to either face (GL's rule
    is exact only for the same vertex positions, and a clipper adds its own vertices)."""
    padded = np.pad(image, ((1, 1), (1, 1), (0, 0)), mode="edge")
    h, w = image.shape[:2]
    around = [padded[1 + a : 1 + a + h, 1 + b : 1 + b + w] for a in (-1, 0, 1) for b in (-1, 0, 1)]
    result: np.ndarray = np.any([np.abs(x - image).max(axis=-1) > 1e-6 for x in around], axis=0)
    return result


def named(mask: np.ndarray, error: np.ndarray, count: int = 8) -> str:
    """The pixels of `mask` as (row, column): error, the largest first, for a failure's
    message."""
    rows, columns = np.nonzero(mask)
    order = np.argsort(-error[rows, columns])[:count]
    return ", ".join(f"({rows[i]}, {columns[i]}): {error[rows[i], columns[i]]:.2e}" for i in order)


def on_edges(covered: np.ndarray) -> np.ndarray:
    """Pixels with a differently covered neighbour (8-connected)."""
    padded = np.pad(covered, 1, mode="edge")
    h, w = covered.shape
    around = [padded[1 + a : 1 + a + h, 1 + b : 1 + b + w] for a in (-1, 0, 1) for b in (-1, 0, 1)]
    result: np.ndarray = np.any([x != covered for x in around], axis=0)
    return result
