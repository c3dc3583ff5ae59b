"""Where pyrender's pixels come from, computed independently: rays through each pixel's centre
or MSAA sample onto a trimesh mesh's triangles (Moller-Trumbore in float64), and the interior
pixels whose centre and four samples all hit one face (there MSAA averages four equal samples,
the fragment's value at the centre). Shared by the tests that compare glshade with pyrender's
own shading and with our shaders in pyrender's pipeline.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass
from typing import Any

import numpy as np
from conftest import require

WIDTH, HEIGHT = 192, 144
ZNEAR, ZFAR = 1.0, 10.0
YFOV = np.radians(40.0)
# llvmpipe's 4x MSAA sample positions, from the pixel centre in image coordinates (rows down).
SAMPLES = ((-0.125, 0.375), (0.375, 0.125), (-0.375, -0.125), (0.125, -0.375))
SNAP = 1 / 128  # px: twice llvmpipe's vertex snapping (1/256 px)
ROUNDING = 0.5 / 255  # the colour buffer's 8 bits


def mesh(seed: int) -> Any:
    """A trimesh mesh in front of the camera (world = eye: the camera pose is the identity),
    with a cap cut off so that its inside (back faces) shows too; normals of the closed mesh."""
    trimesh = require("trimesh")
    rng = np.random.default_rng(seed)
    m = [
        trimesh.creation.icosphere(subdivisions=3),
        trimesh.creation.torus(major_radius=1.0, minor_radius=0.4),
        trimesh.creation.capsule(height=1.0, radius=0.6, count=(16, 16)),
    ][seed % 3]
    m.apply_transform(trimesh.transformations.random_rotation_matrix(rng.random(3)))
    m.apply_translation((*rng.uniform(-0.3, 0.3, 2), -3.5))
    keep = m.triangles_center[:, 2] < -3.5 + 0.7
    return trimesh.Trimesh(
        m.vertices, m.faces[keep], vertex_normals=m.vertex_normals, process=False
    )


def pyrender_scene(m: Any) -> tuple[Any, np.ndarray]:
    """The mesh and a perspective camera at the origin; returns the scene and its projection."""
    pyrender = require("pyrender")
    scene = pyrender.Scene(bg_color=(0, 0, 0, 0))
    # OPAQUE: from_trimesh's default material blends by alpha (GL's alpha is d_cm's).
    material = pyrender.MetallicRoughnessMaterial(alphaMode="OPAQUE")
    scene.add(pyrender.Mesh.from_trimesh(m, material=material, smooth=True))
    camera = pyrender.PerspectiveCamera(yfov=YFOV, znear=ZNEAR, zfar=ZFAR)
    scene.add(camera, pose=np.eye(4))
    return scene, camera.get_projection_matrix(WIDTH, HEIGHT)


# --- ray casting ------------------------------------------------------------------------------


def pixel_rays(projection: np.ndarray, offset: tuple[float, float]) -> np.ndarray:
    """(HEIGHT, WIDTH, 3) eye-space directions through each pixel centre + offset (rows down)."""
    rows, cols = np.mgrid[0:HEIGHT, 0:WIDTH]
    x = (cols + 0.5 + offset[0]) / WIDTH * 2 - 1
    y = 1 - (rows + 0.5 + offset[1]) / HEIGHT * 2
    far = np.stack([x, y, np.ones_like(x), np.ones_like(x)], axis=-1) @ np.linalg.inv(projection).T
    return far[..., :3] / far[..., 3:]


@dataclass
class Hits:
    """Per pixel, the nearest hit of the ray from the eye through centre + offset."""

    depth: np.ndarray  # (HEIGHT, WIDTH) distance along -z, inf for a miss
    gap: np.ndarray  # (HEIGHT, WIDTH) how much deeper the ray's next hit is (inf: none)
    face: np.ndarray  # (HEIGHT, WIDTH) the face hit, -1 for a miss
    point: np.ndarray  # (HEIGHT, WIDTH, 3) eye-space hit point (0 for a miss)
    bary: np.ndarray  # (HEIGHT, WIDTH, 3) its barycentrics in that face


def ray_cast(m: Any, projection: np.ndarray, offset: tuple[float, float]) -> Hits:
    """Moller-Trumbore in float64 against trimesh's triangles, each tested only with the rays
    of the pixels its projection's bounding box touches."""
    triangles = m.triangles
    clip = np.concatenate([triangles, np.ones((*triangles.shape[:2], 1))], axis=2) @ projection.T
    assert (clip[..., 3] > 0).all(), "the mesh is in front of the eye"
    ndc = clip[..., :2] / clip[..., 3:]
    col = (ndc[..., 0] + 1) / 2 * WIDTH - 0.5 - offset[0]  # where ray (row, col) passes
    row = (1 - ndc[..., 1]) / 2 * HEIGHT - 0.5 - offset[1]
    c0 = np.clip(np.floor(col.min(axis=1)).astype(int), 0, WIDTH - 1)
    c1 = np.clip(np.ceil(col.max(axis=1)).astype(int), 0, WIDTH - 1)
    r0 = np.clip(np.floor(row.min(axis=1)).astype(int), 0, HEIGHT - 1)
    r1 = np.clip(np.ceil(row.max(axis=1)).astype(int), 0, HEIGHT - 1)
    widths, heights = c1 - c0 + 1, r1 - r0 + 1
    face = np.repeat(np.arange(len(triangles)), widths * heights)
    k = np.arange(len(face)) - np.repeat(
        np.cumsum(widths * heights) - widths * heights, widths * heights
    )
    pixel = (r0[face] + k // widths[face]) * WIDTH + c0[face] + k % widths[face]
    ray = pixel_rays(projection, offset).reshape(-1, 3)[pixel]
    a, b, c = (triangles[face, i] for i in range(3))
    e1, e2 = b - a, c - a
    p = np.cross(ray, e2)
    with np.errstate(divide="ignore", invalid="ignore"):
        inv = 1.0 / np.sum(e1 * p, axis=1)
        u = np.sum(-a * p, axis=1) * inv
        q = np.cross(-a, e1)
        v = np.sum(ray * q, axis=1) * inv
        t = np.sum(e2 * q, axis=1) * inv
    hit = (u >= 0) & (v >= 0) & (u + v <= 1) & (t > 0) & np.isfinite(t)
    order = np.flatnonzero(hit)[np.lexsort((t[hit], pixel[hit]))]  # by pixel, nearest first
    first = np.r_[True, np.diff(pixel[order]) != 0]
    chosen = order[first]
    second = order[1:][~first[1:]][first[:-1][~first[1:]]]  # the second hit of a pixel
    rays = pixel_rays(projection, offset).reshape(-1, 3)
    size = HEIGHT * WIDTH
    depth, gap, hit_face = np.full(size, np.inf), np.full(size, np.inf), np.full(size, -1)
    point, bary = np.zeros((size, 3)), np.zeros((size, 3))
    where = pixel[chosen]
    depth[where] = t[chosen] * -rays[where, 2]
    gap[pixel[second]] = t[second] * -rays[pixel[second], 2] - depth[pixel[second]]
    hit_face[where] = face[chosen]
    point[where] = rays[where] * t[chosen, None]
    bary[where] = np.c_[1 - u[chosen] - v[chosen], u[chosen], v[chosen]]
    image = (HEIGHT, WIDTH)
    return Hits(
        depth.reshape(image),
        gap.reshape(image),
        hit_face.reshape(image),
        point.reshape(*image, 3),
        bary.reshape(*image, 3),
    )


@functools.cache
def interior(seed: int) -> tuple[Hits, np.ndarray]:
    """`interior_of` mesh(seed)."""
    m = mesh(seed)
    return interior_of(m, pyrender_scene(m)[1])


def interior_of(m: Any, projection: np.ndarray) -> tuple[Hits, np.ndarray]:
    """The hits through the pixel centres of trimesh `m` seen through `projection` from the
    origin, and the pixels whose centre and four MSAA samples, each moved by SNAP either way,
    all hit the centre's face with nothing within 1e-3 behind it (a depth test could tie): the
    resolve then averages four equal samples, the fragment's value at the centre."""
    centre = ray_cast(m, projection, (0.0, 0.0))
    inside = (centre.face >= 0) & (centre.gap > 1e-3)
    for x, y in ((0.0, 0.0), *SAMPLES):
        for dx, dy in ((0, 0), (SNAP, 0), (-SNAP, 0), (0, SNAP), (0, -SNAP)):
            ray = ray_cast(m, projection, (x + dx, y + dy))
            inside &= (ray.face == centre.face) & (ray.gap > 1e-3)
    return centre, inside


def shading_normals(m: Any, hits: Hits) -> np.ndarray:
    """trimesh's vertex normals interpolated at the hits (perspective-correct: 3D barycentrics)."""
    corners = m.vertex_normals[m.faces[np.maximum(hits.face, 0)]]  # (H, W, 3, 3)
    return np.einsum("hwk,hwkj->hwj", hits.bary, corners)
