"""Points against ``GL_POINTS`` on Mesa's llvmpipe (moderngl through EGL): 400 points of random
colours at random depths, some overlapping, at sizes 1, 3 and 8 pixels, square and round (a
fragment shader's ``discard`` outside ``gl_PointCoord``'s circle): coverage identical at every
pixel and colours within 1e-5 (float32's rounding of the colours)."""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest
from conftest import require

import glshade as gs
from support import glpeers  # first: it sets PYOPENGL_PLATFORM=egl before OpenGL is imported

pytestmark = pytest.mark.gl

WIDTH, HEIGHT = 96, 72
VERTEX = """
#version 330
uniform mat4 mvp;
uniform float size;
in vec3 in_position;
in vec4 in_color;
out vec4 color;
void main() {
    gl_Position = mvp * vec4(in_position, 1.0);
    gl_PointSize = size;
    color = in_color;
}
"""
FRAGMENT = """
#version 330
uniform bool round_points;
in vec4 color;
out vec4 frag;
void main() {
    if (round_points && length(gl_PointCoord - 0.5) > 0.5) discard;
    frag = color;
}
"""


def gl_points(
    points: np.ndarray, colors: np.ndarray, camera: gs.Camera, size: float, round_points: bool
) -> np.ndarray:
    """The points drawn by llvmpipe into a float RGBA framebuffer with a depth buffer, image
    rows top-down."""
    moderngl: Any = require("moderngl")
    ctx = glpeers.moderngl_context()
    program = ctx.program(vertex_shader=VERTEX, fragment_shader=FRAGMENT)
    mvp = camera.projection_matrix(WIDTH, HEIGHT) @ camera.view
    program["mvp"].write(mvp.T.astype("f4").tobytes())  # GLSL reads columns
    program["size"].value = size
    program["round_points"].value = round_points
    buffer = ctx.buffer(np.hstack([points, colors]).astype("f4").tobytes())
    vao = ctx.vertex_array(program, [(buffer, "3f 4f", "in_position", "in_color")])
    color = ctx.texture((WIDTH, HEIGHT), 4, dtype="f4")
    depth = ctx.depth_texture((WIDTH, HEIGHT))
    fbo = ctx.framebuffer(color_attachments=[color], depth_attachment=depth)
    try:
        fbo.use()
        ctx.enable(moderngl.DEPTH_TEST | moderngl.PROGRAM_POINT_SIZE)
        ctx.depth_func = "<"
        fbo.clear(0.0, 0.0, 0.0, 0.0, depth=1.0)
        vao.render(moderngl.POINTS)
        data = np.frombuffer(fbo.read(components=4, dtype="f4"), dtype="f4")
        return data.reshape(HEIGHT, WIDTH, 4)[::-1].astype(np.float64)
    finally:
        for resource in (vao, buffer, fbo, color, depth, program):
            resource.release()


@pytest.mark.parametrize("shape", ["square", "round"])
@pytest.mark.parametrize("size", [1.0, 3.0, 8.0])
def test_points_are_gl_points(size: float, shape: str) -> None:
    rng = np.random.default_rng(int(size) + 10 * (shape == "round"))
    points = rng.uniform(-1.2, 1.2, (400, 3))
    colors = np.c_[rng.uniform(0.05, 1.0, (400, 3)), np.ones(400)]
    camera = gs.Camera.look_at((0.3, 0.4, 3.5), fovy=50, near=1.0, far=6.0)
    theirs = gl_points(points, colors, camera, size, shape == "round")
    ours = np.asarray(gs.render(points, None, None, camera, width=WIDTH, height=HEIGHT,
                                colors=colors, point_size=size, point_shape=shape))  # fmt: skip
    covered, their_covered = ours[..., 3] > 0, theirs[..., 3] > 0
    assert covered.sum() > (50 if size == 1 else 300)
    np.testing.assert_array_equal(covered, their_covered)
    np.testing.assert_allclose(ours[covered], theirs[covered], atol=1e-5)
