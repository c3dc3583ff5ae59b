"""The intake's memory layouts: Fortran, reversed, strided, misaligned, byte-swapped, read-only and
column views give the contiguous result, also with an unpickled scene."""

from __future__ import annotations

import pickle
from typing import Any

import numpy as np
import pytest

import glshade as gs
from support.boundary import MIXED, misaligned, rows


@pytest.mark.parametrize("dtype", [np.float32, np.float64])
@pytest.mark.parametrize(
    "layout",
    ["fortran", "reversed", "strided", "misaligned", "byteswapped", "readonly", "column_view"],
)
def test_any_memory_layout_gives_the_contiguous_result(
    dtype: Any, layout: str, rng: np.random.Generator
) -> None:
    p, n = rows(rng, 67, dtype)
    expected = gs.shade(p, n, MIXED)

    def arrange(a: np.ndarray) -> np.ndarray:
        if layout == "fortran":
            return np.asfortranarray(a)
        if layout == "reversed":
            return a[::-1][::-1]
        if layout == "strided":
            return np.repeat(a, 3, axis=0)[::3]
        if layout == "misaligned":
            return misaligned(a)
        if layout == "byteswapped":
            return a.astype(a.dtype.newbyteorder())
        if layout == "readonly":
            b = a.copy()
            b.flags.writeable = False
            return b
        wide = np.zeros((len(a), 7), a.dtype)
        wide[:, 2:5] = a
        return wide[:, 2:5]

    result = gs.shade(arrange(p), arrange(n), MIXED)
    assert result.dtype == dtype
    np.testing.assert_array_equal(result, expected)


def test_unpickled_scene_and_misaligned_arrays_shade_as_the_original(
    rng: np.random.Generator,
) -> None:
    # dask.distributed hands workers unpickled arrays at odd offsets.
    p, n = rows(rng, 40, np.float32)
    scene = pickle.loads(pickle.dumps(MIXED))
    np.testing.assert_array_equal(
        gs.shade(misaligned(p), misaligned(n), scene), gs.shade(p, n, MIXED)
    )
