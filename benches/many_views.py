"""A turntable: 36 views of a mesh of about 100,000 faces at 256 x 256, three ways in the same
process, interleaved in the same rounds: ``gs.render`` given the 36 cameras in one call,
``gs.render`` called once a camera, and pyrender (its OffscreenRenderer on Mesa's llvmpipe
through EGL, one render a camera pose, the scene built once) when it is installed. The one
call's views are checked against the single calls, bit for bit, first.

    python benches/many_views.py [ROUNDS]

Prints the median of the rounds for each, in milliseconds for the 36 views, and the ratios.
"""

from __future__ import annotations

import importlib
import os
import platform
import statistics
import sys
import time
from collections.abc import Callable
from typing import Any

import numpy as np

import glshade as gs

VIEWS, SIZE = 36, 256


def cpu() -> str:
    for line in open("/proc/cpuinfo", encoding="utf-8"):
        if line.startswith("model name"):
            return line.split(":", 1)[1].strip()
    return platform.processor()


def pyrender_turntable(vertices: np.ndarray, faces: np.ndarray, cameras: list[Any]) -> Any:
    """36 pyrender renders of the mesh, one a camera pose, or None without pyrender."""
    os.environ.setdefault("PYOPENGL_PLATFORM", "egl")
    try:  # by name: pyrender ships no types
        pyrender: Any = importlib.import_module("pyrender")
        trimesh: Any = importlib.import_module("trimesh")
    except Exception:  # pyrender's import fails in many ways without GL
        return None
    scene = pyrender.Scene(ambient_light=(0.1, 0.1, 0.1))
    scene.add(pyrender.Mesh.from_trimesh(trimesh.Trimesh(vertices, faces, process=False)))
    scene.add(pyrender.DirectionalLight(intensity=3.0), pose=np.eye(4))
    node = scene.add(pyrender.PerspectiveCamera(np.radians(45), 0.1, 100.0), pose=np.eye(4))
    renderer = pyrender.OffscreenRenderer(SIZE, SIZE)
    poses = [camera.pose for camera in cameras]

    def run() -> None:
        for pose in poses:
            scene.set_pose(node, pose)
            renderer.render(scene)

    return run


def main(rounds: int) -> None:
    vertices, faces = gs.meshes.torus(400, 130, 1.0, 0.4)
    cameras = gs.Camera.orbit(VIEWS, distance=3.5, elevation=25.0)
    scene = gs.Scene(lights=[gs.Light(position=(1, 2, 3, 0))], material=gs.Material(shininess=40))
    together = gs.render(vertices, faces, scene, cameras, width=SIZE, height=SIZE)
    for k, camera in enumerate(cameras):
        single = gs.render(vertices, faces, scene, camera, width=SIZE, height=SIZE)
        if not np.array_equal(together[k], single):
            sys.exit(f"view {k} of the one call differs from its single call")
    ways: dict[str, Callable[[], Any]] = {
        "one call": lambda: gs.render(vertices, faces, scene, cameras, width=SIZE, height=SIZE),
        "36 calls": lambda: [
            gs.render(vertices, faces, scene, c, width=SIZE, height=SIZE) for c in cameras
        ],
    }
    peer = pyrender_turntable(vertices, faces, cameras)
    if peer is not None:
        ways["pyrender"] = peer
    times: dict[str, list[float]] = {name: [] for name in ways}
    for _ in range(rounds):
        for name, way in ways.items():
            start = time.perf_counter()
            way()
            times[name].append(time.perf_counter() - start)
    print(f"{len(faces):,} faces, {VIEWS} views at {SIZE} x {SIZE}, {rounds} rounds; {cpu()}, "
          f"{os.cpu_count()} cores")  # fmt: skip
    medians = {name: statistics.median(t) * 1e3 for name, t in times.items()}
    for name, ms in medians.items():
        ratio = medians["36 calls"] / ms
        print(f"{name:>9}: {ms:8.1f} ms  ({ratio:.2f}x the 36 calls)")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 7)
