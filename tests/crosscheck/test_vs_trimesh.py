"""Normals against trimesh, on a corpus built here: trimesh.creation primitives, jittered meshes,
duplicate vertices, degenerate faces and unreferenced vertices (all with process=False, so
trimesh keeps our vertex order).

- "angle" (default) and face normals: trimesh's `Trimesh.vertex_normals` / `.face_normals`.
- "uniform": `trimesh.geometry.mean_vertex_normals`.
- "area": a float64 transcription of Open3D's rule (sum of (v1 - v0) x (v2 - v0), normalised).
Tolerances: 1e-12 for float64 input, 1e-7 for float32 input: both compute in float64 from the
same float32 vertices, and glshade rounds the result to float32 once.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np
import pytest
from conftest import require

import glshade as gs

trimesh = require("trimesh")
require("scipy")  # trimesh's vertex normals use scipy.sparse

TOL = {np.float64: 1e-12, np.float32: 1e-7}


def jittered(mesh: Any, seed: int, amount: float = 0.05) -> tuple[np.ndarray, np.ndarray]:
    rng = np.random.default_rng(seed)
    return mesh.vertices + rng.normal(scale=amount, size=mesh.vertices.shape), mesh.faces


def with_duplicates(mesh: Any) -> tuple[np.ndarray, np.ndarray]:
    # Every corner its own vertex, plus the originals: seams everywhere.
    v = np.concatenate([mesh.vertices, mesh.vertices[mesh.faces].reshape(-1, 3)])
    f = np.concatenate([mesh.faces, len(mesh.vertices) + np.arange(mesh.faces.size).reshape(-1, 3)])
    return v, f


def with_degenerate_and_unreferenced(mesh: Any) -> tuple[np.ndarray, np.ndarray]:
    v = np.concatenate([mesh.vertices, [[9.0, 9.0, 9.0], [-9.0, 1.0, 2.0]]])
    n = len(mesh.vertices)
    mid = (mesh.vertices[0] + mesh.vertices[1]) / 2
    v = np.concatenate([v, [mid]])
    f = np.concatenate(
        [
            mesh.faces,
            [[0, 0, 1], [1, 1, 1], [0, 1, n + 2]],  # repeated index, a point, collinear corners
        ]
    )
    return v, f


CORPUS: dict[str, Callable[[], tuple[np.ndarray, np.ndarray]]] = {
    "icosphere": lambda: (lambda m: (m.vertices, m.faces))(
        trimesh.creation.icosphere(subdivisions=3)
    ),
    "box": lambda: (lambda m: (m.vertices, m.faces))(trimesh.creation.box(extents=(1, 2, 3))),
    "cylinder": lambda: (lambda m: (m.vertices, m.faces))(
        trimesh.creation.cylinder(radius=0.5, height=2, sections=24)
    ),
    "capsule": lambda: (lambda m: (m.vertices, m.faces))(
        trimesh.creation.capsule(height=1.5, radius=0.4)
    ),
    "torus": lambda: (lambda m: (m.vertices, m.faces))(
        trimesh.creation.torus(major_radius=1, minor_radius=0.3)
    ),
    "annulus": lambda: (lambda m: (m.vertices, m.faces))(
        trimesh.creation.annulus(r_min=0.5, r_max=1, height=0.3)
    ),
    "jittered icosphere": lambda: jittered(trimesh.creation.icosphere(subdivisions=2), 1),
    "jittered torus": lambda: jittered(
        trimesh.creation.torus(major_radius=2, minor_radius=0.5), 2, 0.1
    ),
    "jittered box": lambda: jittered(trimesh.creation.box(), 3, 0.02),
    "duplicated vertices": lambda: with_duplicates(trimesh.creation.icosphere(subdivisions=1)),
    "degenerate and unreferenced": lambda: with_degenerate_and_unreferenced(
        trimesh.creation.icosphere(subdivisions=2)
    ),
    "random soup": lambda: (
        np.random.default_rng(4).normal(size=(300, 3)),
        np.random.default_rng(5).integers(0, 300, (500, 3)),
    ),
}

DTYPES = pytest.mark.parametrize("dtype", [np.float64, np.float32], ids=["f64", "f32"])
MESHES = pytest.mark.parametrize("name", list(CORPUS))


def case(name: str, dtype: Any) -> tuple[np.ndarray, np.ndarray, Any]:
    v, f = CORPUS[name]()
    v = np.asarray(v).astype(dtype)
    reference = trimesh.Trimesh(vertices=v.astype(np.float64), faces=f, process=False)
    assert len(reference.vertices) == len(v)
    return v, np.asarray(f), reference


@DTYPES
@MESHES
def test_face_normals_match_trimesh(name: str, dtype: Any) -> None:
    v, f, mesh = case(name, dtype)
    got = gs.face_normals(v, f)
    assert got.dtype == dtype and got.shape == (len(f), 3)
    np.testing.assert_allclose(got, mesh.face_normals, rtol=0, atol=TOL[dtype])


@DTYPES
@MESHES
def test_angle_weighting_matches_trimesh(name: str, dtype: Any) -> None:
    v, f, mesh = case(name, dtype)
    got = gs.vertex_normals(v, f)
    assert got.dtype == dtype and got.shape == v.shape
    np.testing.assert_allclose(got, mesh.vertex_normals, rtol=0, atol=TOL[dtype])


@DTYPES
@MESHES
def test_uniform_weighting_matches_mean_vertex_normals(name: str, dtype: Any) -> None:
    v, f, mesh = case(name, dtype)
    expected = trimesh.geometry.mean_vertex_normals(len(v), f, mesh.face_normals)
    np.testing.assert_allclose(
        gs.vertex_normals(v, f, "uniform"), expected, rtol=0, atol=TOL[dtype]
    )


def area_weighted_reference(v: np.ndarray, f: np.ndarray) -> np.ndarray:
    """Open3D's ComputeVertexNormals in float64: sum the raw cross products, normalise."""
    v = v.astype(np.float64)
    cross = np.cross(v[f[:, 1]] - v[f[:, 0]], v[f[:, 2]] - v[f[:, 0]])
    summed = np.zeros_like(v)
    for corner in range(3):
        np.add.at(summed, f[:, corner], cross)
    length = np.linalg.norm(summed, axis=1, keepdims=True)
    return np.divide(summed, length, out=np.zeros_like(summed), where=length > 0)


@DTYPES
@MESHES
def test_area_weighting_matches_the_transcription(name: str, dtype: Any) -> None:
    v, f, _ = case(name, dtype)
    expected = area_weighted_reference(v, f)
    np.testing.assert_allclose(gs.vertex_normals(v, f, "area"), expected, rtol=0, atol=TOL[dtype])


def test_the_icosahedron_truth_is_its_positions() -> None:
    # Every vertex of the centred icosahedron has five identical faces around it.
    mesh = trimesh.creation.icosphere(subdivisions=0)
    truth = mesh.vertices / np.linalg.norm(mesh.vertices, axis=1, keepdims=True)
    np.testing.assert_allclose(gs.vertex_normals(mesh.vertices, mesh.faces), truth, atol=1e-15)


def test_a_trimesh_object_is_accepted_directly() -> None:
    mesh = trimesh.creation.capsule()
    np.testing.assert_array_equal(
        gs.vertex_normals(mesh), gs.vertex_normals(mesh.vertices, mesh.faces)
    )
    np.testing.assert_array_equal(gs.face_normals(mesh), gs.face_normals(mesh.vertices, mesh.faces))


def test_tiny_triangles_differ_from_trimesh_as_documented() -> None:
    # Legs of 1e-7: |cross| = 1e-14 is under trimesh's absolute 1e-13, so trimesh calls the face
    # degenerate; glshade's test is relative to the edge lengths and keeps its normal.
    v = np.array([[0, 0, 0], [1e-7, 0, 0], [0, 1e-7, 0]], np.float64)
    f = np.array([[0, 1, 2]])
    assert np.array_equal(trimesh.Trimesh(v, f, process=False).face_normals, [[0, 0, 0]])
    assert np.array_equal(gs.face_normals(v, f), [[0, 0, 1]])
