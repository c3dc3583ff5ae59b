"""Benchmarks run beside their baselines in the same process: ``python -m glshade bench ...``.

Timings are medians of repeated runs, quoted with the ratio to the baseline measured in the same
round; the machine's other load affects both sides alike.
"""

from __future__ import annotations

import os
import statistics
import time
from collections.abc import Callable
from typing import Any

import numpy as np
from numpy.typing import NDArray

import glshade as gs


def grid_mesh(faces: int, seed: int = 0) -> tuple[NDArray[np.float64], NDArray[np.int64]]:
    """A bumpy, jittered height-field mesh of about `faces` triangles."""
    k = int(np.ceil(np.sqrt(faces / 2)))
    rng = np.random.default_rng(seed)
    x, y = np.meshgrid(np.linspace(0, 1, k + 1), np.linspace(0, 1, k + 1))
    z = 0.1 * np.sin(12 * x) * np.cos(9 * y)
    vertices = np.stack([x, y, z], axis=-1).reshape(-1, 3)
    vertices += rng.normal(scale=0.2 / k, size=vertices.shape)
    i, j = np.meshgrid(np.arange(k), np.arange(k))
    a = (j * (k + 1) + i).ravel()
    b, c, d = a + 1, a + k + 1, a + k + 2
    tris = np.concatenate([np.stack([a, b, d], axis=1), np.stack([a, d, c], axis=1)])
    return vertices, tris[:faces].astype(np.int64)


def numpy_area_normals(v: NDArray[np.float64], f: NDArray[np.int64]) -> NDArray[np.float64]:
    """The textbook numpy implementation: scatter-add the cross products, normalise."""
    cross = np.cross(v[f[:, 1]] - v[f[:, 0]], v[f[:, 2]] - v[f[:, 0]])
    summed = np.zeros_like(v)
    for corner in range(3):
        np.add.at(summed, f[:, corner], cross)
    length = np.linalg.norm(summed, axis=1, keepdims=True)
    unit: NDArray[np.float64] = np.divide(
        summed, length, out=np.zeros_like(summed), where=length > 0
    )
    return unit


def in_rounds(
    methods: dict[str, Callable[[], Any]], repeat: int, settle: float
) -> dict[str, list[float]]:
    """Seconds per call of each method, timed in rounds: every round runs every method once, so
    all methods see the same load on a shared machine (ratios are taken within a round). The
    order rotates from round to round and runs backwards every other round, so every method
    takes every place and follows two different methods.

    Each call starts `settle` seconds after the previous one ended: numpy's OpenBLAS keeps its
    threads spinning for about 0.1 s after a call, and on a 2-core machine they would take a
    core from whichever method runs next."""
    for call in methods.values():
        call()  # warm-up
    names = list(methods)
    times: dict[str, list[float]] = {name: [] for name in names}
    for r in range(repeat):
        order = names[r % len(names) :] + names[: r % len(names)]
        for name in order[::-1] if r % 2 else order:
            time.sleep(settle)
            start = time.perf_counter()
            methods[name]()
            times[name].append(time.perf_counter() - start)
    return times


def bench_normals(faces: int, repeat: int, settle: float = 0.25) -> int:
    v, f = grid_mesh(faces)
    v32 = v.astype(np.float32)
    methods: dict[str, Callable[[], Any]] = {
        "glshade vertex_normals angle, float64": lambda: gs.vertex_normals(v, f),
        "glshade vertex_normals angle, float32": lambda: gs.vertex_normals(v32, f),
        "glshade vertex_normals area, float64": lambda: gs.vertex_normals(v, f, "area"),
        "glshade vertex_normals uniform, float64": lambda: gs.vertex_normals(v, f, "uniform"),
        "glshade face_normals, float64": lambda: gs.face_normals(v, f),
        "numpy area-weighted (np.add.at)": lambda: numpy_area_normals(v, f),
    }
    try:
        import trimesh
    except ImportError:
        trimesh = None  # type: ignore[assignment]
    if trimesh is not None:
        # A fresh mesh per call: trimesh caches its normals on the object.
        methods["trimesh vertex_normals"] = lambda: (
            trimesh.Trimesh(v, f, process=False).vertex_normals
        )
        methods["trimesh face_normals"] = lambda: trimesh.Trimesh(v, f, process=False).face_normals
    threads = os.environ.get("RAYON_NUM_THREADS") or f"{os.cpu_count()} (all cores)"
    print(f"{len(f):,} faces, {len(v):,} vertices (a jittered height field, float64, int64)")
    print(f"{repeat} rounds, each method once per round in rotating order, {settle} s apart")
    print(f"glshade threads: {threads}")
    if trimesh is not None:
        print(
            f"trimesh {trimesh.__version__}: trimesh.Trimesh(v, f, process=False).vertex_normals "
            "(and .face_normals) on a fresh mesh per call, so nothing is cached"
        )
    times = in_rounds(methods, repeat, settle)
    print(f"\n  {'method':42} {'median':>10}")
    for name, seconds in times.items():
        print(f"  {name:42} {statistics.median(seconds) * 1e3:7.1f} ms")
    if trimesh is None:
        print("\ntrimesh is not installed (pip install trimesh scipy): no trimesh baseline")
        return 0
    reference = trimesh.Trimesh(v, f, process=False).vertex_normals
    difference = np.abs(gs.vertex_normals(v, f) - reference).max()
    print(f"\nmax |glshade - trimesh|, angle weighting, float64: {difference:.1e}")
    print("\nspeed-up over trimesh, per round (median, and the range over the rounds):")
    pairs = [
        (
            "vertex normals, angle, float64",
            "trimesh vertex_normals",
            "glshade vertex_normals angle, float64",
        ),
        (
            "vertex normals, angle, float32",
            "trimesh vertex_normals",
            "glshade vertex_normals angle, float32",
        ),
        ("face normals, float64", "trimesh face_normals", "glshade face_normals, float64"),
    ]
    for label, baseline, ours in pairs:
        ratios = [b / o for b, o in zip(times[baseline], times[ours], strict=True)]
        print(
            f"  {label:42} {statistics.median(ratios):6.1f}x"
            f"   ({min(ratios):.1f}x to {max(ratios):.1f}x)"
        )
    return 0
