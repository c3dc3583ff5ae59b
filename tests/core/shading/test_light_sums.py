"""Light sums whose error does not depend on the order of the lights: one bright light and 999
dim ones, each dim term below half an ulp of the bright one in float32, in either order.
``"fast"`` sums blocks of 8 lights in float32 and adds the blocks' sums with their rounding
errors kept apart (TwoSum): within 8 ulp of the correctly rounded total, where a running
float32 sum from the bright light on loses every dim term (28 ulp low with 999 of them).
``"exact"`` sums in float64: within 1 ulp. Grey lights (r = g = b) are summed in one channel
by the float32 kernels that have the copy, and the plan says so."""

from __future__ import annotations

import math

import numpy as np
import pytest

import glshade as gs

ULPS = {"fast": 8, "exact": 1}


def _ulps_apart(a: np.float32, b: np.float32) -> int:
    return abs(int(np.float32(a).view(np.int32)) - int(np.float32(b).view(np.int32)))


@pytest.mark.parametrize("accuracy", ["fast", "exact"])
@pytest.mark.parametrize("count", [9, 1000])
@pytest.mark.parametrize("bright", ["first", "last", "middle"])
def test_one_bright_light_among_dim_ones(accuracy: str, count: int, bright: str) -> None:
    terms = np.full(count, np.float32(2.9e-8))
    terms[{"first": 0, "last": -1, "middle": count // 2}[bright]] = np.float32(0.9)
    lights = gs.Lights(position=(0, 0, 1, 0), diffuse=np.c_[terms, terms, terms], specular=(0,) * 3)
    material = gs.Material(ambient=(0, 0, 0), diffuse=(1, 1, 1))
    scene = gs.Scene(lights, material=material, global_ambient=(0, 0, 0))
    p, n = np.zeros((1, 3), np.float32), np.array([[0, 0, 1]], np.float32)
    got = gs.shade(p, n, scene, accuracy=accuracy)  # type: ignore[arg-type]
    total = np.float32(math.fsum(terms.astype(np.float64)))  # correctly rounded
    assert _ulps_apart(got[0, 0], total) <= ULPS[accuracy], (got, total)
    # The running float32 sum from the bright light on loses every dim term.
    if bright == "first" and count == 1000:
        running = np.float32(0)
        for t in terms:
            running += t
        assert _ulps_apart(running, total) > ULPS["fast"]


@pytest.mark.shapes
def test_the_plan_names_grey_sums_where_the_kernel_sums_one_channel() -> None:
    white = gs.Lights(position=[(0, 0, 1, 0), (1, 1, 1, 1)], diffuse=(0.8, 0.8, 0.8))
    tinted = gs.Lights(
        position=[(0, 0, 1, 0), (1, 1, 1, 1)], diffuse=[(0.8, 0.8, 0.8), (1, 0.9, 0.8)]
    )
    material = gs.Material(diffuse=(0.9, 0.2, 0.1), specular=(0.5, 0.5, 0.5), shininess=32)
    grey = gs.Scene(white, material=material, viewer=(0, 0, 0, 1))
    named = "grey lights: one channel summed"
    assert named in grey.plan("float32")
    assert named not in grey.plan("float32", accuracy="exact")  # float64 arithmetic
    assert named not in grey.plan("float64")
    # An infinite viewer puts the point light on the general kernel, which has no such copy.
    assert "general kernel" in gs.Scene(white, material=material).plan("float32")
    assert named not in gs.Scene(white, material=material).plan("float32")
    assert named not in gs.Scene(tinted, material=material, viewer=(0, 0, 0, 1)).plan("float32")
