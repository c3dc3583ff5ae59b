"""One colour intake: the same 0-255 input to every public colour surface (GL's scene objects,
glTF's, three.js', vertex colours, textures, `Image`, `compare`, `render`'s background) gives
the same `ColorRangeWarning`, or, where values above 1 are not allowed (glTF's base colour
factor), a ValueError with the same message; uint8 is divided by 255 everywhere, silently.
three.js' colours also come as hex integers and '#rrggbb' strings, decoded from sRGB as
three.js' colour management decodes them (its formula written out here)."""

from __future__ import annotations

import math
import warnings
from collections.abc import Callable
from typing import Any

import numpy as np
import pytest

import glshade as gs

BYTES = (200, 80, 40)  # what a colour picker shows
FLOAT_BYTES = (200.4, 80.2, 40.0)  # a [0, 1] colour times 255, as arithmetic leaves it
P = np.array([[0.0, 0.0, -2.0], [1.0, 0.0, -2.0], [0.0, 1.0, -2.0]])
F = [[0, 1, 2]]
CAMERA = gs.Camera.look_at((0.3, 0.3, 2.0), (0.3, 0.3, -2.0), fovy=50, near=1, far=10)
PICTURE = np.full((4, 5, 3), 0.5)


def _surfaces(value: Any) -> dict[str, Callable[[], object]]:
    """Every public colour surface, given `value` (3 numbers, of its own dtype) where a colour
    goes."""
    given = np.asarray(value)
    opaque = 255 if given.dtype == np.uint8 else 1.0
    rgba = np.append(given, np.array(opaque, given.dtype))
    vertex = np.tile(given, (3, 1))
    texture = np.tile(given, (2, 2, 1))
    # Pictures come as floats (a picture times 255) or uint8; other integer pictures are
    # refused with the advice to cast them to uint8 (test_integer_pictures_say_what_to_do).
    picture = np.tile(given if given.dtype == np.uint8 else given.astype(float), (4, 5, 1))
    uv = np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]])
    three = gs.threejs
    return {
        "Material": lambda: gs.Material(diffuse=rgba),
        "Light": lambda: gs.Light(specular=value),
        "Scene global_ambient": lambda: gs.Scene(global_ambient=rgba),
        "shade colors": lambda: gs.shade(P, (0, 0, 1), gs.Scene(), colors=vertex),
        "render colors": lambda: gs.render(
            P, F, gs.Scene(), CAMERA, width=4, height=4, colors=vertex
        ),
        "render background": lambda: gs.render(
            P, F, gs.Scene(), CAMERA, width=4, height=4, background=value
        ),
        "render texture": lambda: gs.render(
            P, F, gs.Scene(), CAMERA, width=4, height=4, texture=texture, uv=uv
        ),
        "gltf.Material emissive": lambda: gs.gltf.Material(emissive=value),
        "gltf.DirectionalLight": lambda: gs.gltf.DirectionalLight(color=value),
        "gltf.PointLight": lambda: gs.gltf.PointLight(color=value),
        "gltf.SpotLight": lambda: gs.gltf.SpotLight(color=value),
        "threejs.MeshPhongMaterial color": lambda: three.MeshPhongMaterial(color=value),
        "threejs.MeshPhongMaterial specular": lambda: three.MeshPhongMaterial(specular=value),
        "threejs.MeshPhongMaterial emissive": lambda: three.MeshPhongMaterial(emissive=value),
        "threejs.AmbientLight": lambda: three.AmbientLight(color=value),
        "threejs.HemisphereLight": lambda: three.HemisphereLight(ground_color=value),
        "threejs.DirectionalLight": lambda: three.DirectionalLight(color=value),
        "threejs.PointLight": lambda: three.PointLight(color=value),
        "threejs.SpotLight": lambda: three.SpotLight(color=value),
        "Image": lambda: gs.Image(picture),
        "compare image": lambda: gs.compare(picture, PICTURE),
        "compare reference": lambda: gs.compare(PICTURE, picture),
        "compare background": lambda: gs.compare(PICTURE, PICTURE, background=value),
    }


SURFACES = list(_surfaces(BYTES))


def _caught(call: Callable[[], object]) -> list[warnings.WarningMessage]:
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        call()
    return [w for w in caught if issubclass(w.category, gs.ColorRangeWarning)]


@pytest.mark.parametrize("value", [BYTES, FLOAT_BYTES], ids=["whole", "fractional"])
@pytest.mark.parametrize("surface", SURFACES)
def test_bytes_warn_alike_on_every_surface(surface: str, value: tuple[float, ...]) -> None:
    (warning,) = _caught(_surfaces(value)[surface])
    text = str(warning.message)
    assert "looks like 0-255 byte values" in text and "Divide by 255" in text, text
    assert "colours are in [0, 1]" in text
    assert warning.filename == __file__  # the user's line, whichever function built it


@pytest.mark.parametrize("value", [BYTES, FLOAT_BYTES], ids=["whole", "fractional"])
def test_where_values_above_1_are_refused_the_same_message_is_an_error(
    value: tuple[float, ...],
) -> None:
    with pytest.raises(ValueError) as info:
        gs.gltf.Material(base_color=(*value, 255))
    text = str(info.value)
    assert text.startswith("gltf.Material base_color=(")
    assert "looks like 0-255 byte values" in text and "Divide by 255" in text
    assert "base_color=(0.784, 0.314, 0.157, 1)" in text or "base_color=(0.786" in text


@pytest.mark.parametrize("surface", SURFACES)
def test_uint8_is_divided_by_255_without_a_word(surface: str) -> None:
    """uint8 is GL's normalised unsigned byte on every surface (where numbers go at all)."""
    call = _surfaces(np.array(BYTES, np.uint8))[surface]
    try:
        assert _caught(call) == []
    except TypeError as e:  # three.js' records take numbers; uint8 arrays are numbers too
        pytest.fail(f"{surface} refused uint8: {e}")


NOT_BYTES = [
    (surface, value)
    for value in [(2.0, 2.0, 2.0), (15.0, 15.0, 15.0), (255.5, 0.0, 0.0), (-1.0, 20.0, 20.0)]
    for surface in ["Material", "shade colors", "threejs.PointLight", "Image"]
    if not (surface.startswith("threejs") and min(value) < 0)  # three.js refuses negative ones
]


@pytest.mark.parametrize(("surface", "value"), NOT_BYTES)
def test_what_cannot_be_bytes_does_not_warn(surface: str, value: tuple[float, ...]) -> None:
    """A bright light's (2, 2, 2), values below 16, above 255 or negative are not bytes."""
    assert _caught(_surfaces(value)[surface]) == []


def test_integer_pictures_say_what_to_do() -> None:
    picture = np.tile(np.array(BYTES), (4, 5, 1))  # int64
    with pytest.raises(TypeError, match=r"or cast 0-255 values to uint8"):
        gs.Image(picture)
    with pytest.raises(TypeError, match=r"cast 0-255 values with .astype\(np.uint8\)"):
        gs.compare(picture, PICTURE)


def _three_decode(c: float) -> float:
    """three.js' SRGBToLinear (src/math/ColorManagement.js), which ``Color.setHex`` and
    ``setStyle`` apply under colour management (on by default since r152)."""
    return c * 0.0773993808 if c < 0.04045 else math.pow(c * 0.9478672986 + 0.0521327014, 2.4)


@pytest.mark.parametrize(
    ("given", "srgb"),
    [
        (0xFF8800, (255, 136, 0)),
        ("#ff8800", (255, 136, 0)),
        ("#FF8800", (255, 136, 0)),
        ("#f80", (255, 136, 0)),
        (0x111111, (17, 17, 17)),
        (np.int64(0x0A141E), (10, 20, 30)),
        (0, (0, 0, 0)),
        ("#ffffff", (255, 255, 255)),
    ],
)
def test_threejs_hex_colours_are_their_decoded_values(given: Any, srgb: tuple[int, ...]) -> None:
    expected = [_three_decode(v / 255) for v in srgb]
    for record, field in [
        (gs.threejs.MeshPhongMaterial(color=given), "color"),
        (gs.threejs.MeshPhongMaterial(specular=given), "specular"),
        (gs.threejs.MeshPhongMaterial(emissive=given), "emissive"),
        (gs.threejs.PointLight(color=given), "color"),
        (gs.threejs.HemisphereLight(sky_color=given, ground_color=given), "ground_color"),
    ]:
        np.testing.assert_allclose(getattr(record, field), expected, rtol=1e-9, atol=1e-12)
    # And a scene of it shades as the scene of the decoded numbers does.
    light = gs.threejs.DirectionalLight(color=given, position=(0, 0, 1))
    numbers = gs.threejs.DirectionalLight(color=light.color, position=(0, 0, 1))
    assert light == numbers
    normals = np.array([[0.0, 0.0, 1.0], [0.6, 0.0, 0.8]])
    np.testing.assert_array_equal(
        gs.shade(normals, normals, gs.threejs.Scene(light)),
        gs.shade(normals, normals, gs.threejs.Scene(numbers)),
    )


@pytest.mark.parametrize(
    ("given", "error", "words"),
    [
        (0x1000000, ValueError, "must be in [0, 0xffffff], got 0x1000000"),
        (-1, ValueError, "must be in [0, 0xffffff]"),
        ("red", ValueError, "'#rrggbb' or '#rgb'"),
        ("#ff880", ValueError, "write, say, '#ff8800', 0xff8800"),
        ("#gg8800", ValueError, "'#rrggbb' or '#rgb'"),
        (0.5, TypeError, "a hex integer such as 0xff8800"),
        (True, TypeError, "a hex integer such as 0xff8800"),
    ],
)
def test_a_colour_three_js_would_not_read_says_what_it_takes(
    given: Any, error: type[Exception], words: str
) -> None:
    with pytest.raises(error) as info:
        gs.threejs.MeshPhongMaterial(color=given)
    assert str(info.value).startswith("color ") and words in str(info.value)


@pytest.mark.parametrize("module", [gs.gltf, gs.threejs])
def test_a_single_light_is_taken_where_a_list_is(module: Any) -> None:
    light = module.PointLight(position=(0, 1, 2))
    assert module.Scene(light) == module.Scene([light])
    assert module.Scene(lights=light).lights == (light,)
    with pytest.raises(TypeError, match=f"lights must be a glshade.{module.__name__[8:]} light"):
        module.Scene(lights=3)
    with pytest.raises(TypeError, match=r"lights\[1\] must be"):
        module.Scene(lights=[light, gs.Light()])
