"""Built-in meshes: (vertices, faces) pairs of float64 (n, 3) and int64 (m, 3) arrays, numpy only
(no trimesh), for examples, tests, the demo, the benchmarks and the studies."""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

Mesh = tuple[NDArray[np.float64], NDArray[np.int64]]


def icosphere(subdivisions: int) -> Mesh:
    """A unit sphere of 20 * 4**subdivisions triangles: an icosahedron whose faces are split in
    four, `subdivisions` times, with the new vertices pushed onto the sphere (trimesh's
    ``creation.icosphere``). Faces are counter-clockwise seen from outside.

    Parameters
    ----------
    subdivisions : int
        How many times each face is split in four, >= 0 (0: the icosahedron).

    Returns
    -------
    vertices : (n, 3) float64 ndarray
        Points on the unit sphere.
    faces : (20 * 4**subdivisions, 3) int64 ndarray
        Vertex indices of each triangle.
    """
    t = (1.0 + 5.0**0.5) / 2.0
    vertices = np.array(
        [
            [-1, t, 0],
            [1, t, 0],
            [-1, -t, 0],
            [1, -t, 0],
            [0, -1, t],
            [0, 1, t],
            [0, -1, -t],
            [0, 1, -t],
            [t, 0, -1],
            [t, 0, 1],
            [-t, 0, -1],
            [-t, 0, 1],
        ],
        dtype=np.float64,
    )
    faces = np.array(
        [
            [0, 11, 5], [0, 5, 1], [0, 1, 7], [0, 7, 10], [0, 10, 11],
            [1, 5, 9], [5, 11, 4], [11, 10, 2], [10, 7, 6], [7, 1, 8],
            [3, 9, 4], [3, 4, 2], [3, 2, 6], [3, 6, 8], [3, 8, 9],
            [4, 9, 5], [2, 4, 11], [6, 2, 10], [8, 6, 7], [9, 8, 1],
        ],
        dtype=np.int64,
    )  # fmt: skip
    vertices /= np.linalg.norm(vertices, axis=1, keepdims=True)
    for _ in range(subdivisions):
        # One midpoint per edge: edge k of face i is (faces[i, k], faces[i, (k + 1) % 3]).
        edges = np.sort(np.stack([faces, np.roll(faces, -1, axis=1)], axis=2).reshape(-1, 2))
        unique, inverse = np.unique(edges, axis=0, return_inverse=True)
        middle = vertices[unique].mean(axis=1)
        middle /= np.linalg.norm(middle, axis=1, keepdims=True)
        m = (inverse.reshape(-1, 3) + len(vertices)).astype(np.int64)
        a, b, c = faces.T
        ab, bc, ca = m.T
        faces = np.concatenate(
            [
                np.stack([a, ab, ca], axis=1),
                np.stack([b, bc, ab], axis=1),
                np.stack([c, ca, bc], axis=1),
                np.stack([ab, bc, ca], axis=1),
            ]
        )
        vertices = np.concatenate([vertices, middle])
    return vertices, faces


def torus(rings: int, sides: int, major: float = 1.0, minor: float = 0.4) -> Mesh:
    """A torus around the z axis of 2 * rings * sides triangles: `rings` segments around the
    axis, `sides` around the tube, radii `major` and `minor`. Faces are counter-clockwise seen
    from outside.

    Parameters
    ----------
    rings : int
        The number of segments around the z axis.
    sides : int
        The number of segments around the tube.
    major : float
        The distance from the z axis to the centre of the tube.
    minor : float
        The radius of the tube.

    Returns
    -------
    vertices : (rings * sides, 3) float64 ndarray
        The torus's points.
    faces : (2 * rings * sides, 3) int64 ndarray
        Vertex indices of each triangle.
    """
    u = np.linspace(0.0, 2 * np.pi, rings, endpoint=False)
    v = np.linspace(0.0, 2 * np.pi, sides, endpoint=False)
    uu, vv = np.meshgrid(u, v, indexing="ij")
    radius = major + minor * np.cos(vv)
    vertices = np.stack(
        [radius * np.cos(uu), radius * np.sin(uu), minor * np.sin(vv)], axis=-1
    ).reshape(-1, 3)
    i, j = np.meshgrid(np.arange(rings), np.arange(sides), indexing="ij")
    a = i * sides + j
    b = ((i + 1) % rings) * sides + j
    c = ((i + 1) % rings) * sides + (j + 1) % sides
    d = i * sides + (j + 1) % sides
    faces = np.concatenate(
        [np.stack([a, b, c], -1).reshape(-1, 3), np.stack([a, c, d], -1).reshape(-1, 3)]
    )
    return vertices, faces.astype(np.int64)


def grid(faces: int, seed: int = 0) -> Mesh:
    """A bumpy, jittered height-field mesh over the unit square: the first `faces` triangles of a
    k x k grid of quads (k = ceil(sqrt(faces / 2))), vertices jittered by a seeded generator.

    Parameters
    ----------
    faces : int
        The number of triangles.
    seed : int
        The seed of the generator that jitters the vertices: one seed, one mesh.

    Returns
    -------
    vertices : ((k + 1)**2, 3) float64 ndarray
        The grid's points, jittered.
    faces : (faces, 3) int64 ndarray
        Vertex indices of each triangle.
    """
    k = int(np.ceil(np.sqrt(faces / 2)))
    rng = np.random.default_rng(seed)
    x, y = np.meshgrid(np.linspace(0, 1, k + 1), np.linspace(0, 1, k + 1))
    z = 0.1 * np.sin(12 * x) * np.cos(9 * y)
    vertices = np.stack([x, y, z], axis=-1).reshape(-1, 3)
    vertices += rng.normal(scale=0.2 / k, size=vertices.shape)
    i, j = np.meshgrid(np.arange(k), np.arange(k))
    a = (j * (k + 1) + i).ravel()
    b, c, d = a + 1, a + k + 1, a + k + 2
    tris = np.concatenate([np.stack([a, b, d], axis=1), np.stack([a, d, c], axis=1)])
    return vertices, tris[:faces].astype(np.int64)
