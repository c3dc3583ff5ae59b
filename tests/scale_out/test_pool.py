"""multiprocessing pools with the fork and spawn start methods (tests/scripts/pool_shade.py):
each worker shades its chunks of memory-mapped .npy files into a memory-mapped output, bit for
bit one local `gs.shade` call over the whole array."""

from __future__ import annotations

import pickle
from pathlib import Path

import numpy as np
import pytest

from support.processes import passes
from support.scale_out import CHUNK, SCENE, VERTICES

pytestmark = pytest.mark.subprocess


@pytest.mark.parametrize("method", ["fork", "spawn"])
def test_a_process_pool_shades_a_memmap_bit_identically_to_one_call(
    method: str, data: tuple[Path, Path, np.ndarray], tmp_path: Path
) -> None:
    positions, normals, expected = data
    scene, output = tmp_path / "scene.pickle", tmp_path / "out.npy"
    scene.write_bytes(pickle.dumps(SCENE))
    args = [method, positions, normals, output, VERTICES, CHUNK, scene]
    passes("pool_shade", *map(str, args), timeout=300)
    np.testing.assert_array_equal(np.load(output, mmap_mode="r"), expected)
