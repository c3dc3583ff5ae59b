"""``python -m glshade bench shade``: `gs.shade` beside the numpy and numba baselines
(`baselines`) and the streaming floor (the same reads and writes with no arithmetic) on the
benchmark's scenes, with the display tier and float64 exact mode, timed in the same rounds."""

from __future__ import annotations

import functools
import os
import statistics
import time
from collections.abc import Callable
from typing import Any

import numpy as np

import glshade as gs
from glshade import _glshade

from .baselines import numba_shade, numpy_shade
from .bench import save
from .machine import describe, machine
from .scenes import bench_scenes, bench_vertices
from .timing import BURST, ratio, time_rounds

__all__ = ["BURST", "SIZES", "bench_shade", "call_overhead", "wake_cost"]

SIZES = (10_000, 100_000, 1_000_000, 4_000_000)


def call_overhead(repeat: int = 2000) -> float:
    """Median seconds of `gs.shade` on 16 float32 vertices and one directional light."""
    scene = gs.Scene([gs.Light()])
    p, n = bench_vertices(16)
    for _ in range(100):
        gs.shade(p, n, scene)
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        gs.shade(p, n, scene)
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def wake_cost(n: int = 1_000_000, repeat: int = 7) -> tuple[float, float]:
    """Median seconds of `gs.shade` (one directional light, `n` vertices) right after 50 ms of
    idle, and back to back."""
    scene = bench_scenes()["1 directional"]
    p, normals = bench_vertices(n)
    cold: list[float] = []
    warm: list[float] = []
    for _ in range(repeat):
        time.sleep(0.05)
        for times in (cold, warm):
            start = time.perf_counter()
            gs.shade(p, normals, scene)
            times.append(time.perf_counter() - start)
    return statistics.median(cold), statistics.median(warm)


def bench_shade(sizes: tuple[int, ...], repeat: int, json_path: str | None = None) -> int:
    """Prints (and saves at `json_path`), for every scene and size, the median million vertices
    per second of glshade, numpy and numba, glshade's speed-up over each, its fraction of the
    streaming floor (`_glshade.stream`: the same tasks, reads, transposes and fresh result,
    no lighting), the display tier's speed-up over "fast" and float64 "exact" mode's time over
    float32 "fast" (all medians of per-round ratios)."""
    numba = numba_shade()
    m = machine()
    print(describe(m))
    print(f"CPU: {m['cpu']}; glshade's instruction set: {m['instruction_set']}")
    print(
        f"float32, a new (n, 4) array per call; {repeat} rounds; in each round every method "
        f"runs {BURST} times in a row and its fastest call counts"
    )
    settings: dict[str, Any] = {"sizes": list(sizes), "rounds": repeat, "burst": BURST}
    if isinstance(numba, str):
        print(numba)
    else:
        import numba as nb

        # Compiles the kernel and starts the threading layer, which is named only after that.
        numba(*bench_vertices(64), bench_scenes()["1 directional"])
        layer = nb.threading_layer()  # type: ignore[attr-defined]
        settings["numba"] = {
            "version": nb.__version__,
            "threads": nb.get_num_threads(),
            "threading_layer": layer,
            "OMP_WAIT_POLICY": os.environ["OMP_WAIT_POLICY"],
        }
        print(
            f"numba {nb.__version__} (parallel=True, {nb.get_num_threads()} threads, "
            f"{layer} layer, OMP_WAIT_POLICY={os.environ['OMP_WAIT_POLICY']})"
        )
    overhead = call_overhead()
    print(f"per-call overhead: {overhead * 1e6:.1f} us (16 vertices, one light, median)")
    cold, warm = wake_cost()
    print(
        f"waking idle cores: {cold * 1e3:.2f} ms for the first call after 50 ms of idle, "
        f"{warm * 1e3:.2f} ms for the next (10^6 vertices, one light, medians)"
    )
    results: dict[str, Any] = {
        "call_overhead_us": overhead * 1e6,
        "wake_ms": {"after_idle": cold * 1e3, "next": warm * 1e3},
        "scenes": [],
    }
    for name, scene in bench_scenes().items():
        print(f"\n{name}: {scene.plan()}")
        print(
            f"  {'vertices':>10} {'glshade':>9} {'numpy':>9} {'numba':>9} {'stream':>9}"
            f"   {'x numpy':>8} {'x numba':>8} {'of stream':>9} {'display':>8} {'f64 exact':>9}"
            "   (million vertices/s; ratios: medians of per-round ratios)"
        )
        reads_positions = "reads positions" in scene.plan()
        for n in sizes:
            p, normals = bench_vertices(n)
            p64, normals64 = p.astype(np.float64), normals.astype(np.float64)
            methods: dict[str, Callable[[], Any]] = {
                "glshade": functools.partial(gs.shade, p, normals, scene),
                "stream": functools.partial(_glshade.stream, p, normals, reads_positions),
                "display": functools.partial(gs.shade, p, normals, scene, accuracy="display"),
                "exact64": functools.partial(gs.shade, p64, normals64, scene, accuracy="exact"),
                "numpy": functools.partial(numpy_shade, p, normals, scene),
            }
            if not isinstance(numba, str):
                methods["numba"] = functools.partial(numba, p, normals, scene)
            times = time_rounds(methods, repeat, burst=BURST)
            rate = {k: n / t.median / 1e6 for k, t in times.items()}
            # Per-round ratios: other / glshade, so the stream's is glshade's fraction of the
            # floor, display's its speed-up over fast, and exact64's its time over fast.
            speedup = {k: ratio(times[k], times["glshade"]) for k in times if k != "glshade"}
            cells = [f"{speedup[k].median:7.1f}x" if k in speedup else f"{'-':>8}" for k in
                     ("numpy", "numba")]  # fmt: skip
            display = 1.0 / speedup["display"].median
            exact = 1.0 / speedup["exact64"].median
            print(
                f"  {n:>10,} {rate['glshade']:9.1f} {rate['numpy']:9.1f} "
                f"{rate.get('numba', float('nan')):9.1f} {rate['stream']:9.1f}   {cells[0]} "
                f"{cells[1]} {speedup['stream'].median:9.2f} {display:7.2f}x {exact:8.2f}x"
            )
            results["scenes"].append(
                {
                    "scene": name,
                    "plan": scene.plan(),
                    "vertices": n,
                    "mvert_s": rate,
                    "ms": {k: t.as_dict(1e3) for k, t in times.items()},
                    "speedup": {k: r.as_dict() for k, r in speedup.items()},
                }
            )
    save(json_path, "shade", settings, results)
    return 0
