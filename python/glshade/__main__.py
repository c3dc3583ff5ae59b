"""Command line: ``python -m glshade demo``."""

from __future__ import annotations

import argparse
import functools
import statistics
import sys
import time
from collections.abc import Callable, Sequence
from typing import Any

import numpy as np
from numpy.typing import NDArray

import glshade as gs

from ._bench import bench_normals
from ._png import write_png


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


def median_seconds(call: Callable[[], Any], repeat: int) -> float:
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        call()
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def demo(size: int, repeat: int, output: str) -> int:
    scene = demo_scene()
    positions, normals, inside = sphere_pixels(size)
    n = len(positions)
    print(f"glshade {gs.__version__}: the OpenGL 2.1 lighting equation, per vertex, in parallel")
    shininess = scene.material.shininess
    print(f"scene: {scene.lights!r}; local viewer; Blinn specular, shininess {shininess:g}")
    print(f"vertices: {n:,} points of a unit sphere, one per pixel of a {size}x{size} image\n")
    results = {}
    print(f"{'dtype':8} {'median time':>12} {'Mvertices/s':>12}")
    for dtype in (np.float32, np.float64):
        p, nrm = positions.astype(dtype), normals.astype(dtype)
        out = np.zeros((n, 4), dtype)
        gs.shade(p, nrm, scene, out=out)  # warm-up: first-touch of the pages and thread start
        seconds = median_seconds(functools.partial(gs.shade, p, nrm, scene, out=out), repeat)
        results[dtype] = out.copy()
        print(f"{np.dtype(dtype).name:8} {seconds * 1e3:10.2f} ms {n / seconds / 1e6:12.1f}")
    diff = np.abs(results[np.float32].astype(np.float64) - results[np.float64])
    print(f"\nmax |float32 - float64| over all {n * 4:,} channels: {diff.max():.2e}")
    mean = results[np.float64].mean(axis=0)
    print(f"mean RGBA: ({', '.join(f'{c:.4f}' for c in mean)})")
    image = np.zeros((size, size, 4))
    image[..., 3] = 1.0
    image[inside] = results[np.float64]
    path = write_png(output, image)
    print(f"wrote {path} ({size}x{size}, 8-bit RGBA)")
    return 0


def main(argv: Sequence[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m glshade", description=__doc__)
    commands = parser.add_subparsers(dest="command", required=True)
    run = commands.add_parser("demo", help="shade a built-in scene, print timings, write a PNG")
    run.add_argument("--size", type=int, default=1024, help="image size in pixels (default 1024)")
    run.add_argument("--repeat", type=int, default=7, help="timed runs per dtype (default 7)")
    run.add_argument(
        "--output", default="glshade-demo.png", help="PNG path (default ./glshade-demo.png)"
    )
    bench = commands.add_parser("bench", help="time glshade beside its baselines in the same run")
    bench.add_argument("what", choices=["normals"], help="what to time")
    bench.add_argument("--faces", type=int, default=1_000_000, help="mesh size (default 10^6)")
    bench.add_argument("--repeat", type=int, default=7, help="rounds (default 7)")
    bench.add_argument(
        "--settle",
        type=float,
        default=0.25,
        help="seconds of idle before each timed call (default 0.25)",
    )
    args = parser.parse_args(argv)
    if args.repeat < 1:
        parser.error("--repeat must be positive")
    if args.command == "bench":
        if args.faces < 2:
            parser.error("--faces must be at least 2")
        if not args.settle >= 0:
            parser.error("--settle must not be negative")
        return bench_normals(args.faces, args.repeat, args.settle)
    if args.size < 1:
        parser.error("--size must be positive")
    return demo(args.size, args.repeat, args.output)


if __name__ == "__main__":
    sys.exit(main())
