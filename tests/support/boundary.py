"""The scenes and arrays the boundary's tests share (tests/core/intake, tests/core/objects,
tests/core/shading/test_range.py): a sun, a mixed scene, a two-sided Phong scene, random rows
and misaligned copies."""

from __future__ import annotations

from typing import Any

import numpy as np

import glshade as gs

SUN = gs.Scene(lights=[gs.Light(position=(0, 0, 1, 0))])
MIXED = gs.Scene(
    lights=[
        gs.Light(position=(1, 2, 3, 1), linear_attenuation=0.3, spot_cutoff=40, spot_exponent=3),
        gs.Light(position=(0, 1, 1, 0), diffuse=(0.5, 0.2, 0.1)),
    ],
    material=gs.Material(specular=(1, 1, 1), shininess=20),
    viewer=(0, 0, 0, 1),
)
# Every light-model option off its default: two materials, four outputs, Phong, no gate.
TWO_SIDED = gs.Scene(
    lights=[gs.Light()],
    material=gs.Material(diffuse=(1, 0, 0)),
    back_material=gs.Material(diffuse=(0, 0, 1)),
    two_side=True,
    separate_specular=True,
    specular="phong",
    specular_gate=False,
)
UP = np.array([[0.0, 0.0, 1.0]])
# The default material under one white directional light along the normal: 0.2*0.2 + 0.8.
LIT = 0.84


def rows(
    rng: np.random.Generator, n: int, dtype: Any = np.float64
) -> tuple[np.ndarray, np.ndarray]:
    """n random positions in [-1, 1]³ and n random (not unit) normals."""
    return rng.uniform(-1, 1, (n, 3)).astype(dtype), rng.normal(size=(n, 3)).astype(dtype)


def misaligned(a: np.ndarray) -> np.ndarray:
    """A copy of `a` one byte into a buffer: not aligned for its dtype."""
    buffer = np.zeros(a.nbytes + 1, np.uint8)
    view = buffer[1:].view(a.dtype).reshape(a.shape)
    view[...] = a
    assert not view.flags.aligned
    return view
