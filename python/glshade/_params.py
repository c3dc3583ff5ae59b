"""Checks of user parameters given in a model's own names (``l_a``, ``k_d``, ``view_pos``...), so
an error names the argument the user wrote, not the GL state it becomes."""

from __future__ import annotations

from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from ._intake import real
from ._typing import Float64Array


def real_array(value: ArrayLike, name: str) -> Float64Array:
    """`value` as a finite float64 array (the intake's rule); ValueError for NaN or inf."""
    a = real(value, name)
    if not np.isfinite(a).all():
        raise ValueError(f"{name} must be finite, got {value!r}")
    return a


def scalar(value: Any, name: str, minimum: float | None = None) -> float:
    """A finite real number, at least `minimum` if given."""
    a = real_array(value, name)
    if a.ndim != 0:
        raise ValueError(f"{name} must be a number, got shape {a.shape}")
    x = float(a)
    if minimum is not None and x < minimum:
        raise ValueError(f"{name} must be >= {minimum:g}, got {x:g}")
    return x


def vector3(
    value: ArrayLike, name: str, *, rows: bool = False, nonzero: bool = False
) -> Float64Array:
    """A point or direction of shape (3,), or (L, 3) when `rows`; `nonzero` rejects (0, 0, 0)."""
    a = real_array(value, name)
    if not (a.shape == (3,) or (rows and a.ndim == 2 and a.shape[1] == 3)):
        expected = "(3,) or (L, 3)" if rows else "(3,)"
        raise ValueError(f"{name} must have shape {expected}, got {a.shape}")
    if nonzero and not np.all(np.any(a != 0, axis=-1)):
        raise ValueError(f"{name} must be a nonzero vector, got {value!r}")
    return a


def rgb(value: ArrayLike, name: str, *, alpha: bool = False, grey: bool = False) -> Float64Array:
    """A colour: (3,) RGB, or (4,) RGBA when `alpha`, or a number meaning grey when `grey`."""
    a = real_array(value, name)
    if grey and a.ndim == 0:
        return np.full(3, float(a))
    widths = (3, 4) if alpha else (3,)
    if a.ndim != 1 or a.shape[0] not in widths:
        expected = " or ".join(f"({w},)" for w in widths)
        if grey:
            expected = "a number or " + expected
        raise ValueError(f"{name} must have shape {expected}, got {a.shape}")
    return a
