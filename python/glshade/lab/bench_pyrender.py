"""``python -m glshade bench render``'s pyrender scenes: `gs.render(pyrender_scene)` beside
pyrender's own ``OffscreenRenderer`` on Mesa's llvmpipe (EGL), the same scene objects.

Each scene is lit as pyrender users light one: a directional light, a point light and an
ambient light, metallic-roughness materials. One icosphere at three sizes fills the view; grids
of 64 and 256 small icospheres (1,280 faces each, a material each) stand for scenes of many
meshes. pyrender renders with its default flags (4x MSAA, one pass per shadow-less frame)
and reads the colour back as uint8; glshade returns float64. Before timing, the two images are
compared on the pixels both cover away from silhouettes (where MSAA blends), in 1/255.
"""

from __future__ import annotations

import functools
import os
from collections.abc import Callable
from typing import Any

import numpy as np

import glshade as gs

from ..meshes import icosphere
from .timing import ratio, time_rounds

__all__ = ["PYRENDER_SCENES", "bench_pyrender", "pyrender_scene"]

# Scene name: (icospheres per side of the grid, subdivisions of each).
PYRENDER_SCENES = {
    "1 mesh, 20,480 faces": (1, 5),
    "1 mesh, 327,680 faces": (1, 7),
    "1 mesh, 1,310,720 faces": (1, 8),
    "64 meshes of 1,280 faces": (8, 3),
    "256 meshes of 1,280 faces": (16, 3),
}


def pyrender_scene(per_side: int, subdivisions: int) -> Any:
    """A pyrender scene of `per_side`² icospheres on a grid in the plane z = 0, each with a
    metallic-roughness material of its own, a camera in front, a directional and a point light
    and an ambient light."""
    import pyrender  # type: ignore[import-untyped]
    import trimesh

    v, f = icosphere(subdivisions)
    sphere = trimesh.Trimesh(v, f, vertex_normals=v, process=False)
    rng = np.random.default_rng(per_side)
    scene = pyrender.Scene(bg_color=(0.0, 0.0, 0.0, 0.0), ambient_light=(0.05, 0.05, 0.06))
    spacing = 2.2
    offset = (per_side - 1) * spacing / 2
    for i in range(per_side * per_side):
        material = pyrender.MetallicRoughnessMaterial(
            baseColorFactor=(*rng.uniform(0.3, 0.95, 3), 1.0),
            metallicFactor=float(rng.uniform(0.0, 1.0)),
            roughnessFactor=float(rng.uniform(0.2, 0.9)),
        )
        pose = np.eye(4)
        pose[:2, 3] = (i % per_side) * spacing - offset, (i // per_side) * spacing - offset
        scene.add(pyrender.Mesh.from_trimesh(sphere, material=material), pose=pose)
    extent = per_side * spacing
    distance = 0.6 * extent / np.tan(np.radians(25)) + 1.0
    camera = np.eye(4)
    camera[2, 3] = distance
    scene.add(
        pyrender.PerspectiveCamera(yfov=np.radians(50), znear=distance / 10, zfar=distance * 2),
        pose=camera,
    )
    # A pose whose -z axis (the light's direction) points down, left and into the scene.
    forward = np.array([-0.4, -0.6, -1.0]) / np.linalg.norm([-0.4, -0.6, -1.0])
    right = np.cross(forward, (0.0, 1.0, 0.0))
    right /= np.linalg.norm(right)
    light = np.eye(4)
    light[:3, 0], light[:3, 1], light[:3, 2] = right, np.cross(right, forward), -forward
    scene.add(pyrender.DirectionalLight(color=(1.0, 0.97, 0.92), intensity=3.0), pose=light)
    point = np.eye(4)
    point[:3, 3] = (-0.4 * extent, 0.5 * extent, 0.5 * distance)
    scene.add(pyrender.PointLight(color=(0.7, 0.8, 1.0), intensity=2.0 * extent**2), pose=point)
    return scene


def _interior(covered: np.ndarray) -> np.ndarray:
    """Covered pixels whose eight neighbours are covered too: away from silhouettes."""
    padded = np.pad(covered, 1)
    h, w = covered.shape
    around = [
        padded[1 + dy : 1 + dy + h, 1 + dx : 1 + dx + w] for dy in (-1, 0, 1) for dx in (-1, 0, 1)
    ]
    result: np.ndarray = np.all(around, axis=0)
    return result


def bench_pyrender(size: int, repeat: int, names: list[str] | None = None) -> dict[str, Any]:
    """Prints and returns the median time of `gs.render` and of pyrender's OffscreenRenderer
    on each scene (`names`, default all), with the per-round speed-ups and the largest
    difference on interior pixels, in 1/255."""
    os.environ.setdefault("PYOPENGL_PLATFORM", "egl")
    os.environ.setdefault("LIBGL_ALWAYS_SOFTWARE", "1")
    try:
        import pyrender

        renderer = pyrender.OffscreenRenderer(size, size)
    except Exception as exc:
        print(f"{type(exc).__name__}: {exc}: no pyrender part")
        return {}
    print(
        f"pyrender scenes: pyrender {pyrender.__version__} OffscreenRenderer (EGL), "
        f"{size}x{size}, float64, {repeat} rounds"
    )
    results: dict[str, Any] = {}
    print(f"\n  {'scene':28} {'glshade':>10} {'pyrender':>10} {'speed-up':>9} {'max diff':>9}")
    for name in names or list(PYRENDER_SCENES):
        scene = pyrender_scene(*PYRENDER_SCENES[name])
        methods: dict[str, Callable[[], Any]] = {
            "glshade": functools.partial(gs.render, scene, width=size, height=size),
            "pyrender": functools.partial(renderer.render, scene),
        }
        ours = np.asarray(methods["glshade"](), dtype=np.float64)
        theirs = np.asarray(methods["pyrender"]()[0], dtype=np.float64) / 255
        inside = _interior(ours[..., 3] > 0) & _interior(theirs.max(axis=-1) > 0)
        difference = float(np.abs(ours[..., :3] - theirs)[inside].max() * 255)
        times = time_rounds(methods, repeat)
        r = ratio(times["pyrender"], times["glshade"])
        ms = {k: t.median * 1e3 for k, t in times.items()}
        print(
            f"  {name:28} {ms['glshade']:7.1f} ms {ms['pyrender']:7.1f} ms"
            f" {r.median:8.2f}x {difference:8.2f}"
        )
        results[name] = {
            "ms": {k: t.as_dict(1e3) for k, t in times.items()},
            "speedup_over_pyrender": r.as_dict(),
            "max_interior_difference_255": difference,
            "interior_pixels": int(inside.sum()),
        }
    return results
