"""A dependency-free PNG writer: grey, RGB or RGBA float images at 8 or 16 bits per channel."""

from __future__ import annotations

import struct
import zlib
from typing import Any

import numpy as np
from numpy.typing import NDArray

# PNG's colour type for each channel count: grey, RGB, RGBA (PNG spec, table 11.1).
_COLOUR_TYPE = {1: 0, 3: 2, 4: 6}


def _chunk(kind: bytes, data: bytes) -> bytes:
    body = kind + data
    return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)


def quantize(image: NDArray[np.floating[Any]], bits: int) -> NDArray[np.unsignedinteger[Any]]:
    """A float image as uint8 (``bits=8``) or uint16 (``bits=16``) pixel values: clipped to
    [0, 1], NaN as 0, scaled by 255 or 65535 and rounded to the nearest."""
    if bits not in (8, 16):
        raise ValueError(f"bits must be 8 or 16, got {bits!r}")
    top = 255 if bits == 8 else 65535
    values = np.nan_to_num(np.clip(image, 0.0, 1.0), nan=0.0)
    pixels: NDArray[np.unsignedinteger[Any]] = np.rint(values * top).astype(
        np.uint8 if bits == 8 else np.uint16
    )
    return pixels


def _filtered(rows: NDArray[np.uint8], bpp: int) -> NDArray[np.uint8]:
    """Each scanline of `rows` (height, bytes) under PNG's adaptive filtering: the filter of the
    five (none, sub, up, average, Paeth) whose bytes, read as signed, sum to the least magnitude
    (the spec's recommended heuristic), prefixed by its type byte."""
    out = np.zeros((rows.shape[0], rows.shape[1] + 1), np.uint8)
    # Bands of about a megabyte bound the int16 temporaries of large images.
    band = max(1, (1 << 20) // max(rows.shape[1], 1))
    for top in range(0, rows.shape[0], band):
        above = rows[top - 1] if top else np.zeros(rows.shape[1], np.uint8)
        out[top : top + band] = _filtered_band(rows[top : top + band], above, bpp)
    return out


def _filtered_band(
    rows: NDArray[np.uint8], above: NDArray[np.uint8], bpp: int
) -> NDArray[np.uint8]:
    x = rows.astype(np.int16)
    b = np.concatenate([above.astype(np.int16)[None], x[:-1]])  # the byte above
    a = np.zeros_like(x)  # the byte one pixel to the left
    a[:, bpp:] = x[:, :-bpp]
    c = np.zeros_like(x)  # the byte above and one pixel to the left
    c[:, bpp:] = b[:, :-bpp]
    p = a + b - c
    pa, pb, pc = np.abs(p - a), np.abs(p - b), np.abs(p - c)
    paeth = np.where((pa <= pb) & (pa <= pc), a, np.where(pb <= pc, b, c))
    candidates = [x, x - a, x - b, x - (a + b) // 2, x - paeth]
    costs = [np.abs(k.astype(np.uint8).view(np.int8).astype(np.int16)).sum(1) for k in candidates]
    best = np.argmin(np.stack(costs), axis=0)
    chosen = np.stack(candidates)[best, np.arange(rows.shape[0])].astype(np.uint8)
    return np.concatenate([best.astype(np.uint8)[:, None], chosen], axis=1)


def encode_png(image: NDArray[np.floating[Any]], bits: int = 8) -> bytes:
    """An (height, width), (height, width, 3) or (height, width, 4) float image in [0, 1] as
    the bytes of a grey, RGB or RGBA PNG of `bits` (8 or 16) bits per channel; values are
    clipped to [0, 1] and NaN becomes 0.

    Row 0 is the top of the picture, as in numpy's and every image viewer's convention.
    """
    if not (image.ndim == 2 or (image.ndim == 3 and image.shape[2] in (3, 4))):
        raise ValueError(
            "image must have shape (height, width), (height, width, 3) or (height, width, 4), "
            f"got {image.shape}"
        )
    height, width = image.shape[:2]
    if height == 0 or width == 0:
        raise ValueError(f"a PNG has at least one pixel; the image has shape {image.shape}")
    pixels = quantize(image, bits)
    channels = 1 if pixels.ndim == 2 else pixels.shape[2]
    # PNG stores 16-bit samples most significant byte first.
    raw = pixels.astype(">u2" if bits == 16 else np.uint8).view(np.uint8)
    rows = raw.reshape(height, width * channels * (bits // 8))
    data = _filtered(rows, channels * (bits // 8)).tobytes()
    header = struct.pack(">IIBBBBB", width, height, bits, _COLOUR_TYPE[channels], 0, 0, 0)
    png = b"\x89PNG\r\n\x1a\n" + _chunk(b"IHDR", header) + _chunk(b"IDAT", zlib.compress(data, 6))
    return png + _chunk(b"IEND", b"")
