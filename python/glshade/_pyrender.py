"""`render` of a ``pyrender.Scene``: its meshes, materials, lights, main camera and ambient light,
shaded as pyrender's stock ``mesh.frag`` shades them (glTF metallic-roughness, `glshade.gltf`),
without importing pyrender.

Every primitive is drawn by `render` with its material's `gltf.Scene` and the depths composited
(nearest wins), as pyrender's depth test does. What pyrender's shader reads is reproduced: world
positions ``M @ p``, world normals normalised per vertex before interpolation (its vertex
shader's ``normalize(N * n)``), ``COLOR_0`` multiplying the result, back faces culled unless the
material is double-sided, and its emissive term ``emissiveFactor²``. Left out and refused with
a clear error: textures other than the base colour's (metallic-roughness, normal, occlusion,
emissive), the specular-glossiness material, primitives other than triangles or without
normals; not modelled: shadows (off in pyrender by default), alpha blending of
transparent primitives (each pixel keeps its nearest primitive, with its alpha).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from . import gltf
from ._camera import Camera
from ._image import Image
from ._transfer import apply_transfer
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


def _texture(primitive: Any) -> dict[str, Any]:
    """`render`'s texture arguments for a primitive's ``baseColorTexture``: its image (top row
    first, as pyrender holds it before flipping it onto GL's rows), ``TEXCOORD_0``, and the
    sampler's filter (pyrender magnifies with GL_LINEAR unless told otherwise) and wraps."""
    texture = primitive.material.baseColorTexture
    if texture is None:
        return {"texture": False}
    if primitive.texcoord_0 is None:
        raise ValueError("the primitive has a baseColorTexture but no texcoord_0")
    if primitive.color_0 is not None:
        raise NotImplementedError(
            "the primitive has vertex colours and a base colour texture; glshade takes one"
        )
    sampler = texture.sampler
    magnify = getattr(sampler, "magFilter", None)
    return {
        "texture": texture.source,
        "uv": np.asarray(primitive.texcoord_0, dtype=np.float64),
        "texture_filter": FILTERS.get(magnify, "linear") if magnify is not None else "linear",
        "texture_wrap": (
            WRAPS.get(getattr(sampler, "wrapS", 10497), "repeat"),
            WRAPS.get(getattr(sampler, "wrapT", 10497), "repeat"),
        ),
    }


def _world(primitive: Any, model: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The primitive's positions and unit normals in world coordinates."""
    if primitive.normals is None:
        raise NotImplementedError(
            "a primitive without normals (pyrender lights it with the view vector as its "
            "normal) is not rendered"
        )
    p = np.asarray(primitive.positions, dtype=np.float64)
    n = np.asarray(primitive.normals, dtype=np.float64)
    world = p @ model[:3, :3].T + model[:3, 3]
    normals = n @ np.linalg.inv(model[:3, :3])
    length = np.linalg.norm(normals, axis=1, keepdims=True)
    with np.errstate(invalid="ignore", divide="ignore"):
        unit = np.where(length > 0, normals / length, 0.0)
    return world, unit


def render_pyrender(
    scene: Any,
    *,
    width: int,
    height: int,
    transfer: str,
    clamp: bool,
    depth: bool,
    render: Any,
) -> Image | tuple[Image, FloatArray]:
    """The image pyrender's stock shaders make of `scene` (float64 RGBA, `transfer` applied
    to the lit pixels, the scene's ``bg_color`` elsewhere), and its depth with `depth`;
    `render` is `glshade.render`."""
    if scene.main_camera_node is None:
        raise ValueError("the pyrender scene has no camera (scene.main_camera_node is None)")
    cam_node = scene.main_camera_node
    view = np.linalg.inv(scene.get_pose(cam_node))
    camera = Camera(view, cam_node.camera.get_projection_matrix(width, height))
    lights = _lights(scene)
    ambient = tuple(float(a) for a in np.asarray(scene.ambient_light, dtype=np.float64)[:3])
    image = np.zeros((height, width, 4))
    nearest = np.ones((height, width))
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
            cull = None if primitive.material.doubleSided else "back"
            if primitive.indices is None:
                faces = np.arange(len(primitive.positions)).reshape(-1, 3)
            else:  # pyrender keeps indices as float32 (whole numbers, as GL draws them)
                faces = np.asarray(primitive.indices).astype(np.int64)
            instances = [np.eye(4)] if primitive.poses is None else primitive.poses
            for instance in instances:
                v, n = _world(primitive, pose @ instance)
                colors = primitive.color_0
                drawn, z = render(
                    v, faces, lit, camera, width=width, height=height, shading="phong",
                    normals=n, colors=False if colors is None else colors, cull=cull,
                    transfer="linear", clamp=clamp, depth=True, **_texture(primitive),
                )  # fmt: skip
                nearer = z < nearest
                image[nearer] = drawn[nearer]
                nearest[nearer] = z[nearer]
    covered = nearest < 1
    encoded = apply_transfer(image, transfer)
    background = np.asarray(scene.bg_color, dtype=np.float64)
    result = Image(np.where(covered[..., None], encoded, background))
    return (result, nearest) if depth else result
