"""`compare`: two images side by side, their differences measured and explained."""

from __future__ import annotations

import base64
import html
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, Literal

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ._image import Image
from ._intake import array, color, number, one_of, warn_if_bytes
from ._png import encode_png
from ._records import ValueRecord
from ._typing import Float64Array

if TYPE_CHECKING:
    from matplotlib.axes import Axes

__all__ = ["Comparison", "compare", "coverage_edges", "picture"]

Alpha = Literal["straight", "premultiplied"]
DepthConvention = Literal["window", "linear"]
# The default tolerance between float images: about a fortieth of an 8-bit step, far above
# float32's rounding of values in [0, 1] (6e-8).
_FLOAT_TOLERANCE = 1e-4

# The kinds of difference, as `Comparison.labels` numbers them.
KINDS = (
    "same",
    "color, interior",
    "color, edge",
    "depth, interior",
    "depth, edge",
    "coverage, interior",
    "coverage, edge",
)
# Heatmap colours of the kinds other than colour differences (RGB), with their names.
_MARKS = {
    3: (0.2, 0.4, 1.0),
    4: (0.1, 0.2, 0.6),
    5: (0.0, 1.0, 1.0),
    6: (1.0, 0.0, 1.0),
}
_MARK_NAMES = {3: "blue", 4: "dark blue", 5: "cyan", 6: "magenta"}
# The grey of agreement: _SAME_LOW plus this share of the reference's luminance (Rec. 709
# weights), from dark grey to mid grey; where neither image covers, a light grey above it. The
# heatmap is opaque, so it reads alike on a light and a dark page.
_DIM = 0.35
_SAME_LOW = 0.15
_NEITHER = (0.85, 0.85, 0.85)
_LUMINANCE = (0.2126, 0.7152, 0.0722)
# Colour differences span the tolerance to 10**_DECADES times it on the heatmap's log scales.
_DECADES = 3
# Each scale's ends (RGB at the tolerance, at 10**_DECADES times it and beyond): interior
# differences yellow to dark red, edge differences light to dark green.
_SCALES = {
    1: ((1.0, 0.85, 0.0), (0.7, 0.0, 0.0)),
    2: ((0.55, 1.0, 0.35), (0.0, 0.4, 0.0)),
}
_SCALE_NAMES = {1: ("yellow", "dark red"), 2: ("light green", "dark green")}


def _error_colours(t: NDArray[np.floating[Any]], kind: int = 1) -> Float64Array:
    """(..., 3) RGB of colour differences of `kind` (1 interior, 2 edge) at `t` =
    log10(error / tolerance) / 3 in [0, 1]: the straight line in RGB between the scale's ends,
    `_SCALES[kind]`, so every error beyond 1000 times the tolerance has the dark end's colour."""
    t = np.clip(np.asarray(t, np.float64), 0.0, 1.0)[..., None]
    low, high = (np.array(end) for end in _SCALES[kind])
    rgb: Float64Array = low + (high - low) * t
    return rgb


@dataclass(frozen=True, eq=False)
class Comparison(ValueRecord):
    """What `compare` found. Errors are absolute, per channel, on the [0, 1] scale, over the
    pixels both images cover (`compared` of them).

    Attributes
    ----------
    tolerance : float
        The per-channel tolerance the shares and labels use.
    compared : int
        Pixels both images cover.
    max_error, mean_error : (channels,) float64
        Per channel, over the compared pixels.
    percentiles : dict of float to (channels,) float64
        Per channel error at each requested percentile.
    within_tolerance : float
        The share of compared pixels whose every channel is within `tolerance` (1.0 when
        nothing is compared). A pixel NaN in either picture is a colour difference beyond any
        tolerance, and is left out of `max_error`, `mean_error` and `percentiles`.
    labels : (height, width) uint8
        Each pixel's kind, an index into `KINDS`: "same"; "color" (both cover, colours differ
        beyond the tolerance); "depth" (both cover, depths differ beyond `compare`'s
        ``depth_tolerance`` plus ``depth_shift`` times the local depth slope: the images show
        different surfaces, a depth tie or an occlusion); "coverage" (one
        image covers the pixel, the other not); each split into "edge" (within `edge_width`
        pixels of a silhouette: a coverage boundary or a depth step in either image) and
        "interior".
    counts : dict of str to int
        The number of pixels of each kind but "same".
    largest : list of dict
        The largest differences, largest first: ``row``, ``column``, ``kind``, ``error`` (the
        largest channel's; 1 for coverage), ``image`` and ``reference`` (the pixel values).
    heatmap : Image
        (height, width, 4) float32, opaque (alpha 1), so it reads alike on a light and a dark
        page: grey where the images agree (0.15 plus 0.35 times the reference's luminance,
        Rec. 709 weights: 0.15 to 0.5); light grey (0.85) where neither covers; colour
        differences on a log scale of the largest channel's error, t = log10(error /
        tolerance) / 3 clipped to [0, 1], along a straight line in RGB: in the interior from
        yellow (1, 0.85, 0) at the tolerance to dark red (0.7, 0, 0) at 1000 times it and
        beyond, on edges from light green (0.55, 1, 0.35) to dark green (0, 0.4, 0); depth
        differences blue (0.2, 0.4, 1) in the interior, dark blue (0.1, 0.2, 0.6) on edges;
        coverage differences cyan (interior) and magenta (edge).
    notes : tuple of str
        What `compare` chose or assumed that a reader should know: the default tolerance of
        an integer image, depths converted from eye distances, coverage from a background
        colour, or an image that counts as covered everywhere (with what to pass instead).

    Notes
    -----
    In a notebook a Comparison shows its heatmap beside its summary, with a legend of every
    kind's colour and count and the colour differences' scale (``_repr_html_``, without
    matplotlib); `plot` draws the same with matplotlib, with a colour bar.
    """

    tolerance: float
    compared: int
    max_error: Float64Array
    mean_error: Float64Array
    percentiles: dict[float, Float64Array]
    within_tolerance: float
    labels: NDArray[np.uint8] = field(repr=False)
    counts: dict[str, int]
    largest: list[dict[str, Any]] = field(repr=False)
    heatmap: Image = field(repr=False)
    notes: tuple[str, ...] = ()

    KINDS = KINDS

    @property
    def edge_only(self) -> bool:
        """Every difference beyond the tolerance lies on an edge (silhouette) pixel."""
        return all(n == 0 for kind, n in self.counts.items() if kind.endswith("interior"))

    def __str__(self) -> str:
        lines = [
            f"{self.within_tolerance:.3%} of {self.compared} pixels both cover within "
            f"{self.tolerance:g}; max error per channel "
            + ", ".join(f"{e:.3g}" for e in self.max_error)
        ]
        found = [f"{n} {kind}" for kind, n in self.counts.items() if n]
        lines.append("differences: " + (", ".join(found) if found else "none"))
        lines.extend(f"note: {note}" for note in self.notes)
        for d in self.largest[:3]:
            lines.append(
                f"  ({d['row']}, {d['column']}) {d['kind']}: error {d['error']:.3g}, "
                f"image {np.round(d['image'], 6).tolist()}, "
                f"reference {np.round(d['reference'], 6).tolist()}"
            )
        return "\n".join(lines)

    def _repr_png_(self) -> bytes:
        """The heatmap alone, for frontends that show PNG only."""
        return encode_png(np.asarray(self.heatmap))

    def _repr_html_(self) -> str:
        """The heatmap beside the summary, a legend of the kinds with their colours and
        counts, and the colour differences' scale, for a notebook; no matplotlib needed."""
        height, width = self.labels.shape
        # Small images drawn larger, their pixels kept square and sharp.
        zoom = max(1, 256 // max(width, 1))
        heatmap = base64.b64encode(self._repr_png_()).decode("ascii")
        # The summary's first line; its second, the counts, is the table below; the largest
        # differences' lines are long: folded, a click away.
        head, _, *rest = str(self).splitlines()
        listed = [line for line in rest if not line.startswith("note: ")]
        summary = f"<div>{html.escape(head)}</div>" + "".join(
            f"<div>{html.escape(line)}</div>" for line in rest if line.startswith("note: ")
        )
        text = html.escape("\n".join(listed))
        largest = (
            f'<details><summary>largest differences</summary><pre style="margin:0">{text}</pre>'
            "</details>"
            if listed
            else ""
        )
        rows = "".join(
            f'<tr><td><span style="display:inline-block;width:12px;height:12px;'
            f'{_css_swatch(rgb)};border:1px solid #888"></span></td>'
            f"<td>{html.escape(name)}</td><td style='text-align:right'>{count:,}</td>"
            f"<td>{html.escape(meaning)}</td></tr>"
            for rgb, name, count, meaning in _legend(self)
        )
        return (
            '<div style="display:flex;flex-wrap:wrap;gap:16px;align-items:flex-start;'
            'font-family:sans-serif;font-size:12px">'
            f'<img src="data:image/png;base64,{heatmap}" width="{width * zoom}" '
            f'alt="gs.compare heatmap, {height} x {width} pixels" '
            'style="image-rendering:pixelated;max-width:100%">'
            f"<div>{summary}{largest}"
            f'<table style="font-size:inherit">{rows}</table>'
            f"{_html_scale(self.tolerance)}</div></div>"
        )

    def plot(self, ax: Axes | None = None, *, legend: bool = True) -> Axes:
        """Draws the heatmap with matplotlib, with colour bars for the colour differences
        (interior and edge, log scales from the tolerance to 1000 times it) and a legend of
        every kind's colour and count.

        Parameters
        ----------
        ax : matplotlib.axes.Axes, optional
            Where to draw; None (the default) makes a new pyplot figure.
        legend : bool
            Also draw the colour bar and the legend.

        Returns
        -------
        matplotlib.axes.Axes
            The axes drawn into.

        Raises
        ------
        ImportError
            Without matplotlib (``pip install 'glshade[plot]'``).

        Examples
        --------
        >>> import numpy as np, glshade as gs
        >>> a = np.zeros((4, 4, 4)); a[1:3, 1:3] = (0.5, 0.5, 0.5, 1)
        >>> ax = gs.compare(a, a).plot()  # doctest: +SKIP
        """
        try:
            from matplotlib.cm import ScalarMappable
            from matplotlib.colors import ListedColormap, LogNorm
            from matplotlib.patches import Patch
        except ImportError:
            raise ImportError(
                "Comparison.plot needs matplotlib, which is not installed: "
                "pip install 'glshade[plot]' (or show the comparison in a notebook, "
                "or save comparison.heatmap)"
            ) from None
        if ax is None:
            import matplotlib.pyplot as plt

            _, ax = plt.subplots(figsize=(7, 5.5), layout="constrained")
        ax.imshow(np.asarray(self.heatmap), interpolation="nearest")
        ax.set_xticks([])
        ax.set_yticks([])
        ax.set_title(
            f"{self.within_tolerance:.2%} of {self.compared:,} pixels within {self.tolerance:g}"
        )
        if not legend:
            return ax
        figure = ax.get_figure()
        assert figure is not None  # an Axes that has been drawn into belongs to a figure
        if self.tolerance > 0:
            for kind, where in ((1, "interior"), (2, "edge")):
                colours = _error_colours(np.linspace(0, 1, 1024), kind)
                cmap = ListedColormap(colours, f"glshade-compare-{where}")
                norm = LogNorm(self.tolerance, self.tolerance * 10.0**_DECADES)
                bar = figure.colorbar(ScalarMappable(norm, cmap), ax=ax, fraction=0.05, pad=0.02)
                ticks = self.tolerance * 10.0 ** np.arange(_DECADES + 1)
                bar.set_ticks(list(ticks), labels=[f"{t:.3g}" for t in ticks])
                bar.ax.minorticks_off()
                bar.set_label(f"colour difference, {where} (largest channel), log scale")
        handles = [
            Patch(
                facecolor=rgb,
                edgecolor="0.5",
                # The colour bar states the colour differences' colours.
                label=f"{name} ({count:,})" + ("" if name.startswith("color") else f": {meaning}"),
            )
            for rgb, name, count, meaning in _legend(self)
        ]
        ax.legend(
            handles=handles,
            loc="upper left",
            bbox_to_anchor=(0.0, -0.01),
            frameon=False,
            fontsize="small",
        )
        return ax


def _legend(c: Comparison) -> list[tuple[tuple[float, float, float], str, int, str]]:
    """(colour, kind, pixels, what the colour means), as the heatmap draws each kind; a colour
    difference's colour is its scale's at the tolerance."""
    differ = sum(n for kind, n in c.counts.items() if kind.startswith(("color", "depth")))
    same = c.compared - differ  # of the pixels both cover
    uncovered = sum(n for kind, n in c.counts.items() if kind.startswith("coverage"))
    neither = c.labels.size - c.compared - uncovered
    top = c.tolerance * 10.0**_DECADES
    rows: list[tuple[tuple[float, float, float], str, int, str]] = [
        (
            (_SAME_LOW + _DIM / 2,) * 3,
            "same",
            same,
            f"grey, {_SAME_LOW:g} + {_DIM:g} x the reference's luminance",
        )
    ]
    for kind in (1, 2):
        low, high = _SCALES[kind]
        names = _SCALE_NAMES[kind]
        meaning = (
            f"{names[0]} {_rgb_text(low)} at the tolerance {c.tolerance:g} to {names[1]} "
            f"{_rgb_text(high)} at {top:g} and beyond, log scale"
            if c.tolerance > 0
            else f"{names[1]} {_rgb_text(high)} (tolerance 0)"
        )
        rows.append((low, KINDS[kind], c.counts[KINDS[kind]], meaning))
    for k, rgb in _MARKS.items():
        rows.append((rgb, KINDS[k], c.counts[KINDS[k]], f"{_MARK_NAMES[k]} {_rgb_text(rgb)}"))
    rows.append((_NEITHER, "neither covers", neither, f"light grey {_rgb_text(_NEITHER)}"))
    return rows


def _rgb_text(rgb: tuple[float, float, float]) -> str:
    return "(" + ", ".join(f"{v:g}" for v in rgb) + ")"


def _css_swatch(rgb: tuple[float, float, float]) -> str:
    r, g, b = (round(255 * v) for v in rgb)
    return f"background:rgb({r},{g},{b})"


def _html_scale(tolerance: float) -> str:
    """The colour differences' scales as HTML: for the interior and for edges, a strip of the
    heatmap's own colours, 256 pixels from the tolerance to 1000 times it, and its decades
    below, the first and last aligned with the strip's ends so that none is cut off."""
    if not tolerance > 0:
        return "<div>tolerance 0: every colour difference has its scale's dark end</div>"
    strips = []
    for kind, where in ((1, "interior"), (2, "edge")):
        strip = np.ones((12, 256, 4))
        strip[..., :3] = _error_colours(np.linspace(0, 1, 256), kind)[None]
        data = base64.b64encode(encode_png(strip)).decode("ascii")
        strips.append(
            f'<div style="display:flex;align-items:center;gap:6px">'
            f'<img src="data:image/png;base64,{data}" width="256" height="12" '
            f'alt="colour scale, {where}" style="display:block">{where}</div>'
        )
    ticks = "".join(
        f'<span style="position:absolute;top:0;left:{round(255 * k / _DECADES)}px;'
        f'transform:translateX({-100 * k // _DECADES}%)">{tolerance * 10.0**k:.3g}</span>'
        for k in range(_DECADES + 1)
    )
    return (
        '<div style="margin-top:8px">colour difference (largest channel), log scale:</div>'
        f'<div style="margin:2px 0">{"".join(strips)}'
        f'<div style="position:relative;width:256px;height:16px">{ticks}</div></div>'
    )


# Integer pictures as GL's unsigned normalised formats read them: their value over the largest.
_STEPS = {np.dtype(np.uint8): 255.0, np.dtype(np.uint16): 65535.0}


def picture(value: ArrayLike, name: str, owner: str = "compare") -> tuple[Float64Array, float]:
    """(height, width, 3|4) as float64 in [0, 1], and its quantisation step: uint8 scaled by
    1/255 (step 1/255), uint16 by 1/65535, floats as they are (step 0, a `ColorRangeWarning`
    naming `owner` where they look like 0-255 bytes)."""
    a = array(value, name)
    if a.ndim != 3 or a.shape[2] not in (3, 4):
        raise ValueError(f"{name} must have shape (height, width, 3) or (..., 4), got {a.shape}")
    if a.shape[0] == 0 or a.shape[1] == 0:
        raise ValueError(f"{name} must have at least one pixel, got shape {a.shape}")
    if a.dtype.kind != "f" and a.dtype not in _STEPS:
        raise TypeError(
            f"{name} must be float (values in [0, 1]), uint8 (0-255) or uint16 (0-65535), got "
            f"dtype {a.dtype}: cast 0-255 values with .astype(np.uint8), or divide by the "
            "largest value for floats"
        )
    if a.dtype.kind == "f":
        warn_if_bytes(a, name, owner)
    largest = _STEPS.get(a.dtype, 1.0)
    result: Float64Array = a.astype(np.float64) / largest
    return result, (1.0 / largest if a.dtype in _STEPS else 0.0)


def _straight(a: Float64Array, alpha: object, name: str) -> Float64Array:
    if one_of(alpha, name, ("straight", "premultiplied")) == "straight" or a.shape[2] == 3:
        return a
    out = a.copy()
    w = a[..., 3:]
    out[..., :3] = np.divide(a[..., :3], w, out=np.zeros_like(a[..., :3]), where=w > 0)
    return out


def _window_depth(
    value: ArrayLike | None,
    shape: tuple[int, int],
    name: str,
    convention: str,
    clip: tuple[float | None, float | None],
) -> Float64Array | None:
    """A depth image as GL window depth (1 where nothing is drawn), from the `convention` it
    was given in: "window" as it is; "linear", the eye distance along the view axis with 0
    where nothing is drawn (pyrender's depth), through a perspective projection's near and
    far planes (`clip`; far None or inf: an infinite far plane, as pyrender's ``zfar=None``).
    A depth that cannot be in its stated convention raises ValueError, saying which it looks
    like."""
    if value is None:
        return None
    d = array(value, name).astype(np.float64)
    if d.shape != shape:
        raise ValueError(f"{name} must have shape {shape} (the images'), got {d.shape}")
    option = "depth_convention" if name == "depth" else "reference_depth_convention"
    finite = d[np.isfinite(d)]
    if convention == "window":
        if finite.size and (finite.max() > 1.0 or finite.min() < 0.0):
            raise ValueError(
                f"{name} has values in [{finite.min():g}, {finite.max():g}], outside GL window "
                f"depth's [0, 1]: a linear eye distance, as pyrender's renderer returns it? pass "
                f"{option}='linear' with near= and far= (the camera's znear and zfar)"
            )
        if (finite == 0.0).any() and not (finite == 1.0).any():
            raise ValueError(
                f"{name} is 0 at some pixels and 1 at none: linear eye distances, 0 where nothing "
                f"is drawn (pyrender's depth), rather than window depths, 1 where nothing is? "
                f"pass {option}='linear' with near= and far=; for window depths, clear to 1"
            )
        return d
    near, far = clip
    if near is None:
        raise ValueError(
            f"{option}='linear' needs near= (and far=, None for an infinite far plane): the "
            "camera's clip planes turn eye distances into window depths"
        )
    if finite.size and finite.min() < 0.0:
        raise ValueError(f"{name} as linear eye distances must be >= 0, got {finite.min():g}")
    if (finite == 1.0).any() and not (finite == 0.0).any() and finite.max() <= 1.0:
        raise ValueError(
            f"{name} is 1 at some pixels and 0 at none, within [0, 1]: window depths rather "
            f"than eye distances (0 where nothing is drawn)? pass {option}='window'"
        )
    drawn = d > 0.0
    with np.errstate(divide="ignore", invalid="ignore"):
        if far is None or far == np.inf:
            window = 1.0 - near / d
        else:
            window = far * (d - near) / (d * (far - near))
    result: Float64Array = np.where(drawn, window, 1.0)
    return result


def _clip_planes(near: object, far: object) -> tuple[float | None, float | None]:
    """`near` and `far` checked: 0 < near < far (far may be None or inf)."""
    if near is None:
        if far is not None:
            raise ValueError("far is given without near: give both, the camera's znear and zfar")
        return None, None
    n = number(near, "near")
    f = None if far is None else number(far, "far")
    if not 0 < n < np.inf:
        raise ValueError(f"near must be a finite number > 0, got {n}")
    if f is not None and not f > n:
        raise ValueError(f"far must be greater than near ({n:g}), got {f}")
    return n, f


def _covered(
    img: Float64Array,
    d: Float64Array | None,
    background: Float64Array | None,
    within: float,
) -> tuple[NDArray[np.bool_], str]:
    """Where `img` draws something, and from what: its depth (below 1) when given; else its
    alpha (above 0) when some pixel is transparent; else, with a `background` colour, the
    pixels whose RGB differs from it by more than `within`; else every pixel."""
    shape = img.shape[:2]
    if d is not None:
        return d < 1.0, "depth"
    if img.shape[2] == 4 and (img[..., 3] <= 0).any():
        result: NDArray[np.bool_] = img[..., 3] > 0
        return result, "alpha"
    if background is not None:
        differs: NDArray[np.bool_] = np.abs(img[..., :3] - background[:3]).max(axis=2) > within
        return differs, "background"
    return np.ones(shape, bool), "everywhere"


def coverage_edges(mask: NDArray[Any]) -> NDArray[np.bool_]:
    """Pixels of the coverage `mask` with an 8-neighbour of another coverage: silhouettes."""
    h, w = mask.shape
    padded = np.pad(mask, 1, mode="edge")
    out = np.zeros((h, w), bool)
    for a in (-1, 0, 1):
        for b in (-1, 0, 1):
            out |= padded[1 + a : 1 + a + h, 1 + b : 1 + b + w] != mask
    return out


def depth_steps(depth: Float64Array, covered: NDArray[np.bool_], jump: float) -> NDArray[np.bool_]:
    """Covered pixels with a covered 8-neighbour whose depth differs by more than `jump`:
    inner silhouettes, where one surface passes in front of another."""
    h, w = depth.shape
    d = np.pad(np.where(covered, depth, np.nan), 1, mode="edge")
    out = np.zeros((h, w), bool)
    with np.errstate(invalid="ignore"):
        for a in (-1, 0, 1):
            for b in (-1, 0, 1):
                out |= np.abs(d[1 + a : 1 + a + h, 1 + b : 1 + b + w] - d[1:-1, 1:-1]) > jump
    return out & covered


def _dilate(mask: NDArray[np.bool_], width: int) -> NDArray[np.bool_]:
    h, w = mask.shape
    out = mask.copy()
    padded = np.pad(mask, width)
    for a in range(-width, width + 1):
        for b in range(-width, width + 1):
            out |= padded[width + a : width + a + h, width + b : width + b + w]
    return out


def _depth_slope(depth: Float64Array, covered: NDArray[np.bool_], jump: float) -> Float64Array:
    """Per pixel, the largest change of depth per pixel along the row, the column or a
    diagonal through it: the central difference |d(p + e) - d(p - e)| / 2, which leaves out
    the pixel's own depth, where both neighbours are covered and it is within `jump`; else
    the larger one-sided step |d(p ± e) - d(p)| within `jump` (beside a silhouette or the
    image's border); for a diagonal with neither, the row's change plus the column's; 0
    where nothing is left. On a plane of gradient (gx, gy) that is |gx| + |gy|. One pixel of
    another surface inside a surface does not widen its own tolerance, and a patch of it by
    half its depth difference at most."""
    h, w = depth.shape
    d = np.pad(np.where(covered, depth, np.nan), 1, constant_values=np.nan)
    centre = d[1:-1, 1:-1]
    changes: list[Float64Array] = []
    with np.errstate(invalid="ignore"):
        for a, b in ((0, 1), (1, 0), (1, 1), (1, -1)):
            ahead = d[1 + a : 1 + a + h, 1 + b : 1 + b + w]
            behind = d[1 - a : 1 - a + h, 1 - b : 1 - b + w]
            central = np.abs(ahead - behind) / 2
            # NaN (a neighbour not covered) compares False: it is left out.
            steps = [np.abs(x - centre) for x in (ahead, behind)]
            one_sided = np.fmax(*(np.where(x <= jump, x, np.nan) for x in steps))
            change = np.where(central <= jump, central, one_sided)
            if a == 1 and b != 0:  # a diagonal
                along = np.nan_to_num(changes[0]) + np.nan_to_num(changes[1])
                change = np.where(np.isnan(change), along, change)
            changes.append(change)
    slope: Float64Array = np.nan_to_num(np.fmax.reduce(changes))
    return slope


def compare(
    image: ArrayLike,
    reference: ArrayLike,
    *,
    tolerance: float | None = None,
    depth: ArrayLike | None = None,
    reference_depth: ArrayLike | None = None,
    depth_convention: DepthConvention = "window",
    reference_depth_convention: DepthConvention | None = None,
    near: float | None = None,
    far: float | None = None,
    background: ArrayLike | None = None,
    depth_tolerance: float = 1e-5,
    depth_jump: float = 1e-2,
    depth_shift: float = 1.0,
    alpha: Alpha = "straight",
    reference_alpha: Alpha | None = None,
    edge_width: int = 1,
    percentiles: tuple[float, ...] = (50.0, 90.0, 99.0, 99.9),
    largest: int = 10,
) -> Comparison:
    """Compares an image with a reference and explains where and why they differ.

    A pixel is covered where its depth is below 1 (GL's cleared depth) when depths are given;
    else, in an image with transparent pixels, where its alpha is above 0; else, given a
    `background` colour, where its colour differs from it by more than the tolerance; else
    always. Colours are compared as straight (not premultiplied) RGBA.

    Parameters
    ----------
    image, reference : (height, width, 3) or (height, width, 4) array
        Float images in [0, 1], or uint8 (scaled by 1/255) or uint16 (1/65535); the same
        height and width, at least one pixel. An RGBA image against an RGB one compares RGB
        (the RGBA image's coverage still from its alpha). ``gs.render``'s and
        ``gs.glsl.render``'s images, a framebuffer read back, a PNG. Other integer dtypes
        raise (cast 0-255 values to uint8); float values that look like 0-255 bytes warn
        (`ColorRangeWarning`).
    tolerance : float, optional
        Per channel: a larger difference counts. None (the default): 1e-4 between float
        images; with a uint8 or uint16 image, half its quantisation step more (0.5/255 +
        1e-4 for 8 bits), so an 8-bit copy of the same picture is within it. The result's
        `tolerance` and `notes` state the value used.
    depth, reference_depth : (height, width) float, optional
        Depths in the convention `depth_convention` and `reference_depth_convention` name:
        coverage from them, and pixels where they differ beyond `depth_tolerance` and
        `depth_shift`'s allowance are told apart as depth differences.
    depth_convention : {"window", "linear"}
        How `depth` is given: ``"window"``, GL's window depth in [0, 1], 1 where nothing is
        drawn (`render`'s and a GL depth buffer's); ``"linear"``, the eye distance along the
        view axis, 0 where nothing is drawn (what pyrender's ``OffscreenRenderer.render``
        returns), converted to window depth with `near` and `far`. A depth that cannot be in
        its stated convention (window depths beyond 1, or 0 with no 1; eye distances of 1
        with no 0) raises ValueError naming the other.
    reference_depth_convention : {None, "window", "linear"}
        How `reference_depth` is given; None: `depth_convention`.
    near, far : float, optional
        The perspective camera's near and far planes (pyrender's ``znear`` and ``zfar``) for
        linear depths; far None or inf: an infinite far plane. Depth tolerances stay in
        window depth.
    background : (3,) or (4,) float, optional
        The colour an opaque image is cleared to (pyrender's ``bg_color``, a framebuffer's
        clear colour): in an image without transparent pixels and without a depth, the pixels
        of this colour (within the tolerance, RGB) are not covered, so its silhouettes are
        edges and coverage differences. uint8 is divided by 255 (and then matches within the
        tolerance plus half an 8-bit step).
    depth_tolerance : float
        The depth difference that counts where the depth is flat; it grows with the depth's
        slope (see `depth_shift`).
    depth_jump : float
        A depth step between neighbours that counts as a silhouette (an inner edge).
    depth_shift : float
        The misregistration, in pixels along each axis, that depth differences are forgiven:
        the depths differ at a pixel when ``|depth - reference_depth| > depth_tolerance +
        depth_shift * slope``, slope the larger of the two images' largest change of depth
        per pixel along the row, the column or a diagonal through the pixel (central
        differences over covered neighbours, changes above `depth_jump` left out). Why: on a
        plane of gradient (gx, gy) per pixel these changes are |gx|, |gy| and |gx ± gy|, the
        largest |gx| + |gy|, and moving the geometry by (sx, sy) pixels, |sx|, |sy| <= s,
        moves a pixel's depth by |gx sx + gy sy| <= s (|gx| + |gy|). The default, 1,
        forgives any shift of up to a pixel, so half a pixel (a camera moved by half a
        pixel, another rasteriser's sample positions) with a factor 2 to spare for the
        surface's curvature. Another surface is still told apart: one pixel of it inside a
        surface whose depth differs by more than the slope (central differences leave the
        pixel's own depth out), a larger patch by more than twice the slope.
        0: the fixed `depth_tolerance` alone.
    alpha : {"straight", "premultiplied"}
        How `image` stores colour under alpha; premultiplied colours are divided by alpha (0
        where it is 0). Case-insensitive, as `reference_alpha`.
    reference_alpha : {None, "straight", "premultiplied"}
        How `reference` stores colour under alpha; None (the default) takes `alpha`.
    edge_width : int
        Pixels within this many (8-connected) of a silhouette are edge pixels.
    percentiles : tuple of float
        The percentiles of the per-channel error to report.
    largest : int
        How many of the largest differences to list.

    Returns
    -------
    Comparison

    Raises
    ------
    ValueError, TypeError
        For images or depths of other shapes or dtypes, empty images, depths outside their
        stated convention, or bad parameters, naming them.

    Examples
    --------
    >>> import numpy as np, glshade as gs
    >>> a = np.zeros((4, 4, 4)); a[1:3, 1:3] = (0.5, 0.5, 0.5, 1)
    >>> b = a.copy(); b[1, 1, 0] += 1e-3
    >>> result = gs.compare(a, b)
    >>> result.counts["color, interior"] + result.counts["color, edge"], result.within_tolerance
    (1, 0.75)
    """
    (a, step_a), (r, step_r) = picture(image, "image"), picture(reference, "reference")
    if a.shape[:2] != r.shape[:2]:
        raise ValueError(
            f"image and reference must have one height and width, got {a.shape} and {r.shape}"
        )
    a = _straight(a, alpha, "alpha")
    r = _straight(r, alpha if reference_alpha is None else reference_alpha, "reference_alpha")
    notes: list[str] = []
    channels = min(a.shape[2], r.shape[2])
    if a.shape[2] != r.shape[2]:
        notes.append("one image has alpha and the other none: RGB compared")
    if tolerance is None:
        step = max(step_a, step_r)
        tol = _FLOAT_TOLERANCE + step / 2
        if step:
            bits = 8 if step > 1 / 1000 else 16
            notes.append(
                f"tolerance {tol:.3g}: half a step of the {bits}-bit image (0.5/{1 / step:g}) "
                f"plus {_FLOAT_TOLERANCE:g}"
            )
    else:
        tol = number(tolerance, "tolerance")
    if not tol >= 0:
        raise ValueError(f"tolerance must be >= 0, got {tol}")
    if isinstance(edge_width, bool) or not isinstance(edge_width, int) or edge_width < 0:
        raise ValueError(f"edge_width must be an integer >= 0, got {edge_width!r}")
    depth_tol, jump, shift = (
        number(depth_tolerance, "depth_tolerance"),
        number(depth_jump, "depth_jump"),
        number(depth_shift, "depth_shift"),
    )
    for name, value in (
        ("depth_tolerance", depth_tol),
        ("depth_jump", jump),
        ("depth_shift", shift),
    ):
        if not 0 <= value < np.inf:
            raise ValueError(f"{name} must be a finite number >= 0, got {value}")
    shape = a.shape[:2]
    conventions = ("window", "linear")
    own = one_of(depth_convention, "depth_convention", conventions)
    theirs = (
        own
        if reference_depth_convention is None
        else one_of(reference_depth_convention, "reference_depth_convention", conventions)
    )
    clip = _clip_planes(near, far)
    da = _window_depth(depth, shape, "depth", own, clip)
    dr = _window_depth(reference_depth, shape, "reference_depth", theirs, clip)
    for name, d, convention in (("depth", da, own), ("reference_depth", dr, theirs)):
        if d is not None and convention == "linear":
            notes.append(f"{name}: eye distances, as window depths with near {clip[0]:g}, far "
                         f"{'inf' if clip[1] is None else f'{clip[1]:g}'}")  # fmt: skip
    clear = None if background is None else _background(background)
    # A background in bytes is known to half a step: a float picture's clear colour is within.
    within = tol + (0.5 / 255 if np.asarray(background).dtype == np.uint8 else 0.0)
    ca, how_a = _covered(a, da, clear, within)
    cr, how_r = _covered(r, dr, clear, within)
    a, r = a[..., :channels], r[..., :channels]
    for name, how, img in (("image", how_a, a), ("reference", how_r, r)):
        border = _border_colour(img, tol) if how == "everywhere" else None
        if border is not None:
            notes.append(
                f"{name} has no transparent pixel and no depth, so all of it counts as covered, "
                f"and its border is one colour, {_rgb_text(border)}: if that is its background, "
                f"pass background={_rgb_text(border)} to tell its silhouettes"
            )
        if how == "background":
            notes.append(f"{name}: covered where its colour is not the background")
    silhouette = coverage_edges(ca) | coverage_edges(cr)
    for d, c in ((da, ca), (dr, cr)):
        if d is not None:
            silhouette |= depth_steps(d, c, jump)
    edge = _dilate(silhouette, edge_width) if edge_width else silhouette
    both = ca & cr
    error = np.abs(a - r)
    # A NaN in either picture is a difference of its own: beyond every tolerance (the scale's
    # dark end), and out of the error statistics, which stay finite.
    nan = np.isnan(error).any(axis=2)
    worst = np.where(nan, np.inf, error.max(axis=2))
    if (nan & both).any():
        notes.append(
            f"{int((nan & both).sum())} pixels both cover are NaN in a picture: colour "
            "differences, left out of the error statistics"
        )
    labels = np.zeros(shape, np.uint8)
    labels[both & (worst > tol)] = 1
    if da is not None and dr is not None:
        slope = np.maximum(_depth_slope(da, ca, jump), _depth_slope(dr, cr, jump))
        labels[both & (np.abs(da - dr) > depth_tol + shift * slope)] = 3
    labels[ca != cr] = 5
    labels[(labels > 0) & edge] += 1
    counts = {kind: int(np.count_nonzero(labels == k)) for k, kind in enumerate(KINDS) if k}

    compared = error[both & ~nan]
    empty = np.zeros(channels)
    stats = {p: np.percentile(compared, p, axis=0) if len(compared) else empty for p in percentiles}
    within = float((worst[both] <= tol).mean()) if both.any() else 1.0
    severity = np.where(labels >= 5, np.inf, worst)
    severity[labels == 0] = -1
    order = np.argsort(-severity, axis=None, kind="stable")[: max(0, int(largest))]
    listed = []
    for flat in order:
        row, column = divmod(int(flat), shape[1])
        if labels[row, column] == 0:
            break
        listed.append(
            {
                "row": row,
                "column": column,
                "kind": KINDS[labels[row, column]],
                "error": 1.0 if labels[row, column] >= 5 else float(worst[row, column]),
                "image": a[row, column],
                "reference": r[row, column],
            }
        )
    return Comparison(
        tolerance=tol,
        compared=int(both.sum()),
        max_error=compared.max(axis=0) if len(compared) else empty,
        mean_error=compared.mean(axis=0) if len(compared) else empty,
        percentiles=stats,
        within_tolerance=within,
        labels=labels,
        counts=counts,
        largest=listed,
        heatmap=_heatmap(r, worst, labels, ca | cr, tol),
        notes=tuple(notes),
    )


def _border_colour(img: Float64Array, tol: float) -> tuple[float, float, float] | None:
    """The RGB of `img`'s outermost pixels when they are all one colour (within `tol`): most
    likely a background that an opaque picture was cleared to; else None."""
    edges = np.concatenate([img[0, :, :3], img[-1, :, :3], img[:, 0, :3], img[:, -1, :3]])
    first = edges[0]
    if img.shape[0] < 3 or img.shape[1] < 3 or np.abs(edges - first).max() > tol:
        return None
    r, g, b = (round(float(v), 4) for v in first)
    return (r, g, b)


def _background(value: ArrayLike) -> Float64Array:
    """The `background` colour as (3,) or (4,) float64, by the colour intake's rules."""
    b = color(value, "background")
    if b.shape not in ((3,), (4,)):
        raise ValueError(f"background must have shape (3,) or (4,), got shape {b.shape}")
    if not np.isfinite(b).all():
        raise ValueError(f"background must be finite, got {b.tolist()}")
    warn_if_bytes(b, "background", "compare")
    return b


def _heatmap(
    reference: Float64Array,
    worst: Float64Array,
    labels: NDArray[np.uint8],
    covered: NDArray[np.bool_],
    tol: float,
) -> Image:
    out = np.ones((*labels.shape, 4), np.float32)
    luminance = np.clip(reference[..., :3] @ np.array(_LUMINANCE), 0.0, 1.0)
    out[..., :3] = (_SAME_LOW + _DIM * luminance)[..., None]
    out[~covered, :3] = _NEITHER
    for kind in (1, 2):
        where = labels == kind
        out[where, :3] = _error_colours(_scale_position(worst[where], tol), kind)
    for kind, rgb in _MARKS.items():
        out[labels == kind, :3] = rgb
    return out.view(Image)


def _scale_position(error: NDArray[np.floating[Any]], tol: float) -> Float64Array:
    """Where `error` lies on the colour scale: log10(error / tol) / 3, clipped to [0, 1]."""
    ratio = np.maximum(error, tol) / max(tol, 1e-300)
    t: Float64Array = np.clip(np.log10(ratio) / _DECADES, 0, 1)
    return t
