"""Records (shaders, plans, comparisons) pickle and deepcopy to equal records, and differ when
their values do."""

from __future__ import annotations

import copy
import pickle
from typing import Any

import numpy as np
import pytest

import glshade as gs
from support.boundary import MIXED, TWO_SIDED


def _records() -> list[Any]:
    scene = TWO_SIDED
    # Any image serves: the records are compared with their own clones.
    image = np.random.default_rng(13).uniform(size=(6, 5, 4))
    other = image.copy()
    other[2, 3] += 0.5
    return [
        gs.glsl.compute_shader(scene),
        gs.glsl.raster_shaders(scene, "gouraud"),
        gs.glsl.raster_shaders(MIXED, "flat").plan,
        gs.compare(image, other),
        gs.compare(image, image),
    ]


@pytest.mark.parametrize("record", _records(), ids=lambda r: type(r).__name__)
def test_records_pickle_and_deepcopy_to_equal_records(record: Any) -> None:
    for clone in (pickle.loads(pickle.dumps(record)), copy.deepcopy(record)):
        assert type(clone) is type(record) and clone == record
    if isinstance(record, gs.glsl.Shaders):
        clone = pickle.loads(pickle.dumps(record))
        with pytest.raises(TypeError):
            clone.uniforms["gs_x"] = np.zeros(1)  # type: ignore[index]  # still read-only


def test_records_differ_when_their_values_do() -> None:
    shaders, raster, _, differing, identical = _records()
    assert shaders != raster and differing != identical
    assert shaders == gs.glsl.compute_shader(TWO_SIDED)
