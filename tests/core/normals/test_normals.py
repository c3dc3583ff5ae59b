"""Normals: analytic truths, conventions, dtypes and every error path (no reference library)."""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest

import glshade as gs
from support.processes import passes

CUBE_V = np.array([[i & 1, (i >> 1) & 1, (i >> 2) & 1] for i in range(8)], np.float64)
CUBE_F = np.array(
    [[0, 2, 1], [1, 2, 3], [4, 5, 6], [5, 7, 6], [0, 1, 4], [1, 5, 4],
     [2, 6, 3], [3, 6, 7], [0, 4, 2], [2, 4, 6], [1, 3, 5], [3, 7, 5]]
)  # fmt: skip


@pytest.mark.parametrize("dtype", [np.float32, np.float64])
def test_cube(dtype: Any) -> None:
    v = CUBE_V.astype(dtype)
    fn = gs.face_normals(v, CUBE_F)
    assert fn.dtype == dtype
    # Each face normal is an axis, pointing away from the centre.
    centres = v[CUBE_F].mean(axis=1) - 0.5
    np.testing.assert_allclose(fn, np.sign(centres) * (np.abs(centres) == 0.5), atol=1e-7)
    # Angle weighting: every corner normal is the cube diagonal (three right angles).
    np.testing.assert_allclose(gs.vertex_normals(v, CUBE_F), (2 * v - 1) / np.sqrt(3), atol=1e-7)
    # Uniform weighting: corners with two triangles on one face lean towards that face.
    uniform = gs.vertex_normals(v, CUBE_F, weighting="uniform")
    assert not np.allclose(uniform, (2 * v - 1) / np.sqrt(3), atol=1e-3)
    np.testing.assert_allclose(np.linalg.norm(uniform, axis=1), 1, atol=1e-6)


@pytest.mark.parametrize("weighting", ["angle", "area", "uniform"])
def test_unit_or_zero_and_invariant_under_scale_translation_and_face_order(weighting: str) -> None:
    rng = np.random.default_rng(1)
    v = rng.normal(size=(200, 3))
    f = rng.integers(0, 150, (300, 3))  # vertices 150..199 are unreferenced
    n = gs.vertex_normals(v, f, weighting)
    lengths = np.linalg.norm(n, axis=1)
    assert np.all((np.abs(lengths - 1) < 1e-14) | (lengths == 0))
    assert np.all(lengths[150:] == 0)
    for scale in (2.0**-40, 2.0**40):  # exact in binary: the same bits
        np.testing.assert_array_equal(gs.vertex_normals(v * scale, f, weighting), n)
    np.testing.assert_allclose(gs.vertex_normals(v + 7.0, f, weighting), n, atol=1e-12)
    np.testing.assert_allclose(
        gs.vertex_normals(v, f[rng.permutation(len(f))], weighting), n, atol=1e-14
    )


def test_opposite_faces_cancel_to_zero() -> None:
    v = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0]], float)
    assert np.array_equal(gs.vertex_normals(v, [[0, 1, 2], [0, 2, 1]]), np.zeros((3, 3)))


def test_any_integer_dtype_for_faces() -> None:
    expected = gs.vertex_normals(CUBE_V, CUBE_F)
    for dtype in (np.int8, np.uint8, np.int16, np.uint16, np.int32, np.uint32, np.uint64):
        np.testing.assert_array_equal(gs.vertex_normals(CUBE_V, CUBE_F.astype(dtype)), expected)
    np.testing.assert_array_equal(gs.vertex_normals(CUBE_V.tolist(), CUBE_F.tolist()), expected)
    np.testing.assert_array_equal(
        gs.vertex_normals(np.asfortranarray(CUBE_V), CUBE_F[:, ::1]), expected
    )


def test_nan_vertex_spreads_only_through_its_faces() -> None:
    v = CUBE_V.copy()
    v[0, 0] = np.nan
    n = gs.vertex_normals(v, CUBE_F)
    touching = np.unique(CUBE_F[(CUBE_F == 0).any(axis=1)])
    assert np.isnan(n[touching]).any(axis=1).all()
    others = np.setdiff1d(np.arange(8), touching)
    assert np.isfinite(n[others]).all()


def test_empty_mesh() -> None:
    assert gs.vertex_normals(np.zeros((4, 3)), np.zeros((0, 3), int)).tolist() == [[0, 0, 0]] * 4
    assert gs.face_normals(np.zeros((0, 3)), np.zeros((0, 3), int)).shape == (0, 3)


@pytest.mark.parametrize("weighting", ["angle", "area", "uniform"])
def test_float32_is_the_float64_result_rounded_once(weighting: str) -> None:
    # Geometry and sums run in float64 also for float32 vertices (widening is exact).
    rng = np.random.default_rng(2)
    v = rng.normal(size=(500, 3)).astype(np.float32)
    f = rng.integers(0, 500, (900, 3))
    wide = v.astype(np.float64)
    np.testing.assert_array_equal(
        gs.vertex_normals(v, f, weighting), gs.vertex_normals(wide, f, weighting).astype(np.float32)
    )
    np.testing.assert_array_equal(
        gs.face_normals(v, f), gs.face_normals(wide, f).astype(np.float32)
    )


@pytest.mark.subprocess
def test_results_do_not_depend_on_the_thread_count() -> None:
    # Every normal of a 10^5-face mesh, both dtypes, as one digest, per rayon thread count.
    one = passes("normals_digest", threads=1).strip()
    assert len(one) == 64
    assert passes("normals_digest", threads=2).strip() == one
    assert passes("normals_digest", threads=3).strip() == one


@pytest.mark.parametrize(
    ("call", "exception", "words"),
    [
        (
            lambda: gs.vertex_normals(CUBE_V, [[0, 1, 8]]),
            IndexError,
            ["face 0", "vertex 8", "only 8 vertices"],
        ),
        (
            lambda: gs.face_normals(CUBE_V, [[0, 1, 2], [0, -1, 2]]),
            IndexError,
            ["face 1", "vertex -1", "negative"],
        ),
        (
            lambda: gs.vertex_normals(CUBE_V, np.array([[0, 1, 2**64 - 1]], np.uint64)),
            IndexError,
            ["faces", "index"],
        ),
        (
            lambda: gs.vertex_normals(CUBE_V, CUBE_F[:, :2]),
            ValueError,
            ["faces", "(m, 3)", "(12, 2)"],
        ),
        (lambda: gs.vertex_normals(CUBE_V, CUBE_F[0]), ValueError, ["faces", "(m, 3)", "(3,)"]),
        (
            lambda: gs.vertex_normals(CUBE_V[:, :2], CUBE_F),
            ValueError,
            ["vertices", "(n, 3)", "(8, 2)"],
        ),
        (
            lambda: gs.vertex_normals(CUBE_V.astype(complex), CUBE_F),
            TypeError,
            ["vertices", "complex128"],
        ),
        (
            lambda: gs.vertex_normals(CUBE_V, CUBE_F.astype(float)),
            TypeError,
            ["faces", "integer", "float64"],
        ),
        (
            lambda: gs.vertex_normals(CUBE_V, CUBE_F, weighting="cotangent"),
            ValueError,
            ["weighting", "'cotangent'"],
        ),
        (lambda: gs.vertex_normals(CUBE_V), TypeError, ["faces", "mesh"]),
    ],
)
def test_bad_input(call: Any, exception: type, words: list[str]) -> None:
    with pytest.raises(exception) as info:
        call()
    for word in words:
        assert word in str(info.value), f"{word!r} not in {info.value}"
