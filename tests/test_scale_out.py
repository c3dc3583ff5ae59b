"""Beyond one call and one process: glshade.dask on a real dask.distributed cluster, and
multiprocessing pools with the fork and spawn start methods, over memory-mapped .npy files.

Every result is compared bit for bit with one local `gs.shade` call over the whole array:
glshade's result for a row does not depend on how the rows are split.
"""

from __future__ import annotations

import importlib
import json
import os
import pickle
import subprocess
import sys
import textwrap
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from conftest import require

import glshade as gs

VERTICES, CHUNK = 4_000_000, 500_000
SCENE = gs.Scene(
    lights=[
        gs.Light(position=(1, 2, 3, 1), quadratic_attenuation=0.05, specular=(0.6, 0.6, 0.6)),
        gs.Light(position=(-1, 1, 2, 1), spot_direction=(0.5, -0.4, -1), spot_cutoff=40,
                 spot_exponent=3, diffuse=(0.3, 0.5, 0.9)),
        gs.Light(position=(0, 0, 1, 0), diffuse=(0.2, 0.2, 0.3), specular=(0, 0, 0)),
    ],
    material=gs.Material(specular=(0.8, 0.8, 0.8), shininess=40),
    viewer=(0, 0, 0, 1),
)  # fmt: skip
TWO_SIDED = gs.Scene(
    lights=[gs.Light(position=(1, 2, 3, 1))],
    material=gs.Material(diffuse=(1, 0.2, 0.2), specular=(1, 1, 1), shininess=8),
    back_material=gs.Material(diffuse=(0.2, 0.2, 1)),
    two_side=True,
    separate_specular=True,
)


def write_vertices(folder: Path, count: int, seed: int = 7) -> tuple[Path, Path]:
    """positions.npy and normals.npy of `count` float32 rows, written through memory maps."""
    rng = np.random.default_rng(seed)
    paths = folder / "positions.npy", folder / "normals.npy"
    for path, shift in zip(paths, ((0, 0, -4), (0, 0, 0)), strict=True):
        mapped = np.lib.format.open_memmap(path, mode="w+", dtype=np.float32, shape=(count, 3))
        for start in range(0, count, 1 << 20):
            rows = min(1 << 20, count - start)
            mapped[start : start + rows] = rng.standard_normal((rows, 3), np.float32) + shift
        mapped.flush()
        del mapped
    return paths


@pytest.fixture(scope="module")
def data(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, Path, np.ndarray]:
    """The 4*10^6 vertices on disk, and one local gs.shade call over them."""
    positions, normals = write_vertices(tmp_path_factory.mktemp("scale_out"), VERTICES)
    expected = gs.shade(np.load(positions, mmap_mode="r"), np.load(normals, mmap_mode="r"), SCENE)
    assert expected.dtype == np.float32 and np.ptp(expected[:, :3]) > 0.5
    return positions, normals, expected


@pytest.fixture(scope="module")
def gsd() -> Any:
    """glshade.dask, which needs dask[array]."""
    require("dask.array")
    return importlib.import_module("glshade.dask")


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


POOL_SCRIPT = """
import multiprocessing, pickle, sys
import numpy as np, glshade as gs

def start(scene_bytes):
    global SCENE  # each worker unpickles the scene once
    SCENE = pickle.loads(scene_bytes)

def shade_rows(task):
    positions, normals, output, begin, end = task
    p = np.load(positions, mmap_mode="r")[begin:end]
    n = np.load(normals, mmap_mode="r")[begin:end]
    out = np.load(output, mmap_mode="r+")
    gs.shade(p, n, SCENE, out=out[begin:end])
    out.flush()
    return multiprocessing.current_process().pid

if __name__ == "__main__":
    method, positions, normals, output, count, chunk, scene_path = sys.argv[1:]
    count, chunk = int(count), int(chunk)
    np.lib.format.open_memmap(output, "w+", np.float32, (count, 4)).flush()
    tasks = [(positions, normals, output, b, min(b + chunk, count)) for b in range(0, count, chunk)]
    context = multiprocessing.get_context(method)
    gs.shade(np.zeros((1, 3)), (0, 0, 1), gs.Scene())  # the parent's thread pool exists
    with context.Pool(2, initializer=start, initargs=(open(scene_path, "rb").read(),)) as pool:
        pool.map(shade_rows, tasks)
"""


@pytest.mark.parametrize("method", ["fork", "spawn"])
def test_a_process_pool_shades_a_memmap_bit_identically_to_one_call(
    method: str, data: tuple[Path, Path, np.ndarray], tmp_path: Path
) -> None:
    positions, normals, expected = data
    script, scene, output = tmp_path / "pool.py", tmp_path / "scene.pickle", tmp_path / "out.npy"
    script.write_text(textwrap.dedent(POOL_SCRIPT))
    scene.write_bytes(pickle.dumps(SCENE))
    run = subprocess.run(
        [sys.executable, script, method, positions, normals, output, str(VERTICES), str(CHUNK),
         scene],
        capture_output=True, text=True, timeout=300,
    )  # fmt: skip
    assert run.returncode == 0, run.stderr
    np.testing.assert_array_equal(np.load(output, mmap_mode="r"), expected)


# --- glshade.dask's plumbing, on dask's synchronous scheduler ----------------------------------


def chunked(a: np.ndarray, rows: int) -> Any:
    import dask.array as da

    return da.from_array(a, chunks=(rows, *a.shape[1:]))


RNG = np.random.default_rng(11)
P64 = RNG.standard_normal((1000, 3)) + np.array([0, 0, -4.0])
N64 = RNG.standard_normal((1000, 3))
C64 = RNG.uniform(size=(1000, 4))


@pytest.mark.parametrize(
    ("p_dtype", "n_dtype", "expected"),
    [
        (np.float32, np.float32, np.float32),
        (np.float16, np.float32, np.float32),
        (np.float32, np.float64, np.float64),
        (np.float64, np.float64, np.float64),
        (np.int32, np.float32, np.float64),
    ],
)
def test_dask_results_have_shade_s_dtype_and_values(
    gsd: Any, p_dtype: Any, n_dtype: Any, expected: Any
) -> None:
    p, n = P64.astype(p_dtype), N64.astype(n_dtype)
    rgba = gsd.shade(chunked(p, 300), chunked(n, 300), SCENE)
    assert rgba.dtype == expected and rgba.shape == (1000, 4)
    assert rgba.chunks == ((300, 300, 300, 100), (4,))
    result = rgba.compute(scheduler="sync")
    assert result.dtype == expected
    np.testing.assert_array_equal(result, gs.shade(p, n, SCENE))


@pytest.mark.parametrize(
    ("scene", "leading"),
    [
        (gs.Scene(lights=[gs.Light()], two_side=True), 2),
        (gs.Scene(lights=[gs.Light()], separate_specular=True), 2),
        (TWO_SIDED, 4),
    ],
)
def test_dask_results_of_scenes_with_several_outputs_have_their_leading_axis(
    gsd: Any, scene: gs.Scene, leading: int
) -> None:
    rgba = gsd.shade(chunked(P64, 256), chunked(N64, 256), scene)
    assert rgba.shape == (leading, 1000, 4) and rgba.chunks[0] == (leading,)
    np.testing.assert_array_equal(rgba.compute(scheduler="sync"), gs.shade(P64, N64, scene))


def test_dask_inputs_broadcast_and_take_every_keyword(gsd: Any) -> None:
    image = RNG.standard_normal((40, 30, 3)).astype(np.float32) + np.float32([0, 0, -5])
    modelview = np.array([[1, 0, 0, 0.5], [0, 2, 0, 0], [0, 0, 1, -1], [0, 0, 0, 1.0]])
    kwargs: dict[str, Any] = {
        "modelview": modelview,
        "normalize": True,
        "color_material": "diffuse",
        "accuracy": "exact",
    }
    import dask.array as da

    lazy = gsd.shade(
        da.from_array(image, chunks=(16, 10, 3)),
        (0, 0.6, 0.8),  # one normal for every position
        SCENE,
        colors=da.from_array(C64[:30, :3], chunks=(7, 3)),  # one colour per column
        **kwargs,
    )
    assert lazy.shape == (40, 30, 4) and lazy.dtype == np.float64
    expected = gs.shade(image, (0, 0.6, 0.8), SCENE, colors=C64[:30, :3], **kwargs)
    np.testing.assert_array_equal(lazy.compute(scheduler="sync"), expected)


def test_dask_options_are_checked_when_the_graph_is_built(gsd: Any) -> None:
    p, n = chunked(P64, 100), chunked(N64, 100)
    with pytest.raises(ValueError, match="accuracy"):
        gsd.shade(p, n, SCENE, accuracy="precise")
    with pytest.raises(TypeError, match="normalize"):
        gsd.shade(p, n, SCENE, normalize=1)
    with pytest.raises(TypeError, match="scene"):
        gsd.shade(p, n, "scene")
    with pytest.raises(TypeError, match="out="):
        gsd.shade(p, n, SCENE, out=np.zeros((1000, 4)))
    with pytest.raises(ValueError, match="broadcast"):
        gsd.shade(p, chunked(N64[:10], 5), SCENE)
    with pytest.raises(ValueError, match=r"\(\.\.\., 3\)"):
        gsd.shade(p, chunked(N64[:, :2], 100), SCENE)
    with pytest.raises(ValueError, match="whole mesh"):
        gsd.shade_mesh(p, np.array([[0, 1, 2]]), scene=SCENE)
    with pytest.raises(ValueError, match="chunks"):
        gsd.shade_mesh(P64, np.array([[0, 1, 2]]), scene=SCENE, chunks=0)


def test_dask_graphs_hold_the_scene_once(gsd: Any, tmp_path: Path) -> None:
    many = gs.Scene(lights=gs.Lights(position=RNG.standard_normal((2000, 4))))
    positions, normals = write_vertices(tmp_path, 64_000)
    rgba = gsd.shade(gsd.from_npy(positions, 4000), gsd.from_npy(normals, 4000), many)
    assert rgba.numblocks == (16, 1)
    graph = pickle.dumps(dict(rgba.__dask_graph__()))
    # 16 tasks, one scene: the graph is the scene and a few hundred bytes per task.
    assert len(pickle.dumps(many)) < len(graph) < len(pickle.dumps(many)) + 16 * 2000
    expected = gs.shade(np.load(positions), np.load(normals), many)
    np.testing.assert_array_equal(rgba.compute(scheduler="sync"), expected)


def test_dask_shade_mesh_computes_normals_once_then_shades_in_chunks(gsd: Any) -> None:
    trimesh = require("trimesh")
    mesh = trimesh.creation.icosphere(4)
    rgba = gsd.shade_mesh(mesh, scene=SCENE, chunks=700, weighting="area")
    assert rgba.chunks[0][0] == 700 and rgba.dtype == np.float64
    expected = gs.shade_mesh(mesh, scene=SCENE, weighting="area")
    np.testing.assert_array_equal(rgba.compute(scheduler="sync"), expected)
    normals = gs.vertex_normals(mesh.vertices, mesh.faces)
    given = gsd.shade_mesh(chunked(np.asarray(mesh.vertices), 999), scene=SCENE, normals=normals)
    np.testing.assert_array_equal(given.compute(scheduler="sync"), gs.shade_mesh(mesh, scene=SCENE))


def test_from_npy_reads_chunks_on_the_workers_and_to_npy_writes_them(
    gsd: Any, tmp_path: Path
) -> None:
    stored = RNG.standard_normal((1001, 3))
    np.save(tmp_path / "a.npy", stored)
    lazy = gsd.from_npy(tmp_path / "a.npy", 250)
    assert lazy.chunks == ((250, 250, 250, 250, 1), (3,))
    assert len(pickle.dumps(dict(lazy.__dask_graph__()))) < 4000  # a path, not 24 kB of data
    written = gsd.to_npy(lazy * 2, tmp_path / "b.npy")
    np.testing.assert_array_equal(written, stored * 2)
    np.testing.assert_array_equal(np.load(tmp_path / "b.npy"), stored * 2)
    with pytest.raises(ValueError, match="chunks"):
        gsd.from_npy(tmp_path / "a.npy", -1)
    with pytest.raises(TypeError, match="dask array"):
        gsd.to_npy(stored, tmp_path / "c.npy")


def test_the_cluster_bench_runs_and_finds_the_outputs_bit_identical(
    gsd: Any, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    require("distributed")
    from glshade import __main__ as cli

    path = tmp_path / "cluster.json"
    args = ["bench", "cluster", "--vertices", "300000", "--chunk", "70000", "--repeat", "1"]
    assert cli.main([*args, "--json", str(path), "--dir", str(tmp_path)]) == 0
    out = capsys.readouterr().out
    assert "bit-identical to the local call's: True" in out and "Mvert/s" in out
    saved = json.loads(path.read_text())
    assert saved["bench"] == "cluster" and saved["results"]["bit_identical"] is True
    assert saved["settings"] == {"vertices": 300_000, "chunk": 70_000, "workers": 2, "repeat": 1}
    assert "cpu" in saved["machine"]
    assert list(tmp_path.iterdir()) == [path]  # the scratch files are gone


def test_gs_shade_given_dask_arrays_is_lazy_and_refuses_out(gsd: Any) -> None:
    lazy = gs.shade(chunked(P64.astype(np.float32), 300), np.float32([0, 0.6, 0.8]), TWO_SIDED)
    assert type(lazy).__module__.startswith("dask") and lazy.shape == (4, 1000, 4)
    assert lazy.dtype == np.float32 and lazy.chunks[1] == (300, 300, 300, 100)
    expected = gs.shade(P64.astype(np.float32), np.float32([0, 0.6, 0.8]), TWO_SIDED)
    np.testing.assert_array_equal(lazy.compute(scheduler="sync"), expected)
    with pytest.raises(TypeError, match="out="):
        gs.shade(chunked(P64, 300), N64, SCENE, out=np.zeros((1000, 4)))
    with pytest.raises(ValueError, match="accuracy"):
        gs.shade(P64, chunked(N64, 300), SCENE, accuracy="low")
