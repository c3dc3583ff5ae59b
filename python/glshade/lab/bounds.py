"""The accuracy bounds of each mode, per channel, as the documentation's Accuracy page
(docs/pages/guide/accuracy.md) states them: the one place the report and its tests read them.

    bound = relative · max(1, Σ|terms|) + sensitivity · Σ (s·tanθ / min(1, |h|) + e·tanφ)·|term|
            + rounding

(``Σ|terms|`` is 1 or less on unit normals and colours in [0, 1], where the bound is
``relative + rounding``; ``s·tanθ`` and ``e·tanφ`` are the condition numbers of the specular
and spot powers, and ``h = VP + V`` the unnormalised halfway vector, whose direction is as
uncertain as ``u / |h|`` where the light is nearly opposite the viewer.) Where the exact
value is infinite (an unbounded attenuation) the clamped result must be exactly 1: the bound
is 0. Within `EDGE` of a discontinuity of the
equation (n·VP = 0 where the specular gate switches something, a cone's edge) the arithmetic
may pick the other side; such a vertex is counted apart, not held to the bound.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray

__all__ = ["BOUNDS", "EDGE", "Bound"]

U32, U64 = 2.0**-24, 2.0**-53


@dataclass(frozen=True)
class Bound:
    """One mode's bound: its coefficients (see the module's formula)."""

    relative: float
    sensitivity: float
    rounding: float = 0.0

    @property
    def unit(self) -> float:
        """The bound on unit normals and colours in [0, 1]: the Accuracy page's table."""
        return self.relative + self.rounding

    def per_channel(self, magnitude: NDArray[Any], sensitivity: NDArray[Any]) -> NDArray[Any]:
        """The bound of each channel, from the reference's sum of |terms| and sensitivity."""
        with np.errstate(invalid="ignore"):
            value = (
                self.relative * np.maximum(1.0, magnitude)
                + self.sensitivity * sensitivity
                + self.rounding
            )
        out: NDArray[Any] = np.where(np.isinf(magnitude), 0.0, value)
        return out


BOUNDS: dict[tuple[str, str], Bound] = {
    # Sums of more than 8 lights in blocks of 8, the blocks added by TwoSum with their rounding
    # errors kept apart: the light count adds at most 8 ulp of Σ|terms|.
    ("float32", "fast"): Bound(2e-6, 16 * U32),
    ("float64", "fast"): Bound(1e-12, 16 * U64),
    # float64 arithmetic, rounded once to float32: half an ulp of the result more.
    ("float32", "exact"): Bound(1e-12, 16 * U64, U32),
    ("float64", "exact"): Bound(1e-12, 16 * U64),
}

EDGE = {"float32": 2e-5, "float64": 1e-9}
