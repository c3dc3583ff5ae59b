"""glshade against glshade.glsl, the lighting equation in GLSL, run by Mesa's llvmpipe through
moderngl.

glshade.glsl is written from the GL 2.1 specification, independently of glshade's Rust code
(it shares the plan's rules of what to leave out, not its arithmetic), and covers everything
gs.shade does (Phong, any viewer point, any number
of lights, colour material, two-sided lighting, separate specular, modelview, normalize,
rescale). It runs

(a) per vertex in its compute shader (glpeers.shade_compute) on the random scenes of scenes.py,
    the same ones test_vs_spec.py checks against the float64 oracle;
(b) per pixel: a triangle mesh rasterised with perspective, its interpolated eye-space
    positions and normals written to RGBA32F targets beside the colour lit from them
    (glpeers.rasterize). glshade shades the read-back float32 positions and normals and must
    give the read-back colour.

Tolerance (glpeers.float32_tolerance): 1e-5 per channel for sums of |terms| up to 1, 1e-5 times
that sum above, plus the conditioning of cos^s on the rounding of a float32 cosine (2 u s
|specular term|: the port evaluates pow(n.h, s) as the spec writes it; glshade's evaluation is
better conditioned). Vertices within 2e-5 of a discontinuity or whose specular power exceeds
float32's range are not compared.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest
from conftest import require

import glshade as gs
from support import glpeers
from support.gl_reference import RefScene
from support.scenes import random_case, to_glshade

pytestmark = pytest.mark.gl

trimesh = require("trimesh")

TOL = 1e-5
MARGIN = 2e-5
SEEDS = 100
VERTICES = 1000


@pytest.fixture(scope="module", autouse=True)
def context() -> Any:
    return glpeers.moderngl_context()


def check(
    ref: RefScene,
    positions: np.ndarray,
    normals: np.ndarray,
    got: np.ndarray,
    theirs: np.ndarray,
    what: str,
) -> int:
    """Asserts glshade and the GLSL port agree within the float32 tolerance on the comparable
    rows of every output ((n, 4) or (k, n, 4)); returns the number of rows compared."""
    tolerance = glpeers.float32_tolerance(ref, positions, normals, TOL, MARGIN)
    return glpeers.assert_agree(tolerance, got, theirs, tolerance.comparable, "GLSL", (what, ref))


# --- (a) per vertex ---------------------------------------------------------------------------


def test_compute_shader_agrees_on_random_scenes() -> None:
    compared = 0
    for seed in range(SEEDS):
        case = random_case(seed, VERTICES, np.float32)
        got = gs.shade(case.positions, case.normals, case.scene, **case.kwargs)
        port = glpeers.shade_compute(case.positions, case.normals, case.scene, **case.kwargs)
        assert port.shape == got.shape
        compared += check(case.ref, case.positions, case.normals, got, port, f"seed {seed}")
    assert compared >= 99_000, "10^5 vertex-scene pairs, less the discontinuity bands"


def test_compute_shader_agrees_with_many_lights_from_arrays() -> None:
    rng = np.random.default_rng(3)
    count, n = 256, 5000  # 256 lights: 9216 of llvmpipe's 16384 uniform components
    spot = rng.random(count) < 0.3
    lights = {
        "position": np.c_[rng.uniform(-4, 4, (count, 3)), rng.choice([0.0, 1.0], count)],
        "ambient": rng.uniform(0, 1e-3, (count, 3)),
        "diffuse": rng.uniform(0, 2e-3, (count, 3)),
        "specular": rng.uniform(0, 2e-3, (count, 3)),
        "linear_attenuation": rng.uniform(0, 0.5, count),
        "spot_cutoff": np.where(spot, rng.uniform(10, 90, count), 180.0),
        "spot_direction": rng.normal(size=(count, 3)),
        "spot_exponent": rng.uniform(0, 20, count),
    }
    ref = RefScene(
        lights=[{k: v[i] for k, v in lights.items()} for i in range(count)],
        material={**gs_material(), "shininess": 40.0},
        viewer=(0.0, 0.0, 0.0, 1.0),
    )
    scene = to_glshade(ref)
    assert gs.Scene(lights=gs.Lights(**lights), material=scene.material).lights == scene.lights
    positions = rng.uniform(-1.5, 1.5, (n, 3)).astype(np.float32)
    normals = rng.normal(size=(n, 3))
    normals = (normals / np.linalg.norm(normals, axis=1, keepdims=True)).astype(np.float32)
    got = gs.shade(positions, normals, scene)
    port = glpeers.shade_compute(positions, normals, scene)
    assert check(ref, positions, normals, got, port, f"{count} lights") >= 4900


def gs_material() -> dict[str, Any]:
    return {
        "ambient": (0.2, 0.2, 0.2, 1.0),
        "diffuse": (0.8, 0.6, 0.4, 0.5),
        "specular": (0.5, 0.5, 0.5, 1.0),
        "emission": (0.0, 0.0, 0.0, 1.0),
    }


# --- (b) per pixel ----------------------------------------------------------------------------

WIDTH, HEIGHT = 160, 120


def perspective(fovy_degrees: float, aspect: float, near: float, far: float) -> np.ndarray:
    """gluPerspective's matrix (row-major)."""
    f = 1.0 / np.tan(np.radians(fovy_degrees) / 2)
    return np.array(
        [
            [f / aspect, 0, 0, 0],
            [0, f, 0, 0],
            [0, 0, (far + near) / (near - far), 2 * far * near / (near - far)],
            [0, 0, -1, 0],
        ]
    )


def eye_mesh(seed: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """A trimesh mesh cut open (so that its inside, back-facing, shows too), turned and placed
    in front of the eye: positions, normals (of the closed mesh), faces."""
    rng = np.random.default_rng(seed)
    mesh = [
        trimesh.creation.icosphere(subdivisions=3),
        trimesh.creation.torus(major_radius=1.0, minor_radius=0.4),
        trimesh.creation.capsule(height=1.0, radius=0.6),
        trimesh.creation.box(extents=(1.6, 1.2, 1.0)),
    ][seed % 4]
    rotation = trimesh.transformations.random_rotation_matrix(rng.random(3))
    mesh.apply_transform(rotation)
    mesh.apply_translation((*rng.uniform(-0.3, 0.3, 2), -4.0))
    open_side = mesh.triangles_center[:, 2] > -4.0 + 0.45  # a cap nearest the eye goes
    return mesh.vertices, mesh.vertex_normals, mesh.faces[~open_side]


def pixel_case(seed: int) -> tuple[RefScene, np.ndarray, np.ndarray, np.ndarray]:
    """A random scene (no modelview: the mesh is in eye space; no colour material: the targets
    hold no interpolated colour) and the mesh."""
    case = random_case(seed, 1, np.float32)
    ref = case.ref
    ref.modelview, ref.rescale_normal, ref.colors, ref.color_material = None, False, None, None
    return (ref, *eye_mesh(seed))


@pytest.mark.parametrize("seed", range(8))
def test_per_pixel_lighting_agrees_on_float_targets(seed: int) -> None:
    ref, vertices, normals, faces = pixel_case(seed)
    scene = to_glshade(ref)
    projection = perspective(40.0, WIDTH / HEIGHT, 1.0, 10.0)
    targets = glpeers.rasterize(
        vertices, normals, faces, projection, WIDTH, HEIGHT, scene, normalize=ref.normalize
    )
    covered = targets.covered
    assert covered.sum() > 2000
    assert (targets.normal[covered][:, 3] < 0).sum() > 500, "the open mesh shows its inside"
    p = np.ascontiguousarray(targets.position[covered][:, :3])
    n = np.ascontiguousarray(targets.normal[covered][:, :3])
    front = targets.normal[covered][:, 3] > 0
    got = gs.shade(p, n, scene, normalize=ref.normalize).reshape(len(scene.outputs), -1, 4)
    # What a rasteriser shows: the front colours on front faces, the back ones on back faces.
    per_side = len(got) // (2 if ref.two_side else 1)
    shown = np.where(front[None, :, None], got[:per_side], got[per_side:]) if ref.two_side else got
    port = np.stack([targets.primary[covered], targets.secondary[covered]])[:per_side]
    # The bound covers both sides (its magnitude is the larger of the two).
    compared = check(ref, p, n, shown, port, f"seed {seed}")
    assert compared >= 0.95 * covered.sum()


def test_rasterised_geometry_is_where_the_projection_puts_it() -> None:
    """glpeers.rasterize's contract: positions project to their pixel centres, the depth is
    their window z, uncovered pixels are 0 (depth 1)."""
    vertices, normals, faces = eye_mesh(1)
    projection = perspective(40.0, WIDTH / HEIGHT, 1.0, 10.0)
    targets = glpeers.rasterize(vertices, normals, faces, projection, WIDTH, HEIGHT)
    covered = targets.covered
    rows, cols = np.nonzero(covered)
    clip = np.c_[targets.position[covered][:, :3], np.ones(len(rows))] @ projection.T
    ndc = clip[:, :3] / clip[:, 3:]
    np.testing.assert_allclose((ndc[:, 0] + 1) * WIDTH / 2, cols + 0.5, atol=1e-3)
    np.testing.assert_allclose((ndc[:, 1] + 1) * HEIGHT / 2, HEIGHT - rows - 0.5, atol=1e-3)
    np.testing.assert_allclose(targets.depth[covered], (ndc[:, 2] + 1) / 2, atol=1e-6)
    assert (targets.position[~covered] == 0).all() and (targets.normal[~covered] == 0).all()
    assert (targets.depth[~covered] == 1).all()
    assert set(np.unique(targets.normal[covered][:, 3])) == {-1.0, 1.0}


def test_flat_shading_shows_each_triangles_last_vertex_colour() -> None:
    """shading="flat" lights per vertex in the vertex shader: every pixel shows glshade's
    colour of a mesh vertex (GL's provoking vertex, the triangle's last)."""
    ref, vertices, normals, faces = pixel_case(1)
    scene = to_glshade(ref)
    projection = perspective(40.0, WIDTH / HEIGHT, 1.0, 10.0)
    targets = glpeers.rasterize(
        vertices, normals, faces, projection, WIDTH, HEIGHT, scene, shading="flat"
    )
    lit = gs.shade(vertices.astype(np.float32), normals.astype(np.float32), scene)
    provoking = np.unique(faces[:, 2])
    colours = lit[provoking] if lit.ndim == 2 else lit[0, provoking]
    shown = targets.primary[targets.covered & (targets.normal[..., 3] > 0)]
    distance = np.abs(shown[:, None, :] - colours[None, :, :]).max(axis=2).min(axis=1)
    assert len(shown) > 500
    assert distance.max() <= TOL
