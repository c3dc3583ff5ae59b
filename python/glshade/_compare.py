"""`compare`: two images side by side, their differences measured and explained."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Literal

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ._image import Image
from ._intake import array, number
from ._records import ValueRecord
from ._typing import Float64Array

__all__ = ["Comparison", "compare"]

Alpha = Literal["straight", "premultiplied"]

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
# Heatmap colours of the kinds other than colour differences (RGB).
_MARKS = {
    3: (0.2, 0.4, 1.0),
    4: (0.1, 0.2, 0.6),
    5: (0.0, 1.0, 1.0),
    6: (1.0, 0.0, 1.0),
}


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
        nothing is compared).
    labels : (height, width) uint8
        Each pixel's kind, an index into `KINDS`: "same"; "color" (both cover, colours differ
        beyond the tolerance); "depth" (both cover, depths differ beyond `depth_tolerance`:
        the images show different surfaces, a depth tie or an occlusion); "coverage" (one
        image covers the pixel, the other not); each split into "edge" (within `edge_width`
        pixels of a silhouette: a coverage boundary or a depth step in either image) and
        "interior".
    counts : dict of str to int
        The number of pixels of each kind but "same".
    largest : list of dict
        The largest differences, largest first: ``row``, ``column``, ``kind``, ``error`` (the
        largest channel's; 1 for coverage), ``image`` and ``reference`` (the pixel values).
    heatmap : Image
        (height, width, 4) float32, opaque: the reference's luminance dimmed where the
        images agree, colour differences from orange (the tolerance) to white (1000 times
        it) on a log scale, depth differences blue, coverage differences cyan (interior) and
        magenta (edge); transparent where neither covers. Shows itself in a notebook.
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
        for d in self.largest[:3]:
            lines.append(
                f"  ({d['row']}, {d['column']}) {d['kind']}: error {d['error']:.3g}, "
                f"image {np.round(d['image'], 6).tolist()}, "
                f"reference {np.round(d['reference'], 6).tolist()}"
            )
        return "\n".join(lines)

    def _repr_png_(self) -> bytes:
        """The heatmap, in a notebook."""
        return self.heatmap._repr_png_()


def _as_float(value: ArrayLike, name: str) -> Float64Array:
    """(height, width, 3|4) as float64 in [0, 1]: uint8 scaled by 1/255, uint16 by 1/65535."""
    a = array(value, name)
    if a.ndim != 3 or a.shape[2] not in (3, 4):
        raise ValueError(f"{name} must have shape (height, width, 3) or (..., 4), got {a.shape}")
    scale = {np.dtype(np.uint8): 255.0, np.dtype(np.uint16): 65535.0}.get(a.dtype, 1.0)
    result: Float64Array = a.astype(np.float64) / scale
    return result


def _straight(a: Float64Array, alpha: str, name: str) -> Float64Array:
    if alpha not in ("straight", "premultiplied"):
        raise ValueError(f"{name} must be 'straight' or 'premultiplied', got {alpha!r}")
    if alpha == "straight" or a.shape[2] == 3:
        return a
    out = a.copy()
    w = a[..., 3:]
    out[..., :3] = np.divide(a[..., :3], w, out=np.zeros_like(a[..., :3]), where=w > 0)
    return out


def _depth(value: ArrayLike | None, shape: tuple[int, int], name: str) -> Float64Array | None:
    if value is None:
        return None
    d = array(value, name).astype(np.float64)
    if d.shape != shape:
        raise ValueError(f"{name} must have shape {shape} (the images'), got {d.shape}")
    return d


def _neighbours_differ(mask: NDArray[Any]) -> NDArray[np.bool_]:
    """Pixels with an 8-neighbour of another coverage."""
    h, w = mask.shape
    padded = np.pad(mask, 1, mode="edge")
    out = np.zeros((h, w), bool)
    for a in (-1, 0, 1):
        for b in (-1, 0, 1):
            out |= padded[1 + a : 1 + a + h, 1 + b : 1 + b + w] != mask
    return out


def _depth_steps(depth: Float64Array, covered: NDArray[np.bool_], jump: float) -> NDArray[np.bool_]:
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


def compare(
    image: ArrayLike,
    reference: ArrayLike,
    *,
    tolerance: float = 1e-4,
    depth: ArrayLike | None = None,
    reference_depth: ArrayLike | None = None,
    depth_tolerance: float = 1e-5,
    depth_jump: float = 1e-2,
    alpha: Alpha = "straight",
    reference_alpha: Alpha | None = None,
    edge_width: int = 1,
    percentiles: tuple[float, ...] = (50.0, 90.0, 99.0, 99.9),
    largest: int = 10,
) -> Comparison:
    """Compares an image with a reference and explains where and why they differ.

    A pixel is covered where its depth is below 1 (GL's cleared depth) when depths are given,
    else where its alpha is above 0 (4 channels), else always. Colours are compared as
    straight (not premultiplied) RGBA.

    Parameters
    ----------
    image, reference : (height, width, 3) or (height, width, 4) array
        Float images in [0, 1], or uint8 (scaled by 1/255) or uint16 (1/65535); the same shape.
        ``gs.render``'s and ``gs.glsl.render``'s images, a framebuffer read back, a PNG.
    tolerance : float
        Per channel: a larger difference counts.
    depth, reference_depth : (height, width) float, optional
        Window depths in [0, 1] (1 where nothing is drawn): coverage from them, and pixels
        where they differ beyond `depth_tolerance` are told apart as depth differences.
    depth_tolerance : float
        The depth difference that counts.
    depth_jump : float
        A depth step between neighbours that counts as a silhouette (an inner edge).
    alpha : {"straight", "premultiplied"}
        How `image` stores colour under alpha; premultiplied colours are divided by alpha (0
        where it is 0).
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
        For images or depths of other shapes or dtypes, or bad parameters, naming them.

    Examples
    --------
    >>> import numpy as np, glshade as gs
    >>> a = np.zeros((4, 4, 4)); a[1:3, 1:3] = (0.5, 0.5, 0.5, 1)
    >>> b = a.copy(); b[1, 1, 0] += 1e-3
    >>> result = gs.compare(a, b)
    >>> result.counts["color, interior"] + result.counts["color, edge"], result.within_tolerance
    (1, 0.75)
    """
    a = _as_float(image, "image")
    r = _as_float(reference, "reference")
    if a.shape != r.shape:
        raise ValueError(f"image and reference must have one shape, got {a.shape} and {r.shape}")
    a = _straight(a, alpha, "alpha")
    r = _straight(r, alpha if reference_alpha is None else reference_alpha, "reference_alpha")
    tol = number(tolerance, "tolerance")
    if not tol >= 0:
        raise ValueError(f"tolerance must be >= 0, got {tol}")
    if isinstance(edge_width, bool) or not isinstance(edge_width, int) or edge_width < 0:
        raise ValueError(f"edge_width must be an integer >= 0, got {edge_width!r}")
    shape = a.shape[:2]
    da = _depth(depth, shape, "depth")
    dr = _depth(reference_depth, shape, "reference_depth")

    def coverage(img: Float64Array, d: Float64Array | None) -> NDArray[np.bool_]:
        if d is not None:
            return d < 1.0
        if img.shape[2] == 4:
            result: NDArray[np.bool_] = img[..., 3] > 0
            return result
        return np.ones(shape, bool)

    ca, cr = coverage(a, da), coverage(r, dr)
    silhouette = _neighbours_differ(ca) | _neighbours_differ(cr)
    for d, c in ((da, ca), (dr, cr)):
        if d is not None:
            silhouette |= _depth_steps(d, c, number(depth_jump, "depth_jump"))
    edge = _dilate(silhouette, edge_width) if edge_width else silhouette
    both = ca & cr
    error = np.abs(a - r)
    worst = error.max(axis=2)
    labels = np.zeros(shape, np.uint8)
    labels[both & (worst > tol)] = 1
    if da is not None and dr is not None:
        labels[both & (np.abs(da - dr) > number(depth_tolerance, "depth_tolerance"))] = 3
    labels[ca != cr] = 5
    labels[(labels > 0) & edge] += 1
    counts = {kind: int(np.count_nonzero(labels == k)) for k, kind in enumerate(KINDS) if k}

    compared = error[both]
    channels = a.shape[2]
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
    )


def _heatmap(
    reference: Float64Array,
    worst: Float64Array,
    labels: NDArray[np.uint8],
    covered: NDArray[np.bool_],
    tol: float,
) -> Image:
    out = np.zeros((*labels.shape, 4), np.float32)
    luminance = reference[..., :3] @ np.array([0.2126, 0.7152, 0.0722])
    out[..., :3] = (0.35 * luminance)[..., None]
    colour = (labels == 1) | (labels == 2)
    # log10(error / tol) over [0, 3] from orange through red to white.
    t = np.clip(np.log10(np.maximum(worst, tol) / max(tol, 1e-300)) / 3, 0, 1)[colour]
    out[colour, 0] = 1.0
    out[colour, 1] = 0.5 * (1 - t) + t * t
    out[colour, 2] = t * t
    for kind, rgb in _MARKS.items():
        out[labels == kind, :3] = rgb
    out[..., 3] = covered
    return out.view(Image)
