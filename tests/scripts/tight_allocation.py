"""Shading 4·10^6 float32 vertices with 1 MiB of address space to spare: a MemoryError, or the
right result where the allocator still finds room, never an abort; the interpreter stays usable.

Prints "MemoryError <message>" or "ok", then "usable" once the limit is lifted.

Usage: python tests/scripts/tight_allocation.py {cold,warm}
  cold: the first glshade call runs under the limit (its threads must start there too);
  warm: a call before the limit has started the threads and touched the allocator's arenas.
"""

from __future__ import annotations

import resource
import sys

import numpy as np

import glshade as gs

VERTICES = 4_000_000


def main(mode: str) -> None:
    if mode not in ("cold", "warm"):
        raise SystemExit(f"unknown mode {mode!r}")
    rng = np.random.default_rng(0)
    positions = rng.uniform(-1, 1, (VERTICES, 3)).astype(np.float32)
    normals = rng.normal(size=(VERTICES, 3)).astype(np.float32)
    scene = gs.Scene(lights=[gs.Light(position=(1, 2, 3, 1))], material=gs.Material(shininess=8))
    if mode == "warm":
        gs.shade(positions[:100_000], normals[:100_000], scene)
    with open("/proc/self/statm") as statm:
        virtual = int(statm.read().split()[0]) * resource.getpagesize()
    resource.setrlimit(resource.RLIMIT_AS, (virtual + (1 << 20), resource.RLIM_INFINITY))
    try:
        colors = gs.shade(positions, normals, scene)
    except MemoryError as e:
        colors = None
        print("MemoryError", e)
    resource.setrlimit(resource.RLIMIT_AS, (resource.RLIM_INFINITY, resource.RLIM_INFINITY))
    if colors is not None:
        # Where it fit, every row must be the one a call without the limit gives.
        rows = rng.integers(0, VERTICES, 1000)
        expected = gs.shade(positions[rows], normals[rows], scene)
        assert np.array_equal(colors[rows], expected), "a result under the limit differs"
        print("ok")
    small = gs.shade(positions[:2], normals[:2], scene)
    assert small.shape == (2, 4) and np.isfinite(small).all()
    print("usable")


if __name__ == "__main__":
    main(sys.argv[1])
