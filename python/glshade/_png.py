"""A dependency-free PNG writer for RGBA float images (8 bits per channel)."""

from __future__ import annotations

import struct
import zlib
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import NDArray


def _chunk(kind: bytes, data: bytes) -> bytes:
    body = kind + data
    return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)


def encode_png(image: NDArray[np.floating[Any]]) -> bytes:
    """An (height, width, 4) float image in [0, 1] as the bytes of an 8-bit RGBA PNG; values are
    clipped to [0, 1] and NaN becomes 0.

    Row 0 is the top of the picture, as in numpy's and every image viewer's convention.
    """
    if image.ndim != 3 or image.shape[2] != 4:
        raise ValueError(f"image must have shape (height, width, 4), got {image.shape}")
    pixels = np.round(np.nan_to_num(np.clip(image, 0.0, 1.0)) * 255).astype(np.uint8)
    height, width, _ = pixels.shape
    raw = b"".join(b"\x00" + pixels[y].tobytes() for y in range(height))
    header = struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)
    png = b"\x89PNG\r\n\x1a\n" + _chunk(b"IHDR", header) + _chunk(b"IDAT", zlib.compress(raw, 6))
    return png + _chunk(b"IEND", b"")


def write_png(path: str | Path, image: NDArray[np.floating[Any]]) -> Path:
    """Writes an (height, width, 4) float image as an 8-bit RGBA PNG (see `encode_png`)."""
    path = Path(path)
    path.write_bytes(encode_png(image))
    return path
