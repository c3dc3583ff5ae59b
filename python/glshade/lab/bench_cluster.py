"""``python -m glshade bench cluster``: a dask.distributed LocalCluster shading float32 vertices
from memory-mapped .npy files into another, beside one local `gs.shade` call over the same data.

Both read the positions and normals from the files and write RGBA into a file: the local call
through ``np.load(mmap_mode="r")`` and ``out=`` a mapped output, the cluster through
`glshade.dask.from_npy` and `glshade.dask.to_npy`, its workers reading and writing their own
chunks. Rounds alternate the two, so that both meet the same page cache and the same load on
the machine; the outputs are compared bit for bit.
"""

from __future__ import annotations

import tempfile
import time
from pathlib import Path
from typing import Any

import numpy as np

import glshade as gs

from .bench import save
from .machine import describe, machine
from .scenes import bench_scenes
from .timing import time_rounds


def write_inputs(folder: Path, vertices: int, seed: int = 0) -> tuple[Path, Path]:
    """positions.npy (a unit sphere's points at z = -3, jittered) and normals.npy, float32,
    written 2**22 rows at a time so that memory stays small."""
    rng = np.random.default_rng(seed)
    paths = folder / "positions.npy", folder / "normals.npy"
    p = np.lib.format.open_memmap(paths[0], "w+", np.float32, (vertices, 3))
    n = np.lib.format.open_memmap(paths[1], "w+", np.float32, (vertices, 3))
    for start in range(0, vertices, 1 << 22):
        rows = min(1 << 22, vertices - start)
        normal = rng.standard_normal((rows, 3), np.float32)
        normal /= np.linalg.norm(normal, axis=1, keepdims=True)
        n[start : start + rows] = normal
        p[start : start + rows] = normal + rng.normal(0, 0.01, (rows, 3)).astype(np.float32)
        p[start : start + rows, 2] -= 3
    p.flush()
    n.flush()
    return paths


def bench_cluster(
    vertices: int,
    chunk: int,
    workers: int,
    repeat: int,
    json_path: str | None = None,
    folder: str | None = None,
) -> int:
    """Prints (and saves at `json_path`) the median time and Mvert/s of one local `gs.shade`
    call and of `glshade.dask` on a LocalCluster of `workers` processes, memmap to memmap, with
    the scratch files in `folder` (default: the system's temporary directory)."""
    try:
        import distributed

        import glshade.dask as gsd
    except ImportError as error:
        print(f"{error}: pip install 'glshade[dask]'")
        return 1
    scene = bench_scenes()["8 mixed"]
    with tempfile.TemporaryDirectory(dir=folder, prefix="glshade-cluster-") as scratch:
        where = Path(scratch)
        start = time.perf_counter()
        positions, normals = write_inputs(where, vertices)
        took = time.perf_counter() - start
        print(f"wrote {vertices:,} float32 positions and normals in {took:.1f} s")
        local_out, cluster_out = where / "rgba-local.npy", where / "rgba-cluster.npy"
        rgba = np.lib.format.open_memmap(local_out, "w+", np.float32, (vertices, 4))

        def local() -> None:
            p, n = np.load(positions, mmap_mode="r"), np.load(normals, mmap_mode="r")
            gs.shade(p, n, scene, out=rgba)

        # One thread per worker and one for its glshade calls: the cluster uses as many cores
        # as it has workers, and the local call all of them.
        with (
            distributed.LocalCluster(
                n_workers=workers,
                threads_per_worker=1,
                processes=True,
                dashboard_address=":0",
                silence_logs=40,
                env={"RAYON_NUM_THREADS": "1"},
            ) as cluster,
            distributed.Client(cluster),
        ):

            def on_cluster() -> None:
                p, n = gsd.from_npy(positions, chunk), gsd.from_npy(normals, chunk)
                gsd.to_npy(gsd.shade(p, n, scene), cluster_out)

            methods = {"one gs.shade call": local, f"glshade.dask, {workers} workers": on_cluster}
            times = time_rounds(methods, repeat)
        same = all(
            np.array_equal(a, b)
            for a, b in zip(
                _chunks(np.load(local_out, mmap_mode="r")),
                _chunks(np.load(cluster_out, mmap_mode="r")),
                strict=True,
            )
        )
    print(f"\n{describe(machine())}")
    print(f"8 mixed lights; {vertices:,} float32 vertices from .npy memmaps into a .npy memmap")
    print(f"LocalCluster: {workers} worker processes x 1 thread, chunks of {chunk:,} rows\n")
    print(f"  {'':30} {'median':>9} {'fastest-slowest':>17} {'Mvert/s':>9}")
    results: dict[str, Any] = {}
    for name, timing in times.items():
        speed = vertices / timing.median / 1e6
        print(
            f"  {name:30} {timing.median:8.2f}s {timing.low:7.2f}-{timing.high:.2f} s {speed:9.1f}"
        )
        results[name] = {**timing.as_dict(), "mvert_s": speed}
    print(f"\ncluster output bit-identical to the local call's: {same}")
    results["bit_identical"] = same
    settings = {"vertices": vertices, "chunk": chunk, "workers": workers, "repeat": repeat}
    save(json_path, "cluster", settings, results)
    return 0 if same else 1


def _chunks(array: np.ndarray, rows: int = 1 << 22) -> list[np.ndarray]:
    return [array[i : i + rows] for i in range(0, len(array), rows)]
