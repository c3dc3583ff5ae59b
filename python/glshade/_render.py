"""`render`: a triangle mesh as an image, with flat, Gouraud or Phong shading, encoded by a
transfer function."""

from __future__ import annotations

import functools
import os
from collections.abc import Sequence
from typing import TYPE_CHECKING, Any, Literal, cast, overload

import numpy as np
from numpy.typing import ArrayLike

from . import _glshade
from ._camera import Camera, is_camera_list
from ._image import Image
from ._intake import choice, color, flag, integer, one_of, rgba, transform, warn_if_bytes
from ._normals import face_normals, vertex_normals
from ._points import is_point_cloud, render_points
from ._pyrender import is_pyrender_scene, render_pyrender
from ._render_input import render_input
from ._scenes import AnyScene
from ._texture import FILTERS, texels, wrap_modes
from ._transfer import Transfer, apply_transfer, transfer_name
from ._trimesh import load
from ._typing import ColorMaterialMode, Cull, Face, FloatArray, ProvokingVertex, Shading, Space

if TYPE_CHECKING:
    from typing_extensions import Unpack

    from ._render_options import RenderOptions

__all__ = ["render"]


@overload
def render(
    vertices: Any,
    faces: ArrayLike | AnyScene | None,
    scene: AnyScene | Camera | None,
    camera: Sequence[Camera],
    *,
    depth: Literal[False] = ...,
    **options: Unpack[RenderOptions],
) -> FloatArray: ...
@overload
def render(
    vertices: Any,
    faces: ArrayLike | AnyScene | None,
    scene: AnyScene | Camera | None,
    camera: Sequence[Camera],
    *,
    depth: Literal[True],
    **options: Unpack[RenderOptions],
) -> tuple[FloatArray, FloatArray]: ...
@overload
def render(
    vertices: Any,
    faces: ArrayLike | AnyScene | Sequence[Camera] | None = ...,
    scene: AnyScene | Camera | Sequence[Camera] | None = ...,
    camera: Camera | None = ...,
    *,
    depth: Literal[False] = ...,
    **options: Unpack[RenderOptions],
) -> Image: ...
@overload
def render(
    vertices: Any,
    faces: ArrayLike | AnyScene | Sequence[Camera] | None = ...,
    scene: AnyScene | Camera | Sequence[Camera] | None = ...,
    camera: Camera | None = ...,
    *,
    depth: Literal[True],
    **options: Unpack[RenderOptions],
) -> tuple[Image, FloatArray]: ...
@overload
def render(
    vertices: Any,
    faces: ArrayLike | AnyScene | Sequence[Camera] | None = ...,
    scene: AnyScene | Camera | Sequence[Camera] | None = ...,
    camera: Camera | Sequence[Camera] | None = ...,
    *,
    depth: bool,
    **options: Unpack[RenderOptions],
) -> Image | FloatArray | tuple[Image | FloatArray, FloatArray]: ...
def render(
    vertices: Any,
    faces: ArrayLike | AnyScene | Sequence[Camera] | None = None,
    scene: AnyScene | Camera | Sequence[Camera] | None = None,
    camera: Camera | Sequence[Camera] | None = None,
    *,
    width: int = 512,
    height: int = 512,
    shading: Shading = "phong",
    provoking_vertex: ProvokingVertex = "last",
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
    transfer: Transfer | None = None,
    clamp: bool = True,
    texture: Any = None,
    uv: ArrayLike | None = None,
    texture_filter: str = "linear",
    texture_wrap: str | tuple[str, str] = "repeat",
    point_size: float = 1.0,
    point_shape: str = "square",
    depth: bool = False,
) -> Image | FloatArray | tuple[Image | FloatArray, FloatArray]:
    """Render a triangle mesh the way OpenGL does, lit by the lighting equation of `shade`.

    Parameters
    ----------
    vertices : (n, 3) float32 or float64, or a mesh, or a path
        Vertex positions in model coordinates; or, with `faces` omitted, an object with
        ``.vertices`` and ``.faces`` (a ``trimesh.Trimesh``) or a ``trimesh.Scene`` (flattened
        by ``scene.to_mesh()``, its graph's transforms applied; its own camera, where it has
        one and no `camera` is given), a file's path (a ``str`` or ``os.PathLike``: what
        ``trimesh.load`` reads, glTF, OBJ, PLY, STL..., with its colours and texture), or a
        ``(vertices, faces)``
        tuple as `glshade.meshes` returns: ``render(mesh)``, ``render(mesh, scene)``,
        ``render(mesh, camera)``, ``render(mesh, scene, camera)``. Or a ``pyrender.Scene``,
        alone: ``render(pyrender_scene, width=, height=)`` draws its meshes with their
        materials, its lights, ambient light and main camera as pyrender's stock shader does
        (glTF metallic-roughness, Phong shading, ``transfer="gamma2.2"`` by default, its
        ``bg_color`` where nothing is drawn; textures, shadows and blending are not drawn: see
        the documentation's glTF page, docs/pages/guide/gltf.md); of the options below only
        `transfer`, `clamp` and `depth` apply, and the image is float64.
    faces : (m, 3) int, any integer dtype
        Vertex indices of each triangle; counter-clockwise on screen is the front.
    scene : Scene, gltf.Scene or threejs.Scene, optional
        Lights and viewer in eye coordinates (as for `shade`; see `lights_in`), materials,
        light model. A `glshade.gltf.Scene` lights the mesh with glTF's metallic-roughness
        model as pyrender does: in world coordinates (`lights_in` does not apply), its camera
        position replaced by the camera's eye, vertex colours multiplying the result (the GL
        options `color_material`, `color_material_face`, `normalize` and `rescale_normal` do
        not apply); ``transfer="gamma2.2"`` then gives pyrender's output. A
        `glshade.threejs.Scene` lights it with three.js' ``MeshPhongMaterial`` the same way
        (its camera from the camera: the eye, or an orthographic camera's view direction;
        vertex colours multiplying the material's colour; a double-sided material's back
        faces lit with the negated normal); ``transfer="srgb"`` gives three.js' sRGB output. With
        ``two_side``, back-facing triangles get the back colour; with ``separate_specular``,
        the specular colour is added after interpolation and the sum clamped (GL's colour sum).
        None (the default): a white key light from the upper left of the default view and a
        dim fill from the lower right, both directional and fixed in the world (whatever
        `lights_in` says, so an orbiting camera sees them stay put), a light grey material
        with a soft highlight, GL's global ambient and a local viewer at the eye.
    camera : Camera or a sequence of Camera, optional
        The view and projection (`Camera.look_at`, or a camera as another library gives it:
        `Camera.from_pose`, `Camera.from_opencv`, `Camera.from_pyrender`,
        `Camera.from_trimesh`). A list or tuple of cameras (`Camera.orbit` makes a turntable)
        renders the mesh from each in one call, the normals computed once: the result is a
        (k, height, width, 4) ndarray (and a (k, height, width) depth), view i equal to
        rendering with camera i alone. None (the default): a perspective camera (35 degrees
        vertically) that frames the mesh's bounds wherever it is and whatever its size: it
        looks at the centre of the bounding box of the vertices (placed by `model`) from in
        front, to the right and above (the direction (0.45, 0.35, 1) with +y up), from the
        distance where the bounding sphere fills 95% of the narrower field of view, with the
        near and far planes just outside that sphere.
    width : int
        The image width in pixels, in [1, 16384].
    height : int
        The image height in pixels, in [1, 16384].
    shading : {"phong", "gouraud", "flat"}
        Where the equation is evaluated: at every pixel with the interpolated position and
        normal (``"phong"``), at the vertices with the colours interpolated (``"gouraud"``, GL's
        smooth shading), or once per face with its face normal at its provoking vertex
        (``"flat"``, GL's flat shading). This name and the others below are case-insensitive
        (``"Phong"``).
    provoking_vertex : {"last", "first", "centroid"}, default: "last"
        Where flat shading lights a face, and whose vertex colour it takes: the last vertex
        (GL's default, ``GL_LAST_VERTEX_CONVENTION``), the first (Direct3D's, Vulkan's and
        Metal's, ``GL_FIRST_VERTEX_CONVENTION``), or the face's centroid (where PyTorch3D's
        ``flat_shading`` and `shade_mesh` with ``per="face"`` light a face) with the mean of
        its vertex colours.
    normals : (n, 3), (m, 3) or (m, 3, 3) float, optional
        One normal per vertex for Phong and Gouraud, one per face for flat shading; or, for
        Phong and Gouraud, one per face corner (`crease_normals`: each face then gets corners
        of its own). Default: `vertex_normals` (angle-weighted) or `face_normals` of the mesh.
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
        Which triangles to discard by their winding on screen (None: none, GL's default; for a
        `glshade.threejs.Scene`, its material's ``side``: "front" culls the back, "back" the
        front, "double" none, as three.js draws).
    background : (3,) or (4,) float
        The clear colour; default transparent black.
    lights_in : {"eye", "world"}
        Where the scene's lights and viewer are given. "world": fixed in the world, moved into
        eye coordinates by ``camera.view`` (`Scene.in_eye_space`: GL's ``glLoadMatrix(view)``
        before ``glLight``), so an orbiting camera sees them stay put; GL's own viewers
        (0, 0, 1, 0) and (0, 0, 0, 1) stay with the eye. The default scene is always in world
        coordinates.
    transfer : str or None
        How the image's RGB is encoded (alpha and the depth are not): ``"linear"``,
        ``"srgb"`` or ``"gamma2.2"``. None (the default) is ``"linear"``, or pyrender's
        ``"gamma2.2"`` for a pyrender scene. ``"linear"`` returns the lighting equation's
        values as they are, GL's output without
        ``GL_FRAMEBUFFER_SRGB``; ``"srgb"`` applies `srgb_encode` (IEC 61966-2-1), the
        brightness pyrender's, three.js's and Blender's sRGB output shows; ``"gamma2.2"``
        applies ``x^(1/2.2)``. Names are case-insensitive. The background is encoded too.
    clamp : bool
        GL's clamp of the colours to [0, 1] (the default). False keeps what the lighting
        equation and the colour sum give, values above 1 included (high dynamic range), as
        `shade` with ``clamp=False`` does; the background and alpha as given.
    texture : image, optional, or False
        A texture: (height, width), (height, width, 1, 2, 3 or 4) uint8, uint16 or float, or a
        PIL image, its top row first. With GL's model it multiplies every fragment's primary
        colour, before the separate specular is added (``GL_MODULATE``); with a
        `glshade.gltf.Scene` it is glTF's ``baseColorTexture``: decoded from sRGB and
        multiplied into the base colour wherever the model is evaluated (per pixel with Phong
        shading, at the vertices with Gouraud, at the provoking vertex with flat shading);
        with a `glshade.threejs.Scene` it is the material's ``map`` (sRGB, as current releases
        load colour maps), multiplied into its ``color`` the same way.
        Default: a trimesh mesh's own (``visual.kind == "texture"``: its material's
        ``baseColorTexture`` or ``image``, and its ``visual.uv``); False: none.
    uv : (n, 2) float, optional
        Texture coordinates per vertex, interpolated perspective-correctly; (0, 0) is the
        image's lower-left corner and (1, 1) its upper-right (GL's and trimesh's convention).
    texture_filter : {"linear", "nearest"}
        GL's bilinear filter (pyrender's magnification filter) or the nearest texel. There are
        no mipmaps: where a texture is minified, pyrender's trilinear mipmapping differs.
    texture_wrap : {"repeat", "mirrored_repeat", "clamp_to_edge"}, or a pair (s, t)
        What coordinates outside [0, 1] read, GL's wrap modes (glTF's default: repeat).
    point_size : float
        For points (`vertices` an (n, 3) array or a ``trimesh.PointCloud``, no `faces`): the
        side of each point's square in pixels, in (0, 255], as ``gl_PointSize``. Points are
        drawn as GL draws ``GL_POINTS`` without smoothing: the pixels whose centres lie in the
        square centred on the point's window position (Mesa's rule at the edges), at its depth,
        depth-tested; a point whose centre is outside the view volume is not drawn. With
        `normals` (one per point) they are lit by `scene` at their vertices, as GL lights a
        point (the front material); without, drawn in `colors` (a point cloud's own, else
        white) and no scene may be given. `shading`, `cull`, `texture` and the provoking
        vertex do not apply.
    point_shape : {"square", "round"}
        GL's square, or the disc of the same diameter (the pixels whose centres are within
        half the size of the point: a fragment shader's ``discard`` outside
        ``gl_PointCoord``'s circle).
    depth : bool
        Also return the depth buffer.

    Returns
    -------
    Image
        (height, width, 4) RGBA of the vertices' dtype, row 0 at the top of the picture; for
        a sequence of k cameras a (k, height, width, 4) ndarray.
    depth : (height, width) ndarray, with ``depth=True``
        GL window depth in [0, 1] (``glDepthRange(0, 1)``), 1 where nothing is drawn; (k,
        height, width) for k cameras.

    Raises
    ------
    IndexError
        For a face index out of range.
    FileNotFoundError
        For a path that names no file (and ImportError without trimesh to read one).
    ValueError, TypeError
        For wrong shapes, dtypes, names, sizes or matrices; a colour given by name.

    Warns
    -----
    ColorRangeWarning
        For a `background` whose every value is a whole number in [0, 255], the largest 16
        or more (bytes where GL takes [0, 1]).

    Examples
    --------
    >>> import numpy as np, glshade as gs
    >>> v = np.array([[-1, -1, 0], [1, -1, 0], [0, 1, 0]], np.float32)
    >>> scene = gs.Scene(lights=[gs.Light(position=(0, 0, 1, 0))])
    >>> image = gs.render(v, [[0, 1, 2]], scene, gs.Camera(), width=4, height=4)
    >>> image.shape, image.dtype
    ((4, 4, 4), dtype('float32'))

    Without a scene and a camera, the default lights and a camera that frames the mesh:

    >>> image = gs.render(gs.meshes.torus(24, 12, 1.0, 0.4), width=64, height=48)
    >>> image.shape, bool((image[..., 3] > 0).any())
    ((48, 64, 4), True)
    """
    w = integer(width, "width", 1, _glshade.MAX_SIZE)
    h = integer(height, "height", 1, _glshade.MAX_SIZE)
    mode = one_of(shading, "shading", ("flat", "gouraud", "phong"))
    if is_pyrender_scene(vertices):
        if faces is not None or scene is not None or camera is not None:
            raise TypeError(
                "render(pyrender_scene, width=, height=) takes the scene's own meshes, lights "
                "and camera: no faces, scene or camera after it"
            )
        return render_pyrender(
            vertices, width=w, height=h,
            transfer=transfer_name("gamma2.2" if transfer is None else transfer),
            clamp=flag(clamp, "clamp"), depth=flag(depth, "depth"),
        )  # fmt: skip
    encoding = transfer_name("linear" if transfer is None else transfer)
    if isinstance(vertices, (str, os.PathLike)):
        vertices = load(vertices)
    gl_options = {
        "color_material": (color_material, None),
        "color_material_face": (color_material_face, "front_and_back"),
        "normalize": (normalize, True), "rescale_normal": (rescale_normal, False),
    }  # fmt: skip
    if is_point_cloud(vertices, faces):
        if texture is not None or uv is not None:
            raise TypeError("points take no texture or uv: they are drawn in one colour each")
        return render_points(
            vertices, (faces, scene, camera), width=w, height=h, normals=normals,
            colors=colors, point_size=point_size, point_shape=point_shape,
            gl_options=gl_options, model=model, background=background, lights_in=lights_in,
            encoding=encoding, clamp=clamp, depth=flag(depth, "depth"),
        )  # fmt: skip
    views, (faces, scene, camera) = _views((faces, scene, camera))
    given = render_input(
        vertices,
        faces,
        scene,
        camera,
        shading=mode,
        normals=normals,
        colors=colors,
        color_material=color_material,
        lights_in=lights_in,
        model=model,
        width=w,
        height=h,
        texture=texture,
        uv=uv,
    )
    v, f, n, c, lens = given.vertices, given.faces, given.normals, given.colors, given.camera
    gl = given.scene._gl_options(gl_options, colors=c is not None)
    if cull is None:
        cull = cast(Cull | None, given.scene._default_cull())
    warn_if_bytes(color(background, "background"), "background", "render")
    # The background is encoded as the pixels are, in the image's dtype.
    clear = apply_transfer(np.array([rgba(background, "background")], dtype=v.dtype), encoding)
    draw = functools.partial(
        _glshade.render,
        v,
        f,
        model=transform(model, "model"),
        width=w,
        height=h,
        shading=mode,
        provoking_vertex=one_of(
            provoking_vertex, "provoking_vertex", ("last", "first", "centroid")
        ),
        colors=c,
        cull="none" if cull is None else choice(cull, "cull"),
        background=clear[0].astype(np.float64),
        transfer=encoding,
        clamp=flag(clamp, "clamp"),
        texture=None if given.texture is None else texels(given.texture),
        uv=given.uv,
        texture_filter=one_of(texture_filter, "texture_filter", FILTERS),
        texture_wrap=wrap_modes(texture_wrap),
        **gl,
    )
    if views is None:
        image, z = draw(
            scene=given.scene._native, view=lens.view, projection=lens.projection_matrix(w, h),
            normals=n,
        )  # fmt: skip
        result: Image | FloatArray = image.view(Image)
        return (result, z) if depth else result
    projections = [camera.projection_matrix(w, h) for camera in views]
    assert given.meant is not None
    lit = [given.meant._lit_scene(camera.view, given.space) for camera in views]
    if all(scene is lit[0] for scene in lit):  # one scene for every view: one native call
        image, z = draw(
            scene=lit[0]._native, view=np.stack([camera.view for camera in views]),
            projection=np.stack(projections), normals=n,
        )  # fmt: skip
    else:  # lights fixed in the world: each view lit by its own scene, the normals shared
        if n is None:
            n = face_normals(v, f) if mode == "flat" else vertex_normals(v, f)
        frames = [
            draw(scene=scene._native, view=camera.view, projection=p, normals=n)
            for scene, camera, p in zip(lit, views, projections, strict=True)
        ]
        image, z = np.stack([i for i, _ in frames]), np.stack([d for _, d in frames])
    return (image, z) if depth else image


def _views(slots: tuple[Any, Any, Any]) -> tuple[list[Camera] | None, tuple[Any, Any, Any]]:
    """The cameras of a call given a list or tuple of them (in whichever of the `faces`,
    `scene` and `camera` places the call form puts a camera), and the places with the first
    camera in its stead; None and the places as they are for a call of one camera."""
    for place, value in enumerate(slots):
        if is_camera_list(value):
            changed = list(slots)
            changed[place] = value[0]
            return list(value), (changed[0], changed[1], changed[2])
    return None, slots
