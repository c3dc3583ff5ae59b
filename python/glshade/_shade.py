"""`shade_arrays`: the OpenGL lighting equation over arrays of vertices in memory, one native
call. `glshade.shade` (`_dispatch`) hands dask collections to `glshade.dask`, which shades each
chunk with this."""

from __future__ import annotations

from numpy.typing import ArrayLike

from . import _glshade
from ._intake import choice, flag, matrix, optional_choice, out_array, vertices
from ._scene import Scene
from ._typing import Accuracy, ColorMaterialMode, Face, FloatArray

__all__ = ["shade_arrays"]


def shade_arrays(
    positions: ArrayLike,
    normals: ArrayLike,
    scene: Scene,
    *,
    modelview: ArrayLike | None = None,
    normalize: bool = False,
    rescale_normal: bool = False,
    colors: ArrayLike | None = None,
    color_material: ColorMaterialMode | None = None,
    color_material_face: Face = "front_and_back",
    accuracy: Accuracy = "fast",
    strict: bool = False,
    out: FloatArray | None = None,
) -> FloatArray:
    """`glshade.shade` of arrays in memory (numpy arrays or anything numpy reads)."""
    if not isinstance(scene, Scene):
        raise TypeError(f"scene must be a glshade.Scene, got {type(scene)!r}")
    p, n, c = vertices(positions, normals, colors)
    if c is not None:
        color_material = color_material or "ambient_and_diffuse"
    if out is not None:
        out = out_array(out, {"positions": p, "normals": n, "colors": c})
    result: FloatArray = _glshade.shade(
        p,
        n,
        scene._native,
        modelview=None if modelview is None else matrix(modelview, "modelview"),
        normalize=flag(normalize, "normalize"),
        rescale_normal=flag(rescale_normal, "rescale_normal"),
        colors=c,
        color_material=optional_choice(color_material, "color_material"),
        color_material_face=choice(color_material_face, "color_material_face"),
        accuracy=choice(accuracy, "accuracy"),
        strict=flag(strict, "strict"),
        out=out,
    )
    return result
