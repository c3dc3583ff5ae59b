"""The arguments of `render` (and of `glsl.render`) as the pipeline takes them: the mesh and its
own colours, face colours on unshared vertices, the scene in eye coordinates."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ._camera import Camera
from ._intake import array, color_values, rows
from ._normals import vertex_normals
from ._scene import Scene
from ._trimesh import as_mesh, is_mesh, mesh_arrays, mesh_colors
from ._typing import FloatArray


@dataclass
class RenderInput:
    """vertices (n, 3), faces (m, 3) int64, normals and colours (None or checked rows), the
    colour-material mode, the scene with lights and viewer in eye coordinates, the camera."""

    vertices: FloatArray
    faces: NDArray[np.int64]
    normals: FloatArray | None
    colors: FloatArray | None
    color_material: str | None
    scene: Scene
    camera: Camera


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
) -> RenderInput:
    """Checks and prepares `render`'s arguments (see `render` for their meaning)."""
    if isinstance(faces, Scene) and (camera is None or isinstance(scene, Camera)):
        faces, scene, camera = None, faces, scene  # render(mesh, scene, camera)
    if not isinstance(scene, Scene):
        raise TypeError(f"scene must be a glshade.Scene, got {type(scene)!r}")
    if not isinstance(camera, Camera):
        raise TypeError(f"camera must be a glshade.Camera, got {type(camera)!r}")
    if lights_in not in ("eye", "world"):
        raise ValueError(f"lights_in must be 'eye' or 'world', got {lights_in!r}")
    mesh = as_mesh(vertices) if faces is None and is_mesh(vertices) else None
    v, f = mesh_arrays(vertices if mesh is None else mesh, faces)
    own = None
    if colors is None and mesh is not None:
        own = mesh_colors(mesh)
    elif colors is not None and colors is not False:
        own = (color_values(array(colors, "colors")), "vertex")
    c = n = None
    if normals is not None:
        n = rows(normals, "normals", v.dtype)
    if own is not None:
        values, per = own
        expected = len(f) if per == "face" else len(v)
        c = rows(color_values(values), "colors", v.dtype, (3, 4))
        if len(c) != expected:
            raise ValueError(
                f"colors must have one row per {per} ({expected}), got shape {c.shape}"
            )
        color_material = color_material or "ambient_and_diffuse"
        if per == "face":
            # GL colours vertices: each face gets corners of its own, carrying its colour, and
            # the smooth normals of the shared mesh.
            if shading != "flat":
                n = vertex_normals(v, f) if n is None else n
                n = n[f].reshape(-1, 3)
            v, c = v[f].reshape(-1, 3), np.repeat(c, 3, axis=0)
            f = np.arange(3 * len(f), dtype=np.int64).reshape(-1, 3)
    eye_scene = scene.in_eye_space(camera.view) if lights_in == "world" else scene
    return RenderInput(v, f, n, c, color_material, eye_scene, camera)
