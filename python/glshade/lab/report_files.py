"""The files of ``python -m glshade report --out DIR``: report.md, report.json, report.csv and
the figures (with matplotlib); and the report as it shows itself: `summary` (its repr) and
`html` (in a notebook)."""

from __future__ import annotations

import base64
import html as html_text
import math
import statistics
from pathlib import Path

from .machine import describe
from .records import ReportData, Row

__all__ = ["html", "markdown", "summary", "write"]

NO_FIGURES = "no figures: matplotlib is not installed (pip install 'glshade[plot]')"
NO_FIGURE = "no figure: matplotlib is not installed (pip install 'glshade[plot]')"
# A notebook's report stays under this many characters, its figure included.
HTML_LIMIT = 20_000


def _count(n: int, noun: str) -> str:
    """``"1 row"``, ``"2 rows"``, ``"1,000 vertices"``, ``"2 scene classes"``."""
    if n == 1:
        return f"1 {noun}"
    plural = {"vertex": "vertices"}.get(noun, noun + ("es" if noun.endswith("s") else "s"))
    return f"{n:,} {plural}"


def _names(values: list[str]) -> str:
    return ", ".join(dict.fromkeys(values))


def _worst(rows: list[Row]) -> Row | None:
    """The row of the largest error over its bound (NaN ratios left out)."""
    ratios = [r for r in rows if not math.isnan(r.max_error_over_bound)]
    return max(ratios, key=lambda r: r.max_error_over_bound) if ratios else None


def summary(report: ReportData) -> str:
    """The report in one paragraph, as ``repr(report)`` shows it: its rows, the worst error
    over its bound, the median times, the studies, the machine.

    Parameters
    ----------
    report : ReportData
        The report.

    Returns
    -------
    str
        One paragraph, some hundreds of characters.
    """
    rows = list(report.rows)
    s = report.settings
    scenes = len(dict.fromkeys(r.scene for r in rows))
    text = (
        f"glshade Report: {_count(len(rows), 'row')} ({_count(scenes, 'scene class')} x "
        f"{_names([r.dtype for r in rows]) or 'no dtype'} x "
        f"{_names([r.accuracy for r in rows]) or 'no mode'} x "
        f"{_names([r.isa for r in rows]) or 'no instruction set'}), "
        f"{_count(s.get('vertices', 0), 'vertex')}, {_count(s.get('rounds', 0), 'round')}"
    )
    worst = _worst(rows)
    if worst is not None:
        over = sum(r.max_error_over_bound > 1 for r in rows)
        within = f"{_count(over, 'row')} over the bound" if over else "every row within its bound"
        text += (
            f"; {within}: worst error / bound {worst.max_error_over_bound:.2g} "
            f"({worst.scene}, {worst.dtype} {worst.accuracy}, {worst.isa})"
        )
    if rows:
        text += f"; median {statistics.median(r.time_ns for r in rows):.3g} ns per vertex"
    studies = [
        _count(len(report.area_lights), "area-light row") if report.area_lights else "",
        _count(len(report.gouraud_phong), "Gouraud-Phong row") if report.gouraud_phong else "",
    ]
    text += "; studies: " + (", ".join(t for t in studies if t) or "none")
    if report.machine:
        text += f"; on {report.machine.get('cpu', 'an unknown CPU')}, {report.machine.get('date')}"
    return text + ". .write(directory) writes it all; a notebook shows a table and the figure."


def _table(report: ReportData) -> str:
    """Per dtype and accuracy mode: rows, the largest error, the worst error over its bound,
    flipped vertices and, per instruction set, the median ns per vertex over the classes."""
    isas = list(dict.fromkeys(r.isa for r in report.rows))
    head = "".join(
        f"<th>{html_text.escape(h)}</th>"
        for h in ["dtype", "accuracy", "rows", "max error", "worst error / bound", "flipped"]
        + [f"ns/vertex, {isa}" for isa in isas]
    )
    lines = []
    for dtype in dict.fromkeys(r.dtype for r in report.rows):
        for accuracy in dict.fromkeys(r.accuracy for r in report.rows):
            group = [r for r in report.rows if (r.dtype, r.accuracy) == (dtype, accuracy)]
            if not group:
                continue
            worst = _worst(group)
            ratio = f"{worst.max_error_over_bound:.2g}" if worst is not None else "n/a"
            times = []
            for isa in isas:
                ns = [r.time_ns for r in group if r.isa == isa]
                times.append(f"{statistics.median(ns):.3g}" if ns else "")
            cells = [
                dtype,
                accuracy,
                str(len(group)),
                f"{max(r.max_error for r in group):.2e}",
                ratio,
                str(sum(r.flipped for r in group)),
                *times,
            ]
            lines.append(
                "<tr>" + "".join(f"<td>{html_text.escape(c)}</td>" for c in cells) + "</tr>"
            )
    return f"<table><tr>{head}</tr>{''.join(lines)}</table>"


def _studies(report: ReportData) -> str:
    """A line per study: its error at the first and the last of its steps."""
    lines = []
    if report.area_lights:
        a, b = report.area_lights[0], report.area_lights[-1]
        lines.append(
            f"Area light by k points against k = 16384 (float64): max error "
            f"{a['max_error']:.2e} at k = {a['k']}, {b['max_error']:.2e} at k = {b['k']}."
        )
    if report.gouraud_phong:
        a, b = report.gouraud_phong[0], report.gouraud_phong[-1]
        lines.append(
            f"Gouraud against per-pixel Phong (512 x 512): max error {a['max_error']:.2e} at "
            f"{a['triangles']:,} triangles, {b['max_error']:.2e} at {b['triangles']:,}."
        )
    return "".join(f"<p>{html_text.escape(t)}</p>" for t in lines)


def html(report: ReportData) -> str:
    """The report as a notebook shows it: the machine, a table per dtype and accuracy mode,
    the studies in a line each and the error-against-time figure inline (a PNG, with
    matplotlib), under `HTML_LIMIT` characters in all.

    Parameters
    ----------
    report : ReportData
        The report.

    Returns
    -------
    str
        HTML.
    """
    s = report.settings
    machine = describe(report.machine) if report.machine else "unknown machine"
    text = (
        "<div>"
        "<p><b>glshade: error against run time</b> "
        f"({_count(s.get('vertices', 0), 'vertex')} per scene class, "
        f"{_count(s.get('rounds', 0), 'round')}; "
        "errors against the long-double reference, absolute, over RGB; ns/vertex: the "
        "median over the scene classes of each row's median round)</p>"
        f"<p>{html_text.escape(machine)}</p>"
        f"{_table(report)}{_studies(report)}"
    )
    end = "<p>report.write(directory) writes report.md, .json, .csv and the figures.</p></div>"
    figure = f"<p>{html_text.escape(NO_FIGURE)}</p>"
    if report.rows:
        try:
            from .figures import inline_png
        except ImportError:
            pass
        else:
            tag = '<p><img alt="error against time per vertex" src="data:image/png;base64,'
            # base64 is 4 characters per 3 bytes; what the rest leaves is the figure's.
            room = (HTML_LIMIT - len(text) - len(end) - len(tag) - 200) * 3 // 4
            png = inline_png(report, room)
            figure = f'{tag}{base64.b64encode(png).decode("ascii")}"></p>'
    return text + figure + end


def markdown(report: ReportData) -> str:
    """The report as Markdown: the machine, one table of the rows, the studies' tables."""
    s = report.settings
    lines = [
        "# glshade: error against run time",
        "",
        f"Machine: {describe(report.machine)}.",
        "",
        f"Errors against {s['reference']}; over the RGB channels of {s['vertices']:,} vertices "
        f"per scene class (a hundredth for the thousand lights). Times per vertex over "
        f"{s['rounds']} rounds. The headline, x kernel, is the time over that of the calibration "
        f"kernel, {s['kernel']}: the median of the per-round ratios, with the smallest and "
        f"largest ratio as its spread; runs are compared on it. ns/vertex is the absolute "
        f"median, with the fastest and slowest round.",
        "",
        "| scene | dtype | accuracy | ISA | max error | mean | 99.9% | max ulps | 99.9% ulps "
        "| error / bound | flipped | x kernel | spread | ns/vertex | spread | Mvert/s |",
        "|---|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|",
    ]
    for r in report.rows:
        lines.append(
            f"| {r.scene} | {r.dtype} | {r.accuracy} | {r.isa} | {r.max_error:.2e} | "
            f"{r.mean_error:.2e} | {r.p999_error:.2e} | {r.max_ulps:.3g} | {r.p999_ulps:.3g} | "
            f"{r.max_error_over_bound:.2g} | {r.flipped} | {r.time_over_kernel:.2f} | "
            f"{r.time_over_kernel_low:.2f}-{r.time_over_kernel_high:.2f} | {r.time_ns:.2f} | "
            f"{r.time_low_ns:.2f}-{r.time_high_ns:.2f} | {r.mvert_s:.1f} |"
        )
    if report.area_lights:
        lines += ["", "## Area light sampled by k points (float64), against k = 16384", ""]
        lines += ["| k | max error | mean error | ms per call |", "|---:|---:|---:|---:|"]
        for a in report.area_lights:
            lines.append(
                f"| {a['k']} | {a['max_error']:.2e} | {a['mean_error']:.2e} | {a['ms']:.2f} |"
            )
    if report.gouraud_phong:
        lines += ["", "## Gouraud against per-pixel Phong shading of an icosphere (512 x 512)", ""]
        lines += [
            "| triangles | widest edge (deg) | max error | mean error | 8-bit levels wrong "
            "| Gouraud ms | Phong ms |",
            "|---:|---:|---:|---:|---:|---:|---:|",
        ]
        for g in report.gouraud_phong:
            lines.append(
                f"| {g['triangles']} | {g['edge_degrees']:.1f} | {g['max_error']:.2e} | "
                f"{g['mean_error']:.2e} | {g['levels8_wrong']:.2%} | {g['gouraud_ms']:.1f} | "
                f"{g['phong_ms']:.1f} |"
            )
    return "\n".join(lines) + "\n"


def write(report: ReportData, directory: Path) -> list[Path]:
    """Writes the data files and, where matplotlib is installed, the figures; the paths
    (without matplotlib, one line on stdout says how to get the figures)."""
    directory.mkdir(parents=True, exist_ok=True)
    written = []
    for name, text in (
        ("report.md", markdown(report)),
        ("report.json", report.to_json() + "\n"),
        ("report.csv", report.to_csv()),
    ):
        path = directory / name
        path.write_text(text, encoding="utf-8")
        written.append(path)
    try:
        from .figures import figures
    except ImportError:
        print(NO_FIGURES)
        return written
    return written + figures(report, directory)
