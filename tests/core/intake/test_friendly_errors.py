"""The mistakes a new user makes, each answered by a message that names it: normals forgotten,
colours by name or in bytes, a light position without w, option names in another case."""

from __future__ import annotations

import re
import warnings
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np
import pytest

import glshade as gs

P = np.array([[0.0, 0.0, -2.0], [1.0, 0.0, -2.0], [0.0, 1.0, -2.0]])
N = np.tile([0.0, 0.0, 1.0], (3, 1))
F = [[0, 1, 2]]
SCENE = gs.Scene(lights=[gs.Light(position=(0.2, 0.3, 1.0, 0.0))])
CAMERA = gs.Camera.look_at((0.3, 0.3, 2.0), (0.3, 0.3, -2.0), fovy=50, near=1, far=10)


def _message(call: Callable[[], object], exception: type[Exception]) -> str:
    with pytest.raises(exception) as info:
        call()
    return str(info.value)


def test_forgotten_normals_are_named() -> None:
    text = _message(lambda: gs.shade(P, SCENE), TypeError)  # type: ignore[call-arg]
    assert "missing its normals" in text
    assert "gs.shade(positions, normals, scene)" in text
    assert "gs.shade(positions, (0, 0, 1), scene)" in text
    # The scene as a keyword, or a missing scene, keep Python's own words.
    assert "'normals'" in _message(lambda: gs.shade(P, scene=SCENE), TypeError)  # type: ignore[call-arg]
    assert "'scene'" in _message(lambda: gs.shade(P, N), TypeError)  # type: ignore[call-arg]
    # shade_mesh: the scene is a keyword; given as faces it is named.
    text = _message(lambda: gs.shade_mesh(gs.meshes.icosphere(1), SCENE), TypeError)  # type: ignore[arg-type]
    assert "got a Scene as faces" in text and "gs.shade_mesh(mesh, scene=scene)" in text
    # render: vertices without faces.
    text = _message(lambda: gs.render(P, SCENE, CAMERA), TypeError)
    assert "faces is required" in text and "render(vertices, faces, scene, camera)" in text


@pytest.mark.parametrize(
    ("call", "words"),
    [
        (
            lambda: gs.Material(diffuse="red"),
            ["diffuse", "not a colour name", "'red'", "(1, 0, 0)"],
        ),
        (lambda: gs.Material(emission="orange"), ["emission", "(1, 0.647, 0)"]),
        (lambda: gs.Light(diffuse="white"), ["diffuse", "'white'", "(1, 1, 1)", "(1, 1, 1, 1)"]),
        (lambda: gs.Light(specular="#ff8000"), ["specular", "(1, 0.502, 0)"]),
        (
            lambda: gs.Lights(ambient=["grey", "red"]),
            ["ambient", "'grey'", "(0.502, 0.502, 0.502)"],
        ),
        (lambda: gs.Scene(global_ambient="tan"), ["global_ambient", "'tan'", "e.g.", "RGB"]),
        (lambda: gs.shade(P, N, SCENE, colors="red"), ["colors", "'red'", "(1, 0, 0)"]),
        (
            lambda: gs.shade(P, N, SCENE, colors=["red", "green", "blue"]),
            ["colors", "not colour names", "'red'", "(n, 3) or (n, 4)"],
        ),
        (
            lambda: gs.render(P, F, SCENE, CAMERA, width=4, height=4, colors=["red"] * 3),
            ["colors", "not colour names"],
        ),
        (
            lambda: gs.render(P, F, SCENE, CAMERA, width=4, height=4, background="black"),
            ["background", "(0, 0, 0)"],
        ),
    ],
)
def test_a_colour_name_is_refused_with_the_numbers_to_write(
    call: Callable[[], object], words: list[str]
) -> None:
    text = _message(call, TypeError)
    for word in words:
        assert word in text, f"{word!r} not in {text!r}"
    assert "[0, 1]" in text or "0-255" in text


@pytest.mark.parametrize(
    ("call", "words"),
    [
        (
            lambda: gs.Material(diffuse=(255, 128, 0)),
            ["Material diffuse=(255, 128, 0)", "(1, 0.502, 0)"],
        ),
        (lambda: gs.Material(ambient=(51.0, 51.0, 51.0, 255.0)), ["ambient", "(0.2, 0.2, 0.2, 1)"]),
        (
            lambda: gs.Light(diffuse=(200, 200, 200, 1)),
            ["Light diffuse", "(0.784, 0.784, 0.784, 1)"],
        ),
        (lambda: gs.Lights(specular=np.full((4, 3), 128.0)), ["Lights specular", "up to 128"]),
        (lambda: gs.Scene(global_ambient=(40, 40, 40)), ["Scene global_ambient", "(0.157"]),
        (
            lambda: gs.render(P, F, SCENE, CAMERA, width=4, height=4, background=(255, 255, 255)),
            ["render background", "(1, 1, 1)"],
        ),
    ],
)
def test_colours_in_bytes_warn_naming_the_parameter(
    call: Callable[[], object], words: list[str]
) -> None:
    with pytest.warns(gs.ColorRangeWarning) as record:
        call()
    assert len(record) == 1 and issubclass(gs.ColorRangeWarning, UserWarning)
    text = str(record[0].message)
    for word in [*words, "0-255", "Divide by 255", "[0, 1]"]:
        assert word in text, f"{word!r} not in {text!r}"
    # The warning points at the line that made the colour, here, not inside glshade.
    assert Path(record[0].filename) == Path(__file__)


@pytest.mark.parametrize(
    "call",
    [
        lambda: gs.Material(diffuse=np.array([255, 128, 0], np.uint8)),  # bytes, divided by 255
        lambda: gs.Light(diffuse=(5, 5, 5)),  # a bright light
        lambda: gs.Light(position=(0, 0, 0, 1), diffuse=(100, 100, 100), quadratic_attenuation=1),
        lambda: gs.Material(diffuse=(1, 1, 1), specular=(0.5, 0.5, 0.5)),
        lambda: gs.Material(diffuse=(255.5, 0, 0)),  # not whole numbers
        lambda: gs.Lights(diffuse=np.full((3, 3), 300.0), count=3),  # beyond bytes
        lambda: gs.shade(P, N, SCENE, colors=np.full((3, 3), 255, np.uint8)),
    ],
)
def test_what_is_not_bytes_does_not_warn(call: Callable[[], object]) -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        call()


def test_uint8_material_and_light_colours_are_divided_by_255() -> None:
    material = gs.Material(diffuse=np.array([255, 128, 0], np.uint8))
    np.testing.assert_allclose(material.diffuse, [1.0, 128 / 255, 0.0, 1.0])
    light = gs.Light(specular=np.array([51, 102, 153, 255], np.uint8))
    np.testing.assert_allclose(light.specular, [0.2, 0.4, 0.6, 1.0])
    # As GL's lighting of the divided colours: the diffuse term of a head-on light.
    lit = gs.shade([0, 0, -2], [0, 0, 1], gs.Scene(lights=[gs.Light()], material=material))
    expected = np.minimum(0.2 * 0.2 + np.array([1.0, 128 / 255, 0.0]), 1.0)  # GL clamps
    np.testing.assert_allclose(lit, [*expected, 1.0], atol=1e-12)


def test_a_light_position_without_w_says_which_w_to_add() -> None:
    text = _message(lambda: gs.Light(position=(1, 2, 3)), ValueError)
    for word in ["position", "(1, 2, 3, 1)", "point light", "(1, 2, 3, 0)", "directional"]:
        assert word in text, f"{word!r} not in {text!r}"
    text = _message(lambda: gs.Lights(position=np.ones((5, 3))), ValueError)
    assert "(5, 3)" in text and "np.c_[position, np.ones(5)]" in text and "np.zeros(5)" in text


def _same(a: Any, b: Any) -> None:
    np.testing.assert_array_equal(np.asarray(a), np.asarray(b))


def test_option_names_are_case_insensitive() -> None:
    c = np.array([[1.0, 0.5, 0.0]] * 3)
    _same(gs.shade(P, N, SCENE, accuracy="EXACT"), gs.shade(P, N, SCENE, accuracy="exact"))  # type: ignore[arg-type]
    _same(
        gs.shade(P, N, SCENE, colors=c, color_material="Diffuse", color_material_face="FRONT"),  # type: ignore[arg-type]
        gs.shade(P, N, SCENE, colors=c, color_material="diffuse", color_material_face="front"),
    )
    r = {"width": 16, "height": 16}
    for shading in ("Phong", "GOURAUD", "Flat"):
        _same(
            gs.render(P, F, SCENE, CAMERA, shading=shading, cull="Front", **r),  # type: ignore[arg-type]
            gs.render(P, F, SCENE, CAMERA, shading=shading.lower(), cull="front", **r),  # type: ignore[arg-type]
        )
    _same(
        gs.render(P, F, SCENE, CAMERA, lights_in="World", **r),  # type: ignore[arg-type]
        gs.render(P, F, SCENE, CAMERA, lights_in="world", **r),
    )
    mesh = gs.meshes.icosphere(1)
    _same(
        gs.shade_mesh(mesh, scene=SCENE, per="Vertex", weighting="Area"),  # type: ignore[arg-type]
        gs.shade_mesh(mesh, scene=SCENE, per="vertex", weighting="area"),
    )
    assert gs.Scene(specular="Phong").specular == "phong"  # type: ignore[arg-type]
    # A wrong name still names the choices, as given.
    text = _message(lambda: gs.render(P, F, SCENE, CAMERA, shading="Toon", **r), ValueError)  # type: ignore[arg-type]
    assert text == "shading must be 'flat', 'gouraud' or 'phong', got 'Toon'"
    text = _message(lambda: gs.shade_mesh(mesh, per="Edge"), ValueError)  # type: ignore[arg-type]
    assert text == "per must be 'vertex' or 'face', got 'Edge'"
    assert re.search(
        "lights_in must be 'eye' or 'world', got 'Model'",
        _message(
            lambda: gs.render(P, F, SCENE, CAMERA, lights_in="Model", **r),
            ValueError,  # type: ignore[arg-type]
        ),
    )


def test_a_two_sided_result_given_as_an_image_says_to_take_a_side() -> None:
    scene = gs.Scene(lights=[gs.Light()], two_side=True)
    both = gs.shade(np.zeros((4, 5, 3)), (0, 0, 1), scene)
    assert both.shape == (2, 4, 5, 4)
    text = _message(lambda: gs.Image(both), ValueError)
    assert "got (2, 4, 5, 4)" in text and "take one side, array[0] (front) or array[1]" in text
    text = _message(lambda: gs.Image(np.zeros((3, 4, 5, 4))), ValueError)
    assert "several images" in text and "array[0]" in text


@pytest.mark.parametrize("name", ["azdeg", "altdeg", "hsv_min_val", "hsv_max_sat"])
@pytest.mark.parametrize("value", [float("nan"), float("inf")])
def test_a_light_source_at_no_angle_is_refused(name: str, value: float) -> None:
    with pytest.raises(ValueError, match=f"{name} must be a finite number, got {value}"):
        gs.relief.LightSource(**{name: value})
