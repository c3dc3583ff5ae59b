"""`shade`: the OpenGL lighting equation over arrays of vertices, one native call; dask
collections go to `_lazy`, which shades them chunk by chunk with this same function."""

from __future__ import annotations

import functools
from collections.abc import Callable
from typing import ParamSpec, TypeVar, cast

from numpy.typing import ArrayLike

from . import _glshade
from ._intake import accuracy_choice, flag, out_array, vertices
from ._model import SCENES, is_scene
from ._scenes import AnyScene
from ._transfer import Transfer, transfer_in_place, transfer_name
from ._typing import Accuracy, ColorMaterialMode, Face, FloatArray

__all__ = ["shade"]

_P = ParamSpec("_P")
_R = TypeVar("_R")


def _names_missing_normals(function: Callable[_P, _R]) -> Callable[_P, _R]:
    """`function` (`shade`) saying that the normals are missing when it is called as
    ``shade(positions, scene)``, where Python would say the scene is."""

    @functools.wraps(function)
    def checked(*args: _P.args, **kwargs: _P.kwargs) -> _R:
        if len(args) == 2 and is_scene(args[1]) and "scene" not in kwargs:
            raise TypeError(
                "shade() is missing its normals: the call is gs.shade(positions, normals, "
                "scene), and the second argument was the Scene. Give one normal per position, "
                "or one for all, e.g. gs.shade(positions, (0, 0, 1), scene); "
                "gs.vertex_normals(vertices, faces) computes a mesh's, and gs.shade_mesh(mesh) "
                "lights a mesh with them"
            )
        return function(*args, **kwargs)

    return checked


@_names_missing_normals
def shade(
    positions: ArrayLike,
    normals: ArrayLike,
    scene: AnyScene,
    *,
    modelview: ArrayLike | None = None,
    normalize: bool = False,
    rescale_normal: bool = False,
    colors: ArrayLike | None = None,
    color_material: ColorMaterialMode | None = None,
    color_material_face: Face = "front_and_back",
    accuracy: Accuracy = "fast",
    strict: bool = False,
    clamp: bool = True,
    transfer: Transfer | None = None,
    out: FloatArray | None = None,
) -> FloatArray:
    """Light vertices with OpenGL's fixed-function lighting equation (GL 2.1 section 2.14.1).

    Parameters
    ----------
    positions : (..., 3) array-like
        Vertex positions, in model coordinates (eye coordinates when `modelview` is None).
    normals : (..., 3) array-like
        Vertex normals; positions, normals and colours broadcast against each other (one normal
        for every position, say), and their common leading shape is the result's. Used as
        given, as in GL: a non-unit normal scales the diffuse and specular terms unless
        `normalize` is set.
    scene : Scene, gltf.Scene or threejs.Scene
        Lights (in eye coordinates), materials and light model. A `glshade.gltf.Scene` lights
        the vertices with glTF's metallic-roughness model as pyrender does instead (world
        coordinates, normals always normalised, `colors` multiplying the result, float64
        arithmetic whatever the dtype); a `glshade.threejs.Scene` with three.js'
        ``MeshPhongMaterial`` (the same, `colors` multiplying the material's colour). The
        options of the GL model (`modelview`, `normalize`, `rescale_normal`, `color_material`,
        `color_material_face`, `strict`) then do not apply and raise `TypeError` if set.
    modelview : (4, 4) float, optional
        An affine modelview matrix M (row-major, as numpy prints it): positions become
        ``M @ (p, 1)``, normals ``inv(M[:3, :3]).T @ n`` (GL's normal matrix).
    normalize : bool
        ``GL_NORMALIZE``: scale the transformed normals to unit length.
    rescale_normal : bool
        ``GL_RESCALE_NORMAL``: scale the transformed normals by M's rescale factor.
    colors : (..., 3) or (..., 4) array-like, optional
        Per-vertex colours for ``GL_COLOR_MATERIAL`` (a missing alpha is 1): numbers, uint8
        divided by 255, no colour names.
    color_material : {None, "ambient", "diffuse", "specular", "emission", "ambient_and_diffuse"}
        The material parameter(s) the colours replace; None (the default) stands for
        ``"ambient_and_diffuse"`` (GL's) when `colors` is given. Names of options, here and
        below, are case-insensitive.
    color_material_face : {"front_and_back", "front", "back"}
        The material(s) the colours replace (GL's default: both).
    accuracy : {"fast", "exact"}
        ``"fast"`` (default) computes in the input's precision; ``"exact"`` computes in float64
        whatever the input and rounds the result once to its dtype. The documentation's
        Accuracy page (docs/pages/guide/accuracy.md) states the error bound of each.
        ``"display"``, the removed display tier's name, is a deprecated alias of ``"fast"``: it
        warns (`DeprecationWarning`) and computes exactly what ``"fast"`` does.
    strict : bool
        Reject what GL rejects but glshade allows: shininess and spot exponents above 128.
    clamp : bool
        GL's clamp of every output colour to [0, 1] (the default). False returns the sums as
        they are, for high dynamic range: values above 1 where the terms add up beyond it,
        the primary and the secondary colour each unclamped with ``separate_specular``; the
        same values as with the clamp wherever those lie inside [0, 1], and NaN rows as with it.
    transfer : {None, "linear", "srgb", "gamma2.2"}
        The encoding of the RGB of the result, as `render` takes it: None and ``"linear"``
        return the lighting sums as they are (linear light); ``"srgb"`` encodes them with
        sRGB's curve (`srgb_encode`: three.js' sRGB output, what a PNG viewer expects);
        ``"gamma2.2"`` raises them to 1/2.2 (pyrender's output). Alpha is never encoded.
    out : ndarray, optional
        The array to write the result into: exactly the result's dtype and shape, C-contiguous,
        aligned, writeable, and sharing no memory with an input.

    Returns
    -------
    (..., 4) or (k, ..., 4) ndarray of the computation dtype (a dask array for dask inputs)
        RGBA clamped to [0, 1]. With ``scene.two_side`` or ``scene.separate_specular`` (or a
        double-sided ``threejs.MeshPhongMaterial``) the result has a leading axis of the ``k``
        colours named by ``scene.outputs`` (front and back; primary and secondary; or all
        four). A vertex whose position, normal or colour
        is NaN or infinite gets NaN; no other vertex is affected.

    Notes
    -----
    When `positions`, `normals` or `colors` is a dask array, the call is `glshade.dask.shade`:
    lazy, one task per chunk of rows, and ``out`` is refused.

    The computation runs in float32 when `positions` and `normals` are float32 (or float16)
    and in float64 otherwise (float64, integers, bools, Python sequences); any memory layout
    is accepted (see the intake table of the documentation's Arrays and dtypes page,
    docs/pages/guide/arrays.md). Vertices are shaded in parallel with the GIL
    released; the result does not depend on the number of threads. Ctrl-C stops a long call
    within a fraction of a second; `out` then holds some rows shaded and others as they were.

    Raises
    ------
    TypeError
        For complex, string or object arrays, a non-string name or a non-bool flag; colours
        given by name (``colors="red"``); a call without normals, ``shade(positions, scene)``,
        which says so.
    ValueError
        For wrong shapes, shapes that do not broadcast, unknown names, a bad `out` or one that
        shares memory with an input, or a singular, projective or non-finite `modelview`.
    MemoryError
        When the result cannot be allocated.

    Examples
    --------
    >>> import numpy as np, glshade as gs
    >>> scene = gs.Scene(lights=[gs.Light(position=(0, 0, 1, 0))])
    >>> gs.shade(np.zeros((1, 3)), np.array([[0, 0, 1.0]]), scene)
    array([[0.84, 0.84, 0.84, 1.  ]])
    >>> gs.shade(np.zeros((480, 640, 3), np.float32), (0, 0, 1), scene).shape  # one normal for all
    (480, 640, 4)
    """
    if not is_scene(scene):
        raise TypeError(f"scene must be {SCENES}, got {type(scene)!r}")
    encoding = transfer_name("linear" if transfer is None else transfer)
    # Before the dask branch, so a lazy call warns once, here, and its tasks get "fast".
    mode = accuracy_choice(accuracy)
    if any(_is_dask(x) for x in (positions, normals, colors)):
        from ._lazy import shade_lazily

        if out is not None:
            raise TypeError(
                "out= cannot take a lazy result: store a dask result with "
                "glshade.dask.to_npy or dask.array.store"
            )
        options = {
            "modelview": modelview, "normalize": normalize, "rescale_normal": rescale_normal,
            "color_material": color_material, "color_material_face": color_material_face,
            "accuracy": mode, "strict": strict, "clamp": clamp, "transfer": transfer,
        }  # fmt: skip
        lazy = shade_lazily(shade, positions, normals, scene, colors, options)
        return cast(FloatArray, lazy)  # a dask array, which quacks like the ndarray it computes
    p, n, c = vertices(positions, normals, colors)
    gl_options = {
        "modelview": (modelview, None), "normalize": (normalize, False),
        "rescale_normal": (rescale_normal, False), "color_material": (color_material, None),
        "color_material_face": (color_material_face, "front_and_back"),
        "strict": (strict, False),
    }  # fmt: skip
    gl = scene._gl_options(gl_options, colors=c is not None)
    if out is not None:
        out = out_array(out, {"positions": p, "normals": n, "colors": c})
    result: FloatArray = _glshade.shade(
        p, n, scene._native, colors=c, accuracy=mode, clamp=flag(clamp, "clamp"), out=out, **gl
    )
    transfer_in_place(result, encoding)
    return result


def _is_dask(x: object) -> bool:
    """A dask collection, told without importing dask."""
    return hasattr(x, "__dask_graph__") and type(x).__module__.startswith("dask")
