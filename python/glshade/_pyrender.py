"""`render` of a ``pyrender.Scene``: its meshes, materials, lights, main camera and ambient light,
shaded as pyrender's stock ``mesh.frag`` shades them (glTF metallic-roughness, `glshade.gltf`),
without importing pyrender.

Every primitive and instance is one draw of a single native call: all are rasterised into one
depth-tested frame in pyrender's order (nearest wins, the first drawn on a tie, as GL's
``GL_LESS``), each lit with its material's `gltf.Scene`. What pyrender's shader reads is
reproduced: world positions ``M @ p``, world normals normalised per vertex before
interpolation (its vertex shader's ``normalize(N * n)``; the native render's ``"vertices"``
placement), ``COLOR_0`` multiplying the result, back faces culled unless the
material is double-sided, and its emissive term ``emissiveFactor²``. Left out and refused with
a clear error: textures other than the base colour's (metallic-roughness, normal, occlusion,
emissive), the specular-glossiness material, primitives other than triangles or without
normals; not modelled: shadows (off in pyrender by default), alpha blending of
transparent primitives (each pixel keeps its nearest primitive, with its alpha).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from . import _glshade, gltf
from ._image import Image
from ._intake import color_values, rows
from ._texture import texels
from ._typing import FloatArray

__all__ = ["is_pyrender_scene", "render_pyrender"]

# pyrender's MAX_N_LIGHTS: lights of each kind its shader takes (constants.py).
MAX_LIGHTS = 4
TRIANGLES = 4  # GLTF.TRIANGLES
# The textures of a metallic-roughness material glshade does not apply (the base colour's it does).
UNSUPPORTED_TEXTURES = (
    "metallicRoughnessTexture", "normalTexture", "occlusionTexture", "emissiveTexture",
)  # fmt: skip
# GL's enums for a sampler's filter and wrap modes, as pyrender keeps them.
FILTERS = {9728: "nearest", 9729: "linear"}
WRAPS = {10497: "repeat", 33648: "mirrored_repeat", 33071: "clamp_to_edge"}


def is_pyrender_scene(obj: object) -> bool:
    """A ``pyrender.Scene``, told without importing pyrender."""
    kind = type(obj)
    return kind.__name__ == "Scene" and kind.__module__.startswith("pyrender")


def _light(light: Any, pose: np.ndarray) -> gltf.Light:
    """A pyrender light at `pose` (renderer.py's ``_bind_lighting``: the position is the pose's
    translation, the direction its -z axis)."""
    color = tuple(float(c) for c in np.asarray(light.color, dtype=np.float64)[:3])
    intensity = float(light.intensity)
    position, direction = tuple(pose[:3, 3]), tuple(-pose[:3, 2])
    kind = type(light).__name__
    if kind == "DirectionalLight":
        return gltf.DirectionalLight(color, intensity, direction)
    if kind == "PointLight":
        return gltf.PointLight(color, intensity, position)
    if kind == "SpotLight":
        return gltf.SpotLight(
            color, intensity, position, direction, light.innerConeAngle, light.outerConeAngle
        )
    raise TypeError(f"a pyrender light must be directional, point or spot, got {kind}")


def _lights(scene: Any) -> list[gltf.Light]:
    """The scene's lights; pyrender's shader takes at most four of each kind."""
    lights = [_light(node.light, scene.get_pose(node)) for node in scene.light_nodes]
    for kind in (gltf.DirectionalLight, gltf.PointLight, gltf.SpotLight):
        count = sum(isinstance(light, kind) for light in lights)
        if count > MAX_LIGHTS:
            raise NotImplementedError(
                f"the scene has {count} {kind.__name__}s; pyrender's shader takes "
                f"{MAX_LIGHTS} of each kind and picks them by distance per mesh, which glshade "
                "does not reproduce"
            )
    return lights


def _material(material: Any) -> gltf.Material:
    """A pyrender ``MetallicRoughnessMaterial`` without textures as `gltf.Material`; pyrender's
    shader adds ``emissiveFactor * emissiveFactor``."""
    kind = type(material).__name__
    if kind != "MetallicRoughnessMaterial":
        raise NotImplementedError(
            f"glshade renders pyrender's MetallicRoughnessMaterial only, got a {kind}"
        )
    textured = [name for name in UNSUPPORTED_TEXTURES if getattr(material, name, None) is not None]
    if textured:
        raise NotImplementedError(
            f"glshade applies base colour textures only: the material has {textured}"
        )
    emissive = np.asarray(material.emissiveFactor, dtype=np.float64)
    return gltf.Material(
        base_color=tuple(np.asarray(material.baseColorFactor, dtype=np.float64)),
        metallic=float(material.metallicFactor),
        roughness=float(material.roughnessFactor),
        emissive=tuple(emissive * emissive),
    )


def _texture(primitive: Any) -> tuple[Any, Any, str, tuple[str, str]]:
    """The texels, ``TEXCOORD_0``, filter and wraps of a primitive's ``baseColorTexture``
    (Nones without one): its image (top row first, as pyrender holds it before flipping it onto
    GL's rows), and the sampler's filter (pyrender magnifies with GL_LINEAR unless told
    otherwise) and wraps."""
    texture = primitive.material.baseColorTexture
    if texture is None:
        return None, None, "linear", ("repeat", "repeat")
    if primitive.texcoord_0 is None:
        raise ValueError("the primitive has a baseColorTexture but no texcoord_0")
    if primitive.color_0 is not None:
        raise NotImplementedError(
            "the primitive has vertex colours and a base colour texture; glshade takes one"
        )
    sampler = texture.sampler
    magnify = getattr(sampler, "magFilter", None)
    return (
        texels(texture.source),
        rows(primitive.texcoord_0, "texcoord_0", np.dtype(np.float64), (2,)),
        FILTERS.get(magnify, "linear") if magnify is not None else "linear",
        (
            WRAPS.get(getattr(sampler, "wrapS", 10497), "repeat"),
            WRAPS.get(getattr(sampler, "wrapT", 10497), "repeat"),
        ),
    )


def _arrays(primitive: Any) -> tuple[FloatArray, FloatArray]:
    """The primitive's positions and normals as float64 rows, in model coordinates."""
    if primitive.normals is None:
        raise NotImplementedError(
            "a primitive without normals (pyrender lights it with the view vector as its "
            "normal) is not rendered"
        )
    f64 = np.dtype(np.float64)
    return rows(primitive.positions, "positions", f64), rows(primitive.normals, "normals", f64)


def _draws(scene: Any) -> list[tuple[Any, ...]]:
    """The draws of `render_draws` for every visible primitive and instance of `scene`, in
    pyrender's order, each placed by its node's pose times its instance's."""
    lights = _lights(scene)
    ambient = tuple(float(a) for a in np.asarray(scene.ambient_light, dtype=np.float64)[:3])
    identity = np.eye(4)
    draws: list[tuple[Any, ...]] = []
    for node in scene.mesh_nodes:
        if not node.mesh.is_visible:
            continue
        pose = scene.get_pose(node)
        for primitive in node.mesh.primitives:
            if primitive.mode != TRIANGLES:
                raise NotImplementedError(
                    f"glshade renders triangles only, got a primitive of mode {primitive.mode}"
                )
            lit = gltf.Scene(lights, _material(primitive.material), ambient_light=ambient)
            cull = "none" if primitive.material.doubleSided else "back"
            if primitive.indices is None:
                faces = np.arange(len(primitive.positions)).reshape(-1, 3)
            else:  # pyrender keeps indices as float32 (whole numbers, as GL draws them)
                faces = np.asarray(primitive.indices).astype(np.int64)
            colors = primitive.color_0
            if colors is not None:
                colors = rows(
                    color_values(np.asarray(colors), "color_0", "pyrender mesh"),
                    "color_0",
                    np.dtype(np.float64),
                    (3, 4),
                )
            texture, uv, filter_, wrap = _texture(primitive)
            v, n = _arrays(primitive)
            instances = [identity] if primitive.poses is None else primitive.poses
            for instance in instances:
                model = np.ascontiguousarray(pose @ instance, dtype=np.float64)
                draws.append(
                    (v, faces, lit._native, model, cull, n, colors, texture, uv, filter_, wrap)
                )
    return draws


def render_pyrender(
    scene: Any, *, width: int, height: int, transfer: str, clamp: bool, depth: bool
) -> Image | tuple[Image, FloatArray]:
    """The image pyrender's stock shaders make of `scene` (float64 RGBA, `transfer` applied
    to the lit pixels, the scene's ``bg_color`` elsewhere), and its depth with `depth`."""
    if scene.main_camera_node is None:
        raise ValueError("the pyrender scene has no camera (scene.main_camera_node is None)")
    cam_node = scene.main_camera_node
    view = np.linalg.inv(scene.get_pose(cam_node))
    projection = cam_node.camera.get_projection_matrix(width, height)
    background = np.asarray(scene.bg_color, dtype=np.float64)
    draws = _draws(scene)
    if not draws:
        nothing = Image(np.broadcast_to(background, (height, width, 4)).copy())
        return (nothing, np.ones((height, width))) if depth else nothing
    image, nearest = _glshade.render_draws(
        draws, view=np.ascontiguousarray(view, dtype=np.float64),
        projection=np.ascontiguousarray(projection, dtype=np.float64), width=width,
        height=height, shading="phong", provoking_vertex="last", background=background,
        transfer=transfer, clamp=clamp, placement="vertices",
    )  # fmt: skip
    result = image.view(Image)
    return (result, nearest) if depth else result
