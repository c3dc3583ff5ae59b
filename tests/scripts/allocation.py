"""A call whose allocation fails under an address-space limit raises MemoryError. Prints
"MemoryError <message>", or nothing if the call succeeded.

Usage: python tests/scripts/allocation.py CASE, one of shade, shade-exact, shade-gltf,
shade-threejs, vertex_normals, face_normals, crease_normals, render, render-gltf,
render-views, render-points, relief
"""

from __future__ import annotations

import resource
import sys
from collections.abc import Callable

import numpy as np

import glshade as gs


def prepare(case: str) -> Callable[[], object]:
    """Allocates the inputs of `case` (before the limit) and returns its call."""
    rng = np.random.default_rng(0)
    if case in ("shade", "shade-exact"):
        p = np.zeros((40_000_000, 3), np.float32)
        if case == "shade":
            return lambda: gs.shade(p, p, gs.Scene(lights=[gs.Light()]))
        return lambda: gs.shade(p, p, gs.Scene(lights=[gs.Light()]), accuracy="exact")
    if case in ("shade-gltf", "shade-threejs"):
        p = np.zeros((40_000_000, 3), np.float32)
        world: gs.gltf.Scene | gs.threejs.Scene = (
            gs.gltf.Scene(gs.gltf.PointLight())
            if case == "shade-gltf"
            else gs.threejs.Scene(gs.threejs.PointLight())
        )
        return lambda: gs.shade(p, p, world)
    if case == "relief":
        elevation = np.zeros((8000, 8000))
        return lambda: gs.relief.LightSource().hillshade(elevation)
    if case in ("vertex_normals", "face_normals", "crease_normals"):
        v = rng.normal(size=(4_000_000, 3))
        f = rng.integers(0, 4_000_000, (8_000_000, 3))
        if case == "vertex_normals":
            return lambda: gs.vertex_normals(v, f)
        if case == "crease_normals":
            return lambda: gs.crease_normals(v, f)
        return lambda: gs.face_normals(v, f)
    if case in ("render", "render-gltf"):
        t = np.array([[-1, -1, 0], [1, -1, 0], [0, 1, 0.0]])
        scene = gs.Scene() if case == "render" else gs.gltf.Scene(gs.gltf.PointLight())
        return lambda: gs.render(t, [[0, 1, 2]], scene, gs.Camera(), width=16384, height=16384)
    if case == "render-views":  # two frames of 16384²: the outputs do not fit
        t = np.array([[-1, -1, 0], [1, -1, 0], [0, 1, 0.0]])
        views = [gs.Camera(), gs.Camera()]
        return lambda: gs.render(t, [[0, 1, 2]], gs.Scene(), views, width=16384, height=16384)
    if case == "render-points":
        dots = np.zeros((3, 3))
        return lambda: gs.render(dots, None, None, gs.Camera(), width=16384, height=16384)
    raise SystemExit(f"unknown case {case!r}")


def main(case: str) -> None:
    call = prepare(case)
    gs.shade(np.zeros((100_000, 3)), np.ones((100_000, 3)), gs.Scene(lights=[gs.Light()]))
    with open("/proc/self/statm") as statm:
        virtual = int(statm.read().split()[0]) * resource.getpagesize()
    # 256 MiB above what the process maps now: the inputs fit, the call's outputs do not.
    hard = resource.getrlimit(resource.RLIMIT_AS)[1]
    resource.setrlimit(resource.RLIMIT_AS, (virtual + (256 << 20), hard))
    try:
        call()
    except MemoryError as e:
        print("MemoryError", e)


if __name__ == "__main__":
    main(sys.argv[1])
