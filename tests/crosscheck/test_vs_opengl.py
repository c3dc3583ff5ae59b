"""glshade against Mesa's own fixed-function pipeline: real OpenGL, not a port of the equation.

An EGL compatibility-profile context on llvmpipe gets the scene as glLight*/glMaterial*/
glLightModel* state (glpeers.load_fixed_function, lights specified under an identity modelview:
eye space), the vertices as client arrays with glLoadMatrix'd modelview, GL_NORMALIZE,
GL_RESCALE_NORMAL and GL_COLOR_MATERIAL as asked, and returns its lit, clamped per-vertex
colours as floats:

- GL_FEEDBACK render mode with GL_4D_COLOR_TEXTURE: points give the front colour; triangles,
  once with glFrontFace(GL_CCW) and once with GL_CW, give each vertex its front and its back
  colour (two-sided lighting picks by the facing of the polygon). The texture coordinate
  carries the vertex index, so the order of the feedback buffer does not matter.
- What feedback returns with GL_SEPARATE_SPECULAR_COLOR, measured: the primary colour only
  (without the specular sum), with or without GL_COLOR_SUM; the feedback buffer has no slot
  for the secondary colour. The secondary colours are therefore read by rasterising: one
  flat-shaded triangle per vertex, with that vertex last (GL's provoking vertex), covering
  exactly the centre of its own pixel of an RGBA32F framebuffer, under a fragment shader that
  writes gl_Color and gl_SecondaryColor (fixed-function vertex processing, programmable
  fragments, allowed by the compatibility profile). Points cannot carry back colours, so the
  triangles' winding picks the side.

Tolerance (glpeers.float32_tolerance): 1e-5 per channel where the channel's terms add up to at
most 1 in magnitude (most vertices), 1e-5 times that sum above; plus 2 u s |specular term|, the
conditioning of Mesa's pow(n.h, s) on the float32 rounding of n.h (measured: at s = 128 Mesa is
up to 1.3e-5 from the exact value where glshade is within 3e-7; of 1.2 million rasterised vertex
colours, 4 exceeded the first term, by at most 0.35 u s |specular|). Not compared: vertices
within MARGIN of a discontinuity (n.VP = 0 for f_i, a cone edge where Mesa's SLT is a strict >
and the spec's test >=, a point light), where the inputs' own float32 rounding picks the side;
and vertices whose specular power exceeds float32's range (non-unit normals: (5 n.h)^100 is inf
in float32, and Mesa's 0 * inf = NaN where att * spot = 0 shows as 1; the exact value is finite).

Where Mesa departs from the spec,
the inputs concerned are excluded, each for its reason, and a test at the end pins what Mesa
computes there instead (Mesa 22.3.6; the code is src/mesa/main/ffvertex_prog.c):

1. Shininess 0 (on every lit side) with a light that has a spot or distance attenuation: Mesa's
   specular factor is (n.VP)^(n.VP) for n.VP > 0, not 0^0 = 1 (the notes' addendum saw it as
   "0" with positional lights). With material_shininess_is_zero, build_lighting writes n.VP to
   all four components of `dots`; for lights with an attenuation term it then runs
   `LIT dots`, whose exponent dots.w is n.VP instead of the shininess. Lights without spot or
   attenuation take emit_degenerate_lit and are exact.
2. Shininess 0 on one side while the other side's is not (two-sided lighting): LIT runs with
   exponent 0 and llvmpipe's pow(0, 0) is 0, so where n.VP > 0 and n.h <= 0 the specular term
   is 0, not f_i 0^0 s_cm s_cli (in its old C path).
3. Spot cutoff 90 with exponent 0: GL's cos(90) is exactly 0, so a vertex behind the cone's
   plane has spot = 0^0 = 1 (the spec in exact arithmetic, and glshade's documented
   convention); Mesa's SLT(cos cutoff, -VP.s) leaves it outside (spot = 0).

Every scene is drawn from the generators of scenes.py; each feature combination has at least
10^4 compared vertices.
"""

from __future__ import annotations

import ctypes
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np
import pytest
from conftest import require

import glshade as gs
from support import glpeers
from support.gl_reference import RefScene, dot, eye_space, gl_lighting, unit
from support.scenes import random_light, random_material, random_modelview, shade_kwargs, to_glshade

pytestmark = pytest.mark.gl

GL = require("OpenGL.GL")
from OpenGL.raw.GL.VERSION import GL_1_0, GL_1_1  # noqa: E402  (after require: may be absent)

TOL = 1e-5
MARGIN = 2e-5  # distance to a discontinuity below which the inputs' rounding picks the side
SCENES = 24
VERTICES = 720  # a multiple of 3 (triangles); SCENES * VERTICES >= 10^4 after exclusions
GRID = 64  # mesa_rasterised draws GRID^2 vertices per scene
SEPARATE_SCENES = 4
EYE_BOUND = 16.0  # |eye coordinates| stay below this: nothing is clipped
GRID_HALF_WIDTH = 1.5  # mesa_rasterised's pixel grid covers [-1.5, 1.5]^2 of eye space


@pytest.fixture(scope="module", autouse=True)
def compat() -> glpeers.CompatContext:
    return glpeers.compat_context()


# --- scenes -----------------------------------------------------------------------------------


def is_spot(light: dict[str, Any]) -> bool:
    return light.get("spot_cutoff", 180.0) != 180.0


def is_attenuated(light: dict[str, Any]) -> bool:
    k = tuple(
        light.get(f"{k}_attenuation", d)
        for k, d in (("constant", 1), ("linear", 0), ("quadratic", 0))
    )
    return light["position"][3] != 0 and k != (1, 0, 0)


LIGHT_KINDS: dict[str, Callable[[dict[str, Any]], bool]] = {
    "directional": lambda lt: lt["position"][3] == 0 and not is_spot(lt),
    "positional": lambda lt: lt["position"][3] != 0 and not is_spot(lt) and not is_attenuated(lt),
    "attenuated": lambda lt: is_attenuated(lt) and not is_spot(lt),
    "spot": is_spot,
    "any": lambda lt: True,
}


@dataclass
class Combo:
    """A feature combination: which lights, and which GL state is on."""

    kinds: tuple[str, ...] = ("any",)
    local_viewer: bool | None = False  # None: either
    two_side: bool = False
    separate_specular: bool = False
    color_material: bool = False
    modelview: bool = False
    normalize: bool = False
    rescale_normal: bool = False


COMBOS = {
    "directional": Combo(kinds=("directional",)),
    "positional": Combo(kinds=("positional",)),
    "attenuated": Combo(kinds=("attenuated",)),
    "spot": Combo(kinds=("spot",)),
    "mixed lights, local viewer": Combo(local_viewer=True),
    "two-sided": Combo(two_side=True, local_viewer=None),
    "color material": Combo(color_material=True, local_viewer=None),
    "modelview, non-uniform scale": Combo(modelview=True, local_viewer=None),
    "modelview + normalize": Combo(modelview=True, normalize=True, local_viewer=None),
    "modelview + rescale_normal": Combo(modelview=True, rescale_normal=True, local_viewer=None),
}


@dataclass
class GLCase:
    ref: RefScene
    scene: gs.Scene
    kwargs: dict[str, Any]
    positions: np.ndarray  # float32, model space
    normals: np.ndarray
    colors: np.ndarray | None


def light_of_kind(rng: np.random.Generator, kind: str) -> dict[str, Any]:
    """A light of scenes.random_light, redrawn until it is of `kind`."""
    while not LIGHT_KINDS[kind](light := random_light(rng)):
        pass
    return light


def gl_case(seed: int, combo: Combo, n: int, grid: int = 0) -> GLCase:
    """A random scene of GL's features only (<= 8 lights, Blinn, infinite or local viewer).

    With `grid` > 0 the vertices are laid out for `mesa_rasterised`: vertex i lies in eye
    space just above the centre of pixel (i % grid, i // grid) of a grid x grid viewport over
    [-1.5, 1.5]^2 (the positions are M^-1 of that when there is a modelview).
    """
    rng = np.random.default_rng(seed)
    lights = [light_of_kind(rng, str(rng.choice(combo.kinds))) for _ in range(rng.integers(1, 9))]
    local = bool(rng.random() < 0.5) if combo.local_viewer is None else combo.local_viewer
    ref = RefScene(
        lights=lights,
        material=random_material(rng),
        back_material=random_material(rng) if combo.two_side else None,
        global_ambient=(*rng.uniform(0.0, 0.4, 3), 1.0),
        viewer=(0.0, 0.0, 0.0, 1.0) if local else (0.0, 0.0, 1.0, 0.0),
        two_side=combo.two_side,
        separate_specular=combo.separate_specular,
        modelview=random_modelview(rng) if combo.modelview else None,
        normalize=combo.normalize,
        rescale_normal=combo.rescale_normal,
    )
    positions = rng.uniform(-1.5, 1.5, (n, 3))
    if grid:
        cell = 2 * GRID_HALF_WIDTH / grid
        pixel = np.c_[np.arange(n) % grid, np.arange(n) // grid] + 0.5
        offset = np.c_[rng.uniform(-0.05, 0.05, n), rng.uniform(0.15, 0.4, n)]
        positions[:, :2] = (pixel + offset) * cell - GRID_HALF_WIDTH
        if ref.modelview is not None:
            eye = np.c_[positions, np.ones(n)]
            positions = (eye @ np.linalg.inv(ref.modelview).T)[:, :3]
    normals = rng.normal(size=(n, 3))
    if ref.normalize:
        normals *= rng.uniform(0.01, 10.0, (n, 1)) / np.linalg.norm(normals, axis=1, keepdims=True)
    else:
        normals /= np.linalg.norm(normals, axis=1, keepdims=True)
    if combo.color_material:
        modes = list(glpeers.COLOR_MATERIAL_MODES)[1:]  # every mode and face in 15 seeds
        ref.color_material = str(modes[seed % len(modes)])
        ref.color_material_face = list(glpeers.COLOR_MATERIAL_FACES)[seed // len(modes) % 3]
        ref.colors = rng.uniform(-0.1, 1.0, (n, int(rng.choice([3, 4])))).astype(np.float32)
    return GLCase(
        ref,
        to_glshade(ref),
        shade_kwargs(ref),
        positions.astype(np.float32),
        normals.astype(np.float32),
        ref.colors,
    )


# --- Mesa -------------------------------------------------------------------------------------


def load(case: GLCase) -> None:
    glpeers.load_fixed_function(
        case.scene,
        normalize=case.ref.normalize,
        rescale_normal=case.ref.rescale_normal,
        color_material=case.ref.color_material,
        color_material_face=case.ref.color_material_face,
    )


def set_arrays(
    positions: np.ndarray, normals: np.ndarray, colors: np.ndarray | None, modelview: Any
) -> list[np.ndarray]:
    """Client arrays (vertex, normal, colour, texcoord = index) and the matrices: the
    projection only scales eye space into the clip volume, the modelview is the case's."""
    n = len(positions)
    index = np.zeros((n, 4), np.float32)
    index[:, 0] = np.arange(n)
    index[:, 3] = 1.0
    arrays = [np.ascontiguousarray(a, np.float32) for a in (positions, normals, index)]
    GL.glMatrixMode(GL.GL_PROJECTION)
    GL.glLoadIdentity()
    GL.glScaled(1 / EYE_BOUND, 1 / EYE_BOUND, 1 / EYE_BOUND)
    GL.glMatrixMode(GL.GL_MODELVIEW)
    GL.glLoadMatrixd(np.eye(4) if modelview is None else np.asarray(modelview, np.float64).T.copy())
    GL_1_1.glEnableClientState(GL.GL_VERTEX_ARRAY)
    GL_1_1.glVertexPointer(3, GL.GL_FLOAT, 0, arrays[0].ctypes.data_as(ctypes.c_void_p))
    GL_1_1.glEnableClientState(GL.GL_NORMAL_ARRAY)
    GL_1_1.glNormalPointer(GL.GL_FLOAT, 0, arrays[1].ctypes.data_as(ctypes.c_void_p))
    GL_1_1.glEnableClientState(GL.GL_TEXTURE_COORD_ARRAY)
    GL_1_1.glTexCoordPointer(4, GL.GL_FLOAT, 0, arrays[2].ctypes.data_as(ctypes.c_void_p))
    if colors is None:
        GL_1_1.glDisableClientState(GL.GL_COLOR_ARRAY)
    else:
        c = np.ascontiguousarray(colors, np.float32)
        arrays.append(c)
        GL_1_1.glEnableClientState(GL.GL_COLOR_ARRAY)
        GL_1_1.glColorPointer(c.shape[1], GL.GL_FLOAT, 0, c.ctypes.data_as(ctypes.c_void_p))
    return arrays  # keep alive until the draw


def feedback(case: GLCase, primitive: int) -> np.ndarray:
    """The feedback buffer of one glDrawArrays of all vertices: (records, 12) floats per
    vertex (window x, y, z, w, RGBA, texcoord) in the order GL returns them."""
    n = len(case.positions)
    arrays = set_arrays(case.positions, case.normals, case.colors, case.ref.modelview)
    GL.glViewport(0, 0, 4096, 4096)
    size = n * 13 + 64
    buffer = np.zeros(size, np.float32)
    GL_1_0.glFeedbackBuffer(
        size, GL.GL_4D_COLOR_TEXTURE, buffer.ctypes.data_as(ctypes.POINTER(ctypes.c_float))
    )
    GL_1_0.glRenderMode(GL.GL_FEEDBACK)
    GL_1_1.glDrawArrays(primitive, 0, n)
    used = GL_1_0.glRenderMode(GL.GL_RENDER)
    assert GL.glGetError() == GL.GL_NO_ERROR
    del arrays
    assert used >= 0, "feedback buffer overflow"
    if primitive == GL.GL_POINTS:
        records = buffer[:used].reshape(n, 13)
        assert (records[:, 0] == GL.GL_POINT_TOKEN).all()
        return records[:, 1:]
    records = buffer[:used].reshape(n // 3, 38)  # token, count 3, 3 vertices of 12
    assert (records[:, 0] == GL.GL_POLYGON_TOKEN).all() and (records[:, 1] == 3).all()
    return records[:, 2:].reshape(n, 12)


def by_index(rows: np.ndarray) -> np.ndarray:
    """RGBA per vertex index (texcoord s)."""
    out = np.full((len(rows), 4), np.nan, np.float32)
    out[rows[:, 8].astype(np.int64)] = rows[:, 4:8]
    return out


def mesa_front(case: GLCase) -> np.ndarray:
    """Mesa's front primary colour of every vertex, (n, 4), from feedback of points."""
    load(case)
    return by_index(feedback(case, GL.GL_POINTS))


def mesa_two_sided(case: GLCase) -> tuple[np.ndarray, np.ndarray]:
    """Mesa's front and back primary colours, (n, 4) each, from feedback of triangles
    (vertices 3k, 3k+1, 3k+2) drawn with each winding counted as front in turn."""
    load(case)
    front = np.full((len(case.positions), 4), np.nan, np.float32)
    back = front.copy()
    for front_face in (GL.GL_CCW, GL.GL_CW):
        GL.glFrontFace(front_face)
        rows = feedback(case, GL.GL_TRIANGLES)
        xy = rows[:, :2].reshape(-1, 3, 2).astype(np.float64)
        e1, e2 = xy[:, 1] - xy[:, 0], xy[:, 2] - xy[:, 0]
        area = e1[:, 0] * e2[:, 1] - e1[:, 1] * e2[:, 0]  # counter-clockwise > 0
        facing_front = np.repeat(area > 0 if front_face == GL.GL_CCW else area < 0, 3)
        index = rows[:, 8].astype(np.int64)
        front[index[facing_front]] = rows[facing_front, 4:8]
        back[index[~facing_front & (np.repeat(area, 3) != 0)]] = rows[
            ~facing_front & (np.repeat(area, 3) != 0), 4:8
        ]
    GL.glFrontFace(GL.GL_CCW)
    return front, back


SECONDARY_FRAGMENT_SHADER = """
#version 120
void main() {
    gl_FragData[0] = gl_Color;           // the lit primary colour of the provoking vertex
    gl_FragData[1] = gl_SecondaryColor;  // and its secondary colour
}
"""


class Rasteriser:
    """RGBA32F targets for the primary and secondary colours in the compatibility context."""

    def __init__(self, grid: int) -> None:
        from OpenGL.GL import shaders

        self.grid = grid
        self.program = shaders.compileProgram(
            shaders.compileShader(SECONDARY_FRAGMENT_SHADER, GL.GL_FRAGMENT_SHADER)
        )
        self.framebuffer = GL.glGenFramebuffers(1)
        GL.glBindFramebuffer(GL.GL_FRAMEBUFFER, self.framebuffer)
        self.renderbuffers = GL.glGenRenderbuffers(2)
        for i, rb in enumerate(self.renderbuffers):
            GL.glBindRenderbuffer(GL.GL_RENDERBUFFER, rb)
            GL.glRenderbufferStorage(GL.GL_RENDERBUFFER, GL.GL_RGBA32F, grid, grid)
            GL.glFramebufferRenderbuffer(
                GL.GL_FRAMEBUFFER, GL.GL_COLOR_ATTACHMENT0 + i, GL.GL_RENDERBUFFER, rb
            )
        assert GL.glCheckFramebufferStatus(GL.GL_FRAMEBUFFER) == GL.GL_FRAMEBUFFER_COMPLETE

    def draw(self, case: GLCase, front_face: int) -> tuple[np.ndarray, np.ndarray]:
        """(n, 4) primary and secondary colours of the side `front_face` makes visible."""
        n = len(case.positions)
        g = self.grid
        cell = 2 * GRID_HALF_WIDTH / g
        V, _ = eye_space(case.positions, case.normals, case.ref)
        # Per vertex i, a triangle (left, right, i): two helper vertices below its pixel centre
        # and i above it, counter-clockwise; flat shading colours it with vertex i's colours.
        centre = (np.c_[np.arange(n) % g, np.arange(n) // g] + 0.5) * cell - GRID_HALF_WIDTH
        tri = np.repeat(np.c_[V, np.ones(n)], 3, axis=0).reshape(n, 3, 4)
        tri[:, 0, :2] = centre + np.array([-0.45, -0.4]) * cell
        tri[:, 1, :2] = centre + np.array([0.45, -0.4]) * cell
        if case.ref.modelview is not None:
            tri = tri @ np.linalg.inv(case.ref.modelview).T
        tri[:, 2, :3] = case.positions  # vertex i itself, exactly as glshade sees it
        normals = np.repeat(case.normals, 3, axis=0)
        colors = None if case.colors is None else np.repeat(case.colors, 3, axis=0)
        arrays = set_arrays(tri[..., :3].reshape(-1, 3), normals, colors, case.ref.modelview)
        GL.glMatrixMode(GL.GL_PROJECTION)
        GL.glLoadIdentity()
        GL.glOrtho(
            -GRID_HALF_WIDTH,
            GRID_HALF_WIDTH,
            -GRID_HALF_WIDTH,
            GRID_HALF_WIDTH,
            -EYE_BOUND,
            EYE_BOUND,
        )
        GL.glBindFramebuffer(GL.GL_FRAMEBUFFER, self.framebuffer)
        GL.glDrawBuffers(2, [GL.GL_COLOR_ATTACHMENT0, GL.GL_COLOR_ATTACHMENT1])
        GL.glViewport(0, 0, g, g)
        GL.glClearColor(-1.0, -1.0, -1.0, -1.0)
        GL.glClear(GL.GL_COLOR_BUFFER_BIT)
        GL.glUseProgram(self.program)
        GL.glShadeModel(GL.GL_FLAT)
        GL.glFrontFace(front_face)
        GL_1_1.glDrawArrays(GL.GL_TRIANGLES, 0, 3 * n)
        images = []
        for i in range(2):
            GL.glReadBuffer(GL.GL_COLOR_ATTACHMENT0 + i)
            pixels = np.zeros((g, g, 4), np.float32)
            GL_1_0.glReadPixels(
                0, 0, g, g, GL.GL_RGBA, GL.GL_FLOAT, pixels.ctypes.data_as(ctypes.c_void_p)
            )
            images.append(pixels.reshape(-1, 4)[:n])
        GL.glUseProgram(0)
        GL.glShadeModel(GL.GL_SMOOTH)
        GL.glFrontFace(GL.GL_CCW)
        assert GL.glGetError() == GL.GL_NO_ERROR
        del arrays
        assert (images[0] >= 0).all(), "every vertex's pixel is covered by its triangle"
        return images[0], images[1]


def mesa_rasterised(rasteriser: Rasteriser, case: GLCase) -> list[np.ndarray]:
    """Mesa's colours in gs.shade's order (scene.outputs): front primary and secondary, then
    the back ones with two-sided lighting."""
    load(case)
    outputs = list(rasteriser.draw(case, GL.GL_CCW))
    if case.ref.two_side:
        outputs += rasteriser.draw(case, GL.GL_CW)
    return outputs


# --- comparison -----------------------------------------------------------------------------

SHININESS_0_ATTENUATED = "shininess 0, spot or attenuated light, n.VP > 0"
SHININESS_0_LIT = "shininess 0 beside a shininess > 0, n.VP > 0, n.h <= 0"
CUTOFF_90 = "cutoff 90, exponent 0, on or behind the cone's plane"


def mesa_departures(case: GLCase) -> dict[str, np.ndarray]:
    """Per departure of the module docstring, the vertices (of either side) it concerns."""
    ref = case.ref
    V, n = eye_space(case.positions, case.normals, ref)
    sides = [(n, ref.material)]
    if ref.two_side:
        sides.append((-n, ref.back_material or ref.material))
    # Mesa's state key: the shininess "is zero" when no side it lights has a nonzero one.
    shininess_is_zero = all(m["shininess"] == 0 for _, m in sides)
    VPe = np.broadcast_to([0.0, 0.0, 1.0], V.shape) if ref.viewer[3] == 0 else unit(-V)
    found = {
        k: np.zeros(len(V), bool) for k in (SHININESS_0_ATTENUATED, SHININESS_0_LIT, CUTOFF_90)
    }
    for light in ref.lights:
        p = np.asarray(light["position"], np.float64)
        VP = np.broadcast_to(unit(p[:3]), V.shape) if p[3] == 0 else unit(p[:3] / p[3] - V)
        for normal, material in sides:
            if material["shininess"] != 0:
                continue
            lit = dot(normal, VP) > 0
            if shininess_is_zero and (is_spot(light) or is_attenuated(light)):
                found[SHININESS_0_ATTENUATED] |= lit
            elif not shininess_is_zero:
                found[SHININESS_0_LIT] |= lit & (dot(normal, unit(VP + VPe)) <= MARGIN)
        if light.get("spot_cutoff") == 90.0 and light.get("spot_exponent", 0.0) == 0.0:
            s = unit(np.asarray(light["spot_direction"], np.float64))
            found[CUTOFF_90] |= dot(-VP, s) <= MARGIN
    return found


def check(case: GLCase, got: np.ndarray, mesa: list[np.ndarray]) -> int:
    """Asserts |glshade - Mesa| within glpeers.float32_tolerance on every compared vertex and
    output; returns the number of vertex-output pairs compared."""
    tolerance = glpeers.float32_tolerance(case.ref, case.positions, case.normals, TOL, MARGIN)
    compared = tolerance.comparable & ~np.logical_or.reduce(list(mesa_departures(case).values()))
    rows = glpeers.assert_agree(tolerance, got, np.stack(mesa), compared, "Mesa", case.ref)
    return rows * len(mesa)


@pytest.mark.parametrize("name", list(COMBOS))
def test_feedback_colours_agree_with_mesa(name: str) -> None:
    combo = COMBOS[name]
    compared = 0
    for seed in range(SCENES):
        case = gl_case(seed, combo, VERTICES)
        got = gs.shade(case.positions, case.normals, case.scene, **case.kwargs)
        mesa = list(mesa_two_sided(case)) if combo.two_side else [mesa_front(case)]
        compared += check(case, got, mesa)
    assert compared >= 10_000 * (2 if combo.two_side else 1)


@pytest.mark.parametrize("two_side", [False, True], ids=["one-sided", "two-sided"])
def test_separate_specular_agrees_with_mesa(two_side: bool) -> None:
    """Primary and secondary colours, rasterised (feedback has no secondary colour)."""
    combo = Combo(separate_specular=True, two_side=two_side, local_viewer=None, kinds=("any",))
    rasteriser = Rasteriser(GRID)
    compared = 0
    for seed in range(SEPARATE_SCENES):
        case = gl_case(seed, combo, GRID * GRID, grid=GRID)
        got = gs.shade(case.positions, case.normals, case.scene, **case.kwargs)
        compared += check(case, got, mesa_rasterised(rasteriser, case))
    assert compared >= 10_000 * len(case.scene.outputs)


def test_feedback_returns_the_primary_colour_only() -> None:
    """With GL_SEPARATE_SPECULAR_COLOR, feedback returns the primary colour (no specular),
    with or without GL_COLOR_SUM: what this file relies on, measured."""
    case = gl_case(1, Combo(separate_specular=True), VERTICES)
    primary, secondary = gs.shade(case.positions, case.normals, case.scene, **case.kwargs)
    assert np.abs(secondary[:, :3]).max() > 0.1, "a scene with a visible secondary colour"
    for color_sum in (False, True):
        (GL.glEnable if color_sum else GL.glDisable)(GL.GL_COLOR_SUM)
        mesa = mesa_front(case)
        np.testing.assert_allclose(mesa, primary, rtol=0, atol=TOL)
    GL.glDisable(GL.GL_COLOR_SUM)


def test_the_combinations_cover_every_gl_feature() -> None:
    seen: set[str] = set()
    for combo in COMBOS.values():
        for seed in range(SCENES):
            ref = gl_case(seed, combo, 3).ref
            seen |= {
                f"local_viewer={ref.viewer[3] == 1}",
                f"two_side={ref.two_side}",
                f"modelview={ref.modelview is not None}",
                f"normalize={ref.normalize}",
                f"rescale_normal={ref.rescale_normal}",
                f"color_material={ref.color_material}/{ref.color_material_face}",
                f"shininess0={ref.material['shininess'] == 0}",
            }
            for light in ref.lights:
                kind = "directional" if light["position"][3] == 0 else "positional"
                seen.add(kind + (" attenuated" if is_attenuated(light) else ""))
                if is_spot(light):
                    seen.add(f"{kind} spot, cutoff 90: {light['spot_cutoff'] == 90}")
    expected = {
        "local_viewer=True",
        "local_viewer=False",
        "two_side=True",
        "modelview=True",
        "normalize=True",
        "rescale_normal=True",
        "shininess0=True",
        "shininess0=False",
        "directional",
        "positional",
        "positional attenuated",
        *(
            f"{k} spot, cutoff 90: {c}"
            for k in ("directional", "positional")
            for c in (False, True)
        ),
        *(
            f"color_material={m}/{f}"
            for m in list(glpeers.COLOR_MATERIAL_MODES)[1:]
            for f in glpeers.COLOR_MATERIAL_FACES
        ),
    }
    assert expected <= seen, expected - seen


# --- Mesa's departures, pinned ----------------------------------------------------------------

BLACK = {"ambient": (0, 0, 0), "diffuse": (0, 0, 0), "specular": (0, 0, 0)}


def departure_case(light: dict[str, Any], material: dict[str, Any], two_side: bool) -> GLCase:
    rng = np.random.default_rng(7)
    n = 3000
    ref = RefScene(
        lights=[light],
        material=material,
        back_material={**material, "shininess": 10.0} if two_side else None,
        global_ambient=(0, 0, 0),
        two_side=two_side,
    )
    normals = rng.normal(size=(n, 3))
    normals /= np.linalg.norm(normals, axis=1, keepdims=True)
    positions = rng.uniform(-1.5, 1.5, (n, 3)).astype(np.float32)
    return GLCase(ref, to_glshade(ref), {}, positions, normals.astype(np.float32), None)


def att_spot(case: GLCase) -> np.ndarray:
    """att_i * spot_i of the case's one light, from the oracle (its ambient term alone)."""
    ref = RefScene(
        lights=[{**case.ref.lights[0], **BLACK, "ambient": (1, 1, 1)}],
        material={**BLACK, "emission": (0, 0, 0), "ambient": (1, 1, 1), "shininess": 0.0},
        global_ambient=(0, 0, 0),
    )
    return gl_lighting(case.positions, case.normals, ref).unclamped[0][:, 0]


def test_mesa_shininess_0_with_spot_or_attenuation_uses_n_vp_as_the_exponent() -> None:
    """Departure 1: Mesa's specular factor is (n.VP)^(n.VP), where the spec has 0^0 = 1."""
    material = {**BLACK, "emission": (0, 0, 0), "specular": (0.5, 0.5, 0.5), "shininess": 0.0}
    for light in (
        {**BLACK, "specular": (1, 1, 1), "position": (1, 2, 3, 1), "linear_attenuation": 0.3},
        {**BLACK, "specular": (1, 1, 1), "position": (1, 2, 3, 0), "spot_cutoff": 60.0,
         "spot_direction": (-1, -2, -3)},
    ):  # fmt: skip
        case = departure_case(light, material, two_side=False)
        V, n = eye_space(case.positions, case.normals, case.ref)
        p = np.asarray(light["position"], np.float64)
        n_vp = dot(n, unit(p[:3] - V * p[3]))
        lit = (n_vp > MARGIN) & mesa_departures(case)[SHININESS_0_ATTENUATED]
        mesa = mesa_front(case)[:, 0]
        model = att_spot(case) * np.where(n_vp > 0, np.abs(n_vp) ** n_vp, 0.0) * 0.5
        spec = gl_lighting(case.positions, case.normals, case.ref).outputs[0][:, 0]
        assert lit.sum() > 1000
        np.testing.assert_allclose(mesa[lit], model[lit], rtol=0, atol=TOL)
        assert np.abs(spec - model)[lit].max() > 0.05, "the departure is real"


def test_mesa_shininess_0_beside_a_nonzero_one_gives_0_for_n_h_below_0() -> None:
    """Departure 2: two-sided, front shininess 0, back 10: LIT's pow(0, 0) is 0 in Mesa."""
    material = {**BLACK, "emission": (0, 0, 0), "specular": (0.5, 0.5, 0.5), "shininess": 0.0}
    light = {**BLACK, "specular": (1, 1, 1), "position": (1, 0, -0.8, 0)}
    case = departure_case(light, material, two_side=True)
    front, _ = mesa_two_sided(case)
    spec = gl_lighting(case.positions, case.normals, case.ref).outputs[0][:, 0]
    hit = mesa_departures(case)[SHININESS_0_LIT]
    assert hit.sum() > 100
    np.testing.assert_array_equal(front[hit, 0], 0.0)
    np.testing.assert_allclose(spec[hit], 0.5)  # f_i 0^0 s_cm s_cli


def test_mesa_cutoff_90_exponent_0_leaves_the_back_half_space_dark() -> None:
    """Departure 3: behind a 90-degree spot's plane, spot = 0^0 = 1 (glshade), 0 (Mesa)."""
    material = {**BLACK, "emission": (0, 0, 0), "ambient": (1, 1, 1), "shininess": 0.0}
    light = {**BLACK, "ambient": (0.5, 0.5, 0.5), "position": (0, 0, 0, 1), "spot_cutoff": 90.0,
             "spot_direction": (1, 1, 0)}  # fmt: skip
    case = departure_case(light, material, two_side=False)
    V, _ = eye_space(case.positions, case.normals, case.ref)
    behind = dot(V, unit(np.array([1.0, 1.0, 0.0]))) < -MARGIN  # -VP.s < 0: behind the plane
    assert not (behind & ~mesa_departures(case)[CUTOFF_90]).any()
    mesa = mesa_front(case)[:, 0]
    spec = gl_lighting(case.positions, case.normals, case.ref).outputs[0][:, 0]
    assert behind.sum() > 1000
    np.testing.assert_array_equal(mesa[behind], 0.0)
    np.testing.assert_allclose(spec[behind], 0.5)
    np.testing.assert_allclose(mesa[~behind], spec[~behind], rtol=0, atol=TOL)
