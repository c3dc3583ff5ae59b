"""gs.Image: made from each shape and dtype, saved as PNG (8 and 16 bits, grey, RGB and RGBA) and
read back by Pillow and by a PNG decoder written here from the specification; JPEG, TIFF and
WebP through Pillow, and without it; the notebook display and its size; which results stay
images; the messages of bad arguments."""

from __future__ import annotations

import io
import pickle
import struct
import sys
import zlib
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from conftest import require, unavailable

import glshade as gs

SHAPES = [(5, 7), (5, 7, 3), (5, 7, 4)]
MODES_8 = {1: "L", 3: "RGB", 4: "RGBA"}


def channels(shape: tuple[int, ...]) -> int:
    return shape[2] if len(shape) == 3 else 1


def pillow() -> Any:
    return require("PIL.Image")


def decode_png(data: bytes) -> np.ndarray[Any, Any]:
    """The pixels of a non-interlaced grey, RGB or RGBA PNG of 8 or 16 bits, as uint8 or uint16,
    decoded from the specification (chunks, CRCs, the five scanline filters)."""
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    chunks, at = [], 8
    while at < len(data):
        (length,) = struct.unpack(">I", data[at : at + 4])
        kind, body = data[at + 4 : at + 8], data[at + 8 : at + 8 + length]
        (crc,) = struct.unpack(">I", data[at + 8 + length : at + 12 + length])
        assert crc == zlib.crc32(kind + body) & 0xFFFFFFFF, kind
        chunks.append((kind, body))
        at += 12 + length
    assert chunks[0][0] == b"IHDR" and chunks[-1][0] == b"IEND"
    width, height, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", chunks[0][1])
    assert interlace == 0
    channels = {0: 1, 2: 3, 6: 4}[colour]
    bpp = channels * depth // 8
    raw = zlib.decompress(b"".join(body for kind, body in chunks if kind == b"IDAT"))
    stride = width * bpp
    assert len(raw) == height * (1 + stride)
    previous = [0] * stride
    out = bytearray()
    for y in range(height):
        kind = raw[y * (1 + stride)]
        line = list(raw[y * (1 + stride) + 1 : (y + 1) * (1 + stride)])
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b = previous[i]
            c = previous[i - bpp] if i >= bpp else 0
            if kind == 1:
                line[i] = (line[i] + a) % 256
            elif kind == 2:
                line[i] = (line[i] + b) % 256
            elif kind == 3:
                line[i] = (line[i] + (a + b) // 2) % 256
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                predictor = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
                line[i] = (line[i] + predictor) % 256
            else:
                assert kind == 0, kind
        out += bytes(line)
        previous = line
    pixels = np.frombuffer(bytes(out), ">u2" if depth == 16 else np.uint8).astype(
        np.uint16 if depth == 16 else np.uint8
    )
    return pixels.reshape((height, width) if channels == 1 else (height, width, channels))


def test_decode_png_reads_pillows_png() -> None:
    """The decoder above, checked on a PNG that Pillow (not glshade) wrote."""
    image_module = pillow()
    pixels = np.random.default_rng(1).integers(0, 256, (6, 9, 4), np.uint8)
    buffer = io.BytesIO()
    image_module.fromarray(pixels).save(buffer, format="PNG")
    np.testing.assert_array_equal(decode_png(buffer.getvalue()), pixels)


# --- made from each shape and dtype --------------------------------------------------------------


@pytest.mark.parametrize("shape", SHAPES)
@pytest.mark.parametrize(
    ("dtype", "scale", "kept"),
    [
        (np.float16, 1.0, np.float32),
        (np.float32, 1.0, np.float32),
        (np.float64, 1.0, np.float64),
        (np.longdouble, 1.0, np.float64),
        (np.uint8, 255.0, np.float32),
        (np.uint16, 65535.0, np.float32),
        (np.bool_, 1.0, np.float32),
    ],
)
def test_each_shape_and_dtype_gives_png_bytes_pillow_decodes(
    shape: tuple[int, ...], dtype: Any, scale: float, kept: Any, rng: np.random.Generator
) -> None:
    image_module = pillow()
    if dtype is np.bool_:
        given = rng.uniform(size=shape) > 0.5
    elif np.dtype(dtype).kind == "u":
        given = rng.integers(0, int(scale) + 1, shape).astype(dtype)
    else:
        given = rng.uniform(-0.25, 1.25, shape).astype(dtype)
    image = gs.Image(given)
    assert type(image) is gs.Image and image.shape == shape and image.dtype == kept
    expected = given.astype(np.float64) / scale
    np.testing.assert_allclose(image, expected, rtol=1e-6, atol=0)
    png = image._repr_png_()
    assert isinstance(png, bytes) and png.startswith(b"\x89PNG\r\n\x1a\n")
    decoded = image_module.open(io.BytesIO(png))
    assert decoded.mode == MODES_8[channels(shape)]
    assert decoded.size == (7, 5)
    levels = np.round(np.clip(expected, 0, 1) * 255)
    np.testing.assert_array_equal(np.asarray(decoded), levels)


def test_integer_images_round_trip_exactly(tmp_path: Path, rng: np.random.Generator) -> None:
    image_module = pillow()
    rgba8 = rng.integers(0, 256, (9, 11, 4), np.uint8)
    saved = gs.Image(rgba8).save(tmp_path / "a.png")
    np.testing.assert_array_equal(np.asarray(image_module.open(saved)), rgba8)
    grey16 = rng.integers(0, 65536, (9, 11), np.uint16)
    saved = gs.Image(grey16).save(tmp_path / "b.png", bits=16)
    with image_module.open(saved) as read:
        assert read.mode == "I;16"
        np.testing.assert_array_equal(np.asarray(read), grey16)
    rgb16 = rng.integers(0, 65536, (9, 11, 3), np.uint16)
    data = gs.Image(rgb16).save(tmp_path / "c.png", bits=16).read_bytes()
    np.testing.assert_array_equal(decode_png(data), rgb16)
    # Pillow holds 16-bit colour as 8 bits: the high byte of each sample.
    np.testing.assert_array_equal(np.asarray(image_module.open(io.BytesIO(data))), rgb16 >> 8)


@pytest.mark.parametrize("shape", SHAPES)
@pytest.mark.parametrize("bits", [8, 16])
def test_save_writes_the_png_of_the_images_layout(
    shape: tuple[int, ...], bits: int, tmp_path: Path, rng: np.random.Generator
) -> None:
    image_module = pillow()
    y, x = np.mgrid[0:5, 0:7]
    smooth = (x / 6.0 + y / 4.0)[..., None] / 2 * np.linspace(0.5, 1, 4)  # filters other than 0
    values = smooth[..., : shape[2]] if len(shape) == 3 else smooth[..., 0]
    values = values + rng.uniform(-0.2, 0.2, shape)
    values[0, 0] = np.nan  # shown as 0
    path = gs.Image(values).save(tmp_path / f"image-{bits}.PNG", bits=bits)
    assert path == tmp_path / f"image-{bits}.PNG"
    data = path.read_bytes()
    # IHDR's bit depth and colour type (PNG spec 11.2.2: 0 grey, 2 RGB, 6 RGBA)
    assert (data[24], data[25]) == (bits, {1: 0, 3: 2, 4: 6}[channels(shape)])
    top = 255 if bits == 8 else 65535
    expected = np.round(np.clip(np.nan_to_num(values), 0, 1) * top)
    np.testing.assert_array_equal(decode_png(data), expected)
    read = np.asarray(image_module.open(path))
    np.testing.assert_array_equal(
        read, expected // 256 if bits == 16 and len(shape) == 3 else expected
    )


def test_pillow_images_and_sequences_are_accepted() -> None:
    image_module = pillow()
    red = gs.Image(image_module.new("RGB", (3, 2), (255, 0, 0)))
    assert red.shape == (2, 3, 3)
    np.testing.assert_array_equal(red[..., 0], 1.0)
    np.testing.assert_array_equal(red[..., 1:], 0.0)
    listed = gs.Image([[0.0, 0.5], [1.0, 0.25]])
    assert listed.dtype == np.float64 and listed[1, 0] == 1.0


def test_float_images_share_memory_and_others_are_copies() -> None:
    plain = np.zeros((2, 3, 4), np.float32)
    assert np.shares_memory(gs.Image(plain), plain)
    as_bytes = np.zeros((2, 3, 4), np.uint8)
    assert not np.shares_memory(gs.Image(as_bytes), as_bytes)


# --- JPEG, TIFF, WebP and unknown extensions -----------------------------------------------------


def test_jpeg_is_written_by_pillow_with_alpha_over_white(tmp_path: Path) -> None:
    image_module = pillow()
    image = np.zeros((16, 16, 4))
    image[:, :8] = (1.0, 0.0, 0.0, 1.0)  # opaque red; the right half is transparent black
    for name in ("x.jpg", "y.JPEG"):
        path = gs.Image(image).save(tmp_path / name)
        assert path.read_bytes()[:3] == b"\xff\xd8\xff"
        with image_module.open(path) as read:
            assert (read.format, read.mode, read.size) == ("JPEG", "RGB", (16, 16))
            pixels = np.asarray(read).astype(int)
        np.testing.assert_allclose(pixels[4:12, 1:5].mean(axis=(0, 1)), (255, 0, 0), atol=6)
        np.testing.assert_allclose(pixels[4:12, 11:15].mean(axis=(0, 1)), (255, 255, 255), atol=6)


def test_tiff_round_trips_exactly_and_webp_closely(
    tmp_path: Path, rng: np.random.Generator
) -> None:
    image_module = pillow()
    features = require("PIL.features")
    rgba = rng.integers(0, 256, (12, 10, 4), np.uint8)
    for name in ("a.tif", "b.tiff"):
        with image_module.open(gs.Image(rgba).save(tmp_path / name)) as read:
            assert read.format == "TIFF"
            np.testing.assert_array_equal(np.asarray(read), rgba)
    grey = gs.Image(rng.uniform(size=(12, 10))).save(tmp_path / "g.tif")
    with image_module.open(grey) as read:
        assert read.mode == "L"
    if not features.check("webp"):
        unavailable("this Pillow has no WebP support (a Pillow wheel from PyPI has it)")
    y, x = np.mgrid[0:32, 0:48]
    # Alpha that varies: Pillow reads a WebP whose alpha is all opaque as RGB.
    smooth = np.stack([x / 47, y / 31, 0.5 + 0 * x, 0.5 + x / 94], axis=-1)
    with image_module.open(gs.Image(smooth).save(tmp_path / "c.webp")) as read:
        assert (read.format, read.mode, read.size) == ("WEBP", "RGBA", (48, 32))
        error = np.abs(np.asarray(read) - np.round(smooth * 255)) / 255
    # Lossy colour, lossless alpha (libwebp's default alpha_quality of 100).
    assert error.mean() < 0.01 and error[..., 3].max() == 0


def test_without_pillow_jpeg_raises_and_png_still_works(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    for module in ("PIL", "PIL.Image", "PIL.features"):
        monkeypatch.setitem(sys.modules, module, None)
    image = gs.Image(np.full((2, 2, 4), 0.5))
    for name, extension in (("x.jpg", "'.jpg'"), ("x.tiff", "'.tiff'"), ("x.webp", "'.webp'")):
        with pytest.raises(ValueError, match="needs Pillow") as caught:
            image.save(tmp_path / name)
        assert extension in str(caught.value)
        assert "pip install 'glshade[image]'" in str(caught.value)
        assert not (tmp_path / name).exists()
    assert image.save(tmp_path / "x.png").read_bytes()[:4] == b"\x89PNG"


def test_unknown_or_missing_extensions_and_bad_bits_raise(tmp_path: Path) -> None:
    image = gs.Image(np.zeros((2, 2, 3)))
    with pytest.raises(ValueError, match=r"extension '\.bmp'.*\.png, \.jpg, \.jpeg, \.tif"):
        image.save(tmp_path / "x.bmp")
    with pytest.raises(ValueError, match=r"has no extension; Image\.save writes \.png"):
        image.save(tmp_path / "x")
    with pytest.raises(ValueError, match="bits must be 8 or 16, got 12"):
        image.save(tmp_path / "x.png", bits=12)
    with pytest.raises(ValueError, match="bits must be 8 or 16, got True"):
        image.save(tmp_path / "x.png", bits=True)
    with pytest.raises(ValueError, match=r"bits=16 is written as PNG only; '\.jpg' takes 8 bits"):
        image.save(tmp_path / "x.jpg", bits=16)
    assert list(tmp_path.iterdir()) == []


def test_views_of_other_arrays_are_checked_when_saved_or_shown(tmp_path: Path) -> None:
    as_bytes = np.full((2, 3, 4), 255, np.uint8).view(gs.Image)  # 255 is 1.0
    np.testing.assert_array_equal(decode_png(as_bytes.save(tmp_path / "a.png").read_bytes()), 255)
    flat = np.zeros(5).view(gs.Image)
    assert flat._repr_png_() is None  # IPython shows the text instead
    with pytest.raises(
        ValueError, match=r"the image must have shape \(height, width\).*got \(5,\)"
    ):
        flat.save(tmp_path / "b.png")
    words = np.zeros((2, 2), np.int32).view(gs.Image)
    with pytest.raises(TypeError, match=r"the image must be float.*got dtype int32"):
        words.save(tmp_path / "c.png")
    empty = gs.Image(np.zeros((0, 3, 4)))
    assert empty._repr_png_() is None
    with pytest.raises(ValueError, match=r"at least one pixel; the image has shape \(0, 3, 4\)"):
        empty.save(tmp_path / "d.png")


# --- the notebook display ------------------------------------------------------------------------


def test_notebooks_show_every_layout_at_the_display_width() -> None:
    interactive = require("IPython.core.interactiveshell")
    formatter = interactive.InteractiveShell.instance().display_formatter
    for shape in [(10, 20), (10, 20, 3), (10, 20, 4)]:
        shown, metadata = formatter.format(gs.Image(np.zeros(shape)))
        assert shown["image/png"].startswith(b"\x89PNG") and metadata == {}
        image = gs.Image(np.zeros(shape), display_width=300)
        shown, metadata = formatter.format(image)
        assert metadata == {"image/png": {"width": 300, "height": 150}}
        assert shown["image/png"][16:24] == struct.pack(">II", 20, 10)  # the pixels stay 20x10
    image.display_width = 7
    assert formatter.format(image)[1] == {"image/png": {"width": 7, "height": 4}}  # 3.5 rounded
    image.display_width = None
    assert formatter.format(image)[1] == {}


def test_display_width_is_kept_by_views_copies_and_pickles() -> None:
    image = gs.Image(np.zeros((4, 6, 4)), display_width=120)
    kept = [image[1:], image[..., :3], image * 2, np.clip(image, 0, 1), image.copy()]
    kept.append(pickle.loads(pickle.dumps(image)))
    for result in kept:
        assert type(result) is gs.Image and result.display_width == 120
    assert gs.Image(image).display_width is None  # the constructor's own value


def test_display_width_is_checked() -> None:
    with pytest.raises(ValueError, match="display_width must be at least 1 pixel, got 0"):
        gs.Image(np.zeros((2, 2)), display_width=0)
    with pytest.raises(TypeError, match=r"display_width must be an int .* got float"):
        gs.Image(np.zeros((2, 2)), display_width=2.5)  # type: ignore[arg-type]
    image = gs.Image(np.zeros((2, 2)))
    with pytest.raises(TypeError, match=r"display_width must be an int .* got bool"):
        image.display_width = True
    with pytest.raises(ValueError, match="at least 1 pixel, got -3"):
        image.display_width = -3


# --- which results stay images -------------------------------------------------------------------


def test_results_that_keep_the_layout_stay_images() -> None:
    rgba = gs.Image(np.random.default_rng(2).uniform(size=(4, 6, 4)))
    for result in (rgba[::2], rgba[..., :3], rgba * 0.5, rgba + rgba, rgba.astype(np.float32)):
        assert type(result) is gs.Image
    plain = (
        rgba[..., 0],  # a channel
        rgba[0],  # a row
        rgba[0, 0],
        rgba > 0.5,
        rgba.mean(axis=2),
        rgba.reshape(-1, 4),
        rgba.ravel(),
        rgba.astype(np.uint8),
        rgba[None],
    )
    for result in plain:
        assert type(result) is np.ndarray
    assert type(rgba.max()) is np.float64
    grey = gs.Image(np.random.default_rng(3).uniform(size=(4, 6)))
    for result in (grey[1:], grey.T, grey * 2, grey.reshape(6, 4)):
        assert type(result) is gs.Image
    for result in (grey[0], grey[..., None], grey.sum(axis=0), grey.flatten()):
        assert type(result) is np.ndarray
    assert type(np.asarray(rgba)) is np.ndarray


# --- messages of bad arguments -------------------------------------------------------------------


def test_bad_dtypes_name_the_argument_and_the_dtype() -> None:
    with pytest.raises(TypeError, match=r"array must be float .*uint8 .*uint16 .*got dtype int64"):
        gs.Image(np.zeros((2, 2), np.int64))
    with pytest.raises(TypeError, match="got dtype int32: scale it to floats in"):
        gs.Image(np.zeros((2, 2, 3), np.int32))
    with pytest.raises(TypeError, match="got dtype complex128"):
        gs.Image(np.zeros((2, 2), complex))
    with pytest.raises(TypeError, match="got dtype <U1"):
        gs.Image([["a", "b"], ["c", "d"]])


def test_bad_shapes_name_the_shape_and_the_accepted_ones() -> None:
    accepted = (
        r"array must have shape \(height, width\), \(height, width, 3\) or \(height, width, 4\)"
    )
    with pytest.raises(ValueError, match=accepted + r", got \(5, 7, 2\)$"):
        gs.Image(np.zeros((5, 7, 2)))
    with pytest.raises(
        ValueError, match=r"got \(5, 7, 1\): drop the channel axis with array\[\.\.\., 0\]"
    ):
        gs.Image(np.zeros((5, 7, 1)))
    with pytest.raises(ValueError, match=r"got \(3, 5, 7\): channels first\? .*np\.moveaxis"):
        gs.Image(np.zeros((3, 5, 7), np.uint8))
    with pytest.raises(ValueError, match=r"got \(256,\)"):
        gs.Image(np.zeros(256, np.uint8))
    with pytest.raises(ValueError, match=r"got \(\)"):
        gs.Image(0.5)
