"""sRGB's transfer functions (IEC 61966-2-1) against a float64 transcription of the standard and
its published values, and `render(transfer=...)` against the linear render encoded."""

from __future__ import annotations

import re
from typing import Any

import numpy as np
import pytest
from conftest import require

import glshade as gs


def encode_reference(x: np.ndarray) -> np.ndarray:
    """IEC 61966-2-1, linear to encoded, extended to all reals as sign(x) f(|x|)."""
    a = np.abs(x.astype(np.float64))
    with np.errstate(invalid="ignore"):
        f = np.where(a <= 0.0031308, 12.92 * a, 1.055 * a ** (1 / 2.4) - 0.055)
    return np.sign(x) * f


def decode_reference(x: np.ndarray) -> np.ndarray:
    a = np.abs(x.astype(np.float64))
    with np.errstate(invalid="ignore"):
        f = np.where(a <= 0.04045, a / 12.92, ((a + 0.055) / 1.055) ** 2.4)
    return np.sign(x) * f


def test_both_directions_follow_the_standard(rng: np.random.Generator) -> None:
    x = np.concatenate([rng.uniform(0, 1, 10_000), rng.uniform(0, 0.005, 1000), [0.0, 1.0]])
    np.testing.assert_allclose(gs.srgb_encode(x), encode_reference(x), rtol=1e-14, atol=0)
    np.testing.assert_allclose(gs.srgb_decode(x), decode_reference(x), rtol=1e-14, atol=0)


def test_published_values_and_the_knee() -> None:
    # 18% grey encodes to 0.4614 (118 of 255); byte 128 decodes to 0.2158605; 0.5 to 0.2140411.
    assert gs.srgb_encode(0.18) == pytest.approx(0.461356129, abs=1e-9)
    assert gs.srgb_decode(128 / 255) == pytest.approx(0.215860500, abs=1e-9)
    assert gs.srgb_decode(0.5) == pytest.approx(0.214041140, abs=1e-9)
    assert gs.srgb_encode(1.0) == pytest.approx(1.0, abs=1e-15)
    assert gs.srgb_encode(0.0) == 0.0 and gs.srgb_decode(0.0) == 0.0
    # At the knee, the linear segment's end (12.92 x 0.0031308) and the power curve's value
    # agree to the 7 digits the standard gives; either side of it the curve is continuous.
    knee = 0.0031308
    assert gs.srgb_encode(knee) == pytest.approx(12.92 * knee, abs=1e-15)
    assert gs.srgb_encode(np.nextafter(knee, 1)) == pytest.approx(0.04044993, abs=1e-7)
    assert gs.srgb_decode(0.04045) == pytest.approx(0.04045 / 12.92, abs=1e-15)
    assert gs.srgb_decode(np.nextafter(0.04045, 1)) == pytest.approx(0.0031308, abs=1e-7)


@pytest.mark.parametrize("dtype", [np.float32, np.float64])
def test_decode_then_encode_is_the_identity_on_the_unit_interval(
    dtype: type, rng: np.random.Generator
) -> None:
    x = np.concatenate([np.linspace(0, 1, 10_001), rng.uniform(0, 1, 10_000)]).astype(dtype)
    for there_and_back in (gs.srgb_encode(gs.srgb_decode(x)), gs.srgb_decode(gs.srgb_encode(x))):
        assert there_and_back.dtype == dtype
        assert np.abs(there_and_back.astype(np.float64) - x).max() < 1e-6


def test_outside_the_unit_interval_the_curve_is_extended_symmetrically() -> None:
    x = np.array([-2.0, -0.5, -0.001, 1.5, 10.0])
    np.testing.assert_allclose(gs.srgb_encode(x), encode_reference(x), rtol=1e-14)
    np.testing.assert_array_equal(gs.srgb_encode(-x), -gs.srgb_encode(x))
    assert gs.srgb_encode(1.5) == pytest.approx(1.055 * 1.5 ** (1 / 2.4) - 0.055, rel=1e-14)
    np.testing.assert_allclose(gs.srgb_encode(gs.srgb_decode(x)), x, rtol=1e-12)
    out = gs.srgb_encode(np.array([np.nan, np.inf, -np.inf]))
    assert np.isnan(out[0]) and out[1] == np.inf and out[2] == -np.inf


def test_dtypes_and_shapes() -> None:
    x = np.linspace(0, 1, 24).reshape(2, 3, 4)
    for dtype in (np.float32, np.float64):
        assert gs.srgb_encode(x.astype(dtype)).dtype == dtype
        assert gs.srgb_encode(x.astype(dtype)).shape == (2, 3, 4)
    assert gs.srgb_encode(np.float16(0.5)).dtype == np.float64
    assert gs.srgb_decode([0, 1]).dtype == np.float64  # integers as values
    # Stored image values: uint8 over 255, uint16 over 65535.
    np.testing.assert_allclose(
        gs.srgb_decode(np.array([0, 128, 255], np.uint8)),
        decode_reference(np.array([0, 128, 255]) / 255),
    )
    np.testing.assert_allclose(
        gs.srgb_decode(np.array([0, 32768, 65535], np.uint16)),
        decode_reference(np.array([0, 32768, 65535]) / 65535),
    )
    with pytest.raises(TypeError, match="x must be real numbers"):
        gs.srgb_encode(np.array([1j]))


TRIANGLES = (
    np.array([[-1, -1, 0], [1, -1, 0], [0, 1, 0.3], [0.5, 0.8, -0.4]], np.float32),
    np.array([[0, 1, 2], [1, 3, 2]]),
)
SCENE = gs.Scene(
    lights=[gs.Light(position=(0.3, 0.4, 1, 0), specular=(1, 1, 1))],
    material=gs.Material(diffuse=(0.9, 0.5, 0.2), specular=(0.5, 0.5, 0.5), shininess=20),
)
CAMERA = gs.Camera.look_at((0, 0, 3), fovy=60, near=1, far=5)


@pytest.mark.parametrize("dtype", [np.float32, np.float64])
def test_render_encodes_its_rgb_and_nothing_else(dtype: type) -> None:
    v, f = TRIANGLES[0].astype(dtype), TRIANGLES[1]
    options = {"width": 40, "height": 30, "background": (0.2, 0.1, 0.05, 0.5), "depth": True}
    linear, depth = gs.render(v, f, SCENE, CAMERA, **options)
    assert 0 < (depth < 1).mean() < 1
    srgb, srgb_depth = gs.render(v, f, SCENE, CAMERA, transfer="srgb", **options)
    assert srgb.dtype == linear.dtype == dtype and isinstance(srgb, gs.Image)
    np.testing.assert_array_equal(srgb[..., :3], gs.srgb_encode(np.asarray(linear)[..., :3]))
    np.testing.assert_array_equal(srgb[..., 3], linear[..., 3])
    np.testing.assert_array_equal(srgb_depth, depth)
    # Against the float64 transcription too, within the dtype's rounding.
    tolerance = 1e-6 if dtype == np.float32 else 1e-14
    np.testing.assert_allclose(
        srgb[..., :3], encode_reference(np.asarray(linear)[..., :3]), atol=tolerance
    )
    gamma = gs.render(v, f, SCENE, CAMERA, transfer="gamma2.2", **options)[0]
    np.testing.assert_allclose(
        gamma[..., :3], np.asarray(linear, np.float64)[..., :3] ** (1 / 2.2), atol=tolerance
    )
    np.testing.assert_array_equal(gamma[..., 3], linear[..., 3])
    same = gs.render(v, f, SCENE, CAMERA, transfer="linear", **options)[0]
    np.testing.assert_array_equal(same, linear)


def test_the_transfer_name_is_case_insensitive_and_checked() -> None:
    v, f = TRIANGLES
    a = gs.render(v, f, SCENE, CAMERA, width=8, height=8, transfer="sRGB")  # type: ignore[arg-type]
    np.testing.assert_array_equal(
        a, gs.render(v, f, SCENE, CAMERA, width=8, height=8, transfer="srgb")
    )
    with pytest.raises(
        ValueError, match=re.escape("transfer must be 'linear', 'srgb' or 'gamma2.2', got 'rec709'")
    ):
        gs.render(v, f, SCENE, CAMERA, width=8, height=8, transfer="rec709")  # type: ignore[arg-type]
    with pytest.raises(TypeError, match=re.escape("transfer must be a string, got 2.2")):
        gs.render(v, f, SCENE, CAMERA, width=8, height=8, transfer=2.2)  # type: ignore[arg-type]


SHADE_SCENES = {
    "gl, two-sided": gs.Scene(
        lights=[gs.Light(position=(0.3, 0.4, 1.0, 0.0), specular=(1, 1, 1, 1))],
        material=gs.Material(specular=(0.5, 0.5, 0.5, 0.7), shininess=20),
        two_side=True,
    ),
    "gltf": gs.gltf.Scene(gs.gltf.PointLight(intensity=8, position=(0, 1, 3))),
    "threejs": gs.threejs.Scene(gs.threejs.DirectionalLight(position=(1, 2, 3))),
}


@pytest.mark.parametrize("dtype", [np.float32, np.float64])
@pytest.mark.parametrize("scene", list(SHADE_SCENES))
@pytest.mark.parametrize("transfer", ["srgb", "gamma2.2"])
def test_shade_encodes_its_rgb_as_render_does(
    scene: str, transfer: str, dtype: type, rng: np.random.Generator
) -> None:
    """shade(transfer=...) is the linear result with the transfer applied to RGB (IEC 61966-2-1
    or the power 1/2.2, written out above and here), alpha untouched, in the result's dtype, on
    every output (a two-sided scene's front and back), with out= too, and NaN rows NaN."""
    p = rng.normal(size=(200, 3)).astype(dtype)
    n = rng.normal(size=(200, 3)).astype(dtype)
    n[7] = np.nan
    linear = gs.shade(p, n, SHADE_SCENES[scene])
    encoded = gs.shade(p, n, SHADE_SCENES[scene], transfer=transfer)
    assert encoded.dtype == dtype and encoded.shape == linear.shape
    x = linear[..., :3].astype(np.float64)
    expected = encode_reference(x) if transfer == "srgb" else np.sign(x) * np.abs(x) ** (1 / 2.2)
    tolerance = 1e-6 if dtype == np.float32 else 1e-14
    np.testing.assert_allclose(encoded[..., :3], expected, atol=tolerance, rtol=0)
    np.testing.assert_array_equal(encoded[..., 3], linear[..., 3])
    assert np.isnan(encoded[..., 7, :]).all() and not np.isnan(np.delete(encoded, 7, -2)).any()
    out = np.empty_like(encoded)
    assert gs.shade(p, n, SHADE_SCENES[scene], transfer=transfer, out=out) is out
    np.testing.assert_array_equal(out, encoded)
    assert np.array_equal(gs.shade(p, n, SHADE_SCENES[scene], transfer="linear"), linear,
                          equal_nan=True)  # fmt: skip


def test_shade_takes_transfer_lazily_and_checks_its_name() -> None:
    da: Any = require("dask.array")
    p = np.zeros((6, 3))
    lazy = gs.shade(da.from_array(p, chunks=2), (0, 0, 1), SHADE_SCENES["gltf"], transfer="SRGB")
    np.testing.assert_array_equal(
        lazy.compute(), gs.shade(p, (0, 0, 1), SHADE_SCENES["gltf"], transfer="srgb")
    )
    with pytest.raises(ValueError, match=r"transfer must be 'linear', 'srgb' or 'gamma2\.2'"):
        gs.shade(p, (0, 0, 1), SHADE_SCENES["gltf"], transfer="sRGB2")  # type: ignore[arg-type]
