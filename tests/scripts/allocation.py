"""A call whose allocation fails under an address-space limit raises MemoryError. Prints
"MemoryError <message>", or nothing if the call succeeded.

Usage: python tests/scripts/allocation.py {shade,shade-exact,vertex_normals,face_normals,render}
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
    if case in ("vertex_normals", "face_normals"):
        v = rng.normal(size=(4_000_000, 3))
        f = rng.integers(0, 4_000_000, (8_000_000, 3))
        if case == "vertex_normals":
            return lambda: gs.vertex_normals(v, f)
        return lambda: gs.face_normals(v, f)
    if case == "render":
        t = np.array([[-1, -1, 0], [1, -1, 0], [0, 1, 0.0]])
        return lambda: gs.render(t, [[0, 1, 2]], gs.Scene(), gs.Camera(), width=16384, height=16384)
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
