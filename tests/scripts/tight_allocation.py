"""Shading float32 vertices with 1 MiB of address space to spare: a MemoryError, or the right
result where the allocator still finds room, never an abort; the interpreter stays usable.

Prints "MemoryError <message>" or "ok", then "usable" once the limit is lifted and a call
(which starts whatever threads the limit stopped) has shaded again.

Usage: python tests/scripts/tight_allocation.py {cold,cold-short,warm}
  cold: 4·10^6 vertices as the process's first glshade call, into an `out=` allocated before
    the limit (so every allocation under it is glshade's own): a long call, whose worker thread
    must start under the limit;
  cold-short: the same with 60,000 vertices: a short call, which starts rayon's threads;
  warm: 4·10^6 vertices into a new array, after a call has started the threads and touched the
    allocator: the case that aborted ("memory allocation of 54 bytes failed").
"""

from __future__ import annotations

import resource
import sys

import numpy as np

import glshade as gs

VERTICES = {"cold": 4_000_000, "cold-short": 60_000, "warm": 4_000_000}


def main(mode: str) -> None:
    if mode not in VERTICES:
        raise SystemExit(f"unknown mode {mode!r}")
    rng = np.random.default_rng(0)
    n = VERTICES[mode]
    positions = rng.uniform(-1, 1, (n, 3)).astype(np.float32)
    normals = rng.normal(size=(n, 3)).astype(np.float32)
    out = np.zeros((n, 4), np.float32) if mode != "warm" else None
    scene = gs.Scene(lights=[gs.Light(position=(1, 2, 3, 1))], material=gs.Material(shininess=8))
    if mode == "warm":
        gs.shade(positions[:100_000], normals[:100_000], scene)
    soft, hard = resource.getrlimit(resource.RLIMIT_AS)
    with open("/proc/self/statm") as statm:
        virtual = int(statm.read().split()[0]) * resource.getpagesize()
    resource.setrlimit(resource.RLIMIT_AS, (virtual + (1 << 20), hard))
    error, colors = None, None
    try:
        colors = gs.shade(positions, normals, scene, out=out)
    except MemoryError as e:
        error = e
    resource.setrlimit(resource.RLIMIT_AS, (soft, hard))  # printing may need memory too
    if error is not None:
        print("MemoryError", error)
    else:
        # Where it fit, every row must be the one a call without the limit gives.
        assert colors is not None
        rows = rng.integers(0, n, 1000)
        expected = gs.shade(positions[rows], normals[rows], scene)
        assert np.array_equal(colors[rows], expected), "a result under the limit differs"
        print("ok")
    again = gs.shade(positions, normals, scene)
    assert np.isfinite(again).all()
    print("usable")


if __name__ == "__main__":
    main(sys.argv[1])
