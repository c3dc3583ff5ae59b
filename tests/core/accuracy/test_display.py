"""`accuracy="display"`: every output within 2^-10 of the exact value (a quarter of an 8-bit
step) on the benchmark's scenes, within its bound in `bounds.py`, computed in the input's
dtype, and named in the plan and in the error for an unknown mode. The stiff cases are in
`test_stiff.py`, which runs every case in this tier too."""

from __future__ import annotations

import numpy as np
import pytest

import glshade as gs
from glshade.lab.bounds import BOUNDS
from glshade.lab.scenes import bench_scenes, bench_vertices

QUARTER_STEP = 2.0**-10


def _with_shininess(scene: gs.Scene, shininess: float) -> gs.Scene:
    """`scene` with the material's shininess replaced (a non-integer one takes exp and ln)."""
    m = scene.material
    material = gs.Material(m.ambient, m.diffuse, m.specular, m.emission, shininess)
    return gs.Scene(scene.lights, material=material, viewer=scene.viewer)


@pytest.mark.parametrize("shininess", [None, 31.7])
@pytest.mark.parametrize("dtype", [np.float32, np.float64])
@pytest.mark.parametrize("name", list(bench_scenes()))
def test_the_bench_scenes_are_within_a_quarter_step_of_exact(
    name: str, dtype: type, shininess: float | None
) -> None:
    scene = bench_scenes()[name]
    if shininess is not None:
        scene = _with_shininess(scene, shininess)
    p, n = (a.astype(dtype) for a in bench_vertices(100_000, seed=3))
    exact = gs.shade(p.astype(np.float64), n.astype(np.float64), scene, accuracy="exact")
    got = gs.shade(p, n, scene, accuracy="display")
    assert got.dtype == dtype
    error = np.abs(got.astype(np.float64) - exact).max()
    # Unit normals and colours in [0, 1]: the plain bound, far inside a quarter step.
    assert error <= BOUNDS[(np.dtype(dtype).name, "display")].unit <= QUARTER_STEP, error
    fast = gs.shade(p, n, scene, accuracy="fast")
    if shininess is None:
        # Integer exponents (shininess 32, spot exponents 8 and 2) are squared in every tier.
        np.testing.assert_array_equal(got, fast)
    elif dtype is np.float64 or name != "8 mixed":
        # exp and ln: the tier's own polynomials (in float32 the 8 mixed lights, clamped at 1
        # in most rows, round both tiers to the same values).
        assert not np.array_equal(got, fast)


def test_high_shininess_and_long_normals_stay_within_a_quarter_step() -> None:
    # s = 128 on normals of length 10: |n|^s = 1e128 times cos^s, an exponent of -295 for an
    # output near 1, where the ln's relative error is amplified 295 times.
    rng = np.random.default_rng(5)
    v = rng.normal(size=(20_000, 3)) + np.array([0.0, 0.0, 1.0])
    n = v / np.linalg.norm(v, axis=1, keepdims=True) * 10.0 ** rng.uniform(-1, 1, (20_000, 1))
    light = gs.Light(position=(0.0, 0.3, 1.0, 0.0), specular=(0.2, 0.2, 0.2))
    material = gs.Material(specular=(0.01, 0.01, 0.01, 1), shininess=128.0)
    scene = gs.Scene([light], material=material)
    p = np.zeros_like(n)
    exact = gs.shade(p, n, scene, accuracy="exact")
    for dtype in (np.float32, np.float64):
        got = gs.shade(p.astype(dtype), n.astype(dtype), scene, accuracy="display")
        assert np.abs(got - exact).max() <= QUARTER_STEP


def test_the_plan_names_the_tier_and_bad_modes_list_every_mode() -> None:
    scene = bench_scenes()["8 mixed"]
    assert scene.plan(accuracy="display").startswith("display: float32 arithmetic")
    assert scene.plan(np.float64, accuracy="display").startswith("display: float64 arithmetic")
    p, n = bench_vertices(4)
    with pytest.raises(ValueError, match="'fast', 'exact' or 'display', got 'draft'"):
        gs.shade(p, n, scene, accuracy="draft")  # type: ignore[arg-type]
    with pytest.raises(TypeError, match="accuracy must be a string"):
        gs.shade(p, n, scene, accuracy=1)  # type: ignore[arg-type]
