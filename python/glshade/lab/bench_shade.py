"""``python -m glshade bench shade``: `gs.shade` beside the numpy and numba baselines
(`baselines`), Dr.Jit and JAX (`peers`) and the streaming floor (the same reads and writes with
no arithmetic), with float64 exact mode, all timed in the same rounds.

Before it is timed, every method is checked against the float64 reference (`gs.shade` on the
float64 inputs, ``accuracy="exact"``) on the smooth set (`smooth_set`; `world_smooth_set` for
the world models, whose peers are `world_peers`); one whose largest error there exceeds
`TOLERANCE` (`WORLD_TOLERANCE`) is reported as FAILED and not timed. The results go to JSON
(`bench.save`) and, one row per scene, size and method, to CSV beside it (`write_csv`).
"""

from __future__ import annotations

import csv
import functools
import os
import statistics
import subprocess
import sys
import time
from collections.abc import Callable, Mapping, Sequence
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import NDArray

import glshade as gs
from glshade import _glshade

from .baselines import (
    COS_CUTOFF,
    SHININESS,
    SPECULAR,
    SPOT,
    VIEWER,
    W,
    constants,
    light_table,
    numba_shade,
    numpy_shade,
)
from .bench import save
from .c_loop import OPTIONS as C_OPTIONS
from .c_loop import c_shade, compiler_version
from .machine import describe, machine, usable_cpus
from .peers import drjit_shade, glshade_threads, jax_shade, jax_threads, versions
from .scenes import AnyScene, bench_scenes, bench_vertices, shade_scenes
from .timing import BURST, Timing, ratio, time_rounds
from .world_peers import drjit_world, numba_world

__all__ = [
    "BURST",
    "CSV_COLUMNS",
    "GRAZING",
    "MARGIN",
    "SIZES",
    "TOLERANCE",
    "WORLD_TOLERANCE",
    "bench_shade",
    "call_overhead",
    "smooth_set",
    "thread_scaling",
    "wake_cost",
    "world_smooth_set",
    "write_csv",
]

SIZES = (10_000, 100_000, 1_000_000, 4_000_000)
TOLERANCE = 1e-5  # the largest error on the smooth set of a method that is timed
# The same for the world models: pyrender's own GGX denominator, (n·h)²(alpha² - 1) + 1, cancels
# near the highlight, and in float32 its peers err up to 3e-5 on the bench's vertices.
WORLD_TOLERANCE = 1e-4
MARGIN = 1e-4  # the smooth set's least distance to a kink of the equation
# The world models' smooth set: |n·v| at least this, off grazing views, where float32 knows n·v
# only to u/|n·v| and the metallic-roughness model's specular term is that ill-conditioned.
GRAZING = 1e-2
# The methods, in the order of the table and the CSV; all but the stream are checked.
METHODS = ("glshade", "exact64", "numpy", "numba", "c", "drjit", "jax", "stream")
# The peers glshade's speed is set beside, in the table's order.
PEERS = ("numpy", "numba", "c", "drjit", "jax")
# The numpy baseline is timed up to this many vertex-lights per call (8·10⁶: 10⁶ vertices and 8
# lights, about a second a call); beyond, it would take most of the bench's time.
NUMPY_WORK = 8_000_000
CSV_COLUMNS = (
    "scene",
    "vertices",
    "method",
    "mvert_s",
    "ms_median",
    "err_smooth",
    "ratio_glshade_over_method",
)

Method = Callable[[], Any]


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


def _unit(v: NDArray[np.float64]) -> NDArray[np.float64]:
    """v / |v| per row."""
    out: NDArray[np.float64] = v / np.sqrt(np.einsum("ij,ij->i", v, v))[:, None]
    return out


def smooth_set(
    positions: NDArray[Any], normals: NDArray[Any], scene: gs.Scene, margin: float = MARGIN
) -> NDArray[np.bool_]:
    """The vertices at least `margin` from every kink of the equation, where a correct float32
    method is within a few ulp of the sum: near a kink one rounding can move a vertex across
    it, and the error is then the size of the jump, whatever the method.

    For every light: |n^ . VP| > `margin` (GL's specular gate and the diffuse term's kink);
    for a spot, |cos - cos cutoff| > `margin` (the cone's edge); and where the gate is open and
    the light has a specular colour, |n^ . h^| > `margin` (the kink of max(n . h, 0)). Computed
    in float64 from the inputs as given; a zero normal is never smooth.

    Parameters
    ----------
    positions, normals : (n, 3) float arrays
        Eye-space vertices and their normals, as given to `gs.shade`.
    scene : Scene
        Its lights, material and viewer.
    margin : float
        The least distance to a kink, in units of the cosines above.

    Returns
    -------
    (n,) bool ndarray
        True where the vertex is smooth.
    """
    p = np.asarray(positions, np.float64)
    table, k = light_table(scene, np.float64), constants(scene, np.float64)
    eye = k[VIEWER : VIEWER + 4]
    with np.errstate(divide="ignore", invalid="ignore"):
        n_hat = _unit(np.asarray(normals, np.float64))
        view = _unit(eye[:3] / eye[3] - p) if eye[3] != 0 else _unit(eye[None, :3])
        smooth = np.ones(len(p), bool)
        for row in table:
            vp = _unit(row[:3] - p) if row[W] != 0 else np.broadcast_to(row[:3], p.shape)
            n_dot_vp = np.einsum("ij,ij->i", n_hat, vp)
            smooth &= np.abs(n_dot_vp) > margin
            if row[COS_CUTOFF] > -2:
                smooth &= np.abs(-(vp @ row[SPOT : SPOT + 3]) - row[COS_CUTOFF]) > margin
            if k[SHININESS] != 0 and (row[SPECULAR : SPECULAR + 3] != 0).any():
                n_dot_h = np.einsum("ij,ij->i", n_hat, _unit(vp + view))
                smooth &= (n_dot_vp < 0) | (np.abs(n_dot_h) > margin)
    return smooth


def world_smooth_set(
    positions: NDArray[Any], normals: NDArray[Any], scene: gs.gltf.Scene | gs.threejs.Scene
) -> NDArray[np.bool_]:
    """The vertices of a world model's scene at least `GRAZING` from a grazing view
    (|n̂ . v̂| > `GRAZING`), in float64 from the inputs as given; a zero normal is never smooth.
    (The bench's world scenes have no jump: no spot without penumbra, no shininess below 1.)"""
    p = np.asarray(positions, np.float64)
    direction = getattr(scene, "view_direction", None)
    with np.errstate(divide="ignore", invalid="ignore"):
        n_hat = _unit(np.asarray(normals, np.float64))
        if direction is None:
            view = _unit(np.asarray(scene.camera_position, np.float64) - p)
        else:
            view = _unit(np.asarray(direction, np.float64)[None, :])
        n_dot_v = np.einsum("ij,ij->i", n_hat, np.broadcast_to(view, p.shape))
        return np.asarray(np.abs(n_dot_v) > GRAZING)


def _check(
    methods: Mapping[str, Method],
    reference: NDArray[Any],
    smooth: NDArray[np.bool_],
    tolerance: float,
) -> tuple[dict[str, float | None], dict[str, str]]:
    """Each method's largest |error| on the smooth set (None where it raised), and why each
    that is not to be timed FAILED (an exception, a wrong shape or dtype, an error above
    `tolerance` or NaN)."""
    errors: dict[str, float | None] = {}
    failed: dict[str, str] = {}
    for name, call in methods.items():
        try:
            out = np.asarray(call())
        except Exception as exc:  # a peer's own failure is a result, not the bench's
            errors[name], failed[name] = None, f"raised {type(exc).__name__}: {exc}"
            continue
        if out.shape != reference.shape or out.dtype not in (np.float32, np.float64):
            errors[name], failed[name] = None, f"returned {out.dtype} {out.shape}"
            continue
        error = float(np.abs(out[smooth] - reference[smooth]).max(initial=0.0))
        errors[name] = error
        if not error <= tolerance:  # NaN fails too
            failed[name] = f"error {error:.1e} > {tolerance:.0e}"
    return errors, failed


def _header(compiled: Mapping[str, Any]) -> dict[str, Any]:
    """Prints the machine, the protocol and the version and threads of each compiled method
    (numba, Dr.Jit, JAX: a callable, or why there is none); returns them for the settings."""
    m = machine()
    print(describe(m))
    print(f"CPU: {m['cpu']}; glshade's instruction set: {m['instruction_set']}")
    print(
        f"float32, a new (n, 4) array per call; every method is first checked against "
        f"gs.shade(float64, accuracy='exact') on the smooth set (at least {MARGIN:.0e} from every "
        f"kink; FAILED above {TOLERANCE:.0e}; the world models: |n.v| > {GRAZING:.0e}, FAILED "
        f"above {WORLD_TOLERANCE:.0e}, then not timed); in each round every method "
        f"runs {BURST} times in a row and its fastest call counts"
    )
    found = versions()
    llvm = f" (LLVM {found['drjit_llvm']})" if "drjit_llvm" in found else ""
    print(
        f"versions: numba {found['numba']}, drjit {found['drjit']}{llvm}, jax {found['jax']}, "
        f"jaxlib {found['jaxlib']}"
    )
    settings: dict[str, Any] = {"versions": found}
    numba, peers = compiled["numba"], compiled
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
    threads = glshade_threads()
    if isinstance(peers["c"], str):
        print(peers["c"])
        settings["c"] = {"unavailable": peers["c"]}
    else:
        settings["c"] = {"compiler": compiler_version(), "flags": " ".join(C_OPTIONS)}
        settings["c"]["threads"] = threads
        print(
            f"C loop: {settings['c']['compiler']}, {settings['c']['flags']} (OpenMP over tiles "
            f"of 256 vertices, one vector loop a light; {threads} threads, glshade's)"
        )
    if isinstance(peers["drjit"], str):
        print(peers["drjit"])
        settings["drjit"] = {"unavailable": peers["drjit"]}
    else:
        settings["drjit"] = {"version": found["drjit"], "llvm": found.get("drjit_llvm")}
        settings["drjit"]["threads"] = threads
        print(
            f"Dr.Jit {found['drjit']} (drjit.llvm on LLVM {found.get('drjit_llvm')}, traced per "
            f"call with the scene as literals, one kernel; {threads} threads, glshade's)"
        )
    if isinstance(peers["jax"], str):
        print(peers["jax"])
        settings["jax"] = {"unavailable": peers["jax"]}
    else:
        settings["jax"] = {"version": found["jax"], "jaxlib": found["jaxlib"]}
        settings["jax"]["threads"] = jax_threads()
        print(
            f"JAX {found['jax']}, jaxlib {found['jaxlib']} (jax.jit on the CPU, lights "
            f"unrolled; XLA:CPU's threads follow the affinity mask: {jax_threads()} threads)"
        )
        if jax_threads() != threads:
            print(
                f"note: JAX runs {jax_threads()} threads, glshade and Dr.Jit {threads}; run "
                f"under taskset -c 0-{threads - 1} for {threads} of each"
            )
    return settings


def _methods(
    p: NDArray[np.float32],
    normals: NDArray[np.float32],
    scene: AnyScene,
    compiled: Mapping[str, Any],
) -> dict[str, Method]:
    """Every method of `METHODS` on these vertices, each a call with no arguments; the
    compiled ones (numba, the C loop, Dr.Jit, JAX) where `compiled` holds a callable, not a
    reason; the numpy baseline for GL's scenes alone."""
    p64, normals64 = p.astype(np.float64), normals.astype(np.float64)
    reads_positions = "reads positions" in scene.plan()
    methods: dict[str, Method] = {
        "glshade": functools.partial(gs.shade, p, normals, scene),
        "exact64": functools.partial(gs.shade, p64, normals64, scene, accuracy="exact"),
    }
    # numpy's Python loop over lights takes seconds per call beyond this; its rows get a dash.
    if isinstance(scene, gs.Scene) and len(p) * max(1, len(scene.lights)) <= NUMPY_WORK:
        methods["numpy"] = functools.partial(numpy_shade, p, normals, scene)
    for name, shade in compiled.items():
        if not isinstance(shade, str):
            methods[name] = functools.partial(shade, p, normals, scene)
    methods["stream"] = functools.partial(_glshade.stream, p, normals, reads_positions)
    return methods


def _cell(values: Mapping[str, float], name: str, failed: Mapping[str, str], text: str) -> str:
    """`text` formatted with the value of `name`, FAILED, or a dash, right-aligned as wide."""
    width = len(text.format(1.0))
    if name in values:
        return text.format(values[name])
    return f"{'FAILED' if name in failed else '-':>{width}}"


def _print_row(
    n: int,
    rate: Mapping[str, float],
    speedup: Mapping[str, Timing],
    errors: Mapping[str, float | None],
    failed: Mapping[str, str],
    smooth: int,
) -> None:
    """One size's rates and ratios, then every method's error on the smooth set and why any
    FAILED."""
    ratios = {k: r.median for k, r in speedup.items()}
    inverse = {k: 1.0 / r for k, r in ratios.items()}  # times over "fast", as printed before
    cells = [_cell(rate, k, failed, "{:9.1f}") for k in ("glshade", *PEERS, "stream")]
    cells += [_cell(ratios, k, failed, "{:7.1f}x") for k in PEERS]
    cells.append(_cell(ratios, "stream", failed, "{:9.2f}"))
    cells.append(_cell(inverse, "exact64", failed, "{:8.2f}x"))
    rates = len(PEERS) + 2
    print(f"  {n:>10,} {' '.join(cells[:rates])}   {' '.join(cells[rates:])}")
    shown = ", ".join(
        f"{name} {'-' if error is None else f'{error:.1e}'}" for name, error in errors.items()
    )
    print(f"  {'':>10} max |error| on the smooth set ({smooth:,} of {n:,} vertices): {shown}")
    for name, why in failed.items():
        print(f"  {'':>10} {name} FAILED ({why}): not timed")


def _measure(
    name: str, scene: AnyScene, n: int, repeat: int, compiled: Mapping[str, Any]
) -> dict[str, Any]:
    """Checks and times every method on `n` of the bench's vertices; prints the row and
    returns the JSON's entry for it."""
    p, normals = bench_vertices(n)
    methods = _methods(p, normals, scene, compiled)
    reference = gs.shade(p.astype(np.float64), normals.astype(np.float64), scene, accuracy="exact")
    if isinstance(scene, gs.Scene):
        smooth, tolerance = smooth_set(p, normals, scene), TOLERANCE
    else:
        smooth, tolerance = world_smooth_set(p, normals, scene), WORLD_TOLERANCE
    checked = {k: call for k, call in methods.items() if k != "stream"}
    errors, failed = _check(checked, reference, smooth, tolerance)
    entry: dict[str, Any] = {"scene": name, "plan": scene.plan(), "vertices": n}
    entry.update(smooth_vertices=int(smooth.sum()), error_smooth=errors, failed=failed)
    timed = {k: call for k, call in methods.items() if k not in failed}
    if "glshade" in failed:  # nothing to compare with
        entry.update(mvert_s={}, ms={}, speedup={})
        _print_row(n, {}, {}, errors, failed, int(smooth.sum()))
        return entry
    times = time_rounds(timed, repeat, burst=BURST)
    rate = {k: n / t.median / 1e6 for k, t in times.items()}
    # Per-round ratios: other / glshade, so the stream's is glshade's fraction of the floor,
    # exact64's its time over fast, the rest its speed-up.
    speedup = {k: ratio(times[k], times["glshade"]) for k in times if k != "glshade"}
    _print_row(n, rate, speedup, errors, failed, int(smooth.sum()))
    entry.update(
        mvert_s=rate,
        ms={k: t.as_dict(1e3) for k, t in times.items()},
        speedup={k: r.as_dict() for k, r in speedup.items()},
    )
    return entry


def write_csv(path: str | Path, rows: Sequence[Mapping[str, Any]]) -> None:
    """Writes `CSV_COLUMNS`, one row per scene, size and method, from the JSON's entries.

    Parameters
    ----------
    path : str or Path
        Where the CSV goes.
    rows : sequence of dict
        The entries of ``results["scenes"]``: ``scene``, ``vertices``, ``mvert_s``, ``ms``,
        ``speedup``, ``error_smooth`` and ``failed``. A method that was not timed has empty
        rate, time and ratio cells; the stream, never checked, an empty error.
    """
    with Path(path).open("w", newline="") as file:
        writer = csv.writer(file)
        writer.writerow(CSV_COLUMNS)
        for row in rows:
            present = {*row["mvert_s"], *row["error_smooth"]}
            for method in (m for m in METHODS if m in present):
                error = row["error_smooth"].get(method)
                timed = method in row["mvert_s"]
                speedup = 1.0 if method == "glshade" else row["speedup"].get(method, {})
                writer.writerow(
                    [
                        row["scene"],
                        row["vertices"],
                        method,
                        row["mvert_s"][method] if timed else "",
                        row["ms"][method]["median"] if timed else "",
                        "" if error is None else error,
                        speedup if isinstance(speedup, float) else speedup.get("median", ""),
                    ]
                )


def _serve(n: int) -> None:  # pragma: no cover  (runs in `thread_scaling`'s children)
    """A child of `thread_scaling`: shades "8 mixed" on `n` vertices once, says ``ready``, then
    for every line read runs `BURST` calls and writes the fastest one's seconds."""
    scene = bench_scenes()["8 mixed"]
    p, normals = bench_vertices(n)
    gs.shade(p, normals, scene)
    print("ready", flush=True)
    for _ in sys.stdin:
        fastest = float("inf")
        for _ in range(BURST):
            start = time.perf_counter()
            gs.shade(p, normals, scene)
            fastest = min(fastest, time.perf_counter() - start)
        print(repr(fastest), flush=True)


def _answer(child: subprocess.Popen[str], threads: int, expected: str | None = None) -> str:
    """The next line of a child of `thread_scaling`, after asking it for a burst unless it is
    `expected` unasked; RuntimeError where it ended or said something else."""
    assert child.stdin is not None and child.stdout is not None  # both are pipes
    if expected is None:
        child.stdin.write("\n")
        child.stdin.flush()
    line = child.stdout.readline().strip()
    if not line or (expected is not None and line != expected):
        raise RuntimeError(f"the child with RAYON_NUM_THREADS={threads} said {line!r}")
    return line


def thread_scaling(n: int, repeat: int, threads: tuple[int, ...] = (1, 2)) -> dict[str, Any]:
    """glshade on "8 mixed" at `n` vertices with each thread count, timed in interleaved rounds.

    The pool's size is fixed per process, so each count runs in a child of this Python with
    ``RAYON_NUM_THREADS`` set; all children live through all rounds, and in each round each
    in turn (the order alternating) runs `BURST` calls and reports its fastest, timed inside
    the child, while the others wait on their input.

    Parameters
    ----------
    n : int
        Vertices.
    repeat : int
        Rounds (>= 1).
    threads : tuple of int
        The thread counts; the speed-ups are over the first.

    Returns
    -------
    dict
        ``scene``, ``vertices``, ``threads``, ``mvert_s`` and ``ms`` (`Timing.as_dict`) by
        thread count, and ``speedup``: per count after the first, the per-round ratios of the
        first's time over its (`Timing.as_dict`).
    """
    code = f"from glshade.lab.bench_shade import _serve; _serve({n})"
    children = {
        t: subprocess.Popen(
            [sys.executable, "-c", code],
            stdin=subprocess.PIPE,
            stdout=subprocess.PIPE,
            text=True,
            env={**os.environ, "RAYON_NUM_THREADS": str(t)},
        )
        for t in threads
    }
    seconds: dict[int, list[float]] = {t: [] for t in threads}
    try:
        for t, child in children.items():
            _answer(child, t, "ready")
        for r in range(repeat):
            for t in threads[::-1] if r % 2 else threads:
                seconds[t].append(float(_answer(children[t], t)))
    finally:
        for child in children.values():
            child.communicate()  # closes its input: the child's loop ends
    times = {t: Timing(tuple(s)) for t, s in seconds.items()}
    first = threads[0]
    return {
        "scene": "8 mixed",
        "vertices": n,
        "threads": list(threads),
        "mvert_s": {str(t): n / times[t].median / 1e6 for t in threads},
        "ms": {str(t): times[t].as_dict(1e3) for t in threads},
        "speedup": {str(t): ratio(times[first], times[t]).as_dict() for t in threads[1:]},
    }


def _print_scaling(scaling: dict[str, Any], repeat: int) -> None:
    """The thread-scaling line(s) of `thread_scaling`'s result."""
    rates, ms = scaling["mvert_s"], scaling["ms"]
    print(
        f"\nthreads: glshade on 8 mixed, {scaling['vertices']:,} vertices, each thread count in "
        f"its own process (RAYON_NUM_THREADS), {repeat} interleaved rounds; "
        f"{usable_cpus()} usable CPUs"
    )
    for t in scaling["threads"]:
        line = f"  {t} thread{'s' if t > 1 else ''}: {rates[str(t)]:.1f} million vertices/s "
        line += f"({ms[str(t)]['median']:.2f} ms)"
        if str(t) in scaling["speedup"]:
            s = scaling["speedup"][str(t)]
            line += (
                f", {s['median']:.2f}x one thread's (rounds {s['low']:.2f}x to {s['high']:.2f}x)"
            )
        print(line)


def bench_shade(
    sizes: tuple[int, ...],
    repeat: int,
    json_path: str | None = None,
    scenes: Sequence[str] | None = None,
    threads_check: bool = True,
) -> int:
    """Prints (and saves at `json_path`, with a CSV beside it), for every scene and size, each
    method's error on the smooth set (`smooth_set`; `world_smooth_set` for the world models)
    and the median million vertices per second of glshade, numpy, numba, Dr.Jit and JAX (the
    world models: numba and Dr.Jit, `world_peers`), glshade's speed-up over each, its
    fraction of the streaming floor (`_glshade.stream`: the same tasks, reads, transposes and
    fresh result, no lighting) and float64 "exact" mode's time over float32 "fast" (all
    medians of per-round ratios); then glshade's speed-up from 1 to 2 threads.

    Parameters
    ----------
    sizes : tuple of int
        Vertex counts.
    repeat : int
        Rounds.
    json_path : str, optional
        Where the JSON goes (`bench.save`); the CSV goes beside it with the suffix ``.csv``.
        None: neither is written.
    scenes : sequence of str, optional
        Keys of `scenes.shade_scenes` (`scenes.scene_names` parses the ``--scenes`` list);
        default: every one, GL's and the world models'.
    threads_check : bool
        Also time glshade on "8 mixed" at the largest size with 1 and 2 threads
        (`thread_scaling`).

    Returns
    -------
    int
        The exit status, 0.
    """
    names = list(scenes) if scenes is not None else list(shade_scenes())
    compiled: dict[str, Any] = {
        "numba": numba_shade(),
        "c": c_shade(glshade_threads()),
        "drjit": drjit_shade(),
        "jax": jax_shade(),
    }
    # The world models' peers: numba and Dr.Jit (no JAX or numpy version of them).
    world: dict[str, Any] = {"numba": numba_world(), "drjit": drjit_world()}
    settings = _header(compiled)
    settings.update(sizes=list(sizes), rounds=repeat, burst=BURST, scenes=names)
    settings.update(tolerance=TOLERANCE, margin=MARGIN)
    settings.update(world_tolerance=WORLD_TOLERANCE, grazing=GRAZING)
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
    every = shade_scenes()
    for name in names:
        scene = every[name]
        print(f"\n{name}: {scene.plan()}")
        rates = " ".join(f"{k:>9}" for k in ("glshade", *PEERS, "stream"))
        ratios = " ".join(f"{'x ' + k:>8}" for k in PEERS)
        print(
            f"  {'vertices':>10} {rates}   {ratios} {'of stream':>9} {'f64 exact':>9}"
            "   (million vertices/s; ratios: medians of per-round ratios)"
        )
        for n in sizes:
            peers = compiled if isinstance(scene, gs.Scene) else world
            results["scenes"].append(_measure(name, scene, n, repeat, peers))
    if threads_check:
        results["threads"] = thread_scaling(max(sizes), repeat)
        _print_scaling(results["threads"], repeat)
    save(json_path, "shade", settings, results)
    if json_path is not None:
        table = Path(json_path).with_suffix(".csv")
        write_csv(table, results["scenes"])
        print(f"wrote {table}")
    return 0
