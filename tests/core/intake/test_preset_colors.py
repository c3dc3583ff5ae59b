"""The presets' and area lights' colours (``object_color``, ``l_d``, ``I_a``, an area light's
``diffuse``) answer as `Material` and `Light` do: a colour name is refused with its numbers, in
the very words of the scene's error; uint8 is divided by 255; bytes warn once, under the name the
user wrote, where `Lights` would warn (not for an attenuated light's intensity)."""

from __future__ import annotations

import re
import warnings
from collections.abc import Callable
from typing import Any

import numpy as np
import pytest

import glshade as gs
import glshade.presets as P

DX: dict[str, Any] = {
    "l_a": (0.1, 0.1, 0.1),
    "l_d": (1.0, 1.0, 1.0),
    "l_s": (1.0, 1.0, 1.0),
    "m_a": (1.0, 1.0, 1.0),
    "m_d": (0.5, 0.5, 0.5),
    "m_s": (0.2, 0.2, 0.2),
    "p": 8.0,
    "eye_position": (0.0, 0.0, 3.0),
    "light_vector": (0.0, 0.0, 1.0),
}
LECTURE: dict[str, Any] = {
    "k_a": 0.1,
    "k_d": 0.6,
    "k_s": 0.3,
    "n": 8.0,
    "I_a": 0.2,
    "I_l": 1.0,
    "viewer_position": (0.0, 0.0, 3.0),
}
QUAD = ((0.0, 0.0, 2.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0))


def _message(call: Callable[[], object]) -> str:
    with pytest.raises(TypeError) as info:
        call()
    return str(info.value)


def _warnings(call: Callable[[], object]) -> list[warnings.WarningMessage]:
    """Every warning `call` gives (none filtered out or merged)."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        call()
    return caught


@pytest.mark.parametrize(
    ("call", "name", "given"),
    [
        (lambda: P.learnopengl(object_color="red"), "object_color", "red"),
        (lambda: P.learnopengl(light_color="#ffa500"), "light_color", "#ffa500"),
        (lambda: P.directx11(**{**DX, "l_d": "white"}), "l_d", "white"),
        (lambda: P.directx11(**{**DX, "m_s": ["grey", "grey", "grey"]}), "m_s", "grey"),
        (
            lambda: P.phong_illumination(**{**LECTURE, "I_a": "blue"}, light_position=(0, 2, 0)),
            "I_a",
            "blue",
        ),
        (
            lambda: P.phong_illumination(**{**LECTURE, "I_l": "cyan"}, light_position=(0, 2, 0)),
            "I_l",
            "cyan",
        ),
        (lambda: gs.rectangle_light(*QUAD, 4, diffuse="#ff0000"), "diffuse", "#ff0000"),
        (
            lambda: gs.disc_light((0, 0, 2), (0, 0, -1), 1, 4, specular="orange"),
            "specular",
            "orange",
        ),
        (lambda: gs.disc_light((0, 0, 2), (0, 0, -1), 1, 4, ambient="black"), "ambient", "black"),
    ],
)
def test_a_colour_name_gets_the_scene_error_in_the_users_name(
    call: Callable[[], object], name: str, given: str
) -> None:
    text = _message(call)
    # The scene's own error for this name, with the argument's name: the same function's words.
    scene_text = _message(lambda: gs.Material(diffuse=given))
    assert text == scene_text.replace("diffuse", name)
    assert f"{name} takes numbers, not a colour name: got {given!r}" in text


def test_a_colour_names_numbers_are_the_colours_numbers() -> None:
    # The numbers the message offers build the colour: CSS's orange is (255, 165, 0) / 255.
    text = _message(lambda: P.learnopengl(object_color="orange"))
    assert "object_color=(1, 0.647, 0) for 'orange'" in text
    hexed = _message(lambda: gs.rectangle_light(*QUAD, 2, diffuse="#3366cc"))
    numbers = [float(x) for x in re.search(r"diffuse=\(([^)]*)\)", hexed).group(1).split(",")]  # type: ignore[union-attr]
    np.testing.assert_allclose(numbers, np.array([0x33, 0x66, 0xCC]) / 255, atol=5e-4)


@pytest.mark.parametrize(
    ("call", "expected"),
    [
        (
            lambda: P.learnopengl(object_color=(255, 128, 79)),
            ["learnopengl object_color=(255, 128, 79) looks like 0-255 byte values"],
        ),
        (
            lambda: P.directx11(**{**DX, "l_d": (255, 255, 255), "m_d": (200, 100, 50)}),
            [
                "directx11 l_d=(255, 255, 255) looks like 0-255 byte values",
                "directx11 m_d=(200, 100, 50) looks like 0-255 byte values",
            ],
        ),
        (
            lambda: P.phong_illumination(
                **{**LECTURE, "I_a": 50, "I_l": (255, 255, 255)}, light_direction=(0, 1, 0)
            ),
            [
                "phong_illumination I_a=(50, 50, 50) looks like",
                "phong_illumination I_l=(255, 255, 255) looks like",
            ],
        ),
        (
            lambda: gs.rectangle_light(*QUAD, 4, diffuse=(255, 255, 255)),
            ["rectangle_light diffuse=(255, 255, 255) looks like 0-255 byte values"],
        ),
        (
            lambda: gs.disc_light((0, 0, 2), (0, 0, -1), 1, 1, specular=(128, 128, 128, 255)),
            ["disc_light specular=(128, 128, 128, 255) looks like 0-255 byte values"],
        ),
    ],
)
def test_bytes_warn_once_under_the_users_name(
    call: Callable[[], object], expected: list[str]
) -> None:
    caught = _warnings(call)
    texts = [str(w.message) for w in caught]
    assert [w.category for w in caught] == [gs.ColorRangeWarning] * len(expected), texts
    for text, start in zip(texts, expected, strict=True):
        assert text.startswith(start)
        assert "Divide by 255" in text and "colours are in [0, 1]" in text
    # The warning points at the line that called glshade: this file.
    assert all(w.filename == __file__ for w in caught)


def test_the_warning_offers_the_divided_colour() -> None:
    (caught,) = _warnings(lambda: P.learnopengl(object_color=(255, 128, 79)))
    offered = re.search(r"Divide by 255: object_color=\(([^)]*)\)", str(caught.message))
    assert offered is not None
    np.testing.assert_allclose(
        [float(x) for x in offered.group(1).split(",")], np.array([255, 128, 79]) / 255, atol=5e-4
    )


@pytest.mark.parametrize(
    "call",
    [
        # Colours in [0, 1] and small whole numbers (a bright light) are not bytes.
        lambda: P.learnopengl(object_color=(1, 0.5, 0.31), light_color=(2, 2, 2)),
        lambda: P.directx11(**DX),
        # An attenuated light's colour is an intensity: large values are meant.
        lambda: P.phong_illumination(
            **{**LECTURE, "I_l": (100, 100, 100)},
            light_position=(0, 2, 0),
            attenuation="inverse_square",
        ),
        lambda: gs.rectangle_light(*QUAD, 4, diffuse=(255, 255, 255), quadratic_attenuation=1),
        lambda: gs.disc_light(
            (0, 0, 2), (0, 0, -1), 1, 4, diffuse=(40, 40, 40), linear_attenuation=1
        ),
        # uint8 is divided by 255, so it is not bytes any more.
        lambda: P.learnopengl(object_color=np.array([255, 128, 79], np.uint8)),
        lambda: gs.rectangle_light(*QUAD, 4, diffuse=np.array([255, 255, 255], np.uint8)),
    ],
)
def test_no_warning_where_the_values_are_meant(call: Callable[[], object]) -> None:
    assert _warnings(call) == []


def test_uint8_colours_are_divided_by_255() -> None:
    byte = np.array([255, 128, 79], np.uint8)
    scene = P.learnopengl(object_color=byte).scene
    np.testing.assert_allclose(scene.material.diffuse, [255 / 255, 128 / 255, 79 / 255, 1.0])
    dx = P.directx11(**{**DX, "l_d": np.array([51, 102, 204], np.uint8)}).scene
    np.testing.assert_allclose(dx.lights.diffuse[0], [0.2, 0.4, 0.8, 1.0])
    # An area light shares the divided colour among its k = 4 lights.
    lights = gs.rectangle_light(*QUAD, 4, diffuse=np.array([255, 0, 102], np.uint8))
    np.testing.assert_allclose(lights.diffuse, np.tile([1 / 4, 0, 0.4 / 4, 1.0], (4, 1)))


def test_the_checks_leave_the_warning_filters_as_they_were() -> None:
    def both() -> Any:
        P.learnopengl(object_color=(1, 0.5, 0.31))
        return gs.Material(diffuse=(255, 0, 0))

    # The presets build GL objects with their warnings silenced, and only while they do: a
    # Material made next still warns, and the filters are those before the call.
    caught = _warnings(both)
    assert [str(w.message).split(" looks")[0] for w in caught] == ["Material diffuse=(255, 0, 0)"]
    before = list(warnings.filters)
    P.phong_illumination(**LECTURE, light_position=(0, 2, 0))
    assert warnings.filters == before
