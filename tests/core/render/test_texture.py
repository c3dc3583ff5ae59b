"""Textures in `render`: the intake (image kinds, coordinates, names), GL's modulation of the
fragment colour, and the metallic-roughness model's base colour texture, each against the
render without a texture that it must equal."""

from __future__ import annotations

import numpy as np
import pytest

import glshade as gs

MESH = gs.meshes.torus(32, 16, 1.0, 0.4)
UV = np.random.default_rng(0).uniform(0, 1, (len(MESH[0]), 2))
SIZE = {"width": 48, "height": 40}


def srgb_to_linear(c: np.ndarray) -> np.ndarray:
    """pyrender's srgb_to_linear, written out."""
    return np.where(c < 0.04045, c / 12.92, ((c + 0.055) / 1.055) ** 2.4)


@pytest.mark.parametrize("shading", ["phong", "gouraud", "flat"])
def test_a_uniform_texture_modulates_gl_fragments(shading: str) -> None:
    texel = np.array([200, 100, 50, 255], np.uint8)
    textured = gs.render(MESH, texture=np.tile(texel, (3, 5, 1)), uv=UV, shading=shading, **SIZE)
    plain = gs.render(MESH, shading=shading, **SIZE)
    covered = plain[..., 3] > 0
    np.testing.assert_allclose(textured[covered], plain[covered] * texel / 255, atol=1e-12)


@pytest.mark.parametrize("shading", ["phong", "gouraud", "flat"])
def test_a_uniform_texture_is_a_base_colour_decoded_from_srgb(shading: str) -> None:
    texel = np.array([200, 100, 50, 128], np.uint8)
    base = np.array([0.9, 0.8, 0.7, 1.0])
    lights = [gs.gltf.PointLight(intensity=20.0, position=(2, 2, 3))]
    with_texture = gs.gltf.Scene(
        lights, gs.gltf.Material(base, 0.3, 0.5), ambient_light=(0.1, 0.1, 0.1)
    )
    decoded = srgb_to_linear(texel[:3] / 255)
    folded = gs.gltf.Scene(
        lights,
        gs.gltf.Material((*(base[:3] * decoded), base[3] * texel[3] / 255), 0.3, 0.5),
        ambient_light=(0.1, 0.1, 0.1),
    )
    textured = gs.render(MESH, with_texture, texture=np.tile(texel, (2, 2, 1)), uv=UV,
                         shading=shading, **SIZE)  # fmt: skip
    plain = gs.render(MESH, folded, shading=shading, **SIZE)
    np.testing.assert_allclose(textured, plain, atol=1e-12)


def test_image_kinds() -> None:
    grey = np.full((2, 3), 0.25)
    rgba = gs.render(MESH, texture=grey, uv=UV, **SIZE)
    as_rgb = gs.render(MESH, texture=np.dstack([grey] * 3), uv=UV, **SIZE)
    np.testing.assert_array_equal(rgba, as_rgb)
    grey_alpha = np.dstack([grey, np.full((2, 3), 0.5)])
    half = gs.render(MESH, texture=grey_alpha, uv=UV, **SIZE)
    covered = rgba[..., 3] > 0
    np.testing.assert_allclose(half[covered, 3], rgba[covered, 3] * 0.5)
    sixteen = gs.render(MESH, texture=np.full((2, 2), 65535, np.uint16), uv=UV, **SIZE)
    # A white texture: the bilinear weights sum to 1 within an ulp.
    np.testing.assert_allclose(sixteen, gs.render(MESH, **SIZE), atol=1e-15)


@pytest.mark.parametrize(
    ("kwargs", "error", "message"),
    [
        ({"texture": np.ones((2, 2))}, ValueError, "a texture needs uv"),
        ({"uv": UV}, ValueError, "uv was given without a texture"),
        ({"texture": np.ones((2, 2)), "uv": UV[:5]}, ValueError, "uv must have one row per vertex"),
        ({"texture": np.ones((2, 2, 5)), "uv": UV}, ValueError, "texture must have shape"),
        ({"texture": np.ones((2, 2)), "uv": UV, "texture_filter": "cubic"}, ValueError,
         "texture_filter must be"),
        ({"texture": np.ones((2, 2)), "uv": UV, "texture_wrap": "clamp"}, ValueError,
         "texture_wrap must be"),
        ({"texture": np.ones((2, 2)), "uv": UV, "texture_wrap": 3}, TypeError,
         "texture_wrap must be a mode name or a pair"),
    ],
)  # fmt: skip
def test_bad_textures_name_themselves(kwargs: dict, error: type, message: str) -> None:
    with pytest.raises(error, match=message):
        gs.render(MESH, **SIZE, **kwargs)


def test_a_wrap_pair_and_false() -> None:
    pair = gs.render(MESH, texture=np.eye(3), uv=UV * 3, texture_wrap=("repeat", "clamp_to_edge"),
                     **SIZE)  # fmt: skip
    assert np.isfinite(pair).all()
    assert np.array_equal(gs.render(MESH, texture=False, **SIZE), gs.render(MESH, **SIZE))
