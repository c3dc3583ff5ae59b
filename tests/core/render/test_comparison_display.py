"""A Comparison shows itself: in a notebook its heatmap, a legend of every kind's colour and
count and the colour scale (HTML, read back with Pillow and a parser); `plot` draws the same
with matplotlib, with a colour bar whose colours are the heatmap's. Each colour is checked
against the heatmap's formula, written out here."""

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


def _scale_colour(error: float) -> tuple[float, float, float]:
    """Orange at the tolerance to white at 1000 times it: t = log10(error / tol) / 3."""
    t = min(max(np.log10(error / TOLERANCE) / 3, 0.0), 1.0)
    return (1.0, 0.5 * (1 - t) + t * t, t * t)


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
    depth = np.where(reference[..., 3] > 0, 0.5, 1.0)
    their_depth = depth.copy()
    depth[16, 8] = 0.5
    their_depth[7, 20] = 0.505  # depth, interior
    their_depth[5, 12] = 0.505  # depth, edge (a row inside the silhouette)
    return gs.compare(image, reference, depth=depth, reference_depth=their_depth)


def test_the_fixture_has_each_kind(comparison: gs.Comparison) -> None:
    assert comparison.counts == {
        "color, interior": 4,
        "color, edge": 0,
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
    heatmap, scale = (_decode(src) for src in page.images)
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
    assert "orange (1, 0.5, 0) at the tolerance 0.0001 to white at 0.1, log scale" in words
    assert f"same {comparison.compared - 6:,} grey, 0.35 x the reference's luminance" in words
    assert f"neither covers {20 * 30 - comparison.compared - 1:,} transparent" in words
    # The scale: 256 columns from the tolerance to 1000 times it, and its decades.
    assert scale.shape[1] == 256
    for column in (0, 85, 128, 200, 255):
        error = TOLERANCE * 10.0 ** (3 * column / 255)
        expected_rgb = np.rint(np.array(_scale_colour(error)) * 255)
        np.testing.assert_array_equal(scale[6, column, :3], expected_rgb)
    assert re.findall(r">([0-9.e-]+)</span>", text) == ["0.0001", "0.001", "0.01", "0.1"]
    # The heatmap's colour differences lie on that scale.
    for k, column in enumerate((8, 11, 14, 17)):
        rgb = np.rint(np.array(_scale_colour(1.5 * TOLERANCE * 10.0**k)) * 255)
        np.testing.assert_allclose(heatmap[10, column, :3], rgb, atol=1)
    assert "98.333% of 240 pixels both cover within 0.0001" in words
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
    (bar_axes,) = (a for a in figure.axes if a is not ax)
    labels = [t.get_text() for t in bar_axes.get_yticklabels()]
    assert labels == ["0.0001", "0.001", "0.01", "0.1"]
    assert bar_axes.get_ylabel() == "colour difference (largest channel), log scale"
    # The bar's colours, drawn with its colour map and norm.
    (solids,) = (c for c in bar_axes.collections if isinstance(c, QuadMesh))
    for error in (1.5e-4, 1.5e-3, 1.5e-2, 0.15):
        colour = solids.cmap(solids.norm(np.array(error)))[:3]
        np.testing.assert_allclose(colour, _scale_colour(error), atol=2e-3)
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
    assert "color, interior (4)" in legend and "neither covers (359): transparent" in legend
    assert ax.get_title() == "98.33% of 240 pixels within 0.0001"


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
    assert "tolerance 0: every colour difference is white" in result._repr_html_()
    assert result.heatmap[1, 1, :3].tolist() == [1, 1, 1]
