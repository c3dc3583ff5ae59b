"""Face, vertex and corner (creased) normals of triangle meshes."""

from __future__ import annotations

from typing import Any

from numpy.typing import ArrayLike

from . import _glshade
from ._intake import number, one_of
from ._trimesh import mesh_arrays
from ._typing import FloatArray, Weighting

__all__ = ["crease_normals", "face_normals", "vertex_normals"]


def face_normals(vertices: Any, faces: ArrayLike | None = None) -> FloatArray:
    """Unit normals of the faces of a triangle mesh.

    Parameters
    ----------
    vertices : (n, 3) float32 or float64, or a mesh
        Vertex positions; or an object with ``.vertices`` and ``.faces`` (a ``trimesh.Trimesh``)
        when `faces` is omitted.
    faces : (m, 3) int, any integer dtype
        Vertex indices of each triangle, counter-clockwise seen from the front.

    Returns
    -------
    (m, 3) ndarray of the vertices' dtype
        ``normalize((v1 - v0) x (v2 - v1))`` per face, trimesh's formula (bit for bit for
        float64; float32 vertices are computed in float64 and rounded once), or (0, 0, 0) for a
        degenerate face: one whose first two edges make an angle with ``|sin| <= 8 eps`` of the
        dtype, so that at its precision the cross product is rounding noise.

    Raises
    ------
    IndexError
        For an index that is negative or not below the vertex count, naming the face.
    ValueError, TypeError
        For wrong shapes or dtypes.
    """
    v, f = mesh_arrays(vertices, faces)
    result: FloatArray = _glshade.face_normals(v, f)
    return result


def vertex_normals(
    vertices: Any, faces: ArrayLike | None = None, weighting: Weighting = "angle"
) -> FloatArray:
    """Unit normals of the vertices of a triangle mesh, from the normals of their faces.

    Parameters
    ----------
    vertices : (n, 3) float32 or float64, or a mesh
        Vertex positions; or an object with ``.vertices`` and ``.faces`` (a ``trimesh.Trimesh``)
        when `faces` is omitted.
    faces : (m, 3) int, any integer dtype
        Vertex indices of each triangle.
    weighting : {"angle", "area", "uniform"}
        ``"angle"`` sums the unit face normals weighted by the corner angle at the vertex
        (trimesh's ``Trimesh.vertex_normals``); ``"area"`` sums the unnormalised cross products,
        i.e. weights by area (Open3D's ``compute_vertex_normals``); ``"uniform"`` sums the unit
        face normals (``trimesh.geometry.mean_vertex_normals``). Any case (``"Area"``).

    Returns
    -------
    (n, 3) ndarray of the vertices' dtype
        Unit normals; (0, 0, 0) for a vertex no face uses, whose faces are all degenerate, or
        whose contributions cancel. Geometry and sums run in float64 (float32 vertices too,
        rounded once at the end), summed in face order, so the result does not depend on the
        number of threads.

    Raises
    ------
    IndexError
        For an index that is negative or not below the vertex count, naming the face.
    ValueError, TypeError
        For wrong shapes or dtypes, or an unknown `weighting`.

    Examples
    --------
    >>> import numpy as np, glshade as gs
    >>> v = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0]], np.float32)
    >>> gs.vertex_normals(v, [[0, 1, 2]])
    array([[0., 0., 1.],
           [0., 0., 1.],
           [0., 0., 1.]], dtype=float32)
    """
    weights = one_of(weighting, "weighting", ("angle", "area", "uniform"))
    v, f = mesh_arrays(vertices, faces)
    result: FloatArray = _glshade.vertex_normals(v, f, weights)
    return result


def crease_normals(
    vertices: Any,
    faces: ArrayLike | None = None,
    angle: float = 30.0,
    weighting: Weighting = "angle",
) -> FloatArray:
    """Normals with creases: one per face corner, smooth across edges flatter than `angle` and
    split at sharper ones, as three.js's ``toCreasedNormals`` and Blender's auto smooth make
    them.

    The corner of face f at vertex v gets the normalised sum, under `weighting`, of the faces g
    around v whose unit normals satisfy ``n_f . n_g > cos(angle)`` (three.js's rule, read from
    examples/jsm/utils/BufferGeometryUtils.js; three.js sums unit normals, ``"uniform"``).
    Blender splits by sharp edges instead, which gives the same normals on meshes whose sharp
    edges close around every vertex (a cube, a cylinder's rim).

    Parameters
    ----------
    vertices : (n, 3) float32 or float64, or a mesh
        Vertex positions; or an object with ``.vertices`` and ``.faces`` when `faces` is
        omitted. Vertices are identified by index (three.js merges them by position: merge a
        mesh first, trimesh's ``merge_vertices``, if its faces do not share vertices).
    faces : (m, 3) int, any integer dtype
        Vertex indices of each triangle.
    angle : float
        Degrees, in [0, 180]: the largest angle between face normals that is smoothed over
        (Blender's default auto smooth angle, 30, by default; three.js's default is 60). 180
        gives `vertex_normals` at every corner; 0 gives every face its own normal.
    weighting : {"angle", "area", "uniform"}
        As for `vertex_normals`.

    Returns
    -------
    (m, 3, 3) ndarray of the vertices' dtype
        ``normals[f, i]`` is the normal of corner i of face f; (0, 0, 0) where no face joins
        (the corners of a degenerate face, below 90 degrees) or the sum cancels. `render` takes
        such per-corner normals as they are.

    Raises
    ------
    IndexError
        For an index that is negative or not below the vertex count, naming the face.
    ValueError, TypeError
        For wrong shapes or dtypes, an unknown `weighting`, or an `angle` outside [0, 180].

    Examples
    --------
    >>> import glshade as gs
    >>> v, f = gs.meshes.icosphere(1)
    >>> gs.crease_normals(v, f, angle=30).shape
    (80, 3, 3)
    """
    weights = one_of(weighting, "weighting", ("angle", "area", "uniform"))
    v, f = mesh_arrays(vertices, faces)
    result: FloatArray = _glshade.crease_normals(v, f, weights, number(angle, "angle"))
    return result
