"""A fork pool started after the parent shaded, computed normals and rendered: every child's
results equal the parent's. Prints "ok".

Usage: python tests/scripts/fork_pool.py
"""

from __future__ import annotations

import multiprocessing as mp
from typing import Any

import numpy as np

import glshade as gs

rng = np.random.default_rng(1)
p, n = rng.normal(size=(2, 50_000, 3)).astype(np.float32)
scene = gs.Scene(lights=[gs.Light(position=(1, 2, 3, 1)), gs.Light()])
v = rng.normal(size=(30_000, 3))
f = rng.integers(0, 30_000, (60_000, 3))


def child(i: int) -> tuple[Any, Any, Any, Any]:
    return (
        gs.shade(p, n, scene),
        gs.vertex_normals(v, f),
        gs.face_normals(v, f),
        gs.render(v, f, scene, gs.Camera(), width=64, height=64),
    )


def main() -> None:
    expected = gs.shade(p, n, scene)
    normals = gs.vertex_normals(v, f), gs.face_normals(v, f)
    image = gs.render(v, f, scene, gs.Camera(), width=64, height=64)
    with mp.get_context("fork").Pool(2) as pool:
        for shaded, vn, fn, im in pool.map(child, range(4)):
            assert np.array_equal(shaded, expected)
            assert np.array_equal(vn, normals[0]) and np.array_equal(fn, normals[1])
            assert np.array_equal(im, image)
    print("ok")


if __name__ == "__main__":
    main()
