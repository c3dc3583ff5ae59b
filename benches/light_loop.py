"""glshade and Dr.Jit on the lights of ``benches/light_loop.rs``, one thread each.

The Rust example times light loops of three structures with no exactness safeguard; this script
times ``gs.shade`` (float32, ``"fast"``) and the benchmark's Dr.Jit kernel
(``glshade.lab.peers.drjit_shade``) on the same point lights, material and viewer, and on
vertices of the same distribution, so the example's rates can be read against theirs::

    cargo bench --bench light_loop -- 8 32
    RAYON_NUM_THREADS=1 python benches/light_loop.py 8 32

Both peers write RGBA rows from rows of positions and normals, which the example's kernels do
not (they read planes and write one grey channel).
"""

from __future__ import annotations

import os
import sys
import time
from collections.abc import Callable

import numpy as np
from numpy.typing import NDArray

import glshade as gs
from glshade.lab import peers


def fraction(i: int, a: int, m: int) -> float:
    """``((a·i + 7) mod m)/m``, the example's ``fraction``."""
    return ((a * i + 7) % m) / m


def scene(count: int) -> gs.Scene:
    """The example's first `count` point lights, its grey material and a viewer at the origin."""
    grey = (0.1, 0.1, 0.1, 1.0)
    lights = [
        gs.Light(
            position=(
                6 * fraction(i, 37, 61) - 3,
                6 * fraction(i, 53, 59) - 3,
                3 * fraction(i, 29, 31) - 1,
                1.0,
            ),
            ambient=(0.0, 0.0, 0.0, 1.0),
            diffuse=grey,
            specular=grey,
            constant_attenuation=1.0,
            linear_attenuation=0.1 * (i % 3),
            quadratic_attenuation=0.05 * (i % 2 + 1),
        )
        for i in range(count)
    ]
    material = gs.Material(
        diffuse=(0.8, 0.8, 0.8, 1.0), specular=(0.5, 0.5, 0.5, 1.0), shininess=32
    )
    return gs.Scene(lights, material=material, viewer=(0, 0, 0, 1))


def vertices(count: int = 1 << 20) -> tuple[NDArray[np.float32], NDArray[np.float32]]:
    """The example's distribution: x, y in [-1, 1], z in [-4, -2]; unit normals towards +z."""
    rng = np.random.default_rng(20)
    p = rng.uniform((-1.0, -1.0, -4.0), (1.0, 1.0, -2.0), (count, 3)).astype(np.float32)
    n = rng.uniform((-0.5, -0.5, 0.01), (0.5, 0.5, 1.01), (count, 3))
    n = (n / np.linalg.norm(n, axis=1, keepdims=True)).astype(np.float32)
    return p, n


def median_rate(call: Callable[[], object], count: int) -> float:
    """Million vertices per second: the median of seven calls, after one."""
    call()
    seconds = []
    for _ in range(7):
        start = time.perf_counter()
        call()
        seconds.append(time.perf_counter() - start)
    return count / float(np.median(seconds)) / 1e6


def main(counts: list[int]) -> None:
    if os.environ.get("RAYON_NUM_THREADS") != "1":
        print("set RAYON_NUM_THREADS=1 to time glshade on one thread, as the example runs")
    p, n = vertices()
    out = np.zeros((len(p), 4), np.float32)
    drjit = peers.drjit_shade(threads=1)
    if isinstance(drjit, str):
        print(f"Dr.Jit: {drjit}")

    def kernels(lit: gs.Scene) -> dict[str, Callable[[], object]]:
        found: dict[str, Callable[[], object]] = {"glshade": lambda: gs.shade(p, n, lit, out=out)}
        if not isinstance(drjit, str):
            found["Dr.Jit"] = lambda: drjit(p, n, lit)
        return found

    for count in counts:
        timed = kernels(scene(count))
        rates: dict[str, list[float]] = {name: [] for name in timed}
        for _ in range(3):
            for name, call in timed.items():
                rates[name].append(median_rate(call, len(p)))
        print(f"{count} point lights, {len(p)} vertices: million vertices/s, rounds 1 to 3")
        for name, rate in rates.items():
            print(f"  {name:10} " + "  ".join(f"{r:.1f}" for r in rate))


if __name__ == "__main__":
    main([int(a) for a in sys.argv[1:]] or [8, 32])
