"""Shading dask collections lazily, chunk by chunk, with a shading function the caller passes:
`glshade.shade` (for dask inputs) and `glshade.dask.shade` both come here with the in-memory
`shade`, so this module imports neither of them and no import cycle forms."""

from __future__ import annotations

import string
from collections.abc import Callable, Mapping
from typing import Any

import dask.array as da
import numpy as np
from dask.delayed import delayed
from numpy.typing import ArrayLike, NDArray

from ._intake import accuracy_choice
from ._scenes import AnyScene

__all__ = ["shade_lazily"]

ShadeFunction = Callable[..., NDArray[Any]]


def shade_lazily(
    shade: ShadeFunction,
    positions: ArrayLike | da.Array,
    normals: ArrayLike | da.Array,
    scene: AnyScene,
    colors: ArrayLike | da.Array | None,
    shade_kwargs: Mapping[str, Any],
) -> da.Array:
    """`shade` (glshade's in-memory `shade`) over dask arrays: a lazy dask array of RGBA, one
    task per chunk of rows; see `glshade.dask.shade`, which documents the arguments. The
    options are tried at once on an empty chunk, so a bad one raises here, not in a task."""
    inputs = [_dask_array(positions, "positions"), _dask_array(normals, "normals")]
    if colors is not None:
        inputs.append(_dask_array(colors, "colors"))
    try:
        leading = np.broadcast_shapes(*(x.shape[:-1] for x in inputs))
    except ValueError:
        shapes = ", ".join(f"{name} {x.shape}" for name, x in zip(_NAMES, inputs, strict=False))
        raise ValueError(f"shapes do not broadcast over their leading axes: {shapes}") from None
    if "accuracy" in shade_kwargs:
        # The deprecated "display" warns once, at the caller's line, not in every task.
        shade_kwargs = {**shade_kwargs, "accuracy": accuracy_choice(shade_kwargs["accuracy"])}
    # One empty call checks every option now and gives the result's dtype and leading axis.
    empty = [np.zeros((0, x.shape[-1]), x.dtype) for x in inputs]
    empty_colors = empty[2] if colors is not None else None
    probe = shade(empty[0], empty[1], scene, colors=empty_colors, **shade_kwargs)
    outputs = probe.shape[0] if probe.ndim == 3 else None
    axes = string.ascii_lowercase[: len(leading)]
    arguments: list[Any] = []
    for x, last in zip(inputs, "ccz", strict=False):
        x = da.broadcast_to(x, (*leading, x.shape[-1])).rechunk({len(leading): -1})
        arguments += [x, (*axes, last)]
    # One key for the scene and keywords: every task refers to it; each worker fetches it once.
    call = delayed((shade, scene, shade_kwargs), pure=True)
    index = ("k", *axes, "c") if outputs else (*axes, "c")
    new_axes = {"k": outputs} if outputs else {}
    return da.blockwise(
        _shade_chunk,
        index,
        *arguments,
        call,
        None,
        new_axes=new_axes,
        adjust_chunks={"c": 4},
        dtype=probe.dtype,
        meta=np.zeros((0,) * len(index), probe.dtype),
        concatenate=True,
    )


_NAMES = ("positions", "normals", "colors")


def _dask_array(x: Any, name: str) -> da.Array:
    """`x` as a dask array of at least one axis (its last axis is checked by the probe call)."""
    array = x if isinstance(x, da.Array) else da.from_array(np.asarray(x))
    if array.ndim == 0:
        raise ValueError(f"{name} must have shape (..., 3), got shape ()")
    return array


def _shade_chunk(*arguments: Any) -> NDArray[Any]:
    """One task: `glshade.shade` over one chunk of rows."""
    *arrays, (shade, scene, shade_kwargs) = arguments
    colors = arrays[2] if len(arrays) == 3 else None
    result: NDArray[Any] = shade(arrays[0], arrays[1], scene, colors=colors, **shade_kwargs)
    return result
