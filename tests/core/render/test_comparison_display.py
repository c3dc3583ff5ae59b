"""A Comparison shows itself: in a notebook its heatmap, a legend of every kind's colour and
count and the colour scales (HTML, read back with Pillow and a parser); `plot` draws the same
with matplotlib, with colour bars whose colours are the heatmap's. Each colour is checked
against the heatmap's formula, written out here. The heatmap is opaque, every kind its own
colour."""

from __future__ import annotations

import base64
import io
import re
import sys
from html.parser import HTMLParser
from typing import Any

import numpy as np
import pytest
from conftest import require

import glshade as gs

TOLERANCE = 1e-4
# What the heatmap draws, from the Comparison's documentation.
BLUE, DARK_BLUE, CYAN, MAGENTA = (0.2, 0.4, 1.0), (0.1, 0.2, 0.6), (0, 1, 1), (1, 0, 1)
NEITHER = (0.85, 0.85, 0.85)
# The colour scales' ends: interior yellow to dark red, edge light green to dark green.
ENDS = {
    "interior": ((1.0, 0.85, 0.0), (0.7, 0.0, 0.0)),
    "edge": ((0.55, 1.0, 0.35), (0.0, 0.4, 0.0)),
}


def _scale_colour(error: float, where: str = "interior") -> np.ndarray:
    """The straight line in RGB from the scale's colour at the tolerance to its colour at 1000
    times it: t = log10(error / tol) / 3, clipped to [0, 1]."""
    t = min(max(np.log10(error / TOLERANCE) / 3, 0.0), 1.0)
    low, high = (np.array(end) for end in ENDS[where])
    return low + (high - low) * t


@pytest.fixture(scope="module")
def comparison() -> gs.Comparison:
    """A 20 x 30 picture with one difference of each kind, and colour errors of 1, 10, 100
    and 1000 times the tolerance in a row inside it."""
    reference = np.zeros((20, 30, 4))
    reference[4:16, 5:25] = (0.5, 0.25, 0.75, 1.0)
    image = reference.copy()
    for k, column in enumerate((8, 11, 14, 17)):
        image[10, column, 1] += 1.5 * TOLERANCE * 10.0**k
    image[16, 8] = (0.5, 0.25, 0.75, 1.0)  # coverage, edge
    image[4, 14, 0] += 1.5 * TOLERANCE * 10  # colour, edge (the silhouette's row)
    depth = np.where(reference[..., 3] > 0, 0.5, 1.0)
    their_depth = depth.copy()
    depth[16, 8] = 0.5
    their_depth[7, 20] = 0.505  # depth, interior
    their_depth[5, 12] = 0.505  # depth, edge (a row inside the silhouette)
    return gs.compare(image, reference, depth=depth, reference_depth=their_depth)


def test_the_fixture_has_each_kind(comparison: gs.Comparison) -> None:
    assert comparison.counts == {
        "color, interior": 4,
        "color, edge": 1,
        "depth, interior": 1,
        "depth, edge": 1,
        "coverage, interior": 0,
        "coverage, edge": 1,
    }


class _Page(HTMLParser):
    """The images (src) and the text of an HTML fragment."""

    def __init__(self) -> None:
        super().__init__()
        self.images: list[str] = []
        self.text: list[str] = []

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        if tag == "img":
            self.images.append(dict(attrs)["src"] or "")

    def handle_data(self, data: str) -> None:
        if data.strip():
            self.text.append(data.strip())


def _decode(src: str) -> np.ndarray:
    pil: Any = require("PIL.Image")
    assert src.startswith("data:image/png;base64,")
    picture = pil.open(io.BytesIO(base64.b64decode(src.split(",", 1)[1])))
    assert picture.format == "PNG"
    return np.asarray(picture.convert("RGBA"))


def test_the_notebook_html_shows_the_heatmap_legend_and_scale(comparison: gs.Comparison) -> None:
    text = comparison._repr_html_()
    page = _Page()
    page.feed(text)
    heatmap, interior, edge = (_decode(src) for src in page.images)
    expected = np.rint(np.clip(np.asarray(comparison.heatmap), 0, 1) * 255).astype(np.uint8)
    np.testing.assert_array_equal(heatmap, expected)
    # The legend: each kind's swatch is the heatmap's colour, with its count and colour named.
    swatches = [
        tuple(map(int, m)) for m in re.findall(r"background:rgb\((\d+),(\d+),(\d+)\)", text)
    ]
    words = " ".join(page.text)
    for rgb, kind, name in [
        (BLUE, "depth, interior", "blue (0.2, 0.4, 1)"),
        (DARK_BLUE, "depth, edge", "dark blue (0.1, 0.2, 0.6)"),
        (CYAN, "coverage, interior", "cyan (0, 1, 1)"),
        (MAGENTA, "coverage, edge", "magenta (1, 0, 1)"),
    ]:
        assert tuple(round(255 * v) for v in rgb) in swatches
        assert f"{kind} {comparison.counts[kind]:,} {name}" in words
    assert tuple(heatmap[7, 20, :3]) == tuple(round(255 * v) for v in BLUE)
    assert (heatmap[..., 3] == 255).all()  # opaque
    assert tuple(heatmap[0, 0, :3]) == tuple(round(255 * v) for v in NEITHER)
    assert (
        "color, interior 4 yellow (1, 0.85, 0) at the tolerance 0.0001 to dark red (0.7, 0, 0) "
        "at 0.1 and beyond, log scale" in words
    )
    assert (
        "color, edge 1 light green (0.55, 1, 0.35) at the tolerance 0.0001 to dark green "
        "(0, 0.4, 0) at 0.1 and beyond, log scale" in words
    )
    same = comparison.compared - 7
    assert f"same {same:,} grey, 0.15 + 0.35 x the reference's luminance" in words
    neither = 20 * 30 - comparison.compared - 1
    assert f"neither covers {neither:,} light grey (0.85, 0.85, 0.85)" in words
    # Grey where they agree: 0.15 + 0.35 x the reference's luminance (Rec. 709).
    luminance = 0.2126 * 0.5 + 0.7152 * 0.25 + 0.0722 * 0.75
    assert abs(int(heatmap[12, 22, 0]) - 255 * (0.15 + 0.35 * luminance)) <= 0.5
    # The scales: 256 columns from the tolerance to 1000 times it, and the decades below.
    for scale, where in ((interior, "interior"), (edge, "edge")):
        assert scale.shape[1] == 256
        for column in (0, 85, 128, 200, 255):
            error = TOLERANCE * 10.0 ** (3 * column / 255)
            expected_rgb = np.rint(_scale_colour(error, where) * 255)
            np.testing.assert_array_equal(scale[6, column, :3], expected_rgb)
    assert re.findall(r">([0-9.e-]+)</span>", text) == ["0.0001", "0.001", "0.01", "0.1"]
    # The first decade is aligned left of its tick, the last right: none is cut off.
    assert "left:0px;transform:translateX(0%)" in text
    assert "left:255px;transform:translateX(-100%)" in text
    # The heatmap's colour differences lie on those scales.
    for k, column in enumerate((8, 11, 14, 17)):
        rgb = np.rint(_scale_colour(1.5 * TOLERANCE * 10.0**k) * 255)
        np.testing.assert_allclose(heatmap[10, column, :3], rgb, atol=1)
    np.testing.assert_allclose(
        heatmap[4, 14, :3], np.rint(_scale_colour(1.5e-3, "edge") * 255), atol=1
    )
    assert "97.917% of 240 pixels both cover within 0.0001" in words
    png = "data:image/png;base64," + base64.b64encode(comparison._repr_png_()).decode()
    np.testing.assert_array_equal(_decode(png), expected)  # the PNG alone, as before


def test_plot_draws_the_heatmap_a_colour_bar_and_a_legend(comparison: gs.Comparison) -> None:
    require("matplotlib")
    from matplotlib.collections import QuadMesh
    from matplotlib.figure import Figure

    figure = Figure()
    ax = figure.subplots()
    assert comparison.plot(ax) is ax
    np.testing.assert_array_equal(ax.images[0].get_array(), np.asarray(comparison.heatmap))
    bars = [a for a in figure.axes if a is not ax]
    assert len(bars) == 2
    for bar_axes, where in zip(bars, ("interior", "edge"), strict=True):
        labels = [t.get_text() for t in bar_axes.get_yticklabels()]
        assert labels == ["0.0001", "0.001", "0.01", "0.1"]
        assert bar_axes.get_ylabel() == f"colour difference, {where} (largest channel), log scale"
        # The bar's colours, drawn with its colour map and norm.
        (solids,) = (c for c in bar_axes.collections if isinstance(c, QuadMesh))
        for error in (1.5e-4, 1.5e-3, 1.5e-2, 0.15):
            colour = solids.cmap(solids.norm(np.array(error)))[:3]
            np.testing.assert_allclose(colour, _scale_colour(error, where), atol=2e-3)
    box = ax.get_legend()
    assert box is not None
    texts = (t.get_text() for t in box.get_texts())
    legend: dict[str, Any] = dict(zip(texts, box.legend_handles, strict=True))
    for label, rgb in [
        ("depth, interior (1): blue (0.2, 0.4, 1)", BLUE),
        ("depth, edge (1): dark blue (0.1, 0.2, 0.6)", DARK_BLUE),
        ("coverage, interior (0): cyan (0, 1, 1)", CYAN),
        ("coverage, edge (1): magenta (1, 0, 1)", MAGENTA),
    ]:
        np.testing.assert_allclose(legend[label].get_facecolor()[:3], np.array(rgb))
    assert "color, interior (4)" in legend and "color, edge (1)" in legend
    assert "neither covers (359): light grey (0.85, 0.85, 0.85)" in legend
    assert ax.get_title() == "97.92% of 240 pixels within 0.0001"


def test_plot_without_an_axes_makes_a_pyplot_figure(comparison: gs.Comparison) -> None:
    require("matplotlib")
    import matplotlib.pyplot as plt

    ax = comparison.plot(legend=False)
    figure = plt.gcf()
    try:
        assert ax.figure is figure and len(figure.axes) == 1 and ax.get_legend() is None
    finally:
        plt.close(figure)


def test_plot_without_matplotlib_says_how_to_get_it(
    comparison: gs.Comparison, monkeypatch: pytest.MonkeyPatch
) -> None:
    for name in [m for m in sys.modules if m == "matplotlib" or m.startswith("matplotlib.")]:
        monkeypatch.setitem(sys.modules, name, None)  # import fails
    monkeypatch.setitem(sys.modules, "matplotlib", None)
    with pytest.raises(ImportError, match=r"Comparison.plot needs matplotlib.*glshade\[plot\]"):
        comparison.plot()
    assert "data:image/png;base64," in comparison._repr_html_()  # the notebook needs none


def test_a_zero_tolerance_has_no_scale_and_says_so() -> None:
    a = np.zeros((4, 4, 4))
    a[..., 3] = 1
    b = a.copy()
    b[1, 1] = (0.1, 0, 0, 1)
    result = gs.compare(b, a, tolerance=0)
    assert "tolerance 0: every colour difference has its scale's dark end" in result._repr_html_()
    np.testing.assert_allclose(result.heatmap[1, 1, :3], ENDS["interior"][1], atol=1e-7)


def _shown_on(page: str, comparison: gs.Comparison, tmp_path: Any) -> tuple[np.ndarray, Any]:
    """The notebook display of `comparison` on a page of colour `page`, drawn by Chromium:
    the screenshot (RGB) and the heatmap's box on it."""
    pil: Any = require("PIL.Image")
    from support.chromium import chromium

    path = tmp_path / f"display-{page.strip('#')}.html"
    path.write_text(
        f'<!doctype html><body style="margin:8px;background:{page}">'
        f"{comparison._repr_html_()}</body>",
        encoding="utf-8",
    )
    with chromium("--disable-gpu", "--force-device-scale-factor=1",
                  "--force-color-profile=srgb", "--window-size=900,700") as driver:  # fmt: skip
        driver.get(path.as_uri())
        box = driver.execute_script(
            "const r = document.querySelector('img').getBoundingClientRect();"
            "return [r.left, r.top, r.width, r.height];"
        )
        shot = np.asarray(pil.open(io.BytesIO(driver.get_screenshot_as_png())).convert("RGB"))
    return shot, box


@pytest.mark.parametrize("page", ["#ffffff", "#000000"])
def test_small_and_huge_errors_both_show_on_a_light_and_a_dark_page(
    page: str, tmp_path: Any
) -> None:
    """Errors of 10 and of 10,000 times the tolerance, inside the picture and on its edge,
    drawn by a browser on a white and on a black page: each pixel differs clearly from the
    page and from the grey of agreement around it, and the colour kinds differ from each
    other."""
    reference = np.zeros((24, 32, 4))
    reference[4:20, 4:28] = (0.5, 0.5, 0.5, 1.0)
    image = reference.copy()
    errors = {"10x interior": (10, 10), "10000x interior": (10, 20), "10x edge": (4, 12),
              "10000x edge": (4, 18)}  # fmt: skip
    for name, (row, column) in errors.items():
        image[row, column, 0] += TOLERANCE * (10 if name.startswith("10x") else 10_000)
    comparison = gs.compare(image, reference)
    assert comparison.counts["color, interior"] == 2 and comparison.counts["color, edge"] == 2
    shot, (left, top, width, height) = _shown_on(page, comparison, tmp_path)
    zoom = width / 32
    assert zoom == int(zoom) >= 2 and height == 24 * zoom

    def pixel(row: int, column: int) -> np.ndarray:
        y, x = int(top + (row + 0.5) * zoom), int(left + (column + 0.5) * zoom)
        return shot[y, x].astype(int)

    page_rgb = np.array([int(page[i : i + 2], 16) for i in (1, 3, 5)])
    same = pixel(12, 6)
    assert np.abs(same - page_rgb).max() > 60  # the agreeing picture stands out of the page
    shown = {name: pixel(*where) for name, where in errors.items()}
    for name, rgb in shown.items():
        expected = np.rint(np.asarray(comparison.heatmap)[errors[name]][:3] * 255)
        assert np.abs(rgb - expected).max() <= 3, (name, rgb, expected)
        assert np.abs(rgb - page_rgb).max() > 60, (name, rgb, page)
        assert np.abs(rgb - same).max() > 60, (name, rgb, same)
    assert np.abs(shown["10x interior"] - shown["10000x interior"]).max() > 60
    assert np.abs(shown["10x interior"] - shown["10x edge"]).max() > 60
    assert np.abs(shown["10000x interior"] - shown["10000x edge"]).max() > 60
