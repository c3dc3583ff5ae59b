"""A Report shows itself: ``repr`` is one paragraph, and in a notebook a table per dtype and
accuracy mode with its error-against-time figure inline, under 20,000 characters (on a real
small report and on a made-up one of the full report's 168 rows); without matplotlib a line
says how to get the figure. The table's numbers are recomputed here from the rows."""

from __future__ import annotations

import base64
import io
import statistics
import sys
from html.parser import HTMLParser
from typing import Any

import numpy as np
import pytest
from conftest import require

import glshade as gs
from glshade.lab.records import Row

pytestmark = pytest.mark.lab

LIMIT = 20_000
MACHINE = {
    "cpu": "Test CPU 9000",
    "cpu_flags": ["sse2", "avx2"],
    "logical_cpus": 4,
    "usable_cpus": 2,
    "threads": 2,
    "instruction_set": "avx2",
    "glshade": gs.__version__,
    "numpy": np.__version__,
    "python": "3.11.0",
    "platform": "linux, x86_64",
    "date": "2025-01-01T00:00:00+00:00",
}


def _row(scene: str, dtype: str, accuracy: str, isa: str, error: float, ns: float) -> Row:
    ratios = {"time_over_kernel": 1.0, "time_over_kernel_low": 0.9, "time_over_kernel_high": 1.1}
    return Row(
        scene=scene,
        kind="typical",
        dtype=dtype,
        accuracy=accuracy,
        isa=isa,
        vertices=1000,
        max_error=error,
        mean_error=error / 10,
        p999_error=error / 2,
        max_ulps=1.0,
        mean_ulps=0.1,
        p999_ulps=0.5,
        bound=1e-5,
        max_error_over_bound=error / 1e-5,
        flipped=1 if accuracy == "fast" else 0,
        time_ns=ns,
        time_low_ns=ns * 0.9,
        time_high_ns=ns * 1.1,
        kernel_ns=ns,
        kernel_low_ns=ns,
        kernel_high_ns=ns,
        rounds=3,
        **ratios,
    )


def _made_up(classes: int = 14, isas: tuple[str, ...] = ("avx512", "avx2", "baseline")) -> Any:
    """A report of the full report's shape: 14 classes x 2 dtypes x 2 modes x 3 sets."""
    rng = np.random.default_rng(5)
    rows = [
        _row(
            f"class {c}",
            dtype,
            accuracy,
            isa,
            10 ** rng.uniform(-17, -1),
            10 ** rng.uniform(0.7, 4.5),
        )
        for c in range(classes)
        for dtype in ("float32", "float64")
        for accuracy in ("fast", "exact")
        for isa in isas
    ]
    settings = {"vertices": 1000, "rounds": 3, "reference": "long double", "kernel": "k"}
    area = (
        {"k": 1, "max_error": 0.25, "mean_error": 0.01, "ms": 0.1},
        {"k": 1024, "max_error": 1.5e-4, "mean_error": 1e-5, "ms": 9.0},
    )
    gouraud = (
        {"triangles": 80, "max_error": 0.375, "gouraud_ms": 5.0, "phong_ms": 5.5},
        {"triangles": 20480, "max_error": 0.0375, "gouraud_ms": 9.0, "phong_ms": 6.0},
    )
    return gs.Report(tuple(rows), MACHINE, settings, area, gouraud)


class _Page(HTMLParser):
    """The table's rows of cells, the images and the text of an HTML fragment."""

    def __init__(self) -> None:
        super().__init__()
        self.rows: list[list[str]] = []
        self.images: list[str] = []
        self.text: list[str] = []
        self._cell: list[str] | None = None

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        if tag == "tr":
            self.rows.append([])
        elif tag in ("td", "th"):
            self._cell = []
        elif tag == "img":
            self.images.append(dict(attrs)["src"] or "")

    def handle_endtag(self, tag: str) -> None:
        if tag in ("td", "th") and self._cell is not None:
            self.rows[-1].append("".join(self._cell))
            self._cell = None

    def handle_data(self, data: str) -> None:
        if self._cell is not None:
            self._cell.append(data)
        if data.strip():
            self.text.append(data.strip())


def _parse(report: Any) -> _Page:
    page = _Page()
    page.feed(report._repr_html_())
    return page


def _expected_table(report: Any) -> list[list[str]]:
    isas = list(dict.fromkeys(r.isa for r in report.rows))
    table = [
        ["dtype", "accuracy", "rows", "max error", "worst error / bound", "flipped"]
        + [f"ns/vertex, {isa}" for isa in isas]
    ]
    for dtype in ("float32", "float64"):
        for accuracy in ("fast", "exact"):
            group = [r for r in report.rows if (r.dtype, r.accuracy) == (dtype, accuracy)]
            medians = [statistics.median(r.time_ns for r in group if r.isa == i) for i in isas]
            table.append(
                [
                    dtype,
                    accuracy,
                    str(len(group)),
                    f"{max(r.max_error for r in group):.2e}",
                    f"{max(r.max_error_over_bound for r in group):.2g}",
                    str(sum(r.flipped for r in group)),
                    *(f"{m:.3g}" for m in medians),
                ]
            )
    return table


def _png(src: str) -> tuple[int, int]:
    pil: Any = require("PIL.Image")
    assert src.startswith("data:image/png;base64,")
    picture = pil.open(io.BytesIO(base64.b64decode(src.split(",", 1)[1])))
    picture.load()
    assert picture.format == "PNG"
    size: tuple[int, int] = picture.size
    return size


# gs.report runs a worker process per instruction set: one, for one scene class, under 1 s.
@pytest.fixture(scope="module")
def small() -> Any:
    return gs.report(
        vertices=1000,
        rounds=1,
        isas=["baseline"],
        scenes=["1 directional"],
        studies=False,
        progress=False,
    )


@pytest.mark.subprocess
def test_a_real_report_shows_its_table_and_figure_in_under_20000_characters(small: Any) -> None:
    require("matplotlib")
    text = small._repr_html_()
    assert len(text) < LIMIT
    page = _parse(small)
    assert page.rows == _expected_table(small)
    (figure,) = page.images
    width, height = _png(figure)
    assert width >= 500 and height >= 250  # 72 dpi of an 11 x 5.2 inch figure fits
    words = " ".join(page.text)
    assert small.machine["cpu"] in words and "1,000 vertices per scene class, 1 round" in words


@pytest.mark.subprocess
def test_repr_is_one_short_paragraph(small: Any) -> None:
    text = repr(small)
    assert len(text) < 1000 and "\n" not in text
    worst = max(small.rows, key=lambda r: r.max_error_over_bound)
    assert text.startswith(
        "glshade Report: 4 rows (1 scene class x float32, float64 x fast, exact x baseline), "
        "1,000 vertices, 1 round; every row within its bound: worst error / bound "
        f"{worst.max_error_over_bound:.2g} (1 directional, {worst.dtype} {worst.accuracy}, "
        "baseline); median "
    )
    assert f"{statistics.median(r.time_ns for r in small.rows):.3g} ns per vertex" in text
    assert "studies: none" in text and small.machine["cpu"] in text


def test_the_full_report_shape_stays_under_20000_characters_with_its_figure() -> None:
    require("matplotlib")
    report = _made_up()
    text = report._repr_html_()
    assert len(text) < LIMIT
    page = _parse(report)
    assert page.rows == _expected_table(report)
    (figure,) = page.images
    assert _png(figure)[0] >= 300
    words = " ".join(page.text)
    assert "max error 2.50e-01 at k = 1, 1.50e-04 at k = 1024." in words
    assert "max error 3.75e-01 at 80 triangles, 3.75e-02 at 20,480." in words
    text = repr(report)
    assert text.startswith("glshade Report: 168 rows (14 scene classes x float32, float64 x ")
    assert "avx512, avx2, baseline), 1,000 vertices, 3 rounds; " in text
    over = sum(r.max_error_over_bound > 1 for r in report.rows)
    assert f"; {over} rows over the bound: worst error / bound " in text
    assert "studies: 2 area-light rows, 2 Gouraud-Phong rows; on Test CPU 9000" in text


def test_without_matplotlib_the_table_and_a_line_saying_how(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    monkeypatch.delitem(sys.modules, "glshade.lab.figures", raising=False)
    monkeypatch.setitem(sys.modules, "matplotlib", None)  # import fails
    report = _made_up(classes=2, isas=("avx2",))
    page = _parse(report)
    assert page.images == [] and page.rows == _expected_table(report)
    assert "no figure: matplotlib is not installed (pip install 'glshade[plot]')" in page.text


def test_a_figure_of_less_than_a_decade_gets_whole_decades() -> None:
    require("matplotlib")
    from glshade.lab.figures import error_time

    rows = [
        _row("one", "float32", mode, "avx2", error, ns)
        for mode, error, ns in [
            ("fast", 1.2e-7, 33.0),
            ("exact", 3e-8, 48.0),
        ]
    ]
    figure = error_time(gs.Report(tuple(rows), MACHINE, {"vertices": 1, "rounds": 1}))
    (ax,) = figure.axes
    assert ax.get_xlim() == pytest.approx((10, 100)) and ax.get_ylim() == pytest.approx(
        (1e-8, 1e-6)
    )
    # A power of ten itself lies inside, not on the frame.
    rows = [_row("one", "float32", "fast", "avx2", 1e-7, 10.0)]
    (ax,) = error_time(gs.Report(tuple(rows), MACHINE, {})).axes
    assert ax.get_xlim() == pytest.approx((1, 100)) and ax.get_ylim() == pytest.approx((1e-8, 1e-6))
