"""Textures in `render` against two GL implementations on llvmpipe.

- moderngl: the same mesh, texture coordinates and texture drawn by a four-line GLSL program
  that outputs ``texture(t, uv)`` (no MSAA), against `render` of a white emissive material,
  whose fragments GL_MODULATE then makes the texel: every wrap mode and both filters, on
  coordinates reaching outside [0, 1]. Compared on every pixel both draw, but the silhouette;
  with the nearest filter, pixels within 1e-3 texel of a texel edge are left out (llvmpipe
  interpolates in float32, glshade in float64, so they may pick the other texel there).
- pyrender: a textured trimesh mesh through stock pyrender (its base colour texture decoded
  from sRGB in its metallic-roughness shader) against `gs.render(pyrender_scene)`, on the
  interior pixels of `support.pyrender_rays`. The texture is magnified everywhere (a texel
  covers about 15 pixels), where GL filters level 0 with the magnification filter: glshade
  has no mipmaps.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest
from conftest import require

import glshade as gs
from support import glpeers  # first: it sets PYOPENGL_PLATFORM=egl before OpenGL is imported
from support.pyrender_rays import HEIGHT, WIDTH, YFOV, ZFAR, ZNEAR, interior_of
from support.render_cases import on_edges

pytestmark = pytest.mark.gl

FLOAT32 = 2e-5


def sheet(k: int = 24) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """A curved sheet over x, y in [-1, 1] at z about -3.5 in front of the origin, its (u, v)
    the position across it: vertices (n, 3), faces (m, 3), uv (n, 2)."""
    x, y = np.meshgrid(np.linspace(-1, 1, k + 1), np.linspace(-0.8, 0.8, k + 1))
    z = -3.5 + 0.35 * np.sin(2.1 * x) * np.cos(1.7 * y)
    vertices = np.stack([x, y, z], axis=-1).reshape(-1, 3)
    uv = np.stack([(x + 1) / 2, (y + 0.8) / 1.6], axis=-1).reshape(-1, 2)
    i, j = np.meshgrid(np.arange(k), np.arange(k))
    a = (j * (k + 1) + i).ravel()
    faces = np.concatenate(
        [np.stack([a, a + 1, a + k + 2], 1), np.stack([a, a + k + 2, a + k + 1], 1)]
    )
    return vertices, faces, uv


def image(seed: int, shape: tuple[int, int] = (6, 8)) -> np.ndarray:
    return np.random.default_rng(seed).integers(0, 256, (*shape, 4), dtype=np.uint8)


VERTEX = """
#version 330
uniform mat4 mvp;
in vec3 position;
in vec2 texcoord;
out vec2 uv;
void main() { uv = texcoord; gl_Position = mvp * vec4(position, 1.0); }
"""
FRAGMENT = """
#version 330
uniform sampler2D tex;
in vec2 uv;
out vec4 color;
void main() { color = texture(tex, uv); }
"""
GL_WRAP = {"repeat": 0x2901, "mirrored_repeat": 0x8370, "clamp_to_edge": 0x812F}


def moderngl_texels(
    vertices: np.ndarray, faces: np.ndarray, uv: np.ndarray, texels: np.ndarray, camera: gs.Camera,
    size: tuple[int, int], texture_filter: str, wrap: str,
) -> np.ndarray:  # fmt: skip
    """(height, width, 4) float: what llvmpipe samples at each pixel (alpha 0 where nothing)."""
    moderngl = require("moderngl")
    ctx = glpeers.moderngl_context()
    width, height = size
    program = ctx.program(vertex_shader=VERTEX, fragment_shader=FRAGMENT)
    mvp = camera.projection_matrix(width, height) @ camera.view
    program["mvp"].write(mvp.T.astype("f4").tobytes())
    # GL's row 0 is the image's bottom row: upload it flipped, as pyrender does.
    tex = ctx.texture(texels.shape[1::-1], 4, np.flipud(texels).tobytes())
    gl_filter = moderngl.NEAREST if texture_filter == "nearest" else moderngl.LINEAR
    tex.filter = (gl_filter, gl_filter)
    from OpenGL import GL

    tex.use(0)
    # GL's own wrap mode on the bound texture (moderngl has no mirrored repeat), through
    # PyOpenGL in the same current context, after clearing any error moderngl left unread.
    while GL.glGetError() != GL.GL_NO_ERROR:
        pass
    for axis in (GL.GL_TEXTURE_WRAP_S, GL.GL_TEXTURE_WRAP_T):
        GL.glTexParameteri(GL.GL_TEXTURE_2D, axis, GL_WRAP[wrap])
    program["tex"].value = 0
    data = np.concatenate([vertices, uv], axis=1).astype("f4")
    vbo = ctx.buffer(data.tobytes())
    ibo = ctx.buffer(faces.astype("i4").tobytes())
    vao = ctx.vertex_array(program, [(vbo, "3f 2f", "position", "texcoord")], ibo)
    fbo = ctx.simple_framebuffer((width, height), components=4, dtype="f4")
    fbo.use()
    fbo.clear(0, 0, 0, 0)
    vao.render()
    pixels = np.frombuffer(fbo.read(components=4, dtype="f4"), dtype="f4")
    for thing in (vao, vbo, ibo, fbo, tex, program):
        thing.release()
    return np.flipud(pixels.reshape(height, width, 4))


WHITE = gs.Scene(lights=[], material=gs.Material(ambient=(0, 0, 0), diffuse=(0, 0, 0, 1),
                 emission=(1, 1, 1)), global_ambient=(0, 0, 0))  # fmt: skip


@pytest.mark.parametrize("texture_filter", ["linear", "nearest"])
@pytest.mark.parametrize("wrap", ["repeat", "mirrored_repeat", "clamp_to_edge"])
def test_sampling_matches_moderngl(texture_filter: str, wrap: str) -> None:
    vertices, faces, uv = sheet()
    uv = uv * 2.4 - 0.7  # from -0.7 to 1.7: every wrap mode shows
    texels = image(3)
    camera = gs.Camera.look_at((0.0, 0.0, 0.0), (0.0, 0.0, -3.5), (0, 1, 0))
    size = (160, 120)
    theirs = moderngl_texels(vertices, faces, uv, texels, camera, size, texture_filter, wrap)
    ours = gs.render(
        vertices, faces, WHITE, camera, width=size[0], height=size[1], texture=texels, uv=uv,
        texture_filter=texture_filter, texture_wrap=wrap,
    )  # fmt: skip
    covered = (ours[..., 3] > 0) & (theirs[..., 3] > 0)
    compared = covered & ~on_edges(ours[..., 3] > 0)
    assert compared.sum() > 3000
    if texture_filter == "nearest":
        # The coordinates glshade interpolates at each pixel, in texels.
        at_uv = gs.render(
            vertices, faces, WHITE, camera, width=size[0], height=size[1],
            texture=np.ones((1, 1)), uv=uv, colors=np.c_[uv, np.zeros((len(uv), 2))],
            color_material="emission", clamp=False,
        )  # fmt: skip
        texel = at_uv[..., :2] * (texels.shape[1], texels.shape[0])
        near_edge = np.abs(texel - np.round(texel)).min(axis=-1) < 1e-3
        compared &= ~near_edge
    difference = np.abs(ours - theirs)[compared].max()
    assert difference <= 1e-6 if texture_filter == "nearest" else 2 / 255, difference


def textured_pyrender_scene(material: Any = None) -> tuple[Any, Any]:
    """The sheet as a textured trimesh mesh, in a pyrender scene seen from the identity pose
    (the rays' camera) with a directional and a point light; returns the scene and the mesh."""
    trimesh = require("trimesh")
    pyrender = require("pyrender")
    pil = require("PIL.Image")
    vertices, faces, uv = sheet()
    texels = image(5)
    texels[..., 3] = 255  # opaque: pyrender's default material for it blends by alpha
    visual = trimesh.visual.TextureVisuals(uv=uv, image=pil.fromarray(texels))
    m = trimesh.Trimesh(vertices, faces, visual=visual, process=False)
    scene = pyrender.Scene(bg_color=(0, 0, 0, 0), ambient_light=(0.05, 0.05, 0.05))
    scene.add(pyrender.Mesh.from_trimesh(m, material=material, smooth=True))
    scene.add(pyrender.PerspectiveCamera(yfov=YFOV, znear=ZNEAR, zfar=ZFAR), pose=np.eye(4))
    scene.add(pyrender.DirectionalLight(intensity=2.5), pose=np.eye(4))
    point = np.eye(4)
    point[:3, 3] = (0.8, 0.6, -2.0)
    scene.add(pyrender.PointLight(color=(1.0, 0.9, 0.8), intensity=3.0), pose=point)
    return scene, m


@pytest.mark.parametrize("material", ["trimesh's", "metallic 0.1, roughness 0.6"])
def test_a_textured_trimesh_mesh_matches_pyrender(material: str) -> None:
    pyrender = require("pyrender")
    pil = require("PIL.Image")
    given = None
    if material != "trimesh's":
        texels = image(5)
        texels[..., 3] = 255
        given = pyrender.MetallicRoughnessMaterial(
            baseColorTexture=pyrender.Texture(source=pil.fromarray(texels), source_channels="RGBA"),
            metallicFactor=0.1, roughnessFactor=0.6, alphaMode="OPAQUE",
        )  # fmt: skip
    scene, m = textured_pyrender_scene(given)
    renderer = glpeers.pyrender_renderer(WIDTH, HEIGHT)
    theirs = np.asarray(renderer.render(scene)[0], dtype=np.float64) / 255
    ours = gs.render(scene, width=WIDTH, height=HEIGHT)
    projection = pyrender.PerspectiveCamera(yfov=YFOV, znear=ZNEAR, zfar=ZFAR)
    _, inside = interior_of(m, projection.get_projection_matrix(WIDTH, HEIGHT))
    assert inside.sum() > 5000
    lit = theirs[inside].max(axis=1)
    assert np.ptp(lit) > 0.3, "the texture shows"
    difference = np.abs(ours[..., :3] - theirs)[inside].max()
    assert difference <= 2 / 255, difference * 255
    # Without its texture the same mesh is another picture.
    plain = gs.render(m.vertices, m.faces, texture=False, width=WIDTH, height=HEIGHT)
    assert np.abs(plain[..., :3] - theirs)[inside].max() > 0.1


def test_a_textured_trimesh_mesh_renders_with_its_texture() -> None:
    """`render(mesh, gltf_scene, camera)` finds a trimesh mesh's texture and coordinates itself,
    and draws what the pyrender scene of the same mesh and lights gives."""
    pyrender = require("pyrender")
    scene, m = textured_pyrender_scene()
    material = scene.mesh_nodes.copy().pop().mesh.primitives[0].material
    lights = [
        gs.gltf.DirectionalLight(intensity=2.5, direction=(0, 0, -1)),
        gs.gltf.PointLight(color=(1.0, 0.9, 0.8), intensity=3.0, position=(0.8, 0.6, -2.0)),
    ]
    lit = gs.gltf.Scene(
        lights,
        gs.gltf.Material(
            base_color=np.asarray(material.baseColorFactor, dtype=float),
            metallic=float(material.metallicFactor),
            roughness=float(material.roughnessFactor),
        ),
        ambient_light=(0.05, 0.05, 0.05),
    )
    projection = pyrender.PerspectiveCamera(yfov=YFOV, znear=ZNEAR, zfar=ZFAR)
    camera = gs.Camera(np.eye(4), projection.get_projection_matrix(WIDTH, HEIGHT))
    ours = gs.render(m, lit, camera, width=WIDTH, height=HEIGHT, transfer="gamma2.2", cull="back")
    adapted = gs.render(scene, width=WIDTH, height=HEIGHT)
    covered = (ours[..., 3] > 0) & (adapted[..., 3] > 0)
    assert covered.sum() > 5000
    # pyrender keeps positions and texture coordinates in float32.
    assert np.abs(ours - adapted)[covered].max() < 1e-6
