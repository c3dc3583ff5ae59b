"""A fork pool started after the parent made every O(n) call (each model's shade and render,
the normals, relief): every child's results equal the parent's. Prints "ok".

Usage: python tests/scripts/fork_pool.py
"""

from __future__ import annotations

import multiprocessing as mp
from collections.abc import Callable
from typing import Any

import numpy as np

import glshade as gs

rng = np.random.default_rng(1)
p, n = rng.normal(size=(2, 50_000, 3)).astype(np.float32)
scene = gs.Scene(lights=[gs.Light(position=(1, 2, 3, 1)), gs.Light()])
gltf = gs.gltf.Scene(gs.gltf.PointLight(position=(1, 2, 3)), gs.gltf.Material(roughness=0.4))
threejs = gs.threejs.Scene([gs.threejs.PointLight(position=(1, 2, 3)), gs.threejs.AmbientLight()])
v = rng.normal(size=(30_000, 3))
f = rng.integers(0, 30_000, (60_000, 3))
elevation = rng.normal(size=(300, 400)).cumsum(axis=0)

CALLS: list[Callable[[], Any]] = [
    lambda: gs.shade(p, n, scene),
    lambda: gs.shade(p, n, gltf),
    lambda: gs.shade(p, n, threejs),
    lambda: gs.vertex_normals(v, f),
    lambda: gs.face_normals(v, f),
    lambda: gs.crease_normals(v, f),
    lambda: gs.render(v, f, scene, gs.Camera(), width=64, height=64),
    lambda: gs.render(v, f, gltf, gs.Camera(), width=64, height=64),
    lambda: gs.render(v, f, threejs, gs.Camera(), width=64, height=64),
    lambda: gs.render(v, f, scene, gs.Camera.orbit(3), width=32, height=32),
    lambda: gs.render(v, None, scene, gs.Camera(), normals=v, point_size=3, width=64, height=64),
    lambda: gs.relief.LightSource().hillshade(elevation),
]


def child(i: int) -> list[Any]:
    return [np.asarray(call()) for call in CALLS]


def main() -> None:
    expected = [np.asarray(call()) for call in CALLS]
    with mp.get_context("fork").Pool(2) as pool:
        for results in pool.map(child, range(4)):
            for got, want in zip(results, expected, strict=True):
                assert np.array_equal(got, want)
    print("ok")


if __name__ == "__main__":
    main()
