"""`render` against analytic truths computed here in numpy: coverage by GL's pixel-centre and
edge rules, depth from the projection formula, winding, culling and two-sided colours, and flat,
Gouraud and Phong colours against `shade` evaluated at each pixel's ray hit."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

import glshade as gs
from glshade.meshes import icosphere, torus
from support.gil import count_while
from support.processes import script

SHINY = gs.Scene(
    lights=[
        gs.Light(position=(2.0, 3.0, 2.0, 1.0), linear_attenuation=0.1),
        gs.Light(position=(-1.0, 0.5, 1.0, 0.0), diffuse=(0.3, 0.4, 0.9)),
    ],
    material=gs.Material(specular=(1, 1, 1), shininess=30),
    viewer=(0, 0, 0, 1),
)


def emission_scene(rgb: tuple[float, float, float]) -> gs.Scene:
    """No lights, no ambient: every pixel is the emission colour."""
    material = gs.Material(ambient=(0, 0, 0), diffuse=(0, 0, 0, 1), emission=rgb)
    return gs.Scene(material=material, global_ambient=(0, 0, 0))


# --- independent geometry: rays through pixel centres -----------------------------------------


def eye_rays(camera: gs.Camera, width: int, height: int) -> tuple[np.ndarray, np.ndarray]:
    """Eye-space origin and direction of the ray through every pixel centre (image rows top
    down): the unprojected points at NDC depth -1 and 1 of (x + 1/2, y + 1/2)."""
    x = (np.arange(width) + 0.5) / width * 2 - 1
    y = (np.arange(height)[::-1] + 0.5) / height * 2 - 1
    xx, yy = np.meshgrid(x, y)
    inverse = np.linalg.inv(camera.projection_matrix(width, height))
    ends = []
    for z in (-1.0, 1.0):
        ndc = np.stack([xx, yy, np.full_like(xx, z), np.ones_like(xx)], axis=-1)
        p = ndc @ inverse.T
        ends.append(p[..., :3] / p[..., 3:])
    return ends[0], ends[1] - ends[0]


def hit(
    corners: np.ndarray, origin: np.ndarray, direction: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """Ray parameter and barycentric coordinates of each ray's hit on the plane of `corners`
    (3, 3), in eye space (Cramer's rule on o + t d = a + u (b - a) + v (c - a))."""
    a, b, c = corners
    e1, e2 = b - a, c - a
    s = origin - a
    det = np.einsum("...i,i->...", np.cross(direction, e2), e1)
    u = np.einsum("...i,...i->...", np.cross(direction, e2), s) / det
    v = np.einsum("...i,...i->...", np.cross(s, e1), direction) / det
    t = np.einsum("...i,i->...", np.cross(s, e1), e2) / det
    return t, np.stack([1 - u - v, u, v], axis=-1)


def window_depth(camera: gs.Camera, width: int, height: int, eye: np.ndarray) -> np.ndarray:
    clip = np.concatenate([eye, np.ones((*eye.shape[:-1], 1))], axis=-1)
    clip = clip @ camera.projection_matrix(width, height).T
    return (clip[..., 2] / clip[..., 3] + 1) / 2


# --- coverage ------------------------------------------------------------------------------


def test_a_screen_filling_quad_covers_every_pixel_at_its_depth() -> None:
    quad = np.array([[-1, -1, 0.2], [1, -1, 0.2], [1, 1, 0.2], [-1, 1, 0.2]], np.float32)
    faces = [[0, 1, 2], [0, 2, 3]]
    scene = emission_scene((0.25, 0.5, 0.75))
    image, depth = gs.render(quad, faces, scene, gs.Camera(), width=13, height=7, depth=True)
    assert image.shape == (7, 13, 4) and image.dtype == np.float32 and depth.dtype == np.float32
    np.testing.assert_array_equal(image, np.broadcast_to([0.25, 0.5, 0.75, 1.0], image.shape))
    # Identity projection: z_ndc = z_eye, window depth (z + 1) / 2.
    np.testing.assert_array_equal(depth, np.float32(0.6))


def test_pixel_centres_decide_coverage() -> None:
    # x in [-0.5, 0.5] of NDC is window x in [2, 6] of 8 pixels: centres 2.5 ... 5.5.
    # y in [-0.3, 0.7] is window y in [2.8, 6.8]: centres 3.5 ... 6.5, image rows 1 ... 4.
    quad = np.array([[-0.5, -0.3, 0], [0.5, -0.3, 0], [0.5, 0.7, 0], [-0.5, 0.7, 0]])
    image = gs.render(
        quad, [[0, 1, 2], [0, 2, 3]], emission_scene((1, 1, 1)), gs.Camera(), width=8, height=8
    )
    covered = image[..., 3] > 0
    expected = np.zeros((8, 8), bool)
    expected[1:5, 2:6] = True
    np.testing.assert_array_equal(covered, expected)


def test_edges_through_pixel_centres_belong_to_the_left_and_bottom() -> None:
    # On 8 x 8 pixels a window coordinate w is NDC w / 4 - 1; these edges pass through centres.
    def ndc(points: list[tuple[float, float]]) -> np.ndarray:
        return np.array([[x / 4 - 1, y / 4 - 1, 0] for x, y in points])

    scene = emission_scene((1, 1, 1))

    def covers(points: list[tuple[float, float]], x: int, y: int) -> bool:
        image = gs.render(ndc(points), [[0, 1, 2]], scene, gs.Camera(), width=8, height=8)
        return bool(image[7 - y, x, 3] > 0)

    assert covers([(1.5, 0), (6, 0), (1.5, 6)], 1, 2)  # left edge x = 1.5: included
    assert not covers([(0, 0), (1.5, 0), (1.5, 6)], 1, 2)  # right edge: excluded
    assert covers([(0, 2.5), (6, 2.5), (0, 8)], 2, 2)  # bottom edge y = 2.5: included
    assert not covers([(0, 0), (6, 2.5), (0, 2.5)], 2, 2)  # top edge: excluded


def test_a_shared_edge_covers_each_pixel_exactly_once() -> None:
    rng = np.random.default_rng(3)
    scene = emission_scene((1, 1, 1))
    for _ in range(20):
        p = rng.uniform(-1.2, 1.2, (4, 2))
        e = p[2] - p[1]
        side = [e[0] * (p[k] - p[1])[1] - e[1] * (p[k] - p[1])[0] for k in (0, 3)]
        if side[0] * side[1] > 0:
            p[3] = p[1] + p[2] - p[3]  # through the shared edge's middle, to the other side
        p = np.c_[p, np.zeros(4)]
        a = gs.render(p, [[0, 1, 2]], scene, gs.Camera(), width=32, height=32)[..., 3] > 0
        b = gs.render(p, [[2, 1, 3]], scene, gs.Camera(), width=32, height=32)[..., 3] > 0
        both = gs.render(p, [[0, 1, 2], [2, 1, 3]], scene, gs.Camera(), width=32, height=32)
        assert not (a & b).any()
        np.testing.assert_array_equal(a | b, both[..., 3] > 0)


def test_coverage_matches_the_pixel_centre_test() -> None:
    rng = np.random.default_rng(5)
    v = rng.uniform(-1.1, 1.1, (3, 3)) * [1, 1, 0]
    width, height = 40, 30
    image = gs.render(
        v, [[0, 1, 2]], emission_scene((1, 1, 1)), gs.Camera(), width=width, height=height
    )
    origin, direction = eye_rays(gs.Camera(), width, height)
    _, bary = hit(v, origin, direction)
    inside = (bary > 1e-9).all(axis=-1)
    unsure = (np.abs(bary) <= 1e-9).any(axis=-1)
    covered = image[..., 3] > 0
    np.testing.assert_array_equal(covered[~unsure], inside[~unsure])


@given(
    st.lists(st.floats(-3, 3), min_size=9, max_size=9),
    st.integers(1, 40),
    st.integers(1, 40),
)
def test_random_triangles_cover_the_centres_inside_and_between_the_clip_planes(
    coordinates: list[float], width: int, height: int
) -> None:
    # Identity camera: the visible volume is [-1, 1]^3, so z beyond +-1 is clipped away.
    v = np.array(coordinates).reshape(3, 3)
    image, depth = gs.render(
        v,
        [[0, 1, 2]],
        emission_scene((1, 1, 1)),
        gs.Camera(),
        width=width,
        height=height,
        depth=True,
    )
    covered = depth < 1
    assert (image[covered][:, 3] == 1).all() and (image[~covered] == 0).all()
    origin, direction = eye_rays(gs.Camera(), width, height)
    with np.errstate(all="ignore"):
        t, bary = hit(v, origin, direction)
        z = (origin + t[..., None] * direction)[..., 2]
        margin = 1e-6 * max(1.0, float(np.abs(v).max()))
        (x1, y1), (x2, y2) = v[1, :2] - v[0, :2], v[2, :2] - v[0, :2]
        area = abs(x1 * y2 - x2 * y1)
    if not area > 1e-6:  # edge-on or degenerate: no interior to compare
        return
    # Vertices snap to 1/256 pixel, so centres that close to an edge may go either way.
    window = (v[:, :2] + 1) / 2 * (width, height)
    cx, cy = np.meshgrid(np.arange(width) + 0.5, np.arange(height)[::-1] + 0.5)
    near_edge = np.zeros((height, width), bool)
    for a, b in ((0, 1), (1, 2), (2, 0)):
        d = window[b] - window[a]
        distance = (d[0] * (cy - window[a, 1]) - d[1] * (cx - window[a, 0])) / np.hypot(*d)
        near_edge |= np.abs(distance) < 1 / 128
    # The same for the edges the near and far planes cut: z changes by |grad z| per pixel.
    e1, e2 = window[1] - window[0], window[2] - window[0]
    dz1, dz2 = v[1, 2] - v[0, 2], v[2, 2] - v[0, 2]
    det = e1[0] * e2[1] - e2[0] * e1[1]
    slope = np.hypot(dz1 * e2[1] - dz2 * e1[1], dz2 * e1[0] - dz1 * e2[0]) / abs(det)
    margin += slope / 128
    inside = (bary > 0).all(axis=-1) & (np.abs(z) < 1 - margin) & ~near_edge
    outside = ((bary < 0).any(axis=-1) & ~near_edge) | (np.abs(z) > 1 + margin)
    assert covered[inside].all() and not covered[outside].any()
    np.testing.assert_allclose(depth[inside], (z[inside] + 1) / 2, atol=1e-9)


@pytest.mark.parametrize("scale", [1e-30, 1e30, 1e300])
def test_extreme_coordinates_do_not_crash(scale: float) -> None:
    # Given normals: gs.vertex_normals itself overflows for 1e30 in float32 (its cross product).
    v = np.array([[-1, -1, 0.5], [1, -1, -0.5], [0, 1, 0.0]]) * scale
    n = np.array([[0, 0, 1.0]] * 3)
    for dtype in (np.float32, np.float64):
        with np.errstate(over="ignore"):
            v_ = v.astype(dtype)
        for shading in ("phong", "gouraud"):
            image = gs.render(
                v_, [[0, 1, 2]], SHINY, gs.Camera(), width=9, height=7, shading=shading, normals=n
            )
            assert image.shape == (7, 9, 4)
            assert np.isfinite(image).all()


def test_render_releases_the_gil() -> None:
    v, f = torus(250, 200)
    camera = gs.Camera.look_at((0, -2.5, 2), (0, 0, 0), (0, 0, 1))
    free = count_while(lambda: __import__("time").sleep(0.3))
    during = count_while(lambda: gs.render(v, f, SHINY, camera, width=1024, height=1024))
    assert during > 0.15 * free, f"counter ran at {during / free:.3f} of its free rate"


# --- depth ---------------------------------------------------------------------------------


@pytest.mark.parametrize("orthographic", [False, True])
def test_depth_follows_the_projection(orthographic: bool) -> None:
    width, height = 48, 32
    if orthographic:
        camera = gs.Camera.look_at_orthographic((0.3, 0.2, 4), (0, 0, 0), height=3, near=1, far=9)
    else:
        camera = gs.Camera.look_at((0.3, 0.2, 4), (0, 0, 0), fovy=50, near=1, far=9)
    tri = np.array([[-1.5, -1.0, -0.8], [1.8, -0.6, 0.9], [-0.2, 1.4, 0.1]])
    image, depth = gs.render(
        tri, [[0, 1, 2]], SHINY, camera, width=width, height=height, depth=True
    )
    eye = np.c_[tri, np.ones(3)] @ camera.view.T
    origin, direction = eye_rays(camera, width, height)
    t, _ = hit(eye[:, :3], origin, direction)
    expected = window_depth(camera, width, height, origin + t[..., None] * direction)
    covered = image[..., 3] > 0
    assert covered.sum() > 200
    np.testing.assert_allclose(depth[covered], expected[covered], atol=1e-12)
    assert (depth[~covered] == 1.0).all()


def test_the_nearest_surface_wins() -> None:
    quad = np.array([[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0.0]])
    near = quad - [0, 0, 0.5]  # the identity projection keeps z: depth (z + 1) / 2, -z nearer
    v = np.concatenate([quad, near[:3]])
    faces = [[0, 1, 2], [0, 2, 3], [4, 5, 6]]
    colours = np.array([[1, 0, 0]] * 4 + [[0, 1, 0]] * 3, np.float64)
    scene = emission_scene((0, 0, 0))
    args: dict[str, Any] = {"colors": colours, "color_material": "emission", "shading": "flat"}
    image = gs.render(v, faces, scene, gs.Camera(), width=16, height=16, **args)
    upper = image[..., 1] == 1
    assert upper.sum() == 16 * 17 // 2  # the near lower-right half, with its left-edge diagonal
    np.testing.assert_array_equal(image[~upper][:, 0], 1.0)
    # Drawn the other way round, the depth test gives the same picture.
    image2 = gs.render(v, faces[::-1], scene, gs.Camera(), width=16, height=16, **args)
    np.testing.assert_array_equal(image, image2)


@pytest.mark.parametrize("dtype", [np.float64, np.float32])
def test_flat_shading_takes_the_provoking_vertex_colour(dtype: Any) -> None:
    # Emission colours per vertex: flat shading paints the last vertex's (GL), the first's
    # (Direct3D) or their mean (the centroid, PyTorch3D's) over the whole face.
    tri = np.array([[-0.9, -0.9, 0], [0.9, -0.9, 0], [0, 0.9, 0]], dtype)
    colours = np.array([[0.9, 0.1, 0.2], [0.2, 0.8, 0.1], [0.1, 0.3, 0.7]], dtype)
    args: dict[str, Any] = {"colors": colours, "color_material": "emission", "shading": "flat"}
    scene = emission_scene((0, 0, 0))
    expected = {"last": colours[2], "first": colours[0], "centroid": colours.astype(float).mean(0)}
    for provoking, colour in expected.items():
        image = gs.render(tri, [[0, 1, 2]], scene, gs.Camera(), width=16, height=16,
                          provoking_vertex=provoking, **args)  # fmt: skip
        drawn = image[image[..., 3] > 0]
        assert len(drawn) > 50
        tolerance = 1e-15 if dtype == np.float64 else 1e-7
        np.testing.assert_allclose(drawn[:, :3], np.broadcast_to(colour, drawn[:, :3].shape),
                                   rtol=0, atol=tolerance)  # fmt: skip


# --- winding, culling, two-sided lighting ----------------------------------------------------


def test_winding_culling_and_two_sided_colours() -> None:
    ccw = np.array([[-0.8, -0.8, 0], [0.8, -0.8, 0], [0, 0.8, 0]])
    back = gs.Material(ambient=(0, 0, 0), diffuse=(0, 0, 0, 1), emission=(0, 0, 1))
    front = gs.Material(ambient=(0, 0, 0), diffuse=(0, 0, 0, 1), emission=(1, 0, 0))
    two = gs.Scene(material=front, back_material=back, two_side=True, global_ambient=(0, 0, 0))
    one = gs.Scene(material=front, back_material=back, global_ambient=(0, 0, 0))

    def draw(faces: list[list[int]], scene: gs.Scene, cull: Any = None) -> np.ndarray:
        return gs.render(ccw, faces, scene, gs.Camera(), width=16, height=16, cull=cull)

    f, b = [[0, 1, 2]], [[0, 2, 1]]
    assert (draw(f, two)[..., 0] == 1).sum() > 50
    assert (draw(b, two)[..., 2] == 1).sum() == (draw(f, two)[..., 0] == 1).sum()
    assert (draw(b, one)[..., 0] == 1).sum() > 50  # one-sided: the front colour on both sides
    assert (draw(b, two, "back")[..., 3] == 0).all()
    assert (draw(f, two, "back")[..., 3] > 0).any()
    assert (draw(f, two, "front")[..., 3] == 0).all()
    assert (draw(b + f, two, "front_and_back")[..., 3] == 0).all()
    # Seen from behind (a view rotated by 180 degrees about y) the front face is a back face.
    behind = gs.Camera(view=np.diag([-1.0, 1.0, -1.0, 1.0]))
    image = gs.render(ccw, f, two, behind, width=16, height=16)
    assert (image[..., 2] == 1).sum() > 50 and (image[..., 0] == 0).all()


# --- colours: flat, Gouraud and Phong against shade at the ray hits ----------------------------


@pytest.mark.parametrize("dtype", [np.float64, np.float32])
@pytest.mark.parametrize("shading", ["phong", "gouraud", "flat", "flat:first", "flat:centroid"])
def test_colours_are_shade_at_the_pixel(dtype: Any, shading: Any) -> None:
    shading, _, provoking = shading.partition(":")
    width, height = 40, 36
    camera = gs.Camera.look_at((0.4, -0.3, 3.5), (0, 0, 0), fovy=55, near=0.5, far=20)
    model = np.array([[1, 0, 0, 0.1], [0, 0.8, 0.3, 0], [0, -0.2, 1.1, -0.2], [0, 0, 0, 1.0]])
    tri = np.array([[-1.4, -1.1, 0.3], [1.5, -0.7, -0.4], [-0.1, 1.3, 0.2]])
    normals = np.array([[-0.5, -0.3, 1.0], [0.6, -0.2, 0.8], [0.0, 0.7, 0.7]])
    scene = gs.Scene(
        lights=[*SHINY.lights, gs.Light(position=(0, 0, 1, 0))],
        material=SHINY.material,
        viewer=(0, 0, 0, 1),
        two_side=True,
        back_material=gs.Material(diffuse=(0.9, 0.1, 0.1)),
        separate_specular=True,
    )
    flat_normal = gs.face_normals(tri, [[0, 1, 2]])
    image = gs.render(
        tri.astype(dtype),
        [[0, 1, 2]],
        scene,
        camera,
        width=width,
        height=height,
        shading=shading,
        provoking_vertex=provoking or "last",
        normals=flat_normal if shading == "flat" else normals,
        model=model,
    )
    assert image.dtype == dtype
    modelview = camera.view @ model
    eye = np.c_[tri, np.ones(3)] @ modelview.T
    origin, direction = eye_rays(camera, width, height)
    _, bary = hit(eye[:, :3], origin, direction)
    inside = (bary > 1e-6).all(axis=-1)
    b = bary[inside]
    covered = image[..., 3] > 0
    assert inside.sum() > 200 and covered[inside].all()

    def lit(p: np.ndarray, n: np.ndarray) -> np.ndarray:
        """shade in eye space: the front primary and secondary colours (this triangle faces the
        camera)."""
        normal_matrix = np.linalg.inv(modelview[:3, :3]).T
        n_eye = n @ normal_matrix.T
        n_eye = n_eye / np.linalg.norm(n_eye, axis=-1, keepdims=True)
        out: np.ndarray = gs.shade(p @ modelview[:3, :3].T + modelview[:3, 3], n_eye, scene)
        return out[:2]

    def colour_sum(primary: np.ndarray, secondary: np.ndarray) -> np.ndarray:
        return np.c_[np.clip(primary[:, :3] + secondary[:, :3], 0, 1), primary[:, 3]]

    if shading == "phong":
        expected = colour_sum(*lit(b @ tri, b @ normals))
    elif shading == "gouraud":
        expected = colour_sum(*(b @ lit(tri, normals)))  # both interpolated, then summed
    else:
        at = {"": tri[2:], "first": tri[:1], "centroid": tri.mean(axis=0, keepdims=True)}
        expected = np.broadcast_to(colour_sum(*lit(at[provoking], flat_normal)), (len(b), 4))
    tolerance = 1e-9 if dtype == np.float64 else 2e-5
    np.testing.assert_allclose(image[inside], expected, atol=tolerance)


def test_gouraud_colours_interpolate_perspective_correctly() -> None:
    # A quad receding in depth, lit only by per-vertex emission: black at the near edge, white
    # at the far edge. Perspective-correct weights are the ray hits', not the screen's.
    v = np.array([[-1, -1, -1.0], [1, -1, -1.0], [1, 1, -6.0], [-1, 1, -6.0]])
    colours = np.array([[0, 0, 0], [0, 0, 0], [1, 1, 1], [1, 1, 1.0]])
    camera = gs.Camera(
        projection=gs.Camera.look_at((0, 0, 0), (0, 0, -1), near=0.5, far=10).projection_matrix(
            1, 1
        )
    )
    image = gs.render(
        v,
        [[0, 1, 2], [0, 2, 3]],
        emission_scene((0, 0, 0)),
        camera,
        width=32,
        height=32,
        shading="gouraud",
        colors=colours,
        color_material="emission",
    )
    origin, direction = eye_rays(camera, 32, 32)
    t, _ = hit(v[:3], origin, direction)
    y_eye = (origin + t[..., None] * direction)[..., 1]
    expected = (y_eye + 1) / 2  # the hit's fraction of the way from the near to the far edge
    covered = image[..., 3] > 0
    np.testing.assert_allclose(image[..., 0][covered], expected[covered], atol=1e-12)
    screen_linear = np.linspace(0, 1, 32)
    assert np.abs(image[..., 0][covered].mean() - screen_linear.mean()) > 0.05


# --- clipping, degenerate and odd input --------------------------------------------------------


def test_triangles_behind_the_camera_are_clipped() -> None:
    camera = gs.Camera.look_at((0, 0, 0), (0, 0, -1), near=1, far=10)
    scene = emission_scene((1, 1, 1))
    behind = np.array([[-1, -1, 2.0], [1, -1, 2.0], [0, 1, 2.0]])
    assert (gs.render(behind, [[0, 1, 2]], scene, camera, width=16, height=16)[..., 3] == 0).all()
    # A floor through the eye's depth: only the part beyond the near plane is drawn, and its
    # depth stays in [0, 1].
    floor = np.array([[-5, -1, 5.0], [5, -1, 5.0], [0, -1, -9.0]])
    image, depth = gs.render(floor, [[0, 1, 2]], scene, camera, width=32, height=32, depth=True)
    covered = image[..., 3] > 0
    assert covered[-1].all() and not covered[:16].any()  # the floor is below the horizon
    assert ((depth[covered] >= 0) & (depth[covered] < 1)).all()
    origin, direction = eye_rays(camera, 32, 32)
    t, _ = hit(floor, origin, direction)
    expected = window_depth(camera, 32, 32, origin + t[..., None] * direction)
    np.testing.assert_allclose(depth[covered], expected[covered], atol=1e-12)


def test_degenerate_off_screen_and_non_finite_faces_draw_nothing() -> None:
    v = np.array(
        [[0, 0, 0], [0.5, 0.5, 0], [1, 1, 0], [5, 5, 0], [6, 5, 0], [5, 6, 0], [np.nan, 0, 0]]
    )
    faces = [[0, 1, 2], [0, 0, 0], [3, 4, 5], [6, 1, 3]]
    image, depth = gs.render(v, faces, SHINY, gs.Camera(), width=20, height=20, depth=True)
    assert (image == 0).all() and (depth == 1).all()
    empty = gs.render(
        np.zeros((0, 3)), np.zeros((0, 3), int), SHINY, gs.Camera(), width=3, height=2
    )
    assert empty.shape == (2, 3, 4)


def test_background_and_model_matrix() -> None:
    v, f = icosphere(2)
    move = np.eye(4)
    move[:3, 3] = (0.3, -0.2, -4)
    camera = gs.Camera.look_at((0, 0, 0), (0, 0, -1), fovy=40)
    a = gs.render(v, f, SHINY, camera, width=40, height=30, model=move, background=(0.1, 0.2, 0.3))
    b = gs.render(
        v + move[:3, 3], f, SHINY, camera, width=40, height=30, background=(0.1, 0.2, 0.3)
    )
    np.testing.assert_allclose(a, b, atol=1e-12)
    assert (a[0, 0] == [0.1, 0.2, 0.3, 1.0]).all()


@pytest.mark.subprocess
def test_results_do_not_depend_on_the_thread_count() -> None:
    runs = []
    for threads in ("1", "3"):
        env = {**os.environ, "RAYON_NUM_THREADS": threads}
        command = [sys.executable, script("render_bytes")]
        runs.append(subprocess.run(command, env=env, capture_output=True, check=True).stdout)
    assert len(runs[0]) == 3 * 150 * 120 * 5 * 4
    assert runs[0] == runs[1]


# --- the image type and the camera --------------------------------------------------------------


def test_the_image_saves_and_shows_itself(tmp_path: Path) -> None:
    v, f = torus(30, 20)
    image = gs.render(v, f, SHINY, gs.Camera.look_at((0, -3, 2), up=(0, 0, 1)), width=24, height=16)
    assert isinstance(image, gs.Image) and type(np.asarray(image)) is np.ndarray
    png = image._repr_png_()
    assert png is not None and png.startswith(b"\x89PNG\r\n\x1a\n")
    assert image.save(tmp_path / "a.png").read_bytes() == png
    assert type(image[..., 0]) is np.ndarray and type(image[0, 0]) is np.ndarray
    assert type(image[::2]) is gs.Image and type(image * 0.5) is gs.Image
    assert type(image.max()) is np.float64 and type(image > 0) is np.ndarray


def test_camera_matrices_are_glus() -> None:
    camera = gs.Camera.look_at((1, 2, 3), (1, 2, -2), (0, 3, 0), fovy=90, near=1, far=11)
    np.testing.assert_allclose(
        camera.view, [[1, 0, 0, -1], [0, 1, 0, -2], [0, 0, 1, -3], [0, 0, 0, 1]]
    )
    p = camera.projection_matrix(200, 100)  # aspect 2 from the image
    f = 1 / np.tan(np.radians(45))
    expected = [[f / 2, 0, 0, 0], [0, f, 0, 0], [0, 0, -12 / 10, -22 / 10], [0, 0, -1, 0]]
    np.testing.assert_allclose(p, expected, atol=1e-15)
    ortho = gs.Camera.look_at_orthographic((0, 0, 0), (0, 0, -1), height=4, near=1, far=3)
    np.testing.assert_allclose(
        ortho.projection_matrix(2, 1),
        [[0.25, 0, 0, 0], [0, 0.5, 0, 0], [0, 0, -1, -2], [0, 0, 0, 1]],
    )
    assert "look_at" in repr(camera)


# --- errors ---------------------------------------------------------------------------------


TRI = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0.0]])


@pytest.mark.parametrize(
    ("kwargs", "error", "match"),
    [
        ({"width": 0}, ValueError, r"width must be in \[1, 16384\], got 0"),
        ({"height": 20000}, ValueError, r"height must be in \[1, 16384\]"),
        ({"width": 2.5}, TypeError, "width must be an integer"),
        ({"shading": "toon"}, ValueError, "shading must be 'flat', 'gouraud' or 'phong'"),
        ({"cull": "sideways"}, ValueError, "cull must be None, 'back'"),
        ({"provoking_vertex": "middle"}, ValueError, "provoking_vertex must be 'last', 'first' or"),
        ({"normals": np.zeros((2, 3))}, ValueError, r"normals must have 3 rows \(one per vertex\)"),
        ({"normals": np.zeros((3, 3)), "shading": "flat"}, ValueError, "one per face for flat"),
        ({"colors": np.zeros((3, 5))}, ValueError, "colors must have shape"),
        ({"colors": np.zeros((4, 3))}, ValueError, "colors must have one row per vertex"),
        ({"background": (1, 2)}, ValueError, "background must have shape"),
        ({"model": np.ones((4, 4))}, ValueError, "model must be affine"),
        ({"model": np.full((4, 4), np.nan)}, ValueError, "model must be finite"),
        ({"model": np.eye(3)}, ValueError, r"model must have shape \(4, 4\)"),
        ({"model": np.diag([1, 1, 0, 1.0])}, ValueError, "model must be invertible"),
        ({"color_material": "diffuse"}, ValueError, "color_material needs colors"),
    ],
)
def test_bad_arguments_are_named(kwargs: dict[str, Any], error: type, match: str) -> None:
    with pytest.raises(error, match=match):
        gs.render(TRI, [[0, 1, 2]], SHINY, gs.Camera(), **kwargs)


def test_bad_meshes_cameras_and_types() -> None:
    with pytest.raises(IndexError, match="face 1 refers to vertex 3"):
        gs.render(TRI, [[0, 1, 2], [0, 1, 3]], SHINY, gs.Camera())
    with pytest.raises(TypeError, match="vertices must be real numbers"):
        gs.render(TRI.astype(complex), [[0, 1, 2]], SHINY, gs.Camera())
    with pytest.raises(ValueError, match=r"vertices must have shape \(n, 3\)"):
        gs.render(TRI[0], [[0, 1, 2]], SHINY, gs.Camera())
    with pytest.raises(TypeError, match="faces must be an integer array"):
        gs.render(TRI, [[0.0, 1, 2]], SHINY, gs.Camera())
    with pytest.raises(TypeError, match=r"scene must be a glshade\.Scene"):
        gs.render(TRI, [[0, 1, 2]], "sun", gs.Camera())  # type: ignore[arg-type]
    with pytest.raises(TypeError, match=r"camera must be a glshade\.Camera"):
        gs.render(TRI, [[0, 1, 2]], SHINY, np.eye(4))  # type: ignore[arg-type]
    with pytest.raises(ValueError, match="view must be affine"):
        gs.render(TRI, [[0, 1, 2]], SHINY, gs.Camera(view=np.ones((4, 4))))
    with pytest.raises(ValueError, match="projection must be finite"):
        gs.Camera(projection=np.full((4, 4), np.inf))
    with pytest.raises(ValueError, match="target must differ from eye"):
        gs.Camera.look_at((1, 2, 3), (1, 2, 3))
    with pytest.raises(ValueError, match="up must not be zero or parallel"):
        gs.Camera.look_at((0, 0, 0), (0, 1, 0))
    with pytest.raises(ValueError, match="fovy must be in"):
        gs.Camera.look_at((0, 0, 1), fovy=180)
    with pytest.raises(ValueError, match="near and far must satisfy"):
        gs.Camera.look_at((0, 0, 1), near=2, far=1)
    with pytest.raises(ValueError, match="aspect must be finite and > 0"):
        gs.Camera.look_at_orthographic((0, 0, 1), height=2, aspect=0)
    with pytest.raises(ValueError, match="eye must have shape"):
        gs.Camera.look_at((0, 1))
