"""``python -m glshade bench relief``: `glshade.relief.LightSource` beside matplotlib's own
`LightSource` on one elevation grid, in interleaved rounds, after checking that both give the
same numbers."""

from __future__ import annotations

import functools
from collections.abc import Callable
from typing import Any

import numpy as np

import glshade as gs

from .bench import save
from .machine import describe, machine
from .timing import Timing, ratio, time_rounds

# A difference above this between glshade and matplotlib stops the bench (they agree exactly).
AGREEMENT = 1e-12


def terrain(size: int) -> tuple[np.ndarray, np.ndarray]:
    """A size x size elevation grid (a smooth wave with noise) and an RGB image beside it."""
    rng = np.random.default_rng(0)
    y, x = np.mgrid[0:size, 0:size] / 100
    z = np.sin(x) * np.cos(y) * 50 + rng.normal(0, 1, (size, size))
    return z, rng.uniform(0, 1, (size, size, 3))


def bench_relief(size: int, repeat: int, json_path: str | None = None) -> int:
    """Prints (and saves at `json_path`) the median times of hillshade and of shade_rgb with
    the hsv and overlay blends, glshade's and matplotlib's, and the per-round speed-ups; exit
    status 1 if matplotlib is missing or the two disagree."""
    try:
        import matplotlib
        import matplotlib.colors as mcolors
    except ImportError:
        print("matplotlib is not installed (pip install matplotlib): nothing to compare with")
        return 1
    z, rgb = terrain(size)
    theirs, ours = mcolors.LightSource(315, 45), gs.relief.LightSource(315, 45)
    calls: dict[str, Callable[[Any], Any]] = {
        "hillshade": lambda ls: ls.hillshade(z, vert_exag=0.1),
        "shade_rgb hsv": lambda ls: ls.shade_rgb(rgb, z, blend_mode="hsv", vert_exag=0.1),
        "shade_rgb overlay": lambda ls: ls.shade_rgb(rgb, z, blend_mode="overlay", vert_exag=0.1),
    }
    print(describe(machine()))
    print(f"a {size} x {size} float64 grid and RGB image; matplotlib {matplotlib.__version__}")
    print(f"{repeat} rounds, each method once per round in rotating order")
    results: dict[str, Any] = {}
    for name, call in calls.items():
        difference = float(np.abs(call(theirs) - call(ours)).max())
        if not difference <= AGREEMENT:
            print(f"{name}: glshade and matplotlib differ by {difference:.1e}: not timed")
            return 1
        methods = {
            f"matplotlib {name}": functools.partial(call, theirs),
            f"glshade {name}": functools.partial(call, ours),
        }
        times = time_rounds(methods, repeat)
        mpl, own = times[f"matplotlib {name}"], times[f"glshade {name}"]
        speedup: Timing = ratio(mpl, own)
        print(
            f"  {name:18} matplotlib {mpl.median * 1e3:8.1f} ms   glshade {own.median * 1e3:7.1f}"
            f" ms   x{speedup.median:5.1f}   max |difference| {difference:.1e}"
        )
        results[name] = {
            "matplotlib_ms": mpl.as_dict(1e3),
            "glshade_ms": own.as_dict(1e3),
            "speedup": speedup.as_dict(1.0),
            "max_difference": difference,
        }
    save(json_path, "relief", {"size": size, "rounds": repeat}, results)
    return 0
