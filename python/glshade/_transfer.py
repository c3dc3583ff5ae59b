"""Transfer functions: sRGB's (IEC 61966-2-1) both ways, and the encodings `render` applies to
its linear result (``transfer="linear" | "srgb" | "gamma2.2"``)."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any, Literal

import numpy as np
from numpy.typing import ArrayLike

from . import _glshade
from ._intake import array, one_of
from ._typing import FloatArray

__all__ = ["Transfer", "srgb_decode", "srgb_encode"]

Transfer = Literal["linear", "srgb", "gamma2.2"]
TRANSFERS: tuple[str, ...] = ("linear", "srgb", "gamma2.2")

# IEC 61966-2-1's constants (decoding's; the core holds encoding's): the encoded linear
# segment's end, its slope, and the power segment.
_ENCODED_END = 0.04045
_SLOPE = 12.92
_A = 0.055
_GAMMA = 2.4


def _values(x: ArrayLike) -> FloatArray:
    """`x` as the float array the transfer functions compute in: float32 and float64 as they
    are, uint8 and uint16 (an image's stored values) scaled to [0, 1], anything else real as
    float64."""
    a = array(x, "x")
    if a.dtype == np.uint8 or a.dtype == np.uint16:
        scaled: FloatArray = a / float(np.iinfo(a.dtype).max)
        return scaled
    if a.dtype == np.float32 or a.dtype == np.float64:
        return a
    converted: FloatArray = a.astype(np.float64)
    return converted


def _mirrored(a: Any, curve: Callable[[Any], Any]) -> FloatArray:
    """``sign(a) curve(|a|)`` in `a`'s dtype: a transfer curve of [0, inf) extended to negative
    values (CSS Color 4's extended sRGB); NaN stays NaN."""
    with np.errstate(invalid="ignore"):
        result: FloatArray = np.copysign(curve(np.abs(a)), a).astype(a.dtype, copy=False)
    return result


def _encoded(a: FloatArray, name: str) -> FloatArray:
    """A copy of `a` (float32 or float64) encoded by the transfer `name` in the core, the code
    a render encodes its pixels with: the same bits on every machine (numpy's own power
    differs by an ulp on some, where it runs SIMD code of its own)."""
    out = np.array(a, order="C", copy=True)
    if out.size:
        _glshade.encode(out, name, rgba=False)
    return out


def srgb_encode(x: ArrayLike) -> FloatArray:
    """Linear light to sRGB's encoded values (IEC 61966-2-1), as an sRGB display expects.

    ``12.92 x`` for ``x <= 0.0031308``, else ``1.055 x^(1/2.4) - 0.055``: what a PNG viewer,
    a browser, matplotlib's ``imshow`` and Pillow take an image's values to be. glshade's
    renders are linear (the lighting equation's sums); encode them before showing or saving to
    get the brightness pyrender's, three.js's or Blender's sRGB output shows.

    Parameters
    ----------
    x : array-like, any shape
        Linear values, nominally in [0, 1]. float32 and float64 keep their dtype; uint8 and
        uint16 (stored image values) are first divided by 255 or 65535; any other real dtype
        is computed in float64.

    Returns
    -------
    ndarray, the shape of `x`
        The encoded values: in [0, 1] for `x` in [0, 1], float32 or float64.

    Raises
    ------
    TypeError
        For complex, string or object input.

    Notes
    -----
    Values outside [0, 1] are not clipped: the curve is extended as CSS Color 4's "extended"
    sRGB (and scRGB) extend it, ``sign(x) f(|x|)``, so a negative value stays negative, a value
    above 1 encodes above 1, and `srgb_decode` undoes `srgb_encode` on every real number. Clip
    first (``np.clip(x, 0, 1)``) for a display's range. NaN stays NaN; infinities keep their
    sign.

    Examples
    --------
    >>> import glshade as gs
    >>> gs.srgb_encode([0.0, 0.0031308, 0.18, 1.0]).round(4)
    array([0.    , 0.0404, 0.4614, 1.    ])
    """
    return _encoded(_values(x), "srgb")


def srgb_decode(x: ArrayLike) -> FloatArray:
    """sRGB's encoded values to linear light (IEC 61966-2-1): the inverse of `srgb_encode`.

    ``x / 12.92`` for ``x <= 0.04045``, else ``((x + 0.055) / 1.055)^2.4``: a PNG's or a colour
    picker's values as the light the lighting equation sums.

    Parameters
    ----------
    x : array-like, any shape
        Encoded values, nominally in [0, 1]. float32 and float64 keep their dtype; uint8 and
        uint16 (an 8- or 16-bit image as Pillow or imageio read it) are first divided by 255
        or 65535; any other real dtype is computed in float64.

    Returns
    -------
    ndarray, the shape of `x`
        Linear values: in [0, 1] for `x` in [0, 1], float32 or float64.

    Raises
    ------
    TypeError
        For complex, string or object input.

    Notes
    -----
    Outside [0, 1] the curve is extended as in `srgb_encode` (``sign(x) f(|x|)``), so that
    ``srgb_encode(srgb_decode(x)) == x`` up to rounding for every real `x`. NaN stays NaN.

    Examples
    --------
    >>> import glshade as gs
    >>> gs.srgb_decode([0.0, 0.04045, 0.5, 1.0]).round(4)
    array([0.    , 0.0031, 0.214 , 1.    ])
    """
    return _mirrored(
        _values(x),
        lambda m: np.where(m <= _ENCODED_END, m / _SLOPE, ((m + _A) / (1 + _A)) ** _GAMMA),
    )


def transfer_name(value: object) -> str:
    """`value` checked to be one of `TRANSFERS`, lower-cased."""
    return one_of(value, "transfer", TRANSFERS)


def apply_transfer(rgba: Any, name: str) -> Any:
    """`rgba` (..., 4) with the transfer `name` applied to its RGB, alpha as it is; a new array
    unless `name` is "linear"."""
    if name == "linear":
        return rgba
    out = rgba.copy()
    transfer_in_place(out, name)
    return out


def transfer_in_place(rgba: Any, name: str) -> None:
    """Applies the transfer `name` to the RGB of the float array `rgba` (..., 4), in place."""
    if name == "linear":
        return
    whole = rgba.dtype in (np.float32, np.float64) and rgba.shape[-1:] == (4,)
    if whole and rgba.flags.c_contiguous and rgba.flags.writeable:
        _glshade.encode(rgba, name, rgba=True)
    else:
        rgba[..., :3] = _encoded(rgba[..., :3], name)
