"""`shade_mesh`: flat (one colour per face) or smooth (one colour per vertex) shading of a mesh."""

from __future__ import annotations

from typing import Any, cast

import numpy as np
from numpy.typing import ArrayLike

from ._camera import Camera
from ._framing import default_scene, frame
from ._intake import matrix, one_of
from ._model import SCENES, is_scene
from ._normals import face_normals, vertex_normals
from ._render_input import is_pair
from ._scene import Scene
from ._scenes import AnyScene
from ._shade import shade
from ._trimesh import mesh_arrays
from ._typing import FloatArray, Per, Weighting

__all__ = ["shade_mesh"]


def shade_mesh(
    vertices: Any,
    faces: ArrayLike | None = None,
    *,
    scene: AnyScene | None = None,
    per: Per = "vertex",
    weighting: Weighting = "angle",
    **shade_kwargs: Any,
) -> FloatArray:
    """Light a triangle mesh per vertex (smooth shading) or per face (flat shading).

    Parameters
    ----------
    vertices : (n, 3) float32 or float64, or a mesh
        Vertex positions; or, when `faces` is omitted, an object with ``.vertices`` and
        ``.faces`` (a ``trimesh.Trimesh``) or a ``(vertices, faces)`` tuple.
    faces : (m, 3) int, any integer dtype
        Vertex indices of each triangle, counter-clockwise seen from the front.
    scene : Scene, gltf.Scene or threejs.Scene, optional
        What lights the mesh, in the coordinates it is shaded in (the mesh's own, or eye
        coordinates with a ``modelview``). None (the default): the default scene of `render`
        placed for this mesh: its key light and fill (directional, from the upper left and
        lower right of the view), its material, and a local viewer outside the mesh, at the
        eye of the camera `render` would frame it with (in front of, to the right of and
        above the mesh's bounds), so a mesh around the origin is seen from outside.
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
        For a bad `per` or `weighting`, wrong shapes or dtypes, or a bad `shade` keyword; a
        `Scene` given as `faces` (the scene is a keyword: ``shade_mesh(mesh, scene=scene)``).

    Examples
    --------
    >>> import numpy as np, glshade as gs
    >>> v = np.array([[0, 0, -2], [1, 0, -2], [0, 1, -2]], np.float64)
    >>> gs.shade_mesh(v, [[0, 1, 2]], scene=gs.Scene(lights=[gs.Light()]), per="face")
    array([[0.84, 0.84, 0.84, 1.  ]])
    >>> gs.shade_mesh(gs.meshes.icosphere(1)).shape  # the default scene
    (42, 4)
    """
    if is_scene(faces) or isinstance(faces, Camera):
        raise TypeError(
            f"shade_mesh got a {type(faces).__name__} as faces: the scene is a keyword "
            "argument, gs.shade_mesh(mesh, scene=scene) or gs.shade_mesh(vertices, faces, "
            "scene=scene)"
        )
    if scene is not None and not is_scene(scene):
        raise TypeError(
            f"scene must be {SCENES}, or None for the default lights, got {type(scene)!r}"
        )
    where = one_of(per, "per", ("vertex", "face"))
    weights = cast(Weighting, one_of(weighting, "weighting", ("angle", "area", "uniform")))
    if faces is None and is_pair(vertices):
        vertices, faces = vertices
    v, f = mesh_arrays(vertices, faces)
    if scene is None:
        scene = _placed_scene(v, shade_kwargs.get("modelview"))
    if where == "vertex":
        return shade(v, vertex_normals(v, f, weights), scene, **shade_kwargs)
    normals = face_normals(v, f)  # checks every index before the gather below
    corners = v.astype(np.float64)[f]
    centroids = ((corners[:, 0] + corners[:, 1] + corners[:, 2]) / 3.0).astype(v.dtype)
    return shade(centroids, normals, scene, **shade_kwargs)


def _placed_scene(v: FloatArray, modelview: Any) -> Scene:
    """The default scene with its viewer at the eye of the camera `render` would frame the
    vertices with, in the coordinates they are shaded in (moved by `modelview` if given)."""
    points = v.astype(np.float64)
    if modelview is not None:
        m = matrix(modelview, "modelview")
        points = points @ m[:3, :3].T + m[:3, 3]
    eye, _ = frame(points, 1.0)
    x, y, z = eye.tolist()
    return default_scene(viewer=(x, y, z, 1.0))
