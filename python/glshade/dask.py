"""glshade beyond one machine: `shade` over dask arrays, lazily, chunk by chunk.

Each chunk of rows is shaded by one `glshade.shade` call on whichever worker holds it, so a
dask.distributed cluster shades arrays larger than one machine's memory, and the result is
bit-identical to one `glshade.shade` call over the whole array (glshade's results do not depend
on how rows are split). The scene and the keywords are one key of the graph: a worker receives
them once, not with every chunk.

`from_npy` and `to_npy` read and write ``.npy`` files chunk by chunk on the workers, so that
nothing of the file travels with the graph (``da.from_array(np.load(path, mmap_mode="r"))``
pickles the whole array into it).

Needs ``pip install 'glshade[dask]'`` (dask[array] and distributed).

>>> import numpy as np, dask.array as da, glshade as gs, glshade.dask
>>> scene = gs.Scene(lights=[gs.Light(position=(0, 0, 1, 0))])
>>> positions = da.zeros((10, 3), dtype=np.float32, chunks=4)
>>> rgba = glshade.dask.shade(positions, np.float32([0, 0, 1]), scene)
>>> rgba.dtype, rgba.shape, rgba.chunks
(dtype('float32'), (10, 4), ((4, 4, 2), (4,)))
>>> rgba.compute()[0]
array([0.84000003, 0.84000003, 0.84000003, 1.        ], dtype=float32)
"""

from __future__ import annotations

import os
import sys
from pathlib import Path
from typing import Any, cast

import numpy as np
from numpy.typing import ArrayLike, NDArray

try:
    import dask.array as da
except ImportError as error:  # pragma: no cover - exercised without dask installed
    raise ImportError(
        "glshade.dask needs dask: pip install 'glshade[dask]' (dask[array] and distributed)"
    ) from error

from ._intake import integer
from ._lazy import shade_lazily
from ._normals import vertex_normals
from ._scene import Scene
from ._shade import shade as shade_in_memory
from ._typing import Weighting

__all__ = ["from_npy", "shade", "shade_mesh", "to_npy"]


def shade(
    positions: ArrayLike | da.Array,
    normals: ArrayLike | da.Array,
    scene: Scene,
    *,
    colors: ArrayLike | da.Array | None = None,
    **shade_kwargs: Any,
) -> da.Array:
    """`glshade.shade` over dask arrays: a lazy dask array of RGBA, one task per chunk of rows.

    Parameters
    ----------
    positions, normals : (..., 3) dask arrays or array-likes
        As `glshade.shade` takes them, broadcast against each other over the leading axes; an
        input that is not a dask array becomes one chunk (``normals=(0, 0, 1)`` serves every
        position). Chunks of different inputs are aligned by dask; the last axis is made one
        chunk.
    scene : Scene
        What lights the vertices; sent to each worker once.
    colors : (..., 3) or (..., 4) dask array or array-like, optional
        Per-vertex colours for ``GL_COLOR_MATERIAL``, chunked like the positions.
    **shade_kwargs
        Any keyword of `glshade.shade` but ``out`` (``modelview``, ``normalize``,
        ``color_material``, ``accuracy``...). They are checked now, not when the graph runs.

    Returns
    -------
    (..., 4) or (k, ..., 4) dask array of the computation dtype
        As `glshade.shade` returns it: float32 when positions and normals are float32 (or
        float16), float64 otherwise; with a leading axis of the ``k`` colours named by
        ``scene.outputs`` for two-sided or separate-specular scenes (one chunk along it). The
        leading axes are chunked like the inputs, the channel axis is one chunk of 4.

    Raises
    ------
    TypeError, ValueError
        As `glshade.shade` raises them, at once: the options are tried on an empty chunk.
    """
    if "out" in shade_kwargs:
        raise TypeError(
            "glshade.dask.shade does not take out=: store the result with glshade.dask.to_npy, "
            "dask.array.store or dask.array.to_zarr"
        )
    return shade_lazily(shade_in_memory, positions, normals, scene, colors, shade_kwargs)


def shade_mesh(
    vertices: Any,
    faces: ArrayLike | None = None,
    *,
    scene: Scene,
    normals: ArrayLike | da.Array | None = None,
    weighting: Weighting = "angle",
    chunks: int = 500_000,
    **shade_kwargs: Any,
) -> da.Array:
    """`glshade.shade_mesh` per vertex over dask: normals once, then shading in chunks of rows.

    Vertex normals need the whole mesh (each is a sum over the faces around it), so they are
    computed once, here, with `glshade.vertex_normals`; or given as `normals` (a dask array of
    them, say) when the vertices are a dask array.

    Parameters
    ----------
    vertices : (n, 3) array-like or dask array, or a mesh
        Vertex positions; or an object with ``.vertices`` and ``.faces`` (a ``trimesh.Trimesh``)
        when `faces` is omitted.
    faces : (m, 3) int, optional
        Vertex indices of each triangle; needed when `normals` is not given.
    scene : Scene
        What lights the mesh.
    normals : (n, 3) array-like or dask array, optional
        The vertex normals, when already known; required when `vertices` is a dask array.
    weighting : {"angle", "area", "uniform"}
        How `glshade.vertex_normals` weights the faces.
    chunks : int
        Rows per chunk for vertices that are not already a dask array.
    **shade_kwargs
        Any keyword of `glshade.shade` but ``out``.

    Returns
    -------
    (n, 4) or (k, n, 4) dask array
        As `shade` returns it.
    """
    if faces is None and hasattr(vertices, "vertices") and hasattr(vertices, "faces"):
        vertices, faces = vertices.vertices, vertices.faces
    if normals is None:
        if isinstance(vertices, da.Array):
            raise ValueError(
                "vertex normals need the whole mesh: compute them once with "
                "gs.vertex_normals(vertices, faces) and pass them as normals="
            )
        if faces is None:
            raise TypeError("shade_mesh needs faces (or a mesh with .faces) when normals is None")
        normals = vertex_normals(vertices, faces, weighting=weighting)
    rows = integer(chunks, "chunks", 1, sys.maxsize)
    if not isinstance(vertices, da.Array):
        vertices = da.from_array(np.asarray(vertices), chunks=(rows, -1))
    if not isinstance(normals, da.Array):
        normals = da.from_array(np.asarray(normals), chunks=vertices.chunks)
    return shade(vertices, normals, scene, **shade_kwargs)


def from_npy(path: str | os.PathLike[str], chunks: int = 500_000) -> da.Array:
    """A dask array over a ``.npy`` file whose chunks of rows are read by the tasks that need
    them (``np.load(path, mmap_mode="r")`` on the worker): the graph holds the path, not data.

    Parameters
    ----------
    path : str or PathLike
        A ``.npy`` file that every worker can read at this path.
    chunks : int
        Rows per chunk (the first axis); the other axes are one chunk.

    Returns
    -------
    dask array
        Of the file's shape and dtype.
    """
    path = os.fspath(path)
    header = np.load(path, mmap_mode="r")  # reads only the header and maps the file
    shape, dtype = header.shape, header.dtype
    del header
    rows = integer(chunks, "chunks", 1, sys.maxsize)
    if len(shape) == 0:
        raise ValueError(f"{path} holds a 0-d array; from_npy chunks along the first axis")
    # A blockwise layer of its own, so that dask fuses each read into the task that uses it.
    return da.map_blocks(
        _read_rows,
        _NpyFile(path, shape, dtype),
        chunks=da.core.normalize_chunks((rows, *shape[1:]), shape),
        dtype=dtype,
        meta=np.zeros((0,) * len(shape), dtype),
    )


def to_npy(array: da.Array, path: str | os.PathLike[str]) -> NDArray[Any]:
    """Computes a dask array into a ``.npy`` file, each task writing its own chunk.

    The file is created here (header and size), then written in place by the tasks, so the
    result never passes through this process. Every worker must see the file at `path`.

    Parameters
    ----------
    array : dask array
        What to compute.
    path : str or PathLike
        The ``.npy`` file to create (replaced if it exists).

    Returns
    -------
    np.memmap
        The written file, mapped read-only.
    """
    if not isinstance(array, da.Array):
        raise TypeError(f"array must be a dask array, got {type(array)!r}")
    path = os.fspath(path)
    np.lib.format.open_memmap(path, mode="w+", dtype=array.dtype, shape=array.shape).flush()
    target = _NpyFile(path, array.shape, array.dtype)
    da.store(array, cast(Any, target), lock=False, compute=True)  # dask takes any __setitem__
    mapped: NDArray[Any] = np.load(path, mmap_mode="r")
    return mapped


def _read_rows(file: _NpyFile, block_info: dict[Any, Any] | None = None) -> NDArray[Any]:
    """One task: the rows of one chunk of a ``.npy`` file, mapped, not copied."""
    assert block_info is not None  # dask passes it to functions that take it
    (start, stop), *_ = block_info[None]["array-location"]
    rows: NDArray[Any] = np.load(file.path, mmap_mode="r")[start:stop]
    return rows


class _NpyFile:
    """A ``.npy`` file as tasks read and write it: it pickles as its path, and each access maps
    the file in whichever process makes it."""

    def __init__(self, path: str, shape: tuple[int, ...], dtype: np.dtype[Any]) -> None:
        self.path, self.shape, self.dtype, self.ndim = (
            path,
            tuple(shape),
            np.dtype(dtype),
            len(shape),
        )

    def __setitem__(self, key: Any, value: NDArray[Any]) -> None:
        # No flush: other processes see the pages at once, and the kernel writes them back.
        np.load(self.path, mmap_mode="r+")[key] = value

    def __dask_tokenize__(self) -> tuple[Any, ...]:
        # The file's identity and version, so that a rewritten file gets new keys.
        stat = os.stat(self.path)
        return (self.path, stat.st_mtime_ns, stat.st_size, self.shape, str(self.dtype))

    def __repr__(self) -> str:
        return f"_NpyFile({Path(self.path).name!r}, {self.shape}, {self.dtype})"
