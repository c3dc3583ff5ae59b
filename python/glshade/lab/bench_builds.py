"""``python -m glshade bench builds``: builds of glshade's Rust core timed against each other.

A change to the kernel is measured by building the extension module before and after it
(`maturin develop --release`, copying ``python/glshade/_glshade.abi3.so`` aside each time) and
running the same scenes with each build in turn, alternating the builds for a few rounds: on
the machines measured so far, two builds of the same code can differ by 5 to 10% from where
their loops fall, and one build by a few percent from one round to the next (see the lab
notes). Each build runs in a child interpreter of its own that imports a copy of this
installation's Python package with that build as its extension module, so every build runs the
same Python code and the same call; the child checks that it imported the build it was given.
Every child, in every round, gets a fresh copy.
"""

from __future__ import annotations

import hashlib
import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import numpy as np

from .bench import save
from .machine import describe, machine

__all__ = ["bench_builds", "time_scenes"]

# The child's whole program: time the scenes with the glshade it finds first on its path.
_CHILD = (
    "import json, sys\n"
    "from glshade.lab.bench_builds import time_scenes\n"
    "print(json.dumps(time_scenes(**json.loads(sys.argv[1]))))\n"
)


def time_scenes(
    package: str, scenes: list[str], vertices: int, dtype: str, seconds: float
) -> dict[str, Any]:
    """Times `gs.shade` on each scene with this process's glshade (a child's build).

    Parameters
    ----------
    package : str
        The folder the child's glshade must come from (the copy holding the build).
    scenes : list of str
        Names of `glshade.lab.scenes.shade_scenes`.
    vertices : int
        Vertices per call (`glshade.lab.scenes.bench_vertices`).
    dtype : str
        ``"float32"`` or ``"float64"``: the arrays' type.
    seconds : float
        How long each scene is called for, after one call that is not timed (at least five
        timed calls).

    Returns
    -------
    dict
        ``module`` (the extension module's path), ``instruction_set`` and ``mvert_s`` (million
        vertices per second by scene, from the median call).

    Raises
    ------
    RuntimeError
        If glshade's extension module was not imported from `package`.
    """
    import glshade as gs
    from glshade import _glshade
    from glshade.lab.machine import instruction_set
    from glshade.lab.scenes import bench_vertices, shade_scenes

    module = Path(_glshade.__file__).resolve()
    if Path(package).resolve() not in module.parents:
        raise RuntimeError(
            f"imported glshade's core from {module}, not from the build in {package}"
        )
    every = shade_scenes()
    p, n = (a.astype(dtype) for a in bench_vertices(vertices))
    out = np.zeros((vertices, 4), dtype)
    rates = {}
    for name in scenes:
        scene = every[name]
        gs.shade(p, n, scene, out=out)
        calls: list[float] = []
        start = time.perf_counter()
        while time.perf_counter() - start < seconds or len(calls) < 5:
            t = time.perf_counter()
            gs.shade(p, n, scene, out=out)
            calls.append(time.perf_counter() - t)
        rates[name] = vertices / statistics.median(calls) / 1e6
    return {"module": str(module), "instruction_set": instruction_set(), "mvert_s": rates}


def _labels(builds: Sequence[Path], labels: Sequence[str] | None) -> list[str]:
    """`labels`, or the builds' file names (their paths where two names are the same)."""
    if labels is not None:
        if len(labels) != len(builds):
            raise ValueError(
                f"--labels: expected one label per build ({len(builds)}), got {len(labels)}"
            )
        if len(set(labels)) != len(labels):
            raise ValueError(f"--labels: expected different labels, got {list(labels)}")
        return list(labels)
    names = [b.name for b in builds]
    return names if len(set(names)) == len(names) else [str(b) for b in builds]


def _sha256(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


def _stage(build: Path, folder: Path) -> Path:
    """A copy of this installation's glshade package in `folder` with `build` as its extension
    module; the folder to put first on the child's path."""
    from glshade import _glshade

    installed = Path(_glshade.__file__).resolve()
    package = folder / "glshade"
    shutil.copytree(
        installed.parent,
        package,
        ignore=shutil.ignore_patterns("__pycache__", "_glshade.*.so", "_glshade.*.pyd"),
    )
    shutil.copyfile(build, package / installed.name)
    return folder


def _run_child(folder: Path, threads: int, arguments: dict[str, Any], label: str) -> Any:
    """The result of `time_scenes` run by a child interpreter that imports glshade from
    `folder`, with `threads` threads."""
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(filter(None, [str(folder), env.get("PYTHONPATH")]))
    env["RAYON_NUM_THREADS"] = str(threads)
    done = subprocess.run(
        [sys.executable, "-c", _CHILD, json.dumps(arguments)],
        env=env,
        capture_output=True,
        text=True,
        check=False,
    )
    if done.returncode != 0:
        lines = done.stderr.strip().splitlines()
        raise RuntimeError(
            f"build {label!r} did not run (exit status {done.returncode}): "
            f"{lines[-1] if lines else 'no message'}"
        )
    return json.loads(done.stdout.strip().splitlines()[-1])


def bench_builds(
    builds: Sequence[str | Path],
    *,
    labels: Sequence[str] | None = None,
    rounds: int = 2,
    vertices: int = 1_000_000,
    scenes: Sequence[str] = (),
    dtype: str = "float32",
    threads: int = 1,
    seconds: float = 1.5,
    json_path: str | Path | None = None,
) -> int:
    """Times `scenes` with each of `builds` in turn, `rounds` times, prints million vertices/s
    per build, round and scene and each build's speed over the first's (the median of the
    per-round ratios), and saves them at `json_path`.

    Parameters
    ----------
    builds : sequence of str or Path
        Two or more built extension modules of glshade (copies of ``_glshade.abi3.so``).
    labels : sequence of str, optional
        A name per build for the table (default: the files' names).
    rounds : int
        How many times every build runs every scene (default 2); a round runs the builds in
        the order given.
    vertices : int
        Vertices per call (default 10⁶).
    scenes : sequence of str
        Names of `glshade.lab.scenes.shade_scenes` (default: every one).
    dtype : str
        ``"float32"`` (default) or ``"float64"``.
    threads : int
        glshade's threads in each child (`RAYON_NUM_THREADS`; default 1: a change to the kernel
        shows undiluted by the threads' start and end).
    seconds : float
        How long each scene is called per build and round (default 1.5; the median call
        counts).
    json_path : str or Path, optional
        Where the JSON goes (None: nowhere).

    Returns
    -------
    int
        0.

    Raises
    ------
    ValueError
        If fewer than two builds are given, a build is not a file, the labels do not match the
        builds, or a count, duration, dtype or scene name is out of range.
    RuntimeError
        If a build cannot be imported or does not run the scenes.
    """
    from .scenes import shade_scenes

    paths = [Path(b) for b in builds]
    if len(paths) < 2:
        raise ValueError(f"builds: expected two or more extension modules, got {len(paths)}")
    for path in paths:
        if not path.is_file():
            raise ValueError(f"builds: expected a built extension module file, got {path}")
    names = _labels(paths, labels)
    for what, value in (("repeat", rounds), ("vertices", vertices), ("threads", threads)):
        if value < 1:
            raise ValueError(f"--{what}: expected a positive integer, got {value}")
    if not seconds > 0:
        raise ValueError(f"--seconds: expected a positive duration, got {seconds}")
    if dtype not in ("float32", "float64"):
        raise ValueError(f"--dtype: expected float32 or float64, got {dtype!r}")
    every = list(shade_scenes())
    chosen = list(scenes) or every
    unknown = [s for s in chosen if s not in every]
    if unknown:
        raise ValueError(f"--scenes: unknown scenes {unknown}; the scenes are {every}")

    print(describe(machine()))
    print(
        f"{len(paths)} builds, {rounds} rounds, {vertices:,} {dtype} vertices, {threads} "
        f"thread(s), each scene called for {seconds} s per build and round (the median counts)"
    )
    rows: list[dict[str, Any]] = []
    with tempfile.TemporaryDirectory(prefix="glshade-builds-") as scratch:
        for r in range(1, rounds + 1):
            for i, (label, path) in enumerate(zip(names, paths, strict=True)):
                # A fresh copy for every child: one run read a build 27% slower on one scene in
                # both its rounds, within 1% of the others in the runs before and after (cause
                # not found); whatever a copy's placement does then is not repeated each round.
                folder = _stage(path, Path(scratch) / f"{r}-{i}")
                arguments = {
                    "package": str(folder / "glshade"),
                    "scenes": chosen,
                    "vertices": vertices,
                    "dtype": dtype,
                    "seconds": seconds,
                }
                got = _run_child(folder, threads, arguments, label)
                rows.append({"build": label, "round": r, **got})
                rates = " | ".join(f"{s}: {got['mvert_s'][s]:.1f}" for s in chosen)
                print(f"{label} (round {r}, {got['instruction_set']}) {rates}", flush=True)
    ratios = {
        label: {
            s: statistics.median(
                row["mvert_s"][s] / first["mvert_s"][s]
                for row, first in zip(
                    (x for x in rows if x["build"] == label),
                    (x for x in rows if x["build"] == names[0]),
                    strict=True,
                )
            )
            for s in chosen
        }
        for label in names[1:]
    }
    for label, by_scene in ratios.items():
        print(
            f"{label} / {names[0]} (medians of per-round ratios): "
            + ", ".join(f"{s} {x:.2f}x" for s, x in by_scene.items())
        )
    settings = {
        "builds": [p.name for p in paths],
        "labels": names,
        "rounds": rounds,
        "vertices": vertices,
        "scenes": chosen,
        "dtype": dtype,
        "threads": threads,
        "seconds": seconds,
        "sha256": {label: _sha256(p) for label, p in zip(names, paths, strict=True)},
    }
    save(json_path, "builds", settings, {"rows": rows, "ratios": ratios})
    return 0
