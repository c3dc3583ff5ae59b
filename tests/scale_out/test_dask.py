"""glshade.dask's plumbing on dask's synchronous scheduler: results have `shade`'s dtype, values
and leading axis, inputs broadcast and take every keyword, options are checked when the graph is
built, graphs hold the scene once, .npy files are read and written in chunks, and `gs.shade`
given dask arrays is lazy."""

from __future__ import annotations

import pickle
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from conftest import require

import glshade as gs
from support.scale_out import SCENE, TWO_SIDED, write_vertices


def chunked(a: np.ndarray, rows: int) -> Any:
    import dask.array as da

    return da.from_array(a, chunks=(rows, *a.shape[1:]))


_ARRAYS = np.random.default_rng(11)  # its own seed: the arrays do not depend on test order
P64 = _ARRAYS.standard_normal((1000, 3)) + np.array([0, 0, -4.0])
N64 = _ARRAYS.standard_normal((1000, 3))
C64 = _ARRAYS.uniform(size=(1000, 4))


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


def test_dask_inputs_broadcast_and_take_every_keyword(gsd: Any, rng: np.random.Generator) -> None:
    image = rng.standard_normal((40, 30, 3)).astype(np.float32) + np.float32([0, 0, -5])
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


def test_dask_graphs_hold_the_scene_once(
    gsd: Any, tmp_path: Path, rng: np.random.Generator
) -> None:
    many = gs.Scene(lights=gs.Lights(position=rng.standard_normal((2000, 4))))
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
    gsd: Any, tmp_path: Path, rng: np.random.Generator
) -> None:
    stored = rng.standard_normal((1001, 3))
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
