"""`render` of a point cloud: the points drawn as GL draws ``GL_POINTS`` without smoothing, lit
at their vertices by a scene through their normals, or in their own colours."""

from __future__ import annotations

import os
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from . import _glshade
from ._camera import Camera, is_camera_list
from ._framing import default_scene, frame
from ._image import Image
from ._intake import color_values, flag, number, one_of, rgba, rows, transform, vertex_colors
from ._model import is_scene
from ._render_input import is_pair
from ._transfer import apply_transfer
from ._trimesh import is_mesh
from ._typing import FloatArray

__all__ = ["is_point_cloud", "render_points"]

SHAPES = ("square", "round")


def is_point_cloud(vertices: Any, faces: Any) -> bool:
    """Whether `render` was given points: an object with ``.vertices`` and no ``.faces`` (a
    ``trimesh.PointCloud``), or an (n, 3) array-like, with no faces (None, or the scene or
    camera in their place)."""
    if faces is not None and not (
        is_scene(faces) or isinstance(faces, Camera) or is_camera_list(faces)
    ):
        return False
    if hasattr(vertices, "vertices") and not hasattr(vertices, "faces"):
        return True
    if is_mesh(vertices) or is_pair(vertices) or isinstance(vertices, (str, os.PathLike)):
        return False
    return bool(np.ndim(vertices) == 2) and not is_scene(vertices)


def _scene_and_camera(given: tuple[Any, ...]) -> tuple[Any, Any]:
    """The scene and the camera (or cameras) among the places after the points."""
    scene = camera = None
    for value in given:
        if value is None:
            continue
        if is_scene(value) and scene is None and camera is None:
            scene = value
        elif (isinstance(value, Camera) or is_camera_list(value)) and camera is None:
            camera = value
        else:
            raise TypeError(
                "render(points, None, scene, camera) takes a scene and a camera (or a list of "
                f"cameras) after the points, got {type(value)!r}"
            )
    return scene, camera


def render_points(
    vertices: Any,
    places: tuple[Any, Any, Any],
    *,
    width: int,
    height: int,
    normals: ArrayLike | None,
    colors: Any,
    point_size: float,
    point_shape: str,
    gl_options: dict[str, tuple[Any, Any]],
    model: ArrayLike | None,
    background: ArrayLike,
    lights_in: str,
    encoding: str,
    clamp: bool,
    depth: bool,
) -> Image | FloatArray | tuple[Image | FloatArray, FloatArray]:
    """`render` of points (see there): `places` are its faces, scene and camera arguments."""
    scene, camera = _scene_and_camera(places)
    if colors is None and hasattr(vertices, "colors") and np.size(vertices.colors):
        colors = vertices.colors  # a trimesh.PointCloud's own, uint8 RGBA
    points = vertices.vertices if hasattr(vertices, "vertices") else vertices
    v = rows(points, "vertices")
    n = None if normals is None else rows(normals, "normals", v.dtype)
    c = None
    if colors is not None and colors is not False:
        given = color_values(vertex_colors(colors), "colors", "render")
        c = rows(given, "colors", v.dtype, (3, 4))
    if scene is not None and n is None:  # a mesh's faces forgotten, or points' normals
        raise TypeError(
            "faces is required unless the first argument is a mesh with .vertices and .faces: "
            "the call is render(vertices, faces, scene, camera); for points, a scene lights "
            "them through their normals: render(points, None, scene, camera, normals=...), or "
            "give no scene to draw them in their colours"
        )
    m = transform(model, "model")
    if camera is None:
        _, camera = frame(v @ m[:3, :3].T + m[:3, 3], width / height)
    cameras = camera if isinstance(camera, (list, tuple)) else [camera]
    space = one_of(lights_in, "lights_in", ("eye", "world"))
    if scene is None:
        scene, space = default_scene(), "world"
    gl = scene._gl_options(gl_options, colors=c is not None and n is not None)
    clear = apply_transfer(np.array([rgba(background, "background")], dtype=v.dtype), encoding)
    shape = one_of(point_shape, "point_shape", SHAPES)
    size = number(point_size, "point_size")

    def draw(view: Camera) -> tuple[FloatArray, FloatArray]:
        image, z = _glshade.render_points(
            v, scene._lit_scene(view.view, space)._native, view=view.view,
            projection=view.projection_matrix(width, height), model=m, width=width,
            height=height, normals=n, colors=c, point_size=size, point_shape=shape,
            background=clear[0].astype(np.float64), transfer=encoding,
            clamp=flag(clamp, "clamp"), **gl,
        )  # fmt: skip
        return image, z

    frames = [draw(view) for view in cameras]
    if isinstance(camera, (list, tuple)):
        images: FloatArray = np.stack([f[0] for f in frames])
        depths: FloatArray = np.stack([f[1] for f in frames])
        return (images, depths) if depth else images
    image = frames[0][0].view(Image)
    return (image, frames[0][1]) if depth else image
