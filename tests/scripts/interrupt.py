"""SIGINT half a second into a long call: the call stops with KeyboardInterrupt. Prints
"interrupted <seconds after the signal>" or "finished <seconds>".

Usage: python tests/scripts/interrupt.py CASE, one of shade, shade-out, shade-gltf, shade-threejs,
vertex_normals, face_normals, crease_normals, render, render-gltf, render-threejs,
render-views, render-points, relief
"""

from __future__ import annotations

import os
import signal
import sys
import threading
import time
from collections.abc import Callable

import numpy as np

import glshade as gs


def prepare(case: str) -> Callable[[], object]:
    """Allocates the inputs of `case` and returns its long call."""
    rng = np.random.default_rng(0)
    spot = gs.Light(position=(1, 2, 3, 1), spot_cutoff=45, spot_exponent=3)
    shiny = gs.Material(specular=(1, 1, 1), shininess=9.5)
    if case in ("shade", "shade-out"):
        p = rng.normal(size=(4_000_000, 3))
        if case == "shade":
            scene = gs.Scene(lights=[spot] * 64, material=shiny)
            return lambda: gs.shade(p, p, scene, accuracy="exact")
        out = np.zeros((4_000_000, 4))
        scene = gs.Scene(lights=[spot] * 64, material=shiny)
        return lambda: gs.shade(p, p, scene, out=out)
    if case in ("shade-gltf", "shade-threejs"):
        p = rng.normal(size=(4_000_000, 3))
        if case == "shade-gltf":
            world: gs.gltf.Scene | gs.threejs.Scene = gs.gltf.Scene(
                [gs.gltf.SpotLight(position=(1, 2, 3), direction=(-1, -2, -3))] * 64,
                gs.gltf.Material(metallic=0.3, roughness=0.4),
            )
        else:
            world = gs.threejs.Scene(
                [gs.threejs.SpotLight(position=(1, 2, 3), penumbra=0.3)] * 64,
                gs.threejs.MeshPhongMaterial(shininess=9.5),
            )
        return lambda: gs.shade(p, p, world, accuracy="exact")
    if case == "relief":
        elevation = rng.normal(size=(6000, 6000)).cumsum(axis=0)
        light = gs.relief.LightSource()
        return lambda: [light.hillshade(elevation) for _ in range(20)]
    if case in ("vertex_normals", "face_normals", "crease_normals"):
        v = rng.normal(size=(4_000_000, 3))
        f = rng.integers(0, 4_000_000, (8_000_000, 3))
        if case == "vertex_normals":
            return lambda: [gs.vertex_normals(v, f) for _ in range(20)]
        if case == "crease_normals":
            return lambda: [gs.crease_normals(v, f) for _ in range(20)]
        return lambda: [gs.face_normals(v, f) for _ in range(40)]
    if case in ("render", "render-gltf", "render-threejs"):
        import trimesh

        m = trimesh.creation.icosphere(5)
        lit: gs.Scene | gs.gltf.Scene | gs.threejs.Scene = gs.Scene(
            lights=[spot] * 64, material=shiny
        )
        if case == "render-gltf":
            lit = gs.gltf.Scene([gs.gltf.PointLight(position=(1, 2, 3))] * 64)
        elif case == "render-threejs":
            lit = gs.threejs.Scene([gs.threejs.PointLight(position=(1, 2, 3))] * 64)
        camera = gs.Camera()
        return lambda: gs.render(m.vertices * 0.8, m.faces, lit, camera, width=4096, height=4096)
    if case == "render-views":
        import trimesh

        m = trimesh.creation.icosphere(5)
        views = gs.Camera.orbit(8, distance=3.0)
        lit = gs.Scene(lights=[spot] * 64, material=shiny)
        return lambda: gs.render(m.vertices, m.faces, lit, views, width=4096, height=4096)
    if case == "render-points":
        points = rng.normal(size=(8_000_000, 3)) * 0.5
        lit = gs.Scene(lights=[spot] * 64, material=shiny)
        return lambda: gs.render(points, None, lit, gs.Camera(), normals=points, point_size=8,
                                 width=4096, height=4096)  # fmt: skip
    raise SystemExit(f"unknown case {case!r}")


def main(case: str) -> None:
    # A process started in the background by a shell without job control inherits SIGINT
    # ignored, and Python then installs no handler: restore it, so that the test measures
    # glshade and not how the test run was started.
    signal.signal(signal.SIGINT, signal.default_int_handler)
    call = prepare(case)
    sent: list[float] = []

    def interrupt() -> None:
        time.sleep(0.5)
        sent.append(time.perf_counter())
        os.kill(os.getpid(), signal.SIGINT)

    threading.Thread(target=interrupt).start()
    start = time.perf_counter()
    try:
        call()
        print("finished", time.perf_counter() - start)
    except KeyboardInterrupt:
        print("interrupted", time.perf_counter() - sent[0])


if __name__ == "__main__":
    main(sys.argv[1])
