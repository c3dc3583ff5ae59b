"""The arguments of `render` (and of `glsl.render`) as the pipeline takes them: the mesh and its
own colours, face colours on unshared vertices, the scene in eye coordinates; without a camera
one that frames the mesh (or a trimesh scene's own camera), without a scene the default one
(`_framing`)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ._camera import Camera
from ._framing import default_scene, frame
from ._intake import color_values, one_of, rows, transform, vertex_colors
from ._model import SCENES, Model, is_scene
from ._normals import vertex_normals
from ._trimesh import as_mesh, has_own_camera, is_mesh, mesh_arrays, mesh_colors, mesh_texture
from ._typing import FloatArray


@dataclass
class RenderInput:
    """vertices (n, 3), faces (m, 3) int64, normals and colours (None or checked rows), the
    colour-material mode (GL's), the scene a render lights with (GL's with lights and viewer in
    eye coordinates), the camera."""

    vertices: FloatArray
    faces: NDArray[np.int64]
    normals: FloatArray | None
    colors: FloatArray | None
    color_material: str | None
    scene: Model
    camera: Camera
    uv: FloatArray | None = None
    texture: Any = None
    # The scene as given and where its lights are ("eye" or "world"): another camera's
    # render lights with ``meant._lit_scene(view, space)``.
    meant: Model | None = None
    space: str = "eye"


def is_pair(obj: Any) -> bool:
    """A ``(vertices, faces)`` tuple, as `glshade.meshes` returns: two 2-d array-likes (a
    tuple of vertex rows has 1-d items)."""
    return (
        isinstance(obj, tuple)
        and len(obj) == 2
        and np.ndim(obj[0]) == 2
        and np.ndim(obj[1]) == 2
        and not (is_scene(obj[0]) or isinstance(obj[0], Camera))
    )


def _arranged(vertices: Any, faces: Any, scene: Any, camera: Any) -> tuple[Any, Any, Any, Any]:
    """(vertices, faces, scene, camera) from the positional forms ``(vertices, faces, scene,
    camera)``, ``(mesh, scene, camera)``, ``(mesh, camera)``, ``(vertices, faces, camera)``,
    a mesh being an object with ``.vertices`` and ``.faces`` or a ``(vertices, faces)`` tuple;
    scene and camera None where not given. A TypeError names what does not fit."""
    if is_pair(vertices) and (faces is None or is_scene(faces) or isinstance(faces, Camera)):
        if camera is not None:
            raise TypeError(
                "render((vertices, faces), scene, camera) takes a scene and a camera after the "
                f"mesh, got a {type(camera).__name__} as well"
            )
        (vertices, faces), scene, camera = vertices, faces, scene
    if is_scene(faces) or isinstance(faces, Camera):
        if not is_mesh(vertices):
            raise TypeError(
                "faces is required unless the first argument is a mesh with .vertices and "
                f".faces: got a {type(faces).__name__} as faces after vertices of type "
                f"{type(vertices).__name__}; the call is render(vertices, faces, scene, camera)"
            )
        if scene is not None and camera is not None:
            raise TypeError(
                "render(mesh, scene, camera) takes a scene and a camera after the mesh, got a "
                f"{type(camera).__name__} as well"
            )
        faces, scene, camera = None, faces, scene if scene is not None else camera
    if isinstance(scene, Camera) and camera is None:
        scene, camera = None, scene  # render(mesh, camera): the default scene
    order = "the call is render(vertices, faces, scene, camera) or render(mesh, scene, camera)"
    if scene is not None and not is_scene(scene):
        raise TypeError(
            f"scene must be {SCENES}, or None for the default key light, got {type(scene)!r}; "
            f"{order}"
        )
    if camera is not None and not isinstance(camera, Camera):
        raise TypeError(
            f"camera must be a glshade.Camera, a list of them, or None for one that frames "
            f"the mesh, got {type(camera)!r} (a 4 x 4 pose: Camera.from_pose; OpenCV's K, R, "
            f"t: Camera.from_opencv; a pyrender camera: Camera.from_pyrender); {order}"
        )
    return vertices, faces, scene, camera


def render_input(
    vertices: Any,
    faces: Any,
    scene: Any,
    camera: Any,
    *,
    shading: str,
    normals: ArrayLike | None,
    colors: Any,
    color_material: str | None,
    lights_in: str,
    model: ArrayLike | None = None,
    width: int | None = None,
    height: int | None = None,
    texture: Any = None,
    uv: ArrayLike | None = None,
) -> RenderInput:
    """Checks and prepares `render`'s arguments (see `render` for their meaning). Without a
    camera, one framing the mesh (placed by `model`) in an image of `width` x `height` (square
    when not given); without a scene, the default one, in world coordinates whatever
    `lights_in` says."""
    vertices, faces, scene, camera = _arranged(vertices, faces, scene, camera)
    if camera is None and faces is None and has_own_camera(vertices):
        camera = Camera.from_trimesh(vertices)
    space = one_of(lights_in, "lights_in", ("eye", "world"))
    mesh = as_mesh(vertices) if faces is None and is_mesh(vertices) else None
    v, f = mesh_arrays(vertices if mesh is None else mesh, faces)
    if camera is None:
        m = transform(model, "model")
        aspect = 1.0 if width is None or height is None else width / height
        _, camera = frame(v @ m[:3, :3].T + m[:3, 3], aspect)
    own = None
    if colors is None and mesh is not None:
        own = mesh_colors(mesh)
    elif colors is not None and colors is not False:
        own = (vertex_colors(colors), "vertex")
    c = n = t = None
    corner_normals = normals is not None and np.ndim(normals) == 3
    if normals is not None and not corner_normals:
        n = rows(normals, "normals", v.dtype)
    if texture is None and uv is None and mesh is not None:
        found = mesh_texture(mesh)
        if found is not None:
            uv, texture = found
    if texture is not None and texture is not False:
        if uv is None:
            raise ValueError("a texture needs uv: texture coordinates, one (u, v) per vertex")
        t = rows(uv, "uv", v.dtype, (2,))
        if len(t) != len(v):
            raise ValueError(f"uv must have one row per vertex ({len(v)}), got shape {t.shape}")
    elif uv is not None and texture is None:
        raise ValueError("uv was given without a texture")
    if corner_normals:
        # One normal per face corner (`crease_normals`): every face gets corners of its own.
        given = np.asarray(normals)
        if given.shape != (len(f), 3, 3):
            raise ValueError(
                f"per-corner normals must have shape ({len(f)}, 3, 3), got {given.shape}"
            )
        if isinstance(shading, str) and shading.lower() == "flat":
            raise ValueError(
                "per-corner normals (m, 3, 3) are for phong and gouraud shading; flat shading "
                "takes one normal per face"
            )
        n = rows(given.reshape(-1, 3), "normals", v.dtype)
        if own is not None and own[1] == "vertex":
            values = np.asarray(own[0])
            own = (values[f].reshape(-1, values.shape[1]), "vertex")
        t = None if t is None else t[f].reshape(-1, 2)
        v = v[f].reshape(-1, 3)
        f = np.arange(len(v), dtype=np.int64).reshape(-1, 3)
    if own is not None:
        values, per = own
        expected = len(f) if per == "face" else len(v)
        c = rows(color_values(values, "colors", "render"), "colors", v.dtype, (3, 4))
        if len(c) != expected:
            raise ValueError(
                f"colors must have one row per {per} ({expected}), got shape {c.shape}"
            )
        color_material = color_material or "ambient_and_diffuse"
        if per == "face":
            # GL colours vertices: each face gets corners of its own, carrying its colour, and
            # the smooth normals of the shared mesh.
            if not (isinstance(shading, str) and shading.lower() == "flat"):
                n = vertex_normals(v, f) if n is None else n
                n = n[f].reshape(-1, 3)
            v, c = v[f].reshape(-1, 3), np.repeat(c, 3, axis=0)
            t = None if t is None else t[f].reshape(-1, 2)
            f = np.arange(3 * len(f), dtype=np.int64).reshape(-1, 3)
    image = None if t is None else texture
    if scene is None:
        # The default lights belong to the world: an orbiting camera sees them stay put.
        scene, space = default_scene(), "world"
    lit = scene._lit_scene(camera.view, space)
    return RenderInput(v, f, n, c, color_material, lit, camera, t, image, scene, space)
