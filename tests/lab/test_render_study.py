"""The Gouraud-against-Phong study of the error-versus-run-time report."""

from __future__ import annotations

import itertools

import numpy as np
import pytest

from glshade.lab.studies import gouraud_vs_phong

pytestmark = pytest.mark.lab


def test_gouraud_error_falls_as_the_sphere_is_refined() -> None:
    rows = gouraud_vs_phong(subdivisions=(1, 2, 3, 4), size=128, repeat=1)
    assert [r["triangles"] for r in rows] == [80, 320, 1280, 5120]
    keys = {"triangles", "max_error", "mean_error", "levels8_wrong", "gouraud_ms", "phong_ms"}
    assert all(keys <= set(r) for r in rows)
    edge = np.array([r["edge_degrees"] for r in rows])
    np.testing.assert_allclose(edge[1:] / edge[:-1], 0.5, atol=0.05)  # each level halves it
    for key in ("max_error", "mean_error", "levels8_wrong"):
        values = [r[key] for r in rows]
        assert all(a > b for a, b in itertools.pairwise(values)), (key, values)
    # The mean error follows delta^2: about a quarter per level (cos^s has curvature s at its peak).
    mean = np.array([r["mean_error"] for r in rows])
    assert (mean[1:] / mean[:-1] < 0.5).all(), mean
    assert all(r["gouraud_ms"] > 0 and r["phong_ms"] > 0 for r in rows)
