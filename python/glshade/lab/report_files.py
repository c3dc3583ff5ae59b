"""The files of ``python -m glshade report --out DIR``: report.md, report.json, report.csv and
the figures (with matplotlib)."""

from __future__ import annotations

from pathlib import Path

from .machine import describe
from .records import ReportData

__all__ = ["markdown", "write"]

NO_FIGURES = "no figures: matplotlib is not installed (pip install 'glshade[plot]')"


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
