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


def rgba32f(image: np.ndarray) -> np.ndarray:
    """What a GL RGBA32F texture holds of `image`, written out: unsigned integers normalised
    (c / 255, c / 65535), grey into R, G and B, a missing alpha 1, float32."""
    a = image[..., None] if image.ndim == 2 else image
    if a.dtype.kind == "u":
        a = a / float(np.iinfo(a.dtype).max)
    grey = a.shape[2] <= 2
    rgb = np.repeat(a[..., :1], 3, axis=2) if grey else a[..., :3]
    alpha = a[..., -1:] if a.shape[2] in (2, 4) else np.ones((*a.shape[:2], 1))
    return np.ascontiguousarray(np.concatenate([rgb, alpha], axis=2), dtype=np.float32)


@pytest.mark.parametrize("dtype", ["uint8", "uint16", "float32", "float64", "int32", "float16"])
@pytest.mark.parametrize("channels", [None, 1, 2, 3, 4])
def test_every_storage_samples_as_its_rgba32f_texture(dtype: str, channels: int | None) -> None:
    """A texture is read in the type and channels it comes in (no conversion per call) and
    samples as the float32 RGBA texture GL would upload it into."""
    rng = np.random.default_rng(channels or 0)
    shape = (5, 7) if channels is None else (5, 7, channels)
    top = {"uint8": 255, "uint16": 65535, "int32": 1}.get(dtype, 1)
    image = (
        (rng.uniform(0, 1, shape) * top).astype(dtype)
        if top > 1
        else rng.uniform(0, 1, shape).astype(dtype)
    )
    scene = gs.gltf.Scene(
        [gs.gltf.DirectionalLight((1, 1, 1), 2.0, (0, 0, -1))], gs.gltf.Material()
    )
    for lit in (None, scene):
        ours = gs.render(MESH, lit, texture=image, uv=UV, texture_filter="linear", **SIZE)
        expected = gs.render(
            MESH, lit, texture=rgba32f(image), uv=UV, texture_filter="linear", **SIZE
        )
        np.testing.assert_array_equal(ours, expected)


def test_textures_are_read_in_place() -> None:
    """Arrays of the four stored types reach the renderer without a copy, a grey one as a
    view with a channel axis; a strided or big-endian one is copied once into order."""
    from glshade._texture import texels

    for dtype in (np.uint8, np.uint16, np.float32, np.float64):
        image = np.zeros((4, 3, 3), dtype)
        assert np.shares_memory(texels(image), image)
        grey = np.zeros((4, 3), dtype)
        assert np.shares_memory(texels(grey), grey)
    strided = np.zeros((4, 6, 4), np.uint8)[:, ::2]
    assert texels(strided).flags.c_contiguous
    swapped = np.arange(12, dtype=">u2").reshape(2, 2, 3)
    np.testing.assert_array_equal(texels(swapped), swapped.astype(np.uint16))


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
