"""`out=`: a wrong dtype, byte order, shape, layout or alignment is refused naming out, as is an
out sharing memory with an input (also through another base or a file mapped twice)."""

from __future__ import annotations

import mmap
from pathlib import Path
from typing import Any

import numpy as np
import pytest

import glshade as gs
from support.boundary import LIT, SUN, UP, misaligned, rows


@pytest.mark.parametrize(
    ("make", "exception", "words"),
    [
        (lambda: np.zeros((10, 4), np.float32), TypeError, ["out", "float64", "float32"]),
        (lambda: np.zeros((10, 4), ">f8"), TypeError, ["out", "native byte order"]),
        (lambda: np.zeros((11, 4)), ValueError, ["out", "(10, 4)", "(11, 4)"]),
        (lambda: np.zeros((10, 4), order="F"), ValueError, ["out", "C-contiguous"]),
        (lambda: np.zeros((10, 8))[:, ::2], ValueError, ["out", "C-contiguous"]),
        (lambda: misaligned(np.zeros((10, 4))), ValueError, ["out", "aligned"]),
        (lambda: [[0.0] * 4] * 10, TypeError, ["out", "numpy array"]),
    ],
)
def test_a_wrong_out_is_refused_naming_out(
    make: Any, exception: type, words: list[str], rng: np.random.Generator
) -> None:
    out = make()
    p, n = rows(rng, 10)
    with pytest.raises(exception) as info:
        gs.shade(p, n, SUN, out=out)
    for word in words:
        assert word in str(info.value)


def test_a_readonly_out_is_refused(rng: np.random.Generator) -> None:
    out = np.zeros((10, 4))
    out.flags.writeable = False
    with pytest.raises(ValueError, match="out must be writeable"):
        gs.shade(*rows(rng, 10), SUN, out=out)


def test_out_overlapping_an_input_through_another_base_is_refused() -> None:
    buffer = bytearray(8 * 4 * 16)
    out = np.frombuffer(buffer, np.float64).reshape(16, 4)
    positions = np.frombuffer(buffer, np.float64)[: 16 * 3].reshape(16, 3)
    assert out.base is not positions.base
    with pytest.raises(ValueError, match="out and positions share memory"):
        gs.shade(positions, UP, SUN, out=out)
    normals = np.frombuffer(buffer, np.float64)[16:].reshape(-1, 3)[:16]
    with pytest.raises(ValueError, match="out and normals share memory"):
        gs.shade(np.zeros((16, 3)), normals, SUN, out=out)


def test_out_in_a_file_mapped_twice_is_refused(tmp_path: Path) -> None:
    path = tmp_path / "data.bin"
    np.zeros((8, 4)).tofile(path)
    out = np.memmap(path, np.float64, "r+", shape=(8, 4))
    normals = np.memmap(path, np.float64, "r", shape=(8, 3))
    assert not np.may_share_memory(out, normals)
    with pytest.raises(ValueError, match="out and normals"):
        gs.shade(np.zeros((8, 3)), normals, SUN, out=out)
    with open(path, "r+b") as f, mmap.mmap(f.fileno(), 0) as mapped:
        view = np.frombuffer(mapped, np.float64)[:24].reshape(8, 3)
        with pytest.raises(ValueError, match="out and positions"):
            gs.shade(view, UP, SUN, out=out)
        del view


def test_out_in_a_separate_file_is_accepted(tmp_path: Path) -> None:
    np.zeros((8, 4)).tofile(tmp_path / "out.bin")
    UP.repeat(8, 0).tofile(tmp_path / "n.bin")
    out = np.memmap(tmp_path / "out.bin", np.float64, "r+", shape=(8, 4))
    normals = np.memmap(tmp_path / "n.bin", np.float64, "r", shape=(8, 3))
    assert gs.shade(np.zeros((8, 3)), normals, SUN, out=out) is out
    np.testing.assert_allclose(out[:, 0], LIT)
