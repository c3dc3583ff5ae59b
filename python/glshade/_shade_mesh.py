"""`shade_mesh`: flat (one colour per face) or smooth (one colour per vertex) shading of a mesh."""

from __future__ import annotations

from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from ._normals import face_normals, vertex_normals
from ._scene import Scene
from ._shade import shade
from ._trimesh import mesh_arrays
from ._typing import FloatArray, Per, Weighting

__all__ = ["shade_mesh"]


def shade_mesh(
    vertices: Any,
    faces: ArrayLike | None = None,
    *,
    scene: Scene,
    per: Per = "vertex",
    weighting: Weighting = "angle",
    **shade_kwargs: Any,
) -> FloatArray:
    """Light a triangle mesh per vertex (smooth shading) or per face (flat shading).

    Parameters
    ----------
    vertices : (n, 3) float32 or float64, or a mesh
        Vertex positions; or an object with ``.vertices`` and ``.faces`` (a ``trimesh.Trimesh``)
        when `faces` is omitted.
    faces : (m, 3) int, any integer dtype
        Vertex indices of each triangle, counter-clockwise seen from the front.
    scene : Scene
        What lights the mesh.
    per : {"vertex", "face"}
        ``"vertex"``: each vertex is lit at its position with its `vertex_normals` (the colours
        a Gouraud rasteriser interpolates). ``"face"``: each triangle is lit once, at its
        centroid ``(v0 + v1 + v2) / 3`` with its `face_normals` (flat shading); a degenerate
        face has the zero normal, so it gets the emission and ambient terms only.
    weighting : {"angle", "area", "uniform"}
        How `vertex_normals` weights the faces (``per="vertex"`` only).
    **shade_kwargs
        Any keyword of `shade` (``modelview``, ``normalize``, ``colors``, ``out``...). With
        ``per="face"``, ``colors`` and ``out`` have one row per face.

    Returns
    -------
    (n, 4) or (m, 4) ndarray, or (k, n, 4) / (k, m, 4) for scenes with several outputs
        RGBA per vertex or per face, in the vertices' dtype, as `shade` returns it.

    Raises
    ------
    IndexError
        For a face index out of range, naming the face.
    ValueError, TypeError
        For a bad `per` or `weighting`, wrong shapes or dtypes, or a bad `shade` keyword.

    Examples
    --------
    >>> import numpy as np, glshade as gs
    >>> v = np.array([[0, 0, -2], [1, 0, -2], [0, 1, -2]], np.float64)
    >>> gs.shade_mesh(v, [[0, 1, 2]], scene=gs.Scene(lights=[gs.Light()]), per="face")
    array([[0.84, 0.84, 0.84, 1.  ]])
    """
    if not isinstance(scene, Scene):
        raise TypeError(f"scene must be a glshade.Scene, got {type(scene)!r}")
    if per not in ("vertex", "face"):
        raise ValueError(f"per must be 'vertex' or 'face', got {per!r}")
    if weighting not in ("angle", "area", "uniform"):
        raise ValueError(f"weighting must be 'angle', 'area' or 'uniform', got {weighting!r}")
    v, f = mesh_arrays(vertices, faces)
    if per == "vertex":
        return shade(v, vertex_normals(v, f, weighting), scene, **shade_kwargs)
    normals = face_normals(v, f)  # checks every index before the gather below
    corners = v.astype(np.float64)[f]
    centroids = ((corners[:, 0] + corners[:, 1] + corners[:, 2]) / 3.0).astype(v.dtype)
    return shade(centroids, normals, scene, **shade_kwargs)
