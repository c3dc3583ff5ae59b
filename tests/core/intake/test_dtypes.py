"""The intake's dtypes: every real dtype is accepted and computes as the table says, non-numbers
raise a TypeError naming the argument, array-likes are taken as numpy takes them."""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest

import glshade as gs
from support.boundary import MIXED, SUN, rows


@pytest.mark.parametrize(
    ("dtype", "computes_in"),
    [
        (np.float16, np.float32),
        (np.float32, np.float32),
        (np.float64, np.float64),
        (np.int8, np.float64),
        (np.int32, np.float64),
        (np.int64, np.float64),
        (np.uint16, np.float64),
        (np.bool_, np.float64),
        (">f4", np.float32),
        (">f8", np.float64),
    ],
)
def test_every_real_dtype_is_accepted_and_computes_as_the_table_says(
    dtype: Any, computes_in: Any
) -> None:
    p = np.array([[0, 0, 0], [1, 1, 0]]).astype(dtype)
    n = np.array([[0, 0, 1], [0, 1, 1]]).astype(dtype)
    result = gs.shade(p, n, MIXED)
    assert result.dtype == computes_in
    expected = gs.shade(p.astype(computes_in), n.astype(computes_in), MIXED)
    np.testing.assert_array_equal(result, expected)


@pytest.mark.parametrize(
    "value",
    [
        np.array([[0, 0, 1j]]),
        np.array([["a", "b", "c"]]),
        np.array([[None, None, None]], dtype=object),
        "normals",
        [[0, 0, "1"]],
        {"x": 1},
    ],
)
def test_non_numbers_raise_type_error_naming_the_argument(value: Any) -> None:
    with pytest.raises(TypeError, match="normals"):
        gs.shade(np.zeros((1, 3)), value, SUN)


def test_array_likes_are_taken_as_numpy_takes_them(rng: np.random.Generator) -> None:
    class Wrapped:
        def __init__(self, a: np.ndarray) -> None:
            self.a = a

        def __array__(self, dtype: Any = None, copy: Any = None) -> np.ndarray:
            return self.a

    p, n = rows(rng, 20, np.float32)
    expected = gs.shade(p, n, MIXED)
    np.testing.assert_array_equal(gs.shade(Wrapped(p), Wrapped(n), MIXED), expected)
    np.testing.assert_array_equal(gs.shade(memoryview(p), memoryview(n), MIXED), expected)
    lists = gs.shade(p.tolist(), n.tolist(), MIXED)
    assert lists.dtype == np.float64
    np.testing.assert_allclose(lists, expected, atol=1e-6)
