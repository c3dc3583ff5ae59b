"""Light sums whose error does not depend on the order of the lights: one bright light and 999
dim ones, each dim term below half an ulp of the bright one in float32, in either order,
within 1 ulp of the correctly rounded total (a float32 sum in blocks of 8 lost the seven dim
terms that shared the bright one's block: 3.5 ulp low)."""

from __future__ import annotations

import math

import numpy as np
import pytest

import glshade as gs


@pytest.mark.parametrize("count", [9, 1000])
@pytest.mark.parametrize("bright", ["first", "last", "middle"])
def test_one_bright_light_among_dim_ones(count: int, bright: str) -> None:
    terms = np.full(count, np.float32(2.9e-8))
    terms[{"first": 0, "last": -1, "middle": count // 2}[bright]] = np.float32(0.9)
    lights = gs.Lights(position=(0, 0, 1, 0), diffuse=np.c_[terms, terms, terms], specular=(0,) * 3)
    material = gs.Material(ambient=(0, 0, 0), diffuse=(1, 1, 1))
    scene = gs.Scene(lights, material=material, global_ambient=(0, 0, 0))
    got = gs.shade(np.zeros((1, 3), np.float32), np.array([[0, 0, 1]], np.float32), scene)
    total = np.float32(math.fsum(terms.astype(np.float64)))  # correctly rounded
    assert abs(int(got[0, 0].view(np.int32)) - int(total.view(np.int32))) <= 1, (got, total)
    # The running float32 sum from the bright light on loses every dim term.
    if bright == "first":
        running = np.float32(0)
        for t in terms:
            running += t
        assert abs(int(running.view(np.int32)) - int(total.view(np.int32))) > 1
