"""One instruction set's part of `gs.report`, in a process of its own (glshade picks its
instruction set once per process):
``python -m glshade.lab.report_worker ROUNDS KERNEL_VERTICES FILE...``.

Each FILE is a pickled case of `report._prepare` (a class, a dtype, the inputs, the clamped
reference and the per-channel bounds). The worker shades every case in every mode, measures the
errors, then times all calls in rotating rounds, each beside the calibration kernel
(`report.KERNEL`: a fixed `gs.shade` call on KERNEL_VERTICES vertices); it writes
one JSON line per step on stdout (``{"step": ...}``) and the rows last (``{"rows": [...]}``).
"""

from __future__ import annotations

import functools
import json
import pickle
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any, Literal

import numpy as np

import glshade as gs

from .bounds import BOUNDS
from .machine import instruction_set
from .report import MODES, error_statistics
from .scenes import bench_scenes, bench_vertices
from .timing import BURST, time_calibrated


def _errors(case: dict[str, Any], accuracy: Literal["fast", "exact"]) -> dict[str, Any]:
    """The error fields of a row: `gs.shade` of the case against its reference."""
    dtype = case["dtype"]
    got = gs.shade(case["positions"], case["normals"], case["model"], accuracy=accuracy)[:, :3]
    error, ulps = error_statistics(got, case["reference"], dtype)
    bound = case["bounds"][accuracy]
    over = error > bound
    flipped = over.any(axis=1) & case["edge"]  # at a discontinuity, on its other side
    kept = ~flipped[:, None] & np.ones_like(over)
    with np.errstate(divide="ignore", invalid="ignore"):
        ratio = np.where(bound > 0, error / bound, np.where(error > 0, np.inf, 0.0))
    return {
        "max_error": float(error.max()),
        "mean_error": float(error.mean()),
        "p999_error": float(np.quantile(error, 0.999)),
        "max_ulps": float(ulps.max()),
        "mean_ulps": float(ulps.mean()),
        "p999_ulps": float(np.quantile(ulps, 0.999)),
        "bound": BOUNDS[(dtype, accuracy)].unit,
        "max_error_over_bound": float(ratio[kept].max()) if kept.any() else 0.0,
        "flipped": int(flipped.sum()),
    }


def main(argv: list[str]) -> int:
    rounds, kernel_vertices, files = int(argv[0]), int(argv[1]), [Path(a) for a in argv[2:]]
    isa = instruction_set()
    cases = [pickle.loads(f.read_bytes()) for f in files]
    # The calibration kernel: one fixed call for every row, whatever its class, dtype and mode.
    p32, n32 = bench_vertices(kernel_vertices)
    kernel = functools.partial(gs.shade, p32, n32, bench_scenes()["8 mixed"], accuracy="fast")
    partial: dict[str, dict[str, Any]] = {}
    calls: dict[str, tuple[Callable[[], Any], Callable[[], Any]]] = {}
    for case in cases:
        for dtype, accuracy in MODES:
            if dtype != case["dtype"]:
                continue
            key = f"{case['scene']}|{dtype}|{accuracy}"
            n = len(case["positions"])
            partial[key] = {
                "scene": case["scene"],
                "kind": case["kind"],
                "dtype": dtype,
                "accuracy": accuracy,
                "isa": isa,
                "vertices": n,
                **_errors(case, accuracy),
            }
            p, normals, scene = case["positions"], case["normals"], case["model"]
            own = functools.partial(gs.shade, p, normals, scene, accuracy=accuracy)
            calls[key] = (own, kernel)
    print(json.dumps({"step": "errors"}), flush=True)

    def step() -> None:
        print(json.dumps({"step": "timing"}), flush=True)

    timings = time_calibrated(calls, rounds, burst=BURST, on_round=step)
    rows = []
    for key, row in partial.items():
        t, ns, kernel_ns = timings[key], 1e9 / row["vertices"], 1e9 / kernel_vertices
        # Per vertex over per vertex: the thousand-light class shades fewer vertices per call.
        relative = t.relative.as_dict(kernel_vertices / row["vertices"])
        rows.append(
            {
                **row,
                "time_ns": t.own.median * ns,
                "time_low_ns": t.own.low * ns,
                "time_high_ns": t.own.high * ns,
                "time_over_kernel": relative["median"],
                "time_over_kernel_low": relative["low"],
                "time_over_kernel_high": relative["high"],
                "kernel_ns": t.calibration.median * kernel_ns,
                "kernel_low_ns": t.calibration.low * kernel_ns,
                "kernel_high_ns": t.calibration.high * kernel_ns,
                "rounds": rounds,
            }
        )
    print(json.dumps({"rows": rows}), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
