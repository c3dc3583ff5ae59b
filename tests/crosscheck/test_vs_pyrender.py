"""glshade and trimesh against pyrender, the renderer trimesh users already have.

pyrender is glTF PBR with gamma, always 4x MSAA into an 8-bit colour buffer, and its depth
image is MSAA sample 0 blitted with GL_NEAREST: its colours are not
the GL equation's and nothing it returns is a float colour. What is comparable, on trimesh
meshes with a cap cut off (so that back faces show) and random scenes of scenes.py:

- Geometry, from stock pyrender (its own shaders): its depth image against rays cast through
  each pixel's sample 0 (llvmpipe's 4x pattern puts it at (-1/8, +3/8) px from the centre, in
  image rows-down coordinates) onto trimesh's triangles, within two 24-bit depth quanta plus
  the depth's slope times llvmpipe's 1/256-px vertex snapping; its coverage against whether
  such a ray hits. Rays within 1/128 px of a silhouette or an occluding edge are left out.
  Through the pixel centres instead, the comparison fails (the offset is real).
- Primitive ids, normals and lighting, through our shaders in pyrender's program cache
  (glsl/pyrender.vert and .frag on glsl/ff_lighting.glsl): pyrender's buffers, matrices and
  draw calls, our fragment outputs, on the pixels whose centre and four samples (each moved
  by 1/128 px either way) all hit one face: MSAA then averages four equal samples, the
  fragment's value at the centre. There pyrender's gl_PrimitiveID is the face the rays hit;
  its 8-bit eye normal is trimesh's vertex normals interpolated at the hit (perspective-correct
  barycentrics are the hit's) within rounding, 0.5/255; and glshade, shading the hit point and
  that normal, gives pyrender's 8-bit colour within 0.5/255 plus the float32 bound of
  glpeers.float32_tolerance (1e-5 for well-conditioned pixels). Measured: 0.500/255 at most.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest
from conftest import require

import glshade as gs
from support import glpeers
from support.gl_reference import RefScene
from support.pyrender_rays import (
    HEIGHT,
    ROUNDING,
    SAMPLES,
    SNAP,
    WIDTH,
    ZFAR,
    ZNEAR,
    interior,
    mesh,
    pixel_rays,
    pyrender_scene,
    ray_cast,
    shading_normals,
)
from support.scenes import random_case, to_glshade

pytestmark = pytest.mark.gl

trimesh = require("trimesh")
pyrender = require("pyrender")


@pytest.fixture(scope="module")
def renderer() -> Any:
    def make() -> Any:
        return pyrender.OffscreenRenderer(WIDTH, HEIGHT)

    r = glpeers.gl_resource("pyrender OffscreenRenderer (EGL)", make)
    yield r
    r.delete()


def test_depth_and_coverage_are_the_rays_through_sample_0(renderer: Any) -> None:
    h = SNAP
    for seed in range(3):
        m = mesh(seed)
        scene, projection = pyrender_scene(m)
        # Stock pyrender (its own shaders), culling off: the rays see back faces too.
        _, depth = renderer.render(scene, flags=pyrender.RenderFlags.SKIP_CULL_FACES)
        at = ray_cast(m, projection, SAMPLES[0])
        z, hit = at.depth, at.face >= 0
        nearby = [
            ray_cast(m, projection, (SAMPLES[0][0] + dx, SAMPLES[0][1] + dy))
            for dx, dy in ((h, 0), (-h, 0), (0, h), (0, -h))
        ]
        # Coverage and depth are decided at sample 0; rays within h of a silhouette or of an
        # occluding edge (a nearby ray's depth off the plane of this pixel's face) are left out.
        tri = m.triangles[at.face]
        plane = np.cross(tri[..., 1, :] - tri[..., 0, :], tri[..., 2, :] - tri[..., 0, :])
        offset = np.einsum("...j,...j", plane, tri[..., 0, :])
        edge = np.zeros_like(hit)
        for (dx, dy), near in zip(((h, 0), (-h, 0), (0, h), (0, -h)), nearby, strict=True):
            ray = pixel_rays(projection, (SAMPLES[0][0] + dx, SAMPLES[0][1] + dy))
            with np.errstate(divide="ignore", invalid="ignore"):
                on_plane = offset / np.einsum("...j,...j", plane, ray) * -ray[..., 2]
            edge |= ((near.face >= 0) != hit) | (hit & ~(np.abs(near.depth - on_plane) < 1e-3))
        assert hit.sum() > 1000 and (~edge).sum() > 0.98 * hit.size
        np.testing.assert_array_equal(depth[~edge] > 0, hit[~edge])
        z_near = [near.depth for near in nearby]
        # Depth: two quanta of the 24-bit window depth, as eye depth; llvmpipe snaps vertices
        # to 1/256 px, which moves the depth by the slope times that; float32 rounding.
        inner = hit & ~edge
        slope = np.max([np.abs(zn[inner] - z[inner]) for zn in z_near], axis=0) / h
        zi = z[inner]
        bound = 2 * 2.0**-24 * (ZFAR - ZNEAR) * zi**2 / (ZFAR * ZNEAR) + slope / 256 + 1e-6 * zi
        error = np.abs(depth[inner] - zi)
        assert (error <= bound).all(), (error / bound).max()
        # Through the pixel centres instead, the same comparison fails: the offset is real.
        z_centre = ray_cast(m, projection, (0.0, 0.0)).depth[inner]
        assert (np.abs(depth[inner] - z_centre) > 10 * bound).mean() > 0.5


# --- our shaders in pyrender's program cache -------------------------------------------------


class FixedFunctionProgram(pyrender.shader_program.ShaderProgram):  # type: ignore[misc]
    """pyrender's program wrapper around glsl/pyrender.vert and .frag with glshade.glsl's
    lighting library; on bind it also loads the uniforms of `state` (the scene's
    gs.glsl.Shaders and ff_output)."""

    def __init__(self, defines: dict[str, Any], state: dict[str, Any]) -> None:
        super().__init__("pyrender.vert", "pyrender.frag", defines=defines)
        self.state = state

    def _load(self, shader_filename: str) -> str:
        defines = {k: v for k, v in self.defines.items() if k in ("NORMAL_LOC", "INST_M_LOC")}
        return glpeers.pyrender_source(self.state["shaders"], shader_filename, **defines)

    def _bind(self) -> None:
        super()._bind()
        glpeers.set_uniforms_gl(
            self._program_id, self.state["shaders"], {"ff_output": self.state["output"]}
        )


class FixedFunctionCache(pyrender.shader_program.ShaderProgramCache):  # type: ignore[misc]
    """A program cache that answers every request with our program."""

    def __init__(self, state: dict[str, Any]) -> None:
        super().__init__()
        self.state = state

    def get_program(
        self,
        vertex_shader: str,
        fragment_shader: str,
        geometry_shader: str | None = None,
        defines: dict[str, Any] | None = None,
    ) -> FixedFunctionProgram:
        key = (self.state["shaders"].library, *sorted((defines or {}).items()))
        if key not in self._program_cache:
            self._program_cache[key] = FixedFunctionProgram(dict(defines or {}), self.state)
        program: FixedFunctionProgram = self._program_cache[key]
        return program


def render_ours(renderer: Any, scene: Any, state: dict[str, Any], output: int) -> np.ndarray:
    """(HEIGHT, WIDTH, 3) uint8: pyrender's render with our program, `output` as in
    glsl/pyrender.frag; faces are not culled (two-sided scenes show their backs)."""
    state["output"] = output
    previous = renderer._renderer._program_cache
    renderer._renderer._program_cache = FixedFunctionCache(state)
    try:
        color, _ = renderer.render(scene, flags=pyrender.RenderFlags.SKIP_CULL_FACES)
    finally:
        renderer._renderer._program_cache.clear()
        renderer._renderer._program_cache = previous
    return np.asarray(color)


def primitive_ids(renderer: Any, scene: Any, state: dict[str, Any]) -> np.ndarray:
    """(HEIGHT, WIDTH) the index of the face pyrender drew at each pixel (gl_PrimitiveID)."""
    rgb = render_ours(renderer, scene, state, output=2).astype(np.int64)
    return rgb[..., 0] + (rgb[..., 1] << 8) + (rgb[..., 2] << 16) - 1


def scene_state(ref: RefScene) -> dict[str, Any]:
    scene = to_glshade(ref)
    return {"shaders": gs.glsl.raster_shaders(scene, normalize=ref.normalize), "output": 0}


def lit_case(seed: int) -> RefScene:
    """A random scene of scenes.py without what a mesh in eye space has no use for here
    (modelview, rescale, colour material)."""
    ref = random_case(seed, 1, np.float32).ref
    ref.modelview, ref.rescale_normal, ref.colors, ref.color_material = None, False, None, None
    return ref


@pytest.mark.parametrize("seed", range(3))
def test_primitive_ids_and_normals_are_trimeshs(renderer: Any, seed: int) -> None:
    m = mesh(seed)
    scene, _ = pyrender_scene(m)
    state = scene_state(lit_case(seed))
    centre, inside = interior(seed)
    assert inside.sum() > 2000
    # Geometry: the triangle pyrender drew at an interior pixel is the one the rays hit.
    np.testing.assert_array_equal(
        primitive_ids(renderer, scene, state)[inside], centre.face[inside]
    )
    # Normals: pyrender's interpolated eye normal, 8-bit, against trimesh's.
    encoded = render_ours(renderer, scene, state, output=1)[inside] / 255.0
    normals = shading_normals(m, centre)[inside]
    unit = normals / np.linalg.norm(normals, axis=1, keepdims=True)
    assert np.abs(encoded - (unit / 2 + 0.5)).max() <= ROUNDING + 1e-6  # float32 normalize


@pytest.mark.parametrize("seed", range(6))
def test_lighting_in_pyrender_agrees_within_8_bit_rounding(renderer: Any, seed: int) -> None:
    ref = lit_case(seed)
    m = mesh(seed)
    scene, _ = pyrender_scene(m)
    state = scene_state(ref)
    centre, inside = interior(seed)
    color = render_ours(renderer, scene, state, output=0)[inside] / 255.0
    # The facing of the hit triangle: counter-clockwise seen from the eye is front.
    tri = m.triangles[centre.face[inside]]
    normal = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    front = np.einsum("ij,ij->i", normal, -tri[:, 0]) > 0
    p = centre.point[inside].astype(np.float32)
    n = shading_normals(m, centre)[inside].astype(np.float32)
    got = gs.shade(p, n, to_glshade(ref), normalize=ref.normalize).reshape(-1, len(p), 4)
    per_side = 2 if ref.separate_specular else 1
    side = np.where(front[None, :, None], got[:per_side], got[per_side:]) if ref.two_side else got
    summed = side[0, :, :3] + (side[1, :, :3] if ref.separate_specular else 0.0)
    expected = np.clip(summed, 0.0, 1.0)
    tolerance = glpeers.float32_tolerance(ref, p, n)
    compared = tolerance.comparable
    assert compared.sum() > 2000
    err = np.abs(color - expected).max(axis=1)
    bound = ROUNDING + tolerance.bound  # 8-bit rounding plus the float32 bound
    bad = np.flatnonzero(compared & (err > bound))
    assert not bad.size, (err[bad].max() * 255, seed)
