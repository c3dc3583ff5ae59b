"""Properties over adversarial values (huge, tiny, subnormal, zero, NaN, infinite): finite input
gives finite output in [0, 1]; a non-finite input row gives NaN in that row and nowhere else;
nothing panics. Also invariances that need no reference: thread-free row independence,
power-of-two scaling without attenuation, and two-sided symmetry."""

from __future__ import annotations

import inspect
from typing import Any

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra import numpy as hnp

import glshade as gs
from support.processes import passes


def rebuilt(lights: gs.Lights, **changes: Any) -> gs.Lights:
    """`lights` with the parameters in `changes` replaced."""
    names = inspect.signature(gs.Light).parameters
    return gs.Lights(**{name: changes.get(name, getattr(lights, name)) for name in names})


DTYPES = st.sampled_from([np.float32, np.float64])


def extreme_floats(dtype: Any, allow_non_finite: bool) -> st.SearchStrategy[float]:
    width = 32 if dtype == np.float32 else 64
    finite = st.floats(width=width, allow_nan=False, allow_infinity=False, allow_subnormal=True)
    scaled = st.sampled_from([0.0, 1e-30, 1e-40, 1e30, -1e30, 3e38, 1.0, -1.0, 0.5])
    if dtype == np.float64:
        scaled = st.sampled_from([0.0, 1e-300, 5e-324, 1e300, -1e300, 1.0, -1.0, 1e-20])
    pool = st.one_of(finite, scaled)
    if allow_non_finite:
        pool = st.one_of(pool, st.sampled_from([np.nan, np.inf, -np.inf]))
    return pool


@st.composite
def scenes(draw: st.DrawFn) -> gs.Scene:
    colour = st.tuples(*[st.floats(-2, 2)] * 3)
    lights = []
    for _ in range(draw(st.integers(0, 4))):
        directional = draw(st.booleans())
        xyz = draw(st.tuples(*[st.floats(-1e6, 1e6)] * 3).filter(lambda v: any(v)))
        k = draw(st.tuples(st.floats(0, 10), st.floats(0, 10), st.floats(0, 10)))
        if not directional and not any(k):
            k = (1.0, 0.0, 0.0)
        lights.append(
            gs.Light(
                position=(*xyz, 0.0 if directional else draw(st.sampled_from([1.0, 0.5, -2.0]))),
                ambient=draw(colour),
                diffuse=draw(colour),
                specular=draw(colour),
                constant_attenuation=k[0],
                linear_attenuation=k[1],
                quadratic_attenuation=k[2],
                spot_cutoff=draw(st.one_of(st.just(180.0), st.floats(0, 90))),
                spot_exponent=draw(st.floats(0, 200)),
                spot_direction=draw(st.tuples(*[st.floats(-1, 1)] * 3).filter(lambda v: any(v))),
            )
        )
    material = gs.Material(
        ambient=draw(colour),
        diffuse=draw(colour),
        specular=draw(colour),
        emission=draw(colour),
        shininess=draw(st.one_of(st.sampled_from([0.0, 1.0, 128.0, 1e4, 1e6]), st.floats(0, 200))),
    )
    viewer = draw(st.sampled_from([(0, 0, 1, 0), (0, 0, 0, 1), (1e6, -3, 2, 1), (0.3, 0.2, -1, 0)]))
    return gs.Scene(
        lights=lights,
        material=material,
        viewer=viewer,
        two_side=draw(st.booleans()),
        separate_specular=draw(st.booleans()),
        specular=draw(st.sampled_from(["blinn", "phong"])),
    )


@settings(deadline=None)
@given(data=st.data(), dtype=DTYPES, scene=scenes(), normalize=st.booleans())
def test_finite_in_finite_out_and_nan_stays_in_its_row(
    data: st.DataObject, dtype: Any, scene: gs.Scene, normalize: bool
) -> None:
    n = data.draw(st.integers(1, 20))
    values = extreme_floats(dtype, allow_non_finite=True)
    p = data.draw(hnp.arrays(dtype, (n, 3), elements=values))
    nrm = data.draw(hnp.arrays(dtype, (n, 3), elements=values))
    out = gs.shade(p, nrm, scene, normalize=normalize)
    rows = out.reshape(-1, n, 4)
    # Positions are read only by positional lights and a local viewer.
    reads_positions = bool((scene.lights.position[:, 3] != 0).any() or scene.viewer[3] != 0)
    bad = ~np.isfinite(nrm).all(axis=1)
    if reads_positions:
        bad |= ~np.isfinite(p).all(axis=1)
    assert np.isnan(rows[:, bad]).all()
    good = rows[:, ~bad]
    # A finite row may still overflow to infinity in eye space only through a modelview: none here.
    assert np.isfinite(good).all()
    assert ((good >= 0) & (good <= 1)).all()
    # Each row alone gives the same bits: no row depends on another.
    for i in np.flatnonzero(~bad)[:3]:
        alone = gs.shade(p[i : i + 1], nrm[i : i + 1], scene, normalize=normalize)
        np.testing.assert_array_equal(alone.reshape(-1, 1, 4)[:, 0], rows[:, i])


@settings(deadline=None)
@given(
    dtype=DTYPES,
    scene=scenes(),
    k=st.integers(-60, 60),
    # 0 or at least 1e-3 in magnitude: 2^k scaling stays in the normal range, so it is exact.
    p=hnp.arrays(
        np.float64, (8, 3), elements=st.floats(-10, 10).filter(lambda x: x == 0 or abs(x) > 1e-3)
    ),
    nrm=hnp.arrays(np.float64, (8, 3), elements=st.floats(-1, 1)),
)
def test_power_of_two_scaling_without_attenuation_changes_no_bit(
    dtype: Any, scene: gs.Scene, k: int, p: np.ndarray, nrm: np.ndarray
) -> None:
    # Scale positions, point lights and the viewer point by 2^k: every direction is unchanged
    # bit for bit, and without attenuation nothing else depends on distance.
    unattenuated = {"constant_attenuation": 1.0, "linear_attenuation": 0.0}
    lights = rebuilt(scene.lights, **unattenuated, quadratic_attenuation=0.0)
    position = lights.position.copy()
    position[:, 0:3] *= np.where(position[:, 3:4] != 0, 2.0**k, 1.0)
    scaled_lights = rebuilt(lights, position=position)
    viewer = scene.viewer.copy()
    scaled_viewer = viewer.copy()
    if viewer[3] != 0:
        scaled_viewer[:3] *= 2.0**k
    kwargs = {
        "material": scene.material,
        "two_side": scene.two_side,
        "separate_specular": scene.separate_specular,
        "specular": scene.specular,
    }
    base = gs.Scene(lights=lights, viewer=viewer, **kwargs)
    moved = gs.Scene(lights=scaled_lights, viewer=scaled_viewer, **kwargs)
    p = p.astype(dtype)
    nrm = nrm.astype(dtype)
    got = gs.shade(p * dtype(2.0**k), nrm, moved, normalize=True)
    expected = gs.shade(p, nrm, base, normalize=True)
    if dtype is np.float64:
        np.testing.assert_array_equal(got, expected)
        return
    # float32's lean arithmetic is as scale-free inside its range (squared distances in the
    # normal range), but a block scaled out of it runs the careful path: both within the fast
    # bound of the exact colour, so within twice it of each other (Accuracy page).
    s = scene.material.shininess
    count = len(lights)
    fast_bound = 2e-6 * (1 + 3 * count) + 4 * 2.0**-24 * min(s, 128.0) * count
    np.testing.assert_allclose(got, expected, rtol=0, atol=2 * fast_bound)


@settings(deadline=None)
@given(dtype=DTYPES, scene=scenes(), p=hnp.arrays(np.float64, (6, 3), elements=st.floats(-5, 5)))
def test_the_back_colour_of_n_is_the_front_colour_of_minus_n(
    dtype: Any, scene: gs.Scene, p: np.ndarray
) -> None:
    n = np.random.default_rng(0).normal(size=(6, 3))
    kwargs = {"lights": scene.lights, "material": scene.material, "viewer": scene.viewer}
    two = gs.Scene(two_side=True, **kwargs)
    one = gs.Scene(**kwargs)
    front_back = gs.shade(p.astype(dtype), n.astype(dtype), two)
    flipped = gs.shade(p.astype(dtype), (-n).astype(dtype), one)
    np.testing.assert_array_equal(front_back[1], flipped)


@settings(deadline=None)
@given(
    dtype=DTYPES,
    data=st.data(),
    weighting=st.sampled_from(["angle", "area", "uniform"]),
)
def test_normals_never_panic_and_are_unit_zero_or_nan(
    dtype: Any, data: st.DataObject, weighting: str
) -> None:
    n = data.draw(st.integers(1, 12))
    v = data.draw(hnp.arrays(dtype, (n, 3), elements=extreme_floats(dtype, allow_non_finite=True)))
    f = data.draw(
        hnp.arrays(np.int64, (data.draw(st.integers(0, 20)), 3), elements=st.integers(0, n - 1))
    )
    for normals in (gs.vertex_normals(v, f, weighting), gs.face_normals(v, f)):
        lengths = np.linalg.norm(normals.astype(np.float64), axis=1)
        ok = np.isnan(lengths) | (lengths == 0) | (np.abs(lengths - 1) < 1e-5)
        assert ok.all(), normals[~ok]


@settings(deadline=None)
@given(
    dtype=DTYPES,
    scene=scenes(),
    axis=st.integers(0, 2),
    p=hnp.arrays(np.float64, (8, 3), elements=st.floats(-5, 5)),
    nrm=hnp.arrays(np.float64, (8, 3), elements=st.floats(-1, 1)),
    normalize=st.booleans(),
)
def test_mirroring_the_scene_changes_no_bit(
    dtype: Any, scene: gs.Scene, axis: int, p: np.ndarray, nrm: np.ndarray, normalize: bool
) -> None:
    # Negating one coordinate of everything (positions, normals, lights, spot directions, the
    # viewer) negates both factors of every product in every dot product: the same bits.
    flip = np.ones(3)
    flip[axis] = -1.0
    lights = scene.lights
    position = lights.position * np.r_[flip, 1.0]
    lights = rebuilt(lights, position=position, spot_direction=lights.spot_direction * flip)
    viewer = scene.viewer.copy()
    viewer[:3] *= flip
    mirrored = gs.Scene(
        lights=lights,
        material=scene.material,
        viewer=viewer,
        two_side=scene.two_side,
        separate_specular=scene.separate_specular,
        specular=scene.specular,
    )
    p, nrm = p.astype(dtype), nrm.astype(dtype)
    np.testing.assert_array_equal(
        gs.shade(p * flip.astype(dtype), nrm * flip.astype(dtype), mirrored, normalize=normalize),
        gs.shade(p, nrm, scene, normalize=normalize),
    )


@pytest.mark.subprocess
def test_results_do_not_depend_on_the_thread_count() -> None:
    # rayon's pool size is fixed per process: one process per count, the same bits from each.
    digests = {passes("accuracy_digest", threads=threads).strip() for threads in (1, 2, 3, 8)}
    assert len(digests) == 1, digests
