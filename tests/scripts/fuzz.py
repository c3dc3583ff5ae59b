"""Random arguments to every public function: nothing but the documented exceptions (TypeError,
ValueError, IndexError, MemoryError). Prints the number of calls and the outcomes' counts, or
"UNEXPECTED ..." and exits 1.

Usage: python tests/scripts/fuzz.py [ROUNDS]  (13 calls a round; 600 rounds by default)
"""

from __future__ import annotations

import sys
from collections.abc import Callable
from typing import Any

import numpy as np

import glshade as gs

ALLOWED = (TypeError, ValueError, IndexError, MemoryError)


def main(rounds: int) -> None:
    rng = np.random.default_rng(20261201)
    arrays: list[Any] = [
        np.zeros((0, 3)), np.ones((1, 3)), rng.normal(size=(5, 3)), rng.normal(size=(5, 2)),
        rng.normal(size=3), np.float64(2.0), rng.normal(size=(2, 2, 3)), rng.normal(size=(5, 4)),
        np.full((5, 3), np.nan), np.full((5, 3), np.inf), np.full((5, 3), 1e300),
        np.full((5, 3), -0.0), np.full((5, 3), 3e38, np.float32),
        rng.normal(size=(5, 3)).astype(np.float16), rng.normal(size=(5, 3)).astype(">f4"),
        rng.integers(-3, 9, (5, 3)), rng.integers(0, 5, (4, 3)), np.ones((5, 3), bool),
        np.ones((5, 3), complex), np.array([["a"] * 3] * 5),
        np.array([[None] * 3] * 5, dtype=object), np.zeros((5, 3), np.uint64) + 2**63,
        [[0, 0, 1]] * 5, [[0, 0]], "text", None, 7, -1, 2.5, True, (), {}, object(),
    ]  # fmt: skip
    # Valid vertex arrays, weighted up so that most calls get past the intake into the core.
    valid = [a for a in arrays[:15] if isinstance(a, np.ndarray) and a.shape == (5, 3)] * 4
    faces = [rng.integers(0, 5, (4, 3)), rng.integers(0, 5, (9, 3)), np.zeros((0, 3), int)] * 4
    extra: list[Any] = [
        None, True, False, "phong", "flat", "front", 0, 2**64, np.eye(4), np.zeros((4, 4)),
        np.diag([1e300, 1e300, 1e300, 1]), np.diag([1e-300] * 3 + [1]), (1, 2, 3, 4),
    ]  # fmt: skip
    scenes: list[Any] = [
        gs.Scene(),
        gs.Scene(
            lights=[gs.Light(position=(1, 2, 3, 1), spot_cutoff=30)],
            two_side=True,
            separate_specular=True,
        ),
        "scene",
        None,
    ]
    counts: dict[str, int] = {}

    def attempt(name: str, call: Callable[..., object], *args: Any, **kwargs: Any) -> None:
        # The arguments are drawn by the caller, in the order the calls list them.
        try:
            call(*args, **kwargs)
            outcome = "ok"
        except ALLOWED as e:
            outcome = type(e).__name__
        except BaseException as e:
            print("UNEXPECTED", name, type(e).__module__, type(e).__name__, e)
            raise SystemExit(1) from e
        counts[outcome] = counts.get(outcome, 0) + 1

    def pick(pool: list[Any]) -> Any:
        return pool[rng.integers(len(pool))]

    for _ in range(rounds):
        a, b = pick([*arrays, *valid]), pick([*arrays, *valid])
        c = pick([*arrays, *valid, *[None] * 20])
        f = pick([*arrays, *faces])
        scene, option = pick(scenes), pick(extra)
        attempt("shade", gs.shade, a, b, scene, colors=c)
        attempt("shade out", gs.shade, a, b, scene, out=pick(arrays))
        attempt("shade modelview", gs.shade, a, b, scene, modelview=option, normalize=True)
        attempt("shade accuracy", gs.shade, a, b, scene, accuracy=pick(["exact", option]))
        attempt("face_normals", gs.face_normals, a, f)
        attempt("vertex_normals", gs.vertex_normals, a, f, weighting=pick(["area", option]))
        attempt("shade_mesh", gs.shade_mesh, a, f, scene=scene)
        attempt("render", gs.render, a, f, scene, gs.Camera(), width=pick([1, 8, option]),
                height=8, shading=pick(["gouraud", "flat", option]))  # fmt: skip
        attempt("Light", gs.Light, position=pick([*arrays, *extra]),
                diffuse=pick([*arrays, *extra]))  # fmt: skip
        attempt("Lights", gs.Lights, spot_cutoff=pick([*arrays, *extra]), count=pick(extra))
        attempt("Material", gs.Material, shininess=pick([*arrays, *extra]), emission=option)
        attempt("Scene", gs.Scene, lights=pick([*arrays, *extra, *scenes]), viewer=pick(arrays),
                two_side=option, global_ambient=pick(arrays))  # fmt: skip
        attempt("Camera", gs.Camera.look_at, pick(arrays), near=option, fovy=pick(extra))
    print(sum(counts.values()), sorted(counts.items()))


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 600)
