"""Textures at the boundary: an image (numpy array or PIL image, grey, grey and alpha, RGB or
RGBA, uint8, uint16 or float) as the (height, width, channels) texels `render` samples in place,
and the names of its filter and wrap modes."""

from __future__ import annotations

from typing import Any

import numpy as np
from numpy.typing import NDArray

from ._intake import array, one_of, warn_if_bytes

__all__ = ["FILTERS", "WRAPS", "texels", "wrap_modes"]

FILTERS = ("nearest", "linear")
WRAPS = ("repeat", "mirrored_repeat", "clamp_to_edge")

# The types the renderer reads in place (uint8 and uint16 normalised, as GL's unsigned
# normalised formats); others are converted to float32 on every call.
_IN_PLACE = (np.uint8, np.uint16, np.float32, np.float64)


def texels(image: Any) -> NDArray[Any]:
    """`image` as a C-contiguous (height, width, channels) array, the top row first, without a
    copy where it already is one of uint8, uint16, float32 or float64 (a grey image gains its
    channel axis as a view); other real types as float32. The renderer reads 1 to 4 channels
    (grey, grey and alpha, RGB, RGBA) as GL's texture formats do, a missing alpha 1."""
    a = array(np.asarray(image), "texture")
    if a.ndim == 2:
        a = a[..., None]
    if a.ndim != 3 or a.shape[2] not in (1, 2, 3, 4) or a.shape[0] == 0 or a.shape[1] == 0:
        raise ValueError(
            f"texture must have shape (height, width) or (height, width, 1, 2, 3 or 4), got "
            f"shape {a.shape}"
        )
    if a.dtype.kind not in "fiu":
        raise TypeError(f"texture must be a real image (uint8, uint16 or float), got {a.dtype}")
    if not a.dtype.isnative:  # big-endian data: the same type in this machine's order
        a = a.astype(a.dtype.newbyteorder("="))
    if a.dtype.kind != "u" or a.dtype.itemsize > 2:  # uint8 and uint16 are normalised
        warn_if_bytes(a, "texture", "render")
    if a.dtype.type in _IN_PLACE:
        return np.ascontiguousarray(a)
    return np.ascontiguousarray(a, dtype=np.float32)


def wrap_modes(value: object) -> tuple[str, str]:
    """One wrap mode for both axes, or a pair (s, t)."""
    if isinstance(value, str):
        mode = one_of(value, "texture_wrap", WRAPS)
        return mode, mode
    if isinstance(value, (tuple, list)) and len(value) == 2:
        s, t = (one_of(v, "texture_wrap", WRAPS) for v in value)
        return s, t
    raise TypeError(f"texture_wrap must be a mode name or a pair of them, got {value!r}")
