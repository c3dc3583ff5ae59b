"""`render`: a triangle mesh as an image, with flat, Gouraud or Phong shading."""

from __future__ import annotations

from typing import Any, Literal, overload

import numpy as np
from numpy.typing import ArrayLike

from . import _glshade
from ._camera import Camera
from ._image import Image
from ._intake import choice, flag, integer, optional_choice, rgba, transform
from ._render_input import render_input
from ._scene import Scene
from ._typing import ColorMaterialMode, Cull, Face, FloatArray, Shading, Space

__all__ = ["render"]


@overload
def render(
    vertices: Any,
    faces: ArrayLike | Scene | None = ...,
    scene: Scene | Camera | None = ...,
    camera: Camera | None = ...,
    *,
    width: int = ...,
    height: int = ...,
    shading: Shading = ...,
    normals: ArrayLike | None = ...,
    colors: ArrayLike | Literal[False] | None = ...,
    color_material: ColorMaterialMode | None = ...,
    color_material_face: Face = ...,
    model: ArrayLike | None = ...,
    normalize: bool = ...,
    rescale_normal: bool = ...,
    cull: Cull | None = ...,
    background: ArrayLike = ...,
    lights_in: Space = ...,
    depth: Literal[False] = ...,
) -> Image: ...
@overload
def render(
    vertices: Any,
    faces: ArrayLike | Scene | None = ...,
    scene: Scene | Camera | None = ...,
    camera: Camera | None = ...,
    *,
    width: int = ...,
    height: int = ...,
    shading: Shading = ...,
    normals: ArrayLike | None = ...,
    colors: ArrayLike | Literal[False] | None = ...,
    color_material: ColorMaterialMode | None = ...,
    color_material_face: Face = ...,
    model: ArrayLike | None = ...,
    normalize: bool = ...,
    rescale_normal: bool = ...,
    cull: Cull | None = ...,
    background: ArrayLike = ...,
    lights_in: Space = ...,
    depth: Literal[True],
) -> tuple[Image, FloatArray]: ...
@overload
def render(
    vertices: Any,
    faces: ArrayLike | Scene | None = ...,
    scene: Scene | Camera | None = ...,
    camera: Camera | None = ...,
    *,
    width: int = ...,
    height: int = ...,
    shading: Shading = ...,
    normals: ArrayLike | None = ...,
    colors: ArrayLike | Literal[False] | None = ...,
    color_material: ColorMaterialMode | None = ...,
    color_material_face: Face = ...,
    model: ArrayLike | None = ...,
    normalize: bool = ...,
    rescale_normal: bool = ...,
    cull: Cull | None = ...,
    background: ArrayLike = ...,
    lights_in: Space = ...,
    depth: bool,
) -> Image | tuple[Image, FloatArray]: ...
def render(
    vertices: Any,
    faces: ArrayLike | Scene | None = None,
    scene: Scene | Camera | None = None,
    camera: Camera | None = None,
    *,
    width: int = 512,
    height: int = 512,
    shading: Shading = "phong",
    normals: ArrayLike | None = None,
    colors: ArrayLike | Literal[False] | None = None,
    color_material: ColorMaterialMode | None = None,
    color_material_face: Face = "front_and_back",
    model: ArrayLike | None = None,
    normalize: bool = True,
    rescale_normal: bool = False,
    cull: Cull | None = None,
    background: ArrayLike = (0.0, 0.0, 0.0, 0.0),
    lights_in: Space = "eye",
    depth: bool = False,
) -> Image | tuple[Image, FloatArray]:
    """Render a triangle mesh the way OpenGL does, lit by the lighting equation of `shade`.

    Parameters
    ----------
    vertices : (n, 3) float32 or float64, or a mesh
        Vertex positions in model coordinates; or, with `faces` omitted, an object with
        ``.vertices`` and ``.faces`` (a ``trimesh.Trimesh``) or a ``trimesh.Scene`` (flattened
        by ``scene.to_mesh()``, its graph's transforms applied): ``render(mesh, scene, camera)``.
    faces : (m, 3) int, any integer dtype
        Vertex indices of each triangle; counter-clockwise on screen is the front.
    scene : Scene
        Lights and viewer in eye coordinates (as for `shade`; see `lights_in`), materials,
        light model. With
        ``two_side``, back-facing triangles get the back colour; with ``separate_specular``,
        the specular colour is added after interpolation and the sum clamped (GL's colour sum).
    camera : Camera
        The view and projection.
    width : int
        The image width in pixels, in [1, 16384].
    height : int
        The image height in pixels, in [1, 16384].
    shading : {"phong", "gouraud", "flat"}
        Where the equation is evaluated: at every pixel with the interpolated position and
        normal (``"phong"``), at the vertices with the colours interpolated (``"gouraud"``, GL's
        smooth shading), or once per face with its face normal at its last vertex (``"flat"``,
        GL's flat shading with the provoking vertex convention).
    normals : (n, 3) or (m, 3) float, optional
        One normal per vertex for Phong and Gouraud, one per face for flat shading. Default:
        `vertex_normals` (angle-weighted) or `face_normals` of the mesh.
    colors : (n, 3) or (n, 4) float or uint8, optional, or False
        Per-vertex colours for ``GL_COLOR_MATERIAL``, interpolated like the normals (flat
        shading takes the last vertex's); uint8 colours are scaled by 1/255. `color_material`
        defaults to "ambient_and_diffuse". Default: a mesh's own colours (``mesh.visual`` of
        kind "vertex" or "face"; a face's colour lights its three corners, which then have
        corners of their own), none otherwise. False: no colours, whatever the mesh has.
    color_material : {None, "ambient", "diffuse", "specular", "emission", "ambient_and_diffuse"}
        As for `shade`: None (the default) stands for ``"ambient_and_diffuse"`` when there are
        colours.
    color_material_face : {"front_and_back", "front", "back"}
        As for `shade`.
    model : (4, 4) float, optional
        Model to world coordinates, affine; positions reach eye coordinates through
        ``camera.view @ model`` and normals through its inverse transpose.
    normalize : bool
        ``GL_NORMALIZE`` wherever the equation is evaluated, so per pixel for Phong (where the
        interpolated normal is shorter than 1). On by default, unlike in `shade`.
    rescale_normal : bool
        ``GL_RESCALE_NORMAL``.
    cull : {None, "back", "front", "front_and_back"}
        Which triangles to discard by their winding on screen (None: none, GL's default).
    background : (3,) or (4,) float
        The clear colour; default transparent black.
    lights_in : {"eye", "world"}
        Where the scene's lights and viewer are given. "world": fixed in the world, moved into
        eye coordinates by ``camera.view`` (`Scene.in_eye_space`: GL's ``glLoadMatrix(view)``
        before ``glLight``), so an orbiting camera sees them stay put; GL's own viewers
        (0, 0, 1, 0) and (0, 0, 0, 1) stay with the eye.
    depth : bool
        Also return the depth buffer.

    Returns
    -------
    Image
        (height, width, 4) RGBA of the vertices' dtype, row 0 at the top of the picture.
    depth : (height, width) ndarray, with ``depth=True``
        GL window depth in [0, 1] (``glDepthRange(0, 1)``), 1 where nothing is drawn.

    Raises
    ------
    IndexError
        For a face index out of range.
    ValueError, TypeError
        For wrong shapes, dtypes, names, sizes or matrices.

    Examples
    --------
    >>> import numpy as np, glshade as gs
    >>> v = np.array([[-1, -1, 0], [1, -1, 0], [0, 1, 0]], np.float32)
    >>> scene = gs.Scene(lights=[gs.Light(position=(0, 0, 1, 0))])
    >>> image = gs.render(v, [[0, 1, 2]], scene, gs.Camera(), width=4, height=4)
    >>> image.shape, image.dtype
    ((4, 4, 4), dtype('float32'))
    """
    given = render_input(
        vertices,
        faces,
        scene,
        camera,
        shading=shading,
        normals=normals,
        colors=colors,
        color_material=color_material,
        lights_in=lights_in,
    )
    v, f, n, c, lens = given.vertices, given.faces, given.normals, given.colors, given.camera
    w = integer(width, "width", 1, _glshade.MAX_SIZE)
    h = integer(height, "height", 1, _glshade.MAX_SIZE)
    image, z = _glshade.render(
        v,
        f,
        given.scene._native,
        view=lens.view,
        projection=lens.projection_matrix(w, h),
        model=transform(model, "model"),
        width=w,
        height=h,
        shading=choice(shading, "shading"),
        normals=n,
        colors=c,
        color_material=optional_choice(given.color_material, "color_material"),
        color_material_face=choice(color_material_face, "color_material_face"),
        normalize=flag(normalize, "normalize"),
        rescale_normal=flag(rescale_normal, "rescale_normal"),
        cull="none" if cull is None else choice(cull, "cull"),
        background=np.array(rgba(background, "background")),
    )
    result = image.view(Image)
    return (result, z) if depth else result
