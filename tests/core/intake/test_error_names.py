"""Every error of the scene objects, `shade`, the normals and `render` names its argument."""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest

import glshade as gs
from support.boundary import SUN, UP


@pytest.mark.parametrize(
    ("call", "exception", "words"),
    [
        (lambda: gs.Scene(lights=None), TypeError, ["lights", "None"]),
        (lambda: gs.Scene(lights=5), TypeError, ["lights", "5"]),
        (lambda: gs.Lights(count=1.5), TypeError, ["count", "1.5"]),
        (lambda: gs.Lights(count=-1), ValueError, ["count", "-1"]),
        (lambda: gs.Lights(count=True), TypeError, ["count"]),
        (lambda: gs.Scene(two_side="no"), TypeError, ["two_side", "'no'"]),
        (lambda: gs.Scene(separate_specular=1), TypeError, ["separate_specular"]),
        (lambda: gs.Scene(specular_gate=None), TypeError, ["specular_gate"]),
        (lambda: gs.Scene(specular=1), TypeError, ["specular"]),
        (lambda: gs.Scene(global_ambient=(1, 2)), ValueError, ["global_ambient", "(2,)"]),
        (lambda: gs.Light(diffuse="red"), TypeError, ["diffuse"]),
        (lambda: gs.Light(position=np.ones((2, 4))), ValueError, ["Light", "position", "(2, 4)"]),
        (lambda: gs.Lights(position=np.ones((2, 2, 4))), ValueError, ["position", "(2, 2, 4)"]),
        (lambda: gs.Material(shininess=(1, 2)), ValueError, ["shininess", "number", "(2,)"]),
        (lambda: gs.Material(shininess=None), TypeError, ["shininess"]),
        (lambda: gs.Camera.look_at((0, 0, 5), near=None), TypeError, ["near", "None"]),
        (lambda: gs.Camera.look_at((0, 0, 5), fovy="wide"), TypeError, ["fovy"]),
        (lambda: gs.Camera.look_at((0, 0, 5), aspect=0), ValueError, ["aspect"]),
        (lambda: gs.Camera.look_at((0, 0, 5, 1)), ValueError, ["eye", "(3,)", "(4,)"]),
        (
            lambda: gs.Camera.look_at_orthographic((0, 0, 5), height=0),
            ValueError,
            ["height", "> 0", "0"],
        ),
        (lambda: gs.Camera.look_at_orthographic((0, 0, 5), height=-1), ValueError, ["height"]),
        (
            lambda: gs.Camera.look_at((0, 0, 5)).projection_matrix(64, 0),
            ValueError,
            ["height", "0"],
        ),
        (lambda: gs.Camera().projection_matrix(1.5, 64), TypeError, ["width", "1.5"]),
        (lambda: gs.shade(UP, UP, SUN, normalize="yes"), TypeError, ["normalize", "'yes'"]),
        (lambda: gs.shade(UP, UP, SUN, accuracy=1), TypeError, ["accuracy"]),
        (lambda: gs.shade(UP, UP, SUN, accuracy="best"), ValueError, ["accuracy", "best"]),
        (lambda: gs.shade(UP, UP, SUN, modelview=np.eye(3)), ValueError, ["modelview", "(4, 4)"]),
        (lambda: gs.shade(UP, UP, "scene"), TypeError, ["scene"]),
        (lambda: gs.vertex_normals(UP, [[0, 0, 1]]), IndexError, ["face 0", "vertex 1"]),
        (lambda: gs.vertex_normals(UP, [[0, 0, 0.5]]), TypeError, ["faces", "integer"]),
        (lambda: gs.vertex_normals(UP, [[0, 0]]), ValueError, ["faces", "(m, 3)"]),
        (lambda: gs.face_normals(np.zeros((3, 2)), [[0, 1, 2]]), ValueError, ["vertices"]),
        (lambda: gs.face_normals([["a"] * 3], [[0, 0, 0]]), TypeError, ["vertices"]),
    ],
)
def test_bad_input_names_its_argument(call: Any, exception: type, words: list[str]) -> None:
    with pytest.raises(exception) as info:
        call()
    for word in words:
        assert word in str(info.value), f"{word!r} not in {info.value!r}"


TRIANGLE = np.array([[-1, -1, 0], [1, -1, 0], [0, 1, 0]], np.float64)


@pytest.mark.parametrize(
    ("kwargs", "exception", "words"),
    [
        ({"width": 2**64}, ValueError, ["width", "16384", str(2**64)]),
        ({"width": 0}, ValueError, ["width"]),
        ({"height": 2.5}, TypeError, ["height", "2.5"]),
        ({"height": 16385}, ValueError, ["height", "16384"]),
        ({"shading": "toon"}, ValueError, ["shading", "toon"]),
        ({"shading": None}, TypeError, ["shading"]),
        ({"cull": "sideways"}, ValueError, ["cull", "sideways"]),
        ({"normalize": "no"}, TypeError, ["normalize"]),
        ({"normals": np.zeros((3, 2))}, ValueError, ["normals", "(n, 3)"]),
        ({"colors": np.zeros((3, 5))}, ValueError, ["colors", "(n, 3) or (n, 4)"]),
        ({"background": (1, 2)}, ValueError, ["background"]),
        ({"model": np.eye(3)}, ValueError, ["model", "(4, 4)"]),
    ],
)
def test_bad_render_arguments_are_named(
    kwargs: dict[str, Any], exception: type, words: list[str]
) -> None:
    with pytest.raises(exception) as info:
        gs.render(TRIANGLE, [[0, 1, 2]], SUN, gs.Camera(), **{"width": 4, "height": 4, **kwargs})
    for word in words:
        assert word in str(info.value), f"{word!r} not in {info.value!r}"
