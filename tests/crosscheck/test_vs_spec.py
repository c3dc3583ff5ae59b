"""glshade against the float64 transcription of GL 2.1 section 2.14.1 on random scenes.

Tolerances, per vertex, over every output colour and channel:
  |glshade - reference| <= TOL * max(1, magnitude) + 16 u * sensitivity
where `magnitude` is the largest sum of |terms| of a channel (the scale any rounding error in a
sum is relative to: GL's own precision rule is "1 part in 10^5") and `sensitivity` is
sum s tan(theta) |specular term| (the condition number of cos^s times the term: the f32 rounding
of the unit vectors, about u, is amplified by it). For unit normals and moderate colours both
factors are at most 1 and the bound is TOL itself. Vertices within MARGIN of a discontinuity of
the equation (n.VP = 0, a spot-cone edge) or of a point light are excluded: there the inputs'
own rounding decides the branch.
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import glshade as gs
from support.gl_reference import gl_lighting
from support.scenes import random_case, stacked

TOL = {np.float64: 1e-12, np.float32: 1e-5}
MARGIN = {np.float64: 1e-9, np.float32: 2e-5}
SEEDS = 100
VERTICES = 1000


def check_case(seed: int, n: int, dtype: type, edges: bool = False) -> int:
    """Shades one random case (with soft spot edges and ranges: `edges`), asserts the bound;
    returns the number of vertices compared."""
    case = random_case(seed, n, dtype, edges)
    got = gs.shade(case.positions, case.normals, case.scene, **case.kwargs)
    assert got.dtype == dtype
    ref = gl_lighting(case.positions, case.normals, case.ref)
    expected = stacked(ref.outputs)
    assert got.shape == expected.shape
    assert np.isfinite(got).all()
    u = np.finfo(dtype).eps / 2
    err = np.abs(got.astype(np.float64) - expected).reshape(-1, n, 4).max(axis=(0, 2))
    bound = TOL[dtype] * np.maximum(1.0, ref.magnitude) + 16 * u * ref.sensitivity
    compared = ref.margin > MARGIN[dtype]
    bad = np.flatnonzero(compared & (err > bound))
    if bad.size:
        i = bad[np.argmax(err[bad] / bound[bad])]
        pytest.fail(
            f"seed {seed}, vertex {i}: error {err[i]:.3g} > bound {bound[i]:.3g} "
            f"(magnitude {ref.magnitude[i]:.3g}); {case.description}\n"
            f"got {got.reshape(-1, n, 4)[:, i]}\nexpected {expected.reshape(-1, n, 4)[:, i]}"
        )
    return int(compared.sum())


@pytest.mark.parametrize("dtype", [np.float64, np.float32], ids=["f64", "f32"])
def test_random_scenes_agree_with_the_spec(dtype: type) -> None:
    compared = sum(check_case(seed, VERTICES, dtype) for seed in range(SEEDS))
    assert compared >= 99_000, "at least 10^5 vertex-scene pairs, less the discontinuity bands"


@pytest.mark.parametrize("dtype", [np.float64, np.float32], ids=["f64", "f32"])
def test_soft_spot_edges_and_ranges_agree_with_the_transcription(dtype: type) -> None:
    # learnopengl's soft edge on random lights, Luna's range on positional ones (add_edges).
    compared = sum(check_case(seed, VERTICES, dtype, edges=True) for seed in range(40))
    assert compared >= 38_000
    soft = [
        light["position"][3] == 0
        for seed in range(40)
        for light in random_case(seed, 1, dtype, edges=True).ref.lights
        if light.get("spot_inner_cutoff", 180) < light.get("spot_cutoff", 180)
    ]
    assert sum(soft) >= 5 and len(soft) - sum(soft) >= 20, "soft edges on both kinds of light"


def test_random_scenes_cover_every_feature() -> None:
    seen: set[str] = set()
    for seed in range(SEEDS):
        ref = random_case(seed, 1, np.float64).ref
        seen |= {
            f"viewer w={ref.viewer[3]} local={ref.viewer[:3] == (0, 0, 0)}",
            f"two_side={ref.two_side}",
            f"separate_specular={ref.separate_specular}",
            f"specular={ref.specular}",
            f"specular_gate={ref.specular_gate}",
            f"modelview={ref.modelview is not None}",
            f"normalize={ref.normalize}",
            f"rescale_normal={ref.rescale_normal}",
            f"color_material={ref.color_material}",
            f"color_material_face={ref.color_material_face}",
            f"shininess0={ref.material['shininess'] == 0}",
        }
        for light in ref.lights:
            directional = light["position"][3] == 0
            cutoff = light.get("spot_cutoff", 180)
            seen |= {
                f"directional={directional}",
                f"spot directional={directional} cutoff90={cutoff == 90}" if cutoff != 180 else "",
                "attenuated" if light.get("quadratic_attenuation", 0) > 0 else "",
                "k0=0" if light.get("constant_attenuation", 1) == 0 else "",
            }
    expected = {
        "viewer w=0.0 local=False",
        "viewer w=1.0 local=True",
        "viewer w=1.0 local=False",
        "two_side=True",
        "separate_specular=True",
        "specular=phong",
        "specular=blinn",
        "specular_gate=True",
        "specular_gate=False",
        "modelview=True",
        "normalize=True",
        "normalize=False",
        "rescale_normal=True",
        "shininess0=True",
        "directional=True",
        "directional=False",
        "spot directional=True cutoff90=False",
        "spot directional=False cutoff90=False",
        "spot directional=True cutoff90=True",
        "spot directional=False cutoff90=True",
        "attenuated",
        "k0=0",
        *(
            f"color_material={m}"
            for m in ("ambient", "diffuse", "specular", "emission", "ambient_and_diffuse")
        ),
        *(f"color_material_face={f}" for f in ("front", "back", "front_and_back")),
    }
    assert expected <= seen, expected - seen


@settings(deadline=None)
@given(
    seed=st.integers(min_value=SEEDS, max_value=2**32 - 1),
    n=st.integers(min_value=1, max_value=300),
    dtype=st.sampled_from([np.float64, np.float32]),
)
def test_hypothesis_scenes_agree_with_the_spec(seed: int, n: int, dtype: type) -> None:
    check_case(seed, n, dtype)
