"""Results of 32 MiB and more come from a small pool of buffers (src/memory/recycle.rs): the
memory a freed result held serves the next one, already faulted in. A pooled result is an
ordinary writeable C-contiguous array whose values are those `out=` gets, and a view keeps
its memory alive after the result itself is gone."""

from __future__ import annotations

import gc

import numpy as np

import glshade as gs
from support.boundary import SUN

# 2.2 million float32 RGBA rows: 35 MB, above the pool's 32 MiB.
N = 2_200_000


def _inputs() -> tuple[np.ndarray, np.ndarray]:
    rng = np.random.default_rng(5)
    p = rng.uniform(-1, 1, (N, 3)).astype(np.float32)
    n = rng.normal(size=(N, 3)).astype(np.float32)
    return p, n


def _address(a: np.ndarray) -> int:
    return int(a.__array_interface__["data"][0])


def test_a_freed_large_result_serves_the_next_and_holds_the_same_values() -> None:
    p, n = _inputs()
    first = gs.shade(p, n, SUN)
    assert first.flags.c_contiguous and first.flags.writeable and first.flags.aligned
    expected = np.empty_like(first)
    gs.shade(p, n, SUN, out=expected)
    np.testing.assert_array_equal(first, expected)
    address = _address(first)
    del first
    gc.collect()
    second = gs.shade(p, n, SUN)
    assert _address(second) == address, "the freed buffer was not reused"
    np.testing.assert_array_equal(second, expected)
    second[0] = 2.0  # writeable, like any numpy result
    assert second[0, 0] == 2.0


def test_a_view_keeps_a_pooled_result_alive() -> None:
    p, n = _inputs()
    expected = gs.shade(p, n, SUN).copy()
    view = gs.shade(p, n, SUN)[::1000]
    gc.collect()
    # A new result must not take the memory the view still reads.
    other = gs.shade(p * 2, n, SUN)
    np.testing.assert_array_equal(view, expected[::1000])
    assert other.shape == expected.shape
