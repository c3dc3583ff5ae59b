"""The scenes and the on-disk vertices of the scale-out tests (tests/scale_out, the lab's cluster
bench)."""

from __future__ import annotations

from pathlib import Path

import numpy as np

import glshade as gs

VERTICES, CHUNK = 4_000_000, 500_000
SCENE = gs.Scene(
    lights=[
        gs.Light(position=(1, 2, 3, 1), quadratic_attenuation=0.05, specular=(0.6, 0.6, 0.6)),
        gs.Light(position=(-1, 1, 2, 1), spot_direction=(0.5, -0.4, -1), spot_cutoff=40,
                 spot_exponent=3, diffuse=(0.3, 0.5, 0.9)),
        gs.Light(position=(0, 0, 1, 0), diffuse=(0.2, 0.2, 0.3), specular=(0, 0, 0)),
    ],
    material=gs.Material(specular=(0.8, 0.8, 0.8), shininess=40),
    viewer=(0, 0, 0, 1),
)  # fmt: skip
TWO_SIDED = gs.Scene(
    lights=[gs.Light(position=(1, 2, 3, 1))],
    material=gs.Material(diffuse=(1, 0.2, 0.2), specular=(1, 1, 1), shininess=8),
    back_material=gs.Material(diffuse=(0.2, 0.2, 1)),
    two_side=True,
    separate_specular=True,
)


def write_vertices(folder: Path, count: int, seed: int = 7) -> tuple[Path, Path]:
    """positions.npy and normals.npy of `count` float32 rows, written through memory maps."""
    rng = np.random.default_rng(seed)
    paths = folder / "positions.npy", folder / "normals.npy"
    for path, shift in zip(paths, ((0, 0, -4), (0, 0, 0)), strict=True):
        mapped = np.lib.format.open_memmap(path, mode="w+", dtype=np.float32, shape=(count, 3))
        for start in range(0, count, 1 << 20):
            rows = min(1 << 20, count - start)
            mapped[start : start + rows] = rng.standard_normal((rows, 3), np.float32) + shift
        mapped.flush()
        del mapped
    return paths
