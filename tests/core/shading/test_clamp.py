"""``clamp=False``: the lighting equation's sums without GL's final clamp (high dynamic range).

On the random scenes of the spec test (every option of `gs.shade`), the unclamped result
agrees with the float64 transcription's pre-clamp values (`gl_reference.Reference.unclamped`)
within the spec test's bound, and equals the clamped call wherever that lies inside (0, 1).
"""

from __future__ import annotations

import numpy as np
import pytest
from conftest import require

import glshade as gs
from support.gl_reference import gl_lighting
from support.scenes import random_case, stacked

TOL = {np.float64: 1e-12, np.float32: 1e-5}
MARGIN = {np.float64: 1e-9, np.float32: 2e-5}
# The kernel saturates each factor at 2^64 (float32) or 2^240 (float64), so that no inf·0 can
# arise: a sum of terms that large is not compared (random normals of length 10³ under a
# shininess of 128 reach 10⁸⁷).
SATURATION = {np.float64: 2.0**236, np.float32: 2.0**60}
SEEDS = 40
VERTICES = 500

# Four white lights (two directions, each twice) on a white material: sums up to about 6.
WHITE = gs.Material(ambient=(1, 1, 1), diffuse=(1, 1, 1), specular=(1, 1, 1), shininess=8)
DIRECTIONS = [(0, 0, 1, 0), (0, 1, 1, 0)] * 2


def lit(scale: float, **light_model: bool) -> gs.Scene:
    """The bright scene with every light and the global ambient scaled by `scale`: every term
    of the equation is linear in them (the material has no emission)."""
    c = (scale, scale, scale)
    lights = [gs.Light(position=d, diffuse=c, specular=c) for d in DIRECTIONS]
    return gs.Scene(lights=lights, material=WHITE, global_ambient=(0.2 * scale,) * 3, **light_model)


BRIGHT = lit(1.0)


@pytest.mark.parametrize("dtype", [np.float64, np.float32], ids=["f64", "f32"])
def test_unclamped_sums_agree_with_the_spec_before_its_clamp(dtype: type) -> None:
    u = np.finfo(dtype).eps / 2
    above = 0
    for seed in range(SEEDS):
        case = random_case(seed, VERTICES, dtype)
        got = gs.shade(case.positions, case.normals, case.scene, clamp=False, **case.kwargs)
        ref = gl_lighting(case.positions, case.normals, case.ref)
        expected = stacked(ref.unclamped)
        assert got.shape == expected.shape and got.dtype == dtype
        err = np.abs(got.astype(np.float64) - expected).reshape(-1, VERTICES, 4).max(axis=(0, 2))
        bound = TOL[dtype] * np.maximum(1.0, ref.magnitude) + 16 * u * ref.sensitivity
        compared = (ref.margin > MARGIN[dtype]) & (ref.magnitude < SATURATION[dtype])
        worst = np.max(np.where(compared, err / bound, 0.0))
        assert worst <= 1.0, f"seed {seed}: {worst:.3g} of the bound; {case.description}"
        above += int((expected > 1).sum())
    assert above > 1000, "the random scenes reach above 1, where the clamp would act"


@pytest.mark.parametrize("dtype", [np.float64, np.float32], ids=["f64", "f32"])
@pytest.mark.parametrize("accuracy", ["fast", "exact"])
def test_the_clamp_is_all_that_differs(
    dtype: type, accuracy: str, rng: np.random.Generator
) -> None:
    """Inside (0, 1) the same bits as the clamped call; beyond, the clamp of the unclamped."""
    normals = rng.normal(size=(5000, 3)).astype(dtype)
    positions = rng.normal(size=(5000, 3)).astype(dtype)
    for scene in (BRIGHT, lit(1.0, two_side=True, separate_specular=True)):
        kept = gs.shade(positions, normals, scene, normalize=True, accuracy=accuracy)
        free = gs.shade(positions, normals, scene, normalize=True, accuracy=accuracy, clamp=False)
        assert free.dtype == kept.dtype == dtype and free.shape == kept.shape
        inside = (kept > 0) & (kept < 1)
        np.testing.assert_array_equal(free[inside], kept[inside])
        np.testing.assert_array_equal(np.clip(free, 0, 1), kept)
        assert free.max() > 2.0  # four lights and the ambient add up beyond 1


def test_nan_rows_stay_nan_and_alone() -> None:
    positions = np.zeros((3, 3))
    normals = np.array([[0.0, 0.0, 1.0], [np.nan, 0.0, 1.0], [0.0, 0.0, np.inf]])
    got = gs.shade(positions, normals, BRIGHT, clamp=False)
    assert np.isnan(got[1:]).all()
    assert np.isfinite(got[0]).all() and got[0, 0] > 1


def test_the_plan_says_unclamped() -> None:
    assert BRIGHT.plan(clamp=False).endswith("; unclamped (high dynamic range)")
    assert "unclamped" not in BRIGHT.plan()


def test_clamp_must_be_a_bool() -> None:
    with pytest.raises(TypeError, match="clamp"):
        gs.shade(np.zeros((1, 3)), (0, 0, 1), BRIGHT, clamp="no")  # type: ignore[arg-type]


@pytest.mark.parametrize("shading", ["flat", "gouraud", "phong"])
@pytest.mark.parametrize("separate_specular", [False, True])
def test_render_keeps_the_sums_and_the_colour_sum(shading: str, separate_specular: bool) -> None:
    """gs.render with clamp=False is 16 times the render of the scene with a sixteenth of the
    light, which never reaches 1: every term is linear in the lights, and a power of two scales
    every rounding with it, so the two agree bit for bit. Values above 1 where the
    lights add up, separate specular's colour sum unclamped too, Gouraud interpolating the
    unclamped vertex colours. Flat and Phong light each pixel once, so they also give the
    clamped image's bits wherever it lies inside (0, 1); Gouraud differs there near a clamped
    vertex, whose colour it interpolates."""
    vertices, faces = gs.meshes.icosphere(3)
    camera = gs.Camera.look_at((0, 0, 3.5), (0, 0, 0), fovy=40)
    size = {"width": 96, "height": 96, "shading": shading}
    free = gs.render(
        vertices, faces, lit(1.0, separate_specular=separate_specular), camera, clamp=False, **size
    )
    sixteenth = gs.render(
        vertices, faces, lit(1 / 16, separate_specular=separate_specular), camera, **size
    )
    assert sixteenth[..., :3].max() < 1.0
    np.testing.assert_array_equal(free[..., :3], 16 * sixteenth[..., :3])
    assert free[..., :3].max() > 2.0
    if shading != "gouraud":
        kept = gs.render(
            vertices, faces, lit(1.0, separate_specular=separate_specular), camera, **size
        )
        inside = (kept > 0) & (kept < 1)
        np.testing.assert_array_equal(free[inside], kept[inside])
        np.testing.assert_array_equal(np.clip(free, 0, 1), kept)


def test_dask_passes_clamp_through() -> None:
    da = require("dask.array")
    normals = np.tile([0.0, 0.0, 1.0], (1000, 1))
    lazy = gs.shade(da.from_array(np.zeros((1000, 3)), chunks=250), normals, BRIGHT, clamp=False)
    np.testing.assert_array_equal(
        lazy.compute(), gs.shade(np.zeros((1000, 3)), normals, BRIGHT, clamp=False)
    )
