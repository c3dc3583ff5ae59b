"""The report's figures, drawn with matplotlib (the ``plot`` extra) without pyplot's global
state, as PNG and SVG. SVG text stays text and every point and legend has an id (``row-<i>``
for the i-th row of the report, ``pareto-<dtype>``, ``legend``, ...), so a reader or a test
can find them. `inline_png`: the error-time figure as a small PNG for a notebook."""

from __future__ import annotations

import io
from pathlib import Path
from typing import Any

import matplotlib
import numpy as np
from matplotlib.figure import Figure
from matplotlib.lines import Line2D

from .records import ReportData, Row

__all__ = ["FILES", "figures", "inline_png"]

FILES = ("error-time", "gouraud-phong", "area-lights")
MARKERS = {"avx512": "o", "avx2": "s", "baseline": "^"}
STYLE: dict[str, Any] = {"svg.fonttype": "none", "svg.hashsalt": "glshade", "font.size": 9}
# A notebook's figure: the resolutions tried, finest first, until the PNG fits its budget.
INLINE_DPIS = (72, 60, 50, 40)
# Its text drawn without antialiasing: 9-pixel letters stay legible, the PNG about halves.
INLINE_STYLE: dict[str, Any] = {**STYLE, "text.antialiased": False}
# Colours of the notebook's PNG: 64 keep the 20 scene colours apart (and the greys and blends);
# a full report's figure at 72 dpi is 9.4 kB, matplotlib's own antialiased PNG 66 kB.
INLINE_COLOURS = 64


def _save(figure: Figure, directory: Path, name: str) -> list[Path]:
    paths = [directory / f"{name}.png", directory / f"{name}.svg"]
    figure.savefig(paths[0], dpi=150)
    figure.savefig(paths[1], metadata={"Date": None})
    return paths


def _pareto(points: list[tuple[float, float]]) -> list[tuple[float, float]]:
    """The points no other point beats in both time and error, by increasing time."""
    front: list[tuple[float, float]] = []
    for t, e in sorted(points):
        if not front or e < front[-1][1]:
            front.append((t, e))
    return front


def _whole_decades(values: list[float]) -> tuple[float, float] | None:
    """Log-axis limits at whole decades around `values` where they span less than one decade
    (where matplotlib would label crowded minor ticks, or none), strictly outside them; None
    where they span a decade or more, or hold no positive number."""
    positive = [v for v in values if 0 < v < np.inf]
    if not positive or max(positive) >= 10 * min(positive):
        return None
    low = int(np.floor(np.log10(min(positive))))
    high = int(np.ceil(np.log10(max(positive))))
    low -= 10.0**low >= min(positive)
    high += 10.0**high <= max(positive)
    return 10.0**low, 10.0**high


def error_time(report: ReportData) -> Figure:
    """Max error (log) against time per vertex (log), one panel per dtype: one point per row,
    coloured by scene class, shaped by instruction set, filled for "fast" and hollow for
    "exact"; each panel's Pareto front."""
    classes = list(dict.fromkeys(r.scene for r in report.rows))
    palette = matplotlib.colormaps["tab20"]
    colour = {c: palette(i % 20) for i, c in enumerate(classes)}
    dtypes = list(dict.fromkeys(r.dtype for r in report.rows))
    figure = Figure(figsize=(11, 5.2), layout="constrained")
    axes = figure.subplots(1, len(dtypes), squeeze=False)[0]
    positive = [r.max_error for r in report.rows if r.max_error > 0]
    floor = 10 ** np.floor(np.log10(min(positive))) / 10 if positive else 1e-18
    for ax, dtype in zip(axes, dtypes, strict=True):
        rows: list[tuple[int, Row]] = [
            (i, r) for i, r in enumerate(report.rows) if r.dtype == dtype
        ]
        for i, r in rows:
            fill = "none" if r.accuracy == "exact" else colour[r.scene]
            (point,) = ax.plot(
                [r.time_ns],
                [max(r.max_error, floor)],
                linestyle="none",
                marker=MARKERS.get(r.isa, "D"),
                markersize=6,
                markerfacecolor=fill,
                markeredgecolor=colour[r.scene],
            )
            point.set_gid(f"row-{i}")
        front = _pareto([(r.time_ns, max(r.max_error, floor)) for _, r in rows])
        (line,) = ax.plot(*zip(*front, strict=True), color="0.3", drawstyle="steps-post", lw=1)
        line.set_gid(f"pareto-{dtype}")
        ax.set_xscale("log")
        ax.set_yscale("log")
        for limits, set_limits in (
            (_whole_decades([r.time_ns for _, r in rows]), ax.set_xlim),
            (_whole_decades([max(r.max_error, floor) for _, r in rows]), ax.set_ylim),
        ):
            if limits is not None:
                set_limits(*limits)
        ax.set_title(dtype)
        ax.set_xlabel("time per vertex (ns, median of the rounds)")
        ax.grid(True, which="major", color="0.9")
    axes[0].set_ylabel(
        f"max error against the long-double reference (absolute; 0 drawn at {floor:.0e})"
    )
    handles = [
        Line2D([], [], color=colour[c], marker="o", linestyle="none", label=c) for c in classes
    ]
    handles += [
        Line2D([], [], color="0.2", marker=m, linestyle="none", label=isa)
        for isa, m in MARKERS.items()
        if any(r.isa == isa for r in report.rows)
    ]
    handles += [
        Line2D([], [], color="0.2", marker="o", linestyle="none", label='filled: "fast"'),
        Line2D(
            [],
            [],
            color="0.2",
            marker="o",
            markerfacecolor="none",
            linestyle="none",
            label='hollow: "exact"',
        ),
        Line2D([], [], color="0.3", drawstyle="steps-post", label="Pareto front"),
    ]
    legend = figure.legend(handles=handles, loc="outside right center", frameon=False)
    legend.set_gid("legend")
    figure.suptitle(f"glshade: error against run time ({report.machine['cpu']})")
    return figure


def _study(
    rows: tuple[dict[str, Any], ...],
    x: str,
    errors: list[tuple[str, str]],
    times: list[tuple[str, str]],
    xlabel: str,
    title: str,
    gid: str,
) -> Figure:
    """Errors (log, left) and times (right) of a study's rows against `x` (log)."""
    figure = Figure(figsize=(7, 4.2), layout="constrained")
    ax = figure.subplots()
    twin = ax.twinx()
    xs = [r[x] for r in rows]
    handles = []
    for key, label in errors:
        (line,) = ax.plot(xs, [r[key] for r in rows], marker="o", label=label)
        handles.append(line)
    for i, r in enumerate(rows):  # one mark per row: the max error
        (mark,) = ax.plot([r[x]], [r[errors[0][0]]], linestyle="none", marker="o", color="C0")
        mark.set_gid(f"{gid}-{i}")
    for j, (key, label) in enumerate(times):
        (line,) = twin.plot(
            xs, [r[key] for r in rows], marker="s", linestyle="--", color=f"C{j + 2}", label=label
        )
        handles.append(line)
    ax.set_xscale("log")
    ax.set_yscale("log")
    twin.set_yscale("log")
    ax.set_xlabel(xlabel)
    ax.set_ylabel("error (absolute, RGB channels)")
    twin.set_ylabel("time per call (ms, median)")
    ax.set_title(title)
    ax.grid(True, color="0.9")
    legend = ax.legend(handles=handles, loc="lower left", frameon=False)
    legend.set_gid("legend")
    return figure


def figures(report: ReportData, directory: Path) -> list[Path]:
    """Writes error-time, and with the studies gouraud-phong and area-lights, as PNG and SVG
    into `directory`; the paths."""
    written: list[Path] = []
    with matplotlib.rc_context(STYLE):  # type: ignore[arg-type]
        written += _save(error_time(report), directory, "error-time")
        if report.gouraud_phong:
            figure = _study(
                report.gouraud_phong,
                "triangles",
                [("max_error", "max |Gouraud - Phong|"), ("mean_error", "mean |Gouraud - Phong|")],
                [("gouraud_ms", "Gouraud time"), ("phong_ms", "Phong time")],
                "triangles of the icosphere",
                "Gouraud against Phong shading (512 x 512, float32)",
                "gouraud",
            )
            written += _save(figure, directory, "gouraud-phong")
        if report.area_lights:
            figure = _study(
                report.area_lights,
                "k",
                [("max_error", "max error"), ("mean_error", "mean error")],
                [("ms", "time of one gs.shade call")],
                "k, points sampling the area light",
                "Area light by k points against k = 16384 (float64)",
                "area",
            )
            written += _save(figure, directory, "area-lights")
    return written


def inline_png(report: ReportData, max_bytes: int) -> bytes:
    """The error-time figure as a palette PNG for a notebook, at the finest of `INLINE_DPIS`
    whose file fits `max_bytes` (the coarsest where none does).

    Parameters
    ----------
    report : ReportData
        The report to draw (at least one row).
    max_bytes : int
        The largest PNG wanted, in bytes.

    Returns
    -------
    bytes
        The PNG file.
    """
    # Pillow is a dependency of matplotlib: present wherever this module imports.
    from PIL import Image as PillowImage

    with matplotlib.rc_context(INLINE_STYLE):  # type: ignore[arg-type]
        figure = error_time(report)
        png = b""
        for dpi in INLINE_DPIS:
            buffer = io.BytesIO()
            figure.savefig(buffer, format="png", dpi=dpi)
            buffer.seek(0)
            # No dithering: it would scatter noise over the flat background, and bytes with it.
            picture = (
                PillowImage.open(buffer)
                .convert("RGB")
                .quantize(
                    INLINE_COLOURS,
                    method=PillowImage.Quantize.FASTOCTREE,
                    dither=PillowImage.Dither.NONE,
                )
            )
            out = io.BytesIO()
            picture.save(out, format="PNG", optimize=True)
            png = out.getvalue()
            if len(png) <= max_bytes:
                break
    return png
