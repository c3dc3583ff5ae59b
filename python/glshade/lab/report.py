"""`gs.report`: error against run time of every scene class, dtype, accuracy mode and
instruction set, with the area-light and Gouraud-Phong studies.

Each scene class (`scenes.report_classes`: the benchmark's typical scenes and every class of the
stiff suite) is shaded in float32 and float64, ``accuracy="fast"`` and ``"exact"``, with every
instruction set the CPU has (one child process per set: glshade picks its set once per process,
capped by ``GLSHADE_ISA``). Errors are against the reference: the
same inputs evaluated in long double (x87 extended on x86-64, a 64-bit significand) by
`baselines.equation` with the stable power ``exp(s·log1p(-|n^ - h^|²/2))``, clamped. The
references are computed first, then each instruction set's calls are timed in rotating rounds
(`timing.time_calibrated`), as the benchmarks time theirs, each call beside a fixed calibration
kernel (`KERNEL`) in the same turn: a row's headline time is its time over the kernel's, the
median of the per-round ratios, in which most of a change of the shared machine's speed
between turns, rounds and runs cancels; the absolute time in ns per vertex stays beside it.
The kernel runs in the row's instruction set, so compare instruction sets by ``time_ns``.
"""

from __future__ import annotations

import json
import os
import pickle
import subprocess
import sys
import tempfile
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Literal

import numpy as np
from numpy.typing import NDArray

from .baselines import equation, stable_power
from .bounds import BOUNDS, EDGE
from .machine import machine
from .progress import Progress
from .records import ReportData, Row
from .scenes import report_classes
from .studies import area_light_convergence, gouraud_vs_phong

__all__ = ["ISAS", "KERNEL", "MODES", "Report", "Row", "report"]

MODES: tuple[tuple[str, Literal["fast", "exact"]], ...] = (
    ("float32", "fast"),
    ("float32", "exact"),
    ("float64", "fast"),
    ("float64", "exact"),
)
ISAS = ("avx512", "avx2", "baseline")
REFERENCE = (
    "the GL equation in long double (numpy's longdouble) with the stable power "
    "exp(s log1p(-|n^ - h^|^2 / 2)), on the inputs as rounded to the dtype, clamped"
)
# Lighting arithmetic through the same thread pool, a few ms a call like most rows: under
# other people's load it slows as the rows do, which the streaming floor (memory and dispatch,
# 0.1 ms) did not: per instruction set, ratios to it moved 0.55x to 1.46x between runs, to
# this kernel 0.90x to 1.10x (the documentation's report page, docs/pages/guide/report.md).
KERNEL = (
    "gs.shade of the benchmark's 8 mixed lights, float32, accuracy fast, on as many of the "
    "benchmark's vertices as settings.vertices, in the row's instruction set, timed in the "
    "same turn as the row"
)


@dataclass(frozen=True)
class Report(ReportData):
    """The result of `report`: its rows, the machine they ran on and the studies.

    Attributes
    ----------
    rows : tuple of Row
        One per scene class, dtype, accuracy mode and instruction set.
    machine : dict
        `machine.machine`: CPU model and flags, CPUs, threads, instruction set, glshade, numpy
        and Python versions, platform, date.
    settings : dict
        ``vertices`` and ``rounds`` as asked, ``reference`` (what the errors are against),
        ``kernel`` (the calibration kernel, `KERNEL`).
    area_lights : tuple of dict
        `studies.area_light_convergence` (empty when the studies were left out).
    gouraud_phong : tuple of dict
        `studies.gouraud_vs_phong` (empty when the studies were left out).

    Notes
    -----
    ``repr(report)`` is one paragraph: the rows, the worst error over its bound, the median
    time, the studies and the machine. In a notebook a Report shows a table per dtype and
    accuracy mode (rows, largest error, worst error over its bound, flipped vertices, the
    median ns per vertex of each instruction set) and its error-against-time figure, under
    20,000 characters; without matplotlib, a line saying how to get the figure.
    """

    def __repr__(self) -> str:
        from .report_files import summary

        return summary(self)

    def _repr_html_(self) -> str:
        """A table per dtype and accuracy mode and the error-against-time figure, for a
        notebook (`report_files.html`)."""
        from .report_files import html

        return html(self)

    def write(self, directory: str | Path) -> list[Path]:
        """Writes report.md, report.json, report.csv and, with matplotlib, the figures (PNG and
        SVG) into `directory` (made if missing); returns the paths written.

        Parameters
        ----------
        directory : str or Path
            Where to write the files.

        Returns
        -------
        list of Path
            The paths written.
        """
        from .report_files import write

        return write(self, Path(directory))


def _prepare(classes: Sequence[Any], vertices: int, folder: Path, progress: Progress) -> list[Path]:
    """Inputs, reference and per-channel bounds of every class and dtype, pickled for the
    workers; one file per class and dtype."""
    files = []
    for i, cls in enumerate(classes):
        n = max(1, round(vertices * cls.share))
        p64, n64 = cls.vertices(n, np.random.default_rng(1000 + i))
        for dtype in ("float32", "float64"):
            p, normals = p64.astype(dtype), n64.astype(dtype)
            with np.errstate(over="ignore", invalid="ignore"):  # NaN rows and huge terms
                ref = equation(
                    p.astype(np.longdouble),
                    normals.astype(np.longdouble),
                    cls.scene,
                    stable_power,
                    account=True,
                )
            assert ref.magnitude is not None and ref.sensitivity is not None
            assert ref.edge is not None
            magnitude, sensitivity = ref.magnitude.astype(float), ref.sensitivity.astype(float)
            case = {
                "scene": cls.name,
                "kind": cls.kind,
                "dtype": dtype,
                "model": cls.scene,
                "positions": p,
                "normals": normals,
                "reference": np.clip(ref.rgb.astype(float), 0, 1),
                "edge": ref.edge.astype(float) < EDGE[dtype],
                "bounds": {
                    mode: BOUNDS[(dtype, mode)].per_channel(magnitude, sensitivity)
                    for d, mode in MODES
                    if d == dtype
                },
            }
            path = folder / f"{i:02d}-{dtype}.pickle"
            path.write_bytes(pickle.dumps(case))
            files.append(path)
            progress.step(f"reference: {cls.name}, {dtype}")
    return files


def _supported(isas: Sequence[str]) -> list[str]:
    """The instruction sets of `isas` this CPU runs, each asked of a child process."""
    code = "from glshade.lab.machine import instruction_set as i; print(i())"
    found: list[str] = []
    for isa in isas:
        env = {**os.environ, "GLSHADE_ISA": isa}
        out = subprocess.run(
            [sys.executable, "-c", code], env=env, capture_output=True, text=True, check=True
        )
        if out.stdout.strip() == isa:
            found.append(isa)
    return found


def _run_worker(
    isa: str, files: list[Path], rounds: int, kernel_vertices: int, progress: Progress
) -> list[Row]:
    """Measures every case with `isa` in a child process, following its rounds."""
    env = {**os.environ, "GLSHADE_ISA": isa}
    worker = [sys.executable, "-m", "glshade.lab.report_worker"]
    command = [*worker, str(rounds), str(kernel_vertices), *map(str, files)]
    rows: list[Row] = []
    with subprocess.Popen(command, env=env, stdout=subprocess.PIPE, text=True) as child:
        assert child.stdout is not None
        for line in child.stdout:
            message = json.loads(line)
            if "step" in message:
                progress.step(f"{isa}: {message['step']}")
            else:
                rows = [Row(**r) for r in message["rows"]]
    if child.returncode != 0:
        raise RuntimeError(f"the {isa} measurement failed (exit status {child.returncode})")
    return rows


def report(
    *,
    vertices: int = 100_000,
    rounds: int = 9,
    isas: Sequence[str] | None = None,
    scenes: Sequence[str] | None = None,
    studies: bool = True,
    progress: bool = True,
) -> Report:
    """Runs the error-against-run-time study and returns it as data.

    Parameters
    ----------
    vertices : int
        Vertices per scene class (>= 1; the thousand-light class takes a hundredth).
    rounds : int
        Timed rounds (>= 1); in each, every call runs `timing.BURST` times in a row and the
        fastest counts, as in ``bench shade``, and so does the calibration kernel (`KERNEL`)
        in the same turn. A row's headline, ``time_over_kernel``, is the median of the per-round
        ratios of its time per vertex to the kernel's, the smallest and largest ratio its
        spread; ``time_ns`` is the median ns per vertex, the fastest and slowest round its
        spread.
    isas : sequence of str, optional
        Instruction sets among ``"avx512"``, ``"avx2"``, ``"baseline"``; by default every one
        this CPU runs. A set the CPU lacks is left out.
    scenes : sequence of str, optional
        Names of scene classes (`Report.rows`' ``scene``); by default all of them.
    studies : bool
        Also the area-light and Gouraud-Phong studies.
    progress : bool
        Show a progress bar of the kind the place it runs in shows well: in a Jupyter kernel
        with ipywidgets (the ``notebook`` extra, ``pip install 'glshade[notebook]'``), tqdm's
        notebook widget; in a kernel without ipywidgets, none (tqdm's widget would only warn
        "IProgress not found", and a text bar would clutter the cell); elsewhere (a terminal,
        a log file, a pipe), a text bar on stderr, tqdm's when it is installed, else one line
        rewritten in place. False: no bar anywhere.

    Returns
    -------
    Report
        ``rows`` (one `Row` per scene class, dtype, accuracy mode and instruction set),
        ``machine``, ``settings``, ``area_lights`` and ``gouraud_phong``; ``to_dicts()``,
        ``to_json()``, ``to_csv()`` and ``write(directory)``.

    Examples
    --------
    >>> import glshade as gs
    >>> r = gs.report(vertices=100, rounds=1, isas=["baseline"], scenes=["1 directional"],
    ...               studies=False, progress=False)
    >>> [(row.dtype, row.accuracy, row.max_error <= row.bound)
    ...  for row in r.rows]  # doctest: +NORMALIZE_WHITESPACE
    [('float32', 'fast', True), ('float32', 'exact', True),
     ('float64', 'fast', True), ('float64', 'exact', True)]
    """
    for name, value in (("vertices", vertices), ("rounds", rounds)):
        if isinstance(value, bool) or not isinstance(value, int | np.integer) or value < 1:
            raise ValueError(f"{name} must be a positive integer, got {value!r}")
    chosen = list(ISAS if isas is None else isas)
    unknown = [i for i in chosen if i not in ISAS]
    if unknown or not chosen:
        raise ValueError(f"isas must name some of {', '.join(ISAS)}, got {chosen!r}")
    classes = report_classes()
    if scenes is not None:
        names = [c.name for c in classes]
        missing = [s for s in scenes if s not in names]
        if missing or not scenes:
            raise ValueError(f"scenes must be among {names}, got {list(scenes)!r}")
        classes = [c for c in classes if c.name in scenes]
    chosen = _supported(chosen)
    if not chosen:
        raise ValueError(f"this CPU runs none of the instruction sets {isas!r}")
    total = 2 * len(classes) + len(chosen) * (rounds + 1) + (2 if studies else 0)
    rows: list[Row] = []
    with Progress(total, "glshade report", enabled=progress) as bar:
        with tempfile.TemporaryDirectory(prefix="glshade-report-") as folder:
            files = _prepare(classes, vertices, Path(folder), bar)
            for isa in chosen:
                rows += _run_worker(isa, files, rounds, vertices, bar)
        area: list[dict[str, Any]] = []
        gouraud: list[dict[str, Any]] = []
        if studies:
            area = area_light_convergence()
            bar.step("area lights")
            gouraud = gouraud_vs_phong()
            bar.step("Gouraud against Phong")
    settings = {"vertices": vertices, "rounds": rounds, "reference": REFERENCE, "kernel": KERNEL}
    return Report(tuple(rows), machine(), settings, tuple(area), tuple(gouraud))


def error_statistics(
    got: NDArray[Any], reference: NDArray[np.float64], dtype: str
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Per channel: |got - reference| and that in ulps of `dtype` at the reference; 0 where
    both are NaN, inf where one is."""
    g = got.astype(np.float64)
    with np.errstate(invalid="ignore"):
        error = np.abs(g - reference)
    both = np.isnan(g) & np.isnan(reference)
    error = np.where(both, 0.0, np.where(np.isnan(error), np.inf, error))
    spacing = np.spacing(np.abs(np.nan_to_num(reference)).astype(dtype)).astype(np.float64)
    return error, error / spacing
