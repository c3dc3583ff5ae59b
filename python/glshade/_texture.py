"""Textures at the boundary: an image (numpy array or PIL image, grey, grey and alpha, RGB or
RGBA, uint8, uint16 or float) as the float32 RGBA texels `render` samples, and the names of its
filter and wrap modes."""

from __future__ import annotations

from typing import Any

import numpy as np
from numpy.typing import NDArray

from ._intake import array, one_of

__all__ = ["FILTERS", "WRAPS", "texels", "wrap_modes"]

FILTERS = ("nearest", "linear")
WRAPS = ("repeat", "mirrored_repeat", "clamp_to_edge")


def texels(image: Any) -> NDArray[np.float32]:
    """`image` as C-contiguous (height, width, 4) float32 RGBA, the top row first: uint8 and
    uint16 scaled to [0, 1], grey copied into R, G and B, a missing alpha 1."""
    a = array(np.asarray(image), "texture")
    if a.ndim == 2:
        a = a[..., None]
    if a.ndim != 3 or a.shape[2] not in (1, 2, 3, 4) or a.shape[0] == 0 or a.shape[1] == 0:
        raise ValueError(
            f"texture must have shape (height, width) or (height, width, 1, 2, 3 or 4), got "
            f"shape {a.shape}"
        )
    if a.dtype == np.uint8 or a.dtype == np.uint16:
        values = a / float(np.iinfo(a.dtype).max)
    elif a.dtype.kind in "fiu":
        values = a.astype(np.float64)
    else:
        raise TypeError(f"texture must be a real image (uint8, uint16 or float), got {a.dtype}")
    channels = values.shape[2]
    if channels <= 2:
        grey = np.repeat(values[..., :1], 3, axis=2)
        values = np.concatenate([grey, values[..., 1:]], axis=2)
    if values.shape[2] == 3:
        values = np.concatenate([values, np.ones((*values.shape[:2], 1))], axis=2)
    return np.ascontiguousarray(values, dtype=np.float32)


def wrap_modes(value: object) -> tuple[str, str]:
    """One wrap mode for both axes, or a pair (s, t)."""
    if isinstance(value, str):
        mode = one_of(value, "texture_wrap", WRAPS)
        return mode, mode
    if isinstance(value, (tuple, list)) and len(value) == 2:
        s, t = (one_of(v, "texture_wrap", WRAPS) for v in value)
        return s, t
    raise TypeError(f"texture_wrap must be a mode name or a pair of them, got {value!r}")
