"""The built-in scene and ``python -m glshade demo``: the lighting equation per pixel of a
sphere, then a mesh rendered with flat, Gouraud and Phong shading."""

from __future__ import annotations

import functools
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

import glshade as gs

from ..meshes import torus
from .timing import time_rounds


def sphere_pixels(size: int) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.bool_]]:
    """Eye-space points and normals of a unit sphere at z = -3 seen orthographically, one per
    pixel centre of a size x size image (pixel centres at half-integers, as in GL)."""
    centres = (np.arange(size) + 0.5) / size * 2.4 - 1.2
    x, y = np.meshgrid(centres, -centres)
    inside = x**2 + y**2 < 1.0
    z = np.sqrt(np.clip(1.0 - x**2 - y**2, 0.0, None))
    normals = np.stack([x, y, z], axis=-1)[inside]
    positions = normals + np.array([0.0, 0.0, -3.0])
    return positions, normals, inside


def demo_scene() -> gs.Scene:
    key = gs.Light(
        position=(-1.0, 1.0, 1.0, 0.0), diffuse=(1.0, 0.9, 0.75), specular=(1.0, 1.0, 1.0)
    )
    fill = gs.Light(
        position=(2.0, -1.0, -1.0, 1.0),
        diffuse=(0.25, 0.35, 0.7),
        specular=(0.3, 0.3, 0.6),
        quadratic_attenuation=0.15,
    )
    spot = gs.Light(
        position=(0.0, 2.0, -2.0, 1.0),
        diffuse=(0.9, 0.3, 0.2),
        specular=(0.9, 0.5, 0.4),
        spot_direction=(0.0, -2.0, -1.0),
        spot_cutoff=20.0,
        spot_exponent=10.0,
    )
    material = gs.Material(
        ambient=(0.3, 0.3, 0.35), diffuse=(0.7, 0.7, 0.75), specular=(0.6, 0.6, 0.6), shininess=60
    )
    return gs.Scene(
        lights=[key, fill, spot],
        material=material,
        global_ambient=(0.15, 0.15, 0.2),
        viewer=(0, 0, 0, 1),
    )


def demo_camera() -> gs.Camera:
    """The view of `demo_mesh` in the demo and the render benchmark."""
    return gs.Camera.look_at(
        (0.0, -3.1, 2.4), (0.0, 0.15, -0.2), (0, 0, 1), fovy=40, near=1, far=10
    )


def demo_mesh() -> tuple[NDArray[np.float64], NDArray[np.int64]]:
    """A coarse torus (1,152 triangles): large enough triangles to show flat shading's facets
    and Gouraud shading's lost and smeared highlights."""
    return torus(36, 16, 1.0, 0.45)


def shade_vertices(scene: gs.Scene, size: int, repeat: int) -> NDArray[np.float64]:
    """Part 1: the equation at one point per pixel of a sphere; the float64 image."""
    positions, normals, inside = sphere_pixels(size)
    n = len(positions)
    print(f"1. gs.shade: {n:,} points of a unit sphere, one per pixel of a {size}x{size} image\n")
    print(f"{'dtype':8} {'median time':>12} {'Mvertices/s':>12}")
    inputs = {d: (positions.astype(d), normals.astype(d)) for d in (np.float32, np.float64)}
    outs = {d: np.zeros((n, 4), d) for d in inputs}
    calls = {
        np.dtype(d).name: functools.partial(gs.shade, p, nrm, scene, out=outs[d])
        for d, (p, nrm) in inputs.items()
    }
    for name, timing in time_rounds(calls, repeat).items():
        seconds = timing.median
        print(f"{name:8} {seconds * 1e3:10.2f} ms {n / seconds / 1e6:12.1f}")
    diff = np.abs(outs[np.float32].astype(np.float64) - outs[np.float64])
    print(f"\nmax |float32 - float64| over all {n * 4:,} channels: {diff.max():.2e}")
    mean = outs[np.float64].mean(axis=0)
    print(f"mean RGBA: ({', '.join(f'{c:.4f}' for c in mean)})")
    image = np.zeros((size, size, 4))
    image[..., 3] = 1.0
    image[inside] = outs[np.float64]
    return image


def render_modes(scene: gs.Scene, size: int, repeat: int) -> dict[str, gs.Image]:
    """Part 2: the demo mesh rendered with each shading, float32; the images by mode."""
    v, f = demo_mesh()
    v32, camera = v.astype(np.float32), demo_camera()
    print(f"\n2. gs.render: a torus of {len(f):,} triangles, {size}x{size}, float32\n")
    print(f"{'shading':8} {'median time':>12} {'evaluations':>12}")
    calls = {
        shading: functools.partial(
            gs.render,
            v32,
            f,
            scene,
            camera,
            width=size,
            height=size,
            shading=shading,
            background=(1, 1, 1, 1),
        )
        for shading in ("flat", "gouraud", "phong")
    }
    timings = time_rounds(calls, repeat)
    images = {}
    for shading, call in calls.items():
        images[shading], depth = call(depth=True)
        seconds = timings[shading].median
        evaluations = {"flat": len(f), "gouraud": len(v), "phong": int((depth < 1).sum())}[shading]
        print(f"{shading:8} {seconds * 1e3:10.2f} ms {evaluations:12,}")
    return images


def demo(size: int, repeat: int, output: str) -> int:
    """Runs the demo: prints the timings of both parts and writes the sphere's image to
    `output` and the three renders beside it; its exit status."""
    path = Path(output)
    # Made (or refused) before the minutes of work, not after: a missing folder is created.
    path.parent.mkdir(parents=True, exist_ok=True)
    scene = demo_scene()
    print(f"glshade {gs.__version__}: the OpenGL 2.1 lighting equation, per vertex, in parallel")
    shininess = scene.material.shininess
    print(f"scene: {scene.lights!r}; local viewer; Blinn specular, shininess {shininess:g}\n")
    sphere = shade_vertices(scene, size, repeat)
    images = render_modes(scene, size, repeat)
    difference = np.abs(images["gouraud"] - images["phong"])[..., :3]
    print(f"\nGouraud against Phong: max |difference| {difference.max():.3f}", end="")
    print(f", mean {difference.mean():.4f}")
    written = [sphere.view(gs.Image).save(path)]
    for shading, image in images.items():
        written.append(image.save(path.with_name(f"{path.stem}-{shading}{path.suffix}")))
    for p in written:
        print(f"wrote {p} ({size}x{size}, 8-bit RGBA)")
    return 0
