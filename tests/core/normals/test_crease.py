"""`crease_normals` against a float64 transcription of three.js's toCreasedNormals rule (with
glshade's weightings, vertices by index), written here; and the shapes the issue names: a cube
gives 24 corner normals, a sphere trimesh's smooth normals, a cylinder a sharp rim at 30
degrees; and `render` taking per-corner normals."""

from __future__ import annotations

import numpy as np
import pytest
from conftest import require

import glshade as gs

CUBE_V = np.array([[i & 1, (i >> 1) & 1, (i >> 2) & 1] for i in range(8)], np.float64)
CUBE_F = np.array(
    [[0, 2, 1], [1, 2, 3], [4, 5, 6], [5, 7, 6], [0, 1, 4], [1, 5, 4],
     [2, 6, 3], [3, 6, 7], [0, 4, 2], [2, 4, 6], [1, 3, 5], [3, 7, 5]]
)  # fmt: skip


def transcription(v: np.ndarray, f: np.ndarray, angle: float, weighting: str) -> np.ndarray:
    """Per corner (face g, corner i at vertex w): normalize(sum over faces h at w with
    n_g . n_h > cos(angle) of h's term at w), terms as `vertex_normals` weighs them."""
    v = v.astype(np.float64)
    a, b, c = (v[f[:, i]] for i in range(3))
    cross = np.cross(b - a, c - b)
    length = np.linalg.norm(cross, axis=1)
    unit = np.divide(cross, length[:, None], out=np.zeros_like(cross), where=length[:, None] > 0)
    corners = np.stack([a, b, c], axis=1)
    if weighting == "angle":
        e1 = np.roll(corners, -1, axis=1) - corners
        e2 = np.roll(corners, 1, axis=1) - corners
        cos = np.einsum("fij,fij->fi", e1, e2) / (
            np.linalg.norm(e1, axis=2) * np.linalg.norm(e2, axis=2)
        )
        weights = np.arccos(np.clip(cos, -1, 1))
        weights[length == 0] = 0
        terms = unit[:, None, :] * weights[:, :, None]
    elif weighting == "area":
        terms = np.repeat(cross[:, None, :], 3, axis=1)
    else:
        terms = np.repeat(unit[:, None, :], 3, axis=1)
    around: dict[int, list[tuple[int, int]]] = {}
    for g, face in enumerate(f):
        for i, w in enumerate(face):
            around.setdefault(int(w), []).append((g, i))
    limit = np.cos(np.radians(angle))
    out = np.zeros((len(f), 3, 3))
    for g, face in enumerate(f):
        for i, w in enumerate(face):
            total = np.zeros(3)
            for h, j in around[int(w)]:
                if h == g or unit[g] @ unit[h] > limit:  # its own face always
                    total += terms[h, j]
            norm = np.linalg.norm(total)
            out[g, i] = total / norm if norm > 0 else 0
    return out


@pytest.mark.parametrize("weighting", ["angle", "area", "uniform"])
@pytest.mark.parametrize("angle", [0.0, 10.0, 30.0, 60.0, 120.0, 180.0])
def test_agrees_with_the_transcription(weighting: str, angle: float) -> None:
    rng = np.random.default_rng(int(angle))
    v, f = gs.meshes.icosphere(2)
    v = v * rng.uniform(0.7, 1.3, (len(v), 1))  # bumps: some edges sharp, some smooth
    got = gs.crease_normals(v, f, angle=angle, weighting=weighting)
    np.testing.assert_allclose(got, transcription(v, f, angle, weighting), rtol=0, atol=1e-12)
    got32 = gs.crease_normals(v.astype(np.float32), f, angle=angle, weighting=weighting)
    assert got32.dtype == np.float32 and got32.shape == (len(f), 3, 3)


def test_a_cube_gives_24_corner_normals() -> None:
    n = gs.crease_normals(CUBE_V, CUBE_F, angle=30)
    pairs = {(int(w), *np.round(n[g, i], 12)) for g, face in enumerate(CUBE_F) for i, w in
             enumerate(face)}  # fmt: skip
    assert len(pairs) == 24
    faces = gs.face_normals(CUBE_V, CUBE_F)
    np.testing.assert_array_equal(n, np.repeat(faces[:, None, :], 3, axis=1))


def test_a_sphere_gives_trimeshs_smooth_normals() -> None:
    trimesh = require("trimesh")
    sphere = trimesh.creation.icosphere(subdivisions=3)
    n = gs.crease_normals(sphere, angle=30)
    smooth = np.asarray(sphere.vertex_normals)[sphere.faces]
    np.testing.assert_allclose(n, smooth, rtol=0, atol=1e-12)


def test_a_cylinder_keeps_its_rim_sharp_at_30_degrees() -> None:
    trimesh = require("trimesh")
    cylinder = trimesh.creation.cylinder(radius=1.0, height=2.0, sections=32)
    n = gs.crease_normals(cylinder, angle=30)
    faces = gs.face_normals(cylinder)
    cap = np.abs(faces[:, 2]) > 0.999
    side = np.abs(faces[:, 2]) < 1e-9
    assert cap.sum() > 0 and side.sum() > 0 and (cap | side).all()
    # Cap corners: the cap's own normal, rim vertices too.
    np.testing.assert_allclose(n[cap], np.repeat(faces[cap, None, :], 3, axis=1), atol=1e-12)
    # Side corners: horizontal, the radial direction of their vertex (32 sections: 11.25
    # degrees between neighbours, smoothed over).
    corners = cylinder.vertices[cylinder.faces[side]]
    radial = corners * (1, 1, 0)
    radial /= np.linalg.norm(radial, axis=2, keepdims=True)
    np.testing.assert_allclose(n[side], radial, atol=1e-12)
    assert not np.allclose(gs.crease_normals(cylinder, angle=5)[side], radial, atol=1e-3)


def test_180_degrees_is_vertex_normals() -> None:
    v, f = gs.meshes.torus(24, 12, 1.0, 0.4)
    np.testing.assert_allclose(
        gs.crease_normals(v, f, angle=180), gs.vertex_normals(v, f)[f], rtol=0, atol=1e-15
    )


@pytest.mark.parametrize("angle", [-1.0, 180.5, float("nan")])
def test_bad_angles_name_themselves(angle: float) -> None:
    with pytest.raises(ValueError, match=r"angle must be in \[0, 180\] degrees"):
        gs.crease_normals(CUBE_V, CUBE_F, angle=angle)


@pytest.mark.parametrize("shading", ["phong", "gouraud"])
def test_render_takes_per_corner_normals(shading: str) -> None:
    creased = gs.crease_normals(CUBE_V, CUBE_F, angle=30)
    camera = gs.Camera.look_at((2.5, 2.0, 3.0), (0.5, 0.5, 0.5), (0, 1, 0))
    ours = gs.render(CUBE_V, CUBE_F, None, camera, width=40, height=32, normals=creased,
                     shading=shading)  # fmt: skip
    split_v = CUBE_V[CUBE_F].reshape(-1, 3)
    split_f = np.arange(len(split_v)).reshape(-1, 3)
    by_hand = gs.render(split_v, split_f, None, camera, width=40, height=32,
                        normals=creased.reshape(-1, 3), shading=shading)  # fmt: skip
    np.testing.assert_array_equal(ours, by_hand)
    with pytest.raises(ValueError, match="per-corner normals"):
        gs.render(CUBE_V, CUBE_F, None, camera, width=8, height=8, normals=creased,
                  shading="flat")  # fmt: skip
