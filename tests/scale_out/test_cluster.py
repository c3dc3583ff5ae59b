"""glshade.dask on a real dask.distributed cluster (two worker processes): a memory-mapped .npy
shaded chunk by chunk on the workers is bit for bit one local `gs.shade` call over the whole
array, also for scenes with several outputs."""

from __future__ import annotations

import os
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from conftest import require

import glshade as gs
from support.scale_out import CHUNK, SCENE, TWO_SIDED, VERTICES

pytestmark = pytest.mark.cluster


@pytest.fixture(scope="module")
def client() -> Iterator[Any]:
    distributed = require("distributed")
    with (
        distributed.LocalCluster(
            n_workers=2,
            threads_per_worker=1,
            processes=True,
            dashboard_address=":0",
            silence_logs=40,
        ) as cluster,
        distributed.Client(cluster) as client,
    ):
        yield client


def test_a_local_cluster_shades_a_memmap_bit_identically_to_one_call(
    client: Any, gsd: Any, data: tuple[Path, Path, np.ndarray], tmp_path: Path
) -> None:
    positions, normals, expected = data
    p, n = gsd.from_npy(positions, CHUNK), gsd.from_npy(normals, CHUNK)
    assert p.chunks == ((CHUNK,) * (VERTICES // CHUNK), (3,))
    rgba = gsd.shade(p, n, SCENE)
    assert rgba.dtype == np.float32 and rgba.chunks[0] == p.chunks[0]
    written = gsd.to_npy(rgba, tmp_path / "rgba.npy")  # the workers write their own chunks
    np.testing.assert_array_equal(written, expected)
    workers = set(client.run(os.getpid).values())
    assert len(workers) == 2 and os.getpid() not in workers


def test_a_local_cluster_gives_the_leading_axis_of_two_sided_scenes(
    client: Any, gsd: Any, data: tuple[Path, Path, np.ndarray]
) -> None:
    positions, normals, _ = data
    p, n = np.load(positions, mmap_mode="r")[:200_000], np.load(normals, mmap_mode="r")[:200_000]
    import dask.array as da

    rgba = gsd.shade(da.from_array(p, chunks=30_000), da.from_array(n, chunks=30_000), TWO_SIDED)
    assert rgba.shape == (4, 200_000, 4) and rgba.chunks[0] == (4,)
    np.testing.assert_array_equal(client.compute(rgba).result(), gs.shade(p, n, TWO_SIDED))
