"""How much of one directional light's distance from the streaming floor is the equation.

``bench shade``'s "1 directional" scene three ways, in the same process, interleaved in the same
rounds, each call writing a fresh (n, 4) float32 result through the same tasks, row reads,
transposes and stores: ``gs.shade`` (the fast mode), ``lean`` (``_glshade.lean_directional``:
the same light with none of the fast mode's safeguards, its exponent compiled in, as a scene
compiler would write it; ``src/lab/lean.rs``), ``lean`` with each safeguard put back (``nan``:
NaN for a non-finite normal; ``power``: |n|² - 1 from exact squares and the power on the
complement; ``saturate``: the weights saturated) and with all three, and ``stream`` (the floor:
the same traffic, no lighting). ``lean`` is the lab's, not the wheel's: it needs a build with
the ``lab`` feature::

    maturin develop --release --features lab
    python benches/lean_directional.py                      # every thread
    RAYON_NUM_THREADS=1 python benches/lean_directional.py  # one

Prints million vertices/s (medians of the rounds), each as a fraction of the floor, and each
result's largest difference from ``gs.shade``; then the errors of ``gs.shade`` and ``lean``
near the highlight, where they differ most.
"""

from __future__ import annotations

import functools
import sys
import time
from collections.abc import Callable

import numpy as np

import glshade as gs
from glshade import _glshade
from glshade.lab import scenes

ROUNDS = 7
BURST = 5


def rates(methods: dict[str, Callable[[], object]], n: int) -> dict[str, float]:
    """Million vertices/s of each method: the median over `ROUNDS` of the best of `BURST`
    calls, the methods taking turns within each round."""
    times: dict[str, list[float]] = {name: [] for name in methods}
    for _ in range(ROUNDS):
        for name, call in methods.items():
            best = float("inf")
            for _ in range(BURST):
                start = time.perf_counter()
                call()
                best = min(best, time.perf_counter() - start)
            times[name].append(best)
    return {name: n / float(np.median(t)) / 1e6 for name, t in times.items()}


def lean_directional() -> Callable[..., np.ndarray]:
    """The lab build's lean bound; without it, an exit that names the build it needs."""
    found: Callable[..., np.ndarray] | None = getattr(_glshade, "lean_directional", None)
    if found is None:
        sys.exit(
            "this glshade build has no lean bound: build it with the lab feature, "
            "maturin develop --release --features lab"
        )
    return found


def candidates(scene: gs.Scene, normals: np.ndarray) -> dict[str, Callable[[], object]]:
    """The calls timed on `normals`, by name."""
    lean = functools.partial(lean_directional(), scene._native, normals)
    return {
        "gs.shade": functools.partial(gs.shade, normals, normals, scene),
        "lean": lean,
        "lean+nan": functools.partial(lean, nan=True),
        "lean+power": functools.partial(lean, power=True),
        "lean+saturate": functools.partial(lean, saturate=True),
        "lean+all": functools.partial(lean, nan=True, power=True, saturate=True),
        "stream": functools.partial(_glshade.stream, normals, normals, False),
    }


def main(sizes: list[int]) -> None:
    scene = scenes.bench_scenes()["1 directional"]
    for n in sizes:
        _, normals = scenes.bench_vertices(n)
        methods = candidates(scene, normals)
        for call in methods.values():
            call()  # warm: pages, pools, threads
        got = rates(methods, n)
        shaded = gs.shade(normals, normals, scene)
        print(f"n = {n:,}, million vertices/s (of the floor), |Δ| from gs.shade:")
        for name, rate in got.items():
            difference = np.abs(np.asarray(methods[name]()) - shaded).max()
            gap = "" if name == "stream" else f", |Δ| {difference:.1e}"
            print(f"  {name:14} {rate:6.0f} ({rate / got['stream']:.2f}){gap}")


def highlight_errors(n: int = 4_000_000) -> None:
    """The error that decides: near the highlight, where (n⊙ĥ)^32 is close to 1 and plain
    squaring multiplies the rounding of n⊙ĥ by 32. A dim diffuse and a bright specular colour,
    no ambient or emission, keep the sums below GL's clamp, which would hide it; the reference
    is float64 ``"exact"`` on the same float32 normals, and the bound the fast mode states
    (docs/pages/guide/accuracy.md) is 2e-6·max(1, Σ|terms|) + 16u·s·tanθ·|specular| here
    (|h| = |VP + (0, 0, 1)| > 1)."""
    diffuse, specular, s = 0.2, 0.75, 32
    material = gs.Material(
        ambient=(0, 0, 0, 1),
        diffuse=(diffuse, diffuse, diffuse, 1),
        specular=(specular, specular, specular, 1),
        shininess=s,
    )
    scene = gs.Scene([gs.Light(position=(0.3, 0.5, 1.0, 0.0))], material=material)
    light = np.array([0.3, 0.5, 1.0]) / np.linalg.norm([0.3, 0.5, 1.0])
    halfway = light + np.array([0.0, 0.0, 1.0])
    halfway /= np.linalg.norm(halfway)
    rng = np.random.default_rng(1)
    for spread in (1e-3, 1e-2, 1e-1):
        around = halfway + rng.normal(scale=spread, size=(n, 3))
        normals = (around / np.linalg.norm(around, axis=1, keepdims=True)).astype(np.float32)
        wide = normals.astype(np.float64)
        exact = gs.shade(wide, wide, scene, accuracy="exact")
        assert exact[:, :3].max() < 1, "the clamp would hide the error"
        cos = np.clip(wide @ halfway, -1.0, 1.0)
        n_dot_vp = wide @ light
        terms = diffuse * np.maximum(n_dot_vp, 0) + np.where(n_dot_vp > 0, specular * cos**s, 0)
        u = 2.0**-24
        bound = 2e-6 * np.maximum(1, terms) + 16 * u * s * np.tan(np.arccos(cos)) * specular
        line = [f"normals within ~{spread:g} of ĥ:"]
        for name, got in (
            ("fast", gs.shade(normals, normals, scene)),
            ("lean", lean_directional()(scene._native, normals)),
        ):
            error = np.abs(got - exact)[:, :3].max(axis=1)
            over = int((error > bound).sum())
            line.append(
                f"{name} |Δ| <= {error.max():.1e}, {(error / bound).max():.2f} of the bound"
            )
            line.append(f"{over} rows over")
        print(" ".join(line[:1]) + " " + ", ".join(line[1:]))


if __name__ == "__main__":
    main([int(a) for a in sys.argv[1:]] or [1_000_000, 4_000_000])
    highlight_errors()
