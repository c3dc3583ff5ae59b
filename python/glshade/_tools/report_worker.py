"""One instruction set's part of `gs.report`, in a process of its own (glshade picks its
instruction set once per process): ``python -m glshade._tools.report_worker ROUNDS FILE...``.

Each FILE is a pickled case of `report._prepare` (a class, a dtype, the inputs, the clamped
reference and the per-channel bounds). The worker shades every case in both modes, measures the
errors, then times all calls in rotating rounds; it writes one JSON line per step on stdout
(``{"step": ...}``) and the rows last (``{"rows": [...]}``).
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
from .timing import BURST, time_rounds


def _errors(case: dict[str, Any], accuracy: Literal["fast", "exact", "display"]) -> dict[str, Any]:
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
    rounds, files = int(argv[0]), [Path(a) for a in argv[1:]]
    isa = instruction_set()
    cases = [pickle.loads(f.read_bytes()) for f in files]
    partial: dict[str, dict[str, Any]] = {}
    calls: dict[str, Callable[[], Any]] = {}
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
            calls[key] = functools.partial(gs.shade, p, normals, scene, accuracy=accuracy)
    print(json.dumps({"step": "errors"}), flush=True)

    def step() -> None:
        print(json.dumps({"step": "timing"}), flush=True)

    timings = time_rounds(calls, rounds, burst=BURST, on_round=step)
    rows = []
    for key, row in partial.items():
        t, ns = timings[key], 1e9 / row["vertices"]
        rows.append(
            {
                **row,
                "time_ns": t.median * ns,
                "time_low_ns": t.low * ns,
                "time_high_ns": t.high * ns,
                "rounds": rounds,
            }
        )
    print(json.dumps({"rows": rows}), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
