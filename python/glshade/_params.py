"""Checks of user parameters given in a model's own names (``l_a``, ``k_d``, ``view_pos``...), so
an error names the argument the user wrote, not the GL state it becomes.

Colours follow `_intake`'s rules for a scene's colours (`_intake.color`): a colour name raises
the TypeError that gives its numbers, uint8 is divided by 255, and one that looks like 0-255
bytes warns (`ColorRangeWarning`, `warn_bytes`) under the user's name, once: the `Light`,
`Material` and `Scene` made from it are built inside `colors_checked`, so they do not warn
again under GL's names."""

from __future__ import annotations

from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from ._intake import color, real, warn_if_bytes
from ._typing import Float64Array


def _finite(a: Float64Array, value: Any, name: str) -> Float64Array:
    if not np.isfinite(a).all():
        raise ValueError(f"{name} must be finite, got {value!r}")
    return a


def real_array(value: ArrayLike, name: str) -> Float64Array:
    """`value` as a finite float64 array (the intake's rule); ValueError for NaN or inf."""
    return _finite(real(value, name), value, name)


def color_array(value: ArrayLike, name: str) -> Float64Array:
    """A colour or intensity of any shape as a finite float64 array, by `_intake.color`'s rule:
    a colour name raises a TypeError giving its numbers, uint8 is divided by 255."""
    return _finite(color(value, name), value, name)


def warn_bytes(colors: dict[str, Float64Array], owner: str) -> None:
    """`_intake.warn_if_bytes` on each colour of `colors` (checked by `rgb` or `color_array`,
    by the user's name), naming `owner`, the function they were given to. Called once the
    objects are built, as `Material` and `Lights` warn, so a wrong argument raises first; an
    attenuated light's colour, an intensity, is left out by the caller, as `Lights` does."""
    for name, values in colors.items():
        warn_if_bytes(values, name, owner)


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
    """A colour: (3,) RGB, or (4,) RGBA when `alpha`, or a number meaning grey when `grey`, by
    `color_array`'s rule (a name refused, uint8 divided by 255). `warn_bytes` warns about it
    once the objects it makes are built."""
    a = color_array(value, name)
    if grey and a.ndim == 0:
        a = np.full(3, float(a))
    widths = (3, 4) if alpha else (3,)
    if a.ndim != 1 or a.shape[0] not in widths:
        expected = " or ".join(f"({w},)" for w in widths)
        if grey:
            expected = "a number or " + expected
        raise ValueError(f"{name} must have shape {expected}, got {a.shape}")
    return a
