"""The moderngl helper: `shade`, `rasterize` and `render` run `glshade.glsl`'s shaders on an
OpenGL context (Mesa's llvmpipe headless, or a GPU), with `gs.shade`'s and `gs.render`'s
arguments and results. moderngl is an optional dependency, imported on first use."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, Literal, cast, overload

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._image import Image
from .._intake import (
    array,
    color,
    color_values,
    integer,
    one_of,
    rgba,
    rows,
    transform,
    vertices,
    warn_if_bytes,
)
from .._records import ValueRecord
from .._render import render as gs_render
from .._render_input import render_input
from .._render_options import shared_defaults
from .._scene import Scene
from .._transfer import apply_transfer, transfer_name
from .._typing import Cull, Face, Shading
from ._shaders import Shaders, compute_shader, raster_shaders

if TYPE_CHECKING:
    from typing_extensions import Unpack

    from .._render_options import SharedRenderOptions

_contexts: list[Any] = []
_programs: dict[tuple[int, str], Any] = {}


def _moderngl() -> Any:
    try:
        import moderngl
    except ImportError:
        raise ImportError(
            "glshade.glsl's GL helpers need moderngl: pip install moderngl "
            "(or pip install 'glshade[gl]')"
        ) from None
    return moderngl


def context() -> Any:
    """The process's standalone moderngl context (OpenGL >= 4.3 core, for compute shaders),
    made on first use and made current on every call.

    Headless through EGL first (Mesa's llvmpipe on a machine without a GPU; set
    ``LIBGL_ALWAYS_SOFTWARE=1`` to stay on it where a GPU driver exists), else moderngl's
    default platform. Pass ``context=`` to the helpers to use a context of your own instead.

    Raises
    ------
    ImportError
        Without moderngl, naming ``pip install moderngl``.
    RuntimeError
        When no context with OpenGL 4.3 can be made, with each backend's reason.
    """
    moderngl = _moderngl()
    if not _contexts:
        reasons = []
        for backend in ("egl", None):
            try:
                kwargs = {"backend": backend} if backend else {}
                _contexts.append(moderngl.create_standalone_context(require=430, **kwargs))
                break
            except Exception as exc:  # each backend fails in its own way (EGL, X, driver)
                reasons.append(f"{backend or 'default'}: {type(exc).__name__}: {exc}")
        else:
            raise RuntimeError("no OpenGL 4.3 context: " + "; ".join(reasons))
    ctx = _contexts[0]
    ctx.__enter__()  # current again: another library (pyrender, PyOpenGL) may have switched
    return ctx


# The functions below take a `context=` argument, which hides this module's `context`.
_default_context = context


def _program(ctx: Any, shaders: Shaders) -> Any:
    """The linked program of `shaders` on `ctx`, compiled once per source."""
    sources = shaders.sources
    key = (id(ctx), "\0".join(sources.values()))
    if key not in _programs:
        if "compute_shader" in sources:
            _programs[key] = ctx.compute_shader(sources["compute_shader"])
        else:
            _programs[key] = ctx.program(**sources)
    program = _programs[key]
    shaders.bind(program)
    return program


def shade(
    positions: ArrayLike,
    normals: ArrayLike,
    scene: Scene,
    *,
    modelview: ArrayLike | None = None,
    normalize: bool = False,
    rescale_normal: bool = False,
    colors: ArrayLike | None = None,
    color_material: str | None = None,
    color_material_face: Face = "front_and_back",
    context: Any = None,
) -> NDArray[np.float32]:
    """`gs.shade` computed by `compute_shader`'s GLSL on an OpenGL context, in float32.

    Parameters
    ----------
    positions : (..., 3) array-like
        As for `gs.shade` (arrays broadcast).
    normals : (..., 3) array-like
        As for `gs.shade`.
    scene : Scene
        As for `gs.shade`.
    modelview : (4, 4) float, optional
        As for `gs.shade`.
    normalize : bool
        As for `gs.shade`.
    rescale_normal : bool
        As for `gs.shade`.
    colors : (..., 3) or (..., 4) array-like, optional
        As for `gs.shade`; uint8 colours are scaled by 1/255.
    color_material : {None, "ambient", "diffuse", "specular", "emission", "ambient_and_diffuse"}
        As for `gs.shade`.
    color_material_face : {"front_and_back", "front", "back"}
        As for `gs.shade`.
    context : moderngl.Context, optional
        Default: `context()`.

    Returns
    -------
    (..., 4) or (k, ..., 4) float32 ndarray
        `gs.shade`'s layout: one RGBA plane per name of ``scene.outputs``.
    """
    p, n, c = vertices(positions, normals, colors, "glsl.shade")
    leading = p.shape[:-1]
    if c is not None:
        color_material = color_material or "ambient_and_diffuse"
    shaders = compute_shader(
        scene,
        modelview=modelview,
        normalize=normalize,
        rescale_normal=rescale_normal,
        color_material=color_material,
        color_material_face=color_material_face,
    )
    ctx = context if context is not None else _default_context()
    count = int(np.prod(leading, dtype=np.int64))
    planes = len(shaders.outputs)
    program = _program(ctx, shaders)
    member = program.get("gs_count", None)
    if member is not None:
        member.value = count
    p32 = np.ascontiguousarray(p, np.float32).reshape(-1, 3)
    n32 = np.ascontiguousarray(n, np.float32).reshape(-1, 3)
    c32 = np.ones((count, 4), np.float32)
    if c is not None:
        flat = c.reshape(count, -1)
        c32[:, : flat.shape[1]] = flat
    data = {0: p32, 1: n32, 2: c32}
    buffers = {b: ctx.buffer(a.tobytes() or b"\0" * 16) for b, a in data.items()}
    result = ctx.buffer(reserve=max(16, planes * count * 16))
    try:
        for binding, buffer in [*buffers.items(), (3, result)]:
            buffer.bind_to_storage_buffer(binding)
        groups = -(-count // 64)
        x = max(1, min(groups, 65535))
        program.run(group_x=x, group_y=max(1, -(-groups // x)))
        out = np.frombuffer(result.read(), np.float32)[: planes * count * 4]
    finally:
        for buffer in [*buffers.values(), result]:
            buffer.release()
    shaped = out.reshape(planes, *leading, 4).copy()
    return shaped[0] if planes == 1 else shaped


@dataclass(eq=False)
class Targets(ValueRecord):
    """Float32 images of `rasterize`, row 0 at the top: pixel (row r, column c) has its centre
    at window coordinates (c + 0.5, height - r - 0.5).

    Attributes
    ----------
    color : (height, width, 4)
        GL's colour sum (what `gs.render` returns); the background where nothing is drawn.
    primary, secondary : (height, width, 4)
        The lit primary and secondary colours (front or back by the facing), clamped; 0 where
        nothing is drawn.
    position : (height, width, 4)
        The interpolated eye-space position; w = 1 where covered, 0 elsewhere.
    normal : (height, width, 4)
        The interpolated eye-space normal (not normalised); w = +1 where the covering triangle
        is front-facing (counter-clockwise), -1 back-facing, 0 uncovered.
    depth : (height, width)
        Window depth in [0, 1] (a 24-bit depth buffer), 1 where nothing is drawn.
    """

    color: NDArray[np.float32]
    primary: NDArray[np.float32]
    secondary: NDArray[np.float32]
    position: NDArray[np.float32]
    normal: NDArray[np.float32]
    depth: NDArray[np.float32]

    @property
    def covered(self) -> NDArray[np.bool_]:
        """(height, width) bool: a triangle covers the pixel centre."""
        result: NDArray[np.bool_] = self.position[..., 3] == 1.0
        return result


def rasterize(
    positions: ArrayLike,
    normals: ArrayLike,
    faces: ArrayLike,
    projection: ArrayLike,
    width: int,
    height: int,
    scene: Scene,
    *,
    shading: Shading = "phong",
    normalize: bool = True,
    colors: ArrayLike | None = None,
    color_material: str | None = None,
    color_material_face: Face = "front_and_back",
    cull: Cull | None = None,
    background: ArrayLike = (0.0, 0.0, 0.0, 0.0),
    context: Any = None,
) -> Targets:
    """Draws an eye-space triangle mesh with `raster_shaders` into float32 targets.

    Parameters
    ----------
    positions : (n, 3) float
        Eye-space vertex positions (rounded to float32).
    normals : (n, 3) float
        Eye-space vertex normals (rounded to float32).
    faces : (m, 3) int
        Vertex indices; counter-clockwise in window space is front-facing.
    projection : (4, 4) float
        Row-major: clip = projection @ (position, 1).
    width : int
        The viewport's width, in pixels.
    height : int
        The viewport's height, in pixels.
    scene : Scene
        Lights and viewer in eye coordinates.
    shading : {"phong", "gouraud", "flat"}
        As for `raster_shaders` and `gs.render`.
    normalize : bool
        As for `raster_shaders` and `gs.render` (normals already in eye space: a rescale
        factor belongs in them).
    colors : (n, 3) or (n, 4) float or uint8, optional
        Per-vertex colours for `color_material`, rounded to float32; uint8 colours are divided
        by 255, as in `gs.shade` and `gs.render`.
    color_material : {None, "ambient", "diffuse", "specular", "emission", "ambient_and_diffuse"}
        As for `raster_shaders` and `gs.render`.
    color_material_face : {"front_and_back", "front", "back"}
        As for `raster_shaders` and `gs.render`.
    cull : {None, "back", "front", "front_and_back"}
        Which windings to discard; names are case-insensitive.
    background : (3,) or (4,) float
        The clear colour of `Targets.color`.
    context : moderngl.Context, optional
        Default: `context()`.

    Returns
    -------
    Targets
        The depth test is on (less), blending off, no multisampling, GL's last-vertex
        convention for flat shading.
    """
    moderngl = _moderngl()
    culled = None if cull is None else one_of(cull, "cull", ("back", "front", "front_and_back"))
    ctx = context if context is not None else _default_context()
    p = rows(positions, "positions").astype(np.float32)
    attributes = np.ones((len(p), 10), np.float32)
    attributes[:, 0:3] = p
    attributes[:, 3:6] = rows(normals, "normals").astype(np.float32)
    if colors is not None:
        # uint8 colours are GL's normalised bytes here too, as in gs.shade and gs.render.
        given = rows(
            color_values(array(colors, "colors"), "colors", "glsl.rasterize"),
            "colors",
            None,
            (3, 4),
        )
        attributes[:, 6 : 6 + given.shape[1]] = given
        color_material = color_material or "ambient_and_diffuse"
    shaders = raster_shaders(
        scene,
        shading,
        normalize=normalize,
        color_material=color_material,
        color_material_face=color_material_face,
    )
    program = _program(ctx, shaders)
    program["gs_projection"].write(
        np.asarray(projection, np.float64).T.astype(np.float32).tobytes()
    )
    size = (integer(width, "width", 1, 16384), integer(height, "height", 1, 16384))
    names = ["gs_position", "gs_normal"] + (["gs_color"] if color_material else [])
    layout = "3f 3f " + ("4f" if color_material else "4x4")
    vbo = ctx.buffer(attributes.tobytes() or b"\0" * 40)
    ibo = ctx.buffer(np.ascontiguousarray(faces, np.uint32).tobytes() or b"\0" * 12)
    vao = ctx.vertex_array(program, [(vbo, layout, *names)], index_buffer=ibo,
                           index_element_size=4, skip_errors=True)  # fmt: skip
    textures = [ctx.texture(size, 4, dtype="f4") for _ in range(5)]
    depth = ctx.depth_texture(size)
    fbo = ctx.framebuffer(color_attachments=textures, depth_attachment=depth)
    try:
        fbo.use()
        ctx.enable_only(moderngl.DEPTH_TEST | (moderngl.CULL_FACE if culled else 0))
        if culled:
            ctx.cull_face = culled
        ctx.depth_func = "<"
        ctx.provoking_vertex = moderngl.LAST_VERTEX_CONVENTION
        fbo.clear(0.0, 0.0, 0.0, 0.0, depth=1.0)
        textures[0].write(
            np.tile(np.asarray(rgba(background, "background"), np.float32), size[0] * size[1])
        )
        if len(np.asarray(faces)):
            vao.render(moderngl.TRIANGLES)
        images = [
            np.frombuffer(t.read(), np.float32).reshape(size[1], size[0], 4)[::-1].copy()
            for t in textures
        ]
        z = np.frombuffer(depth.read(), np.float32).reshape(size[1], size[0])[::-1].copy()
    finally:
        for obj in (vao, fbo, depth, *textures, vbo, ibo):
            obj.release()
    return Targets(images[0], images[1], images[2], images[3], images[4], z)


@overload
def render(
    vertices: Any,
    faces: Any = ...,
    scene: Any = ...,
    camera: Any = ...,
    *,
    depth: Literal[False] = ...,
    context: Any = ...,
    **options: Unpack[SharedRenderOptions],
) -> Image: ...
@overload
def render(
    vertices: Any,
    faces: Any = ...,
    scene: Any = ...,
    camera: Any = ...,
    *,
    depth: Literal[True],
    context: Any = ...,
    **options: Unpack[SharedRenderOptions],
) -> tuple[Image, NDArray[np.float32]]: ...
@overload
def render(
    vertices: Any,
    faces: Any = ...,
    scene: Any = ...,
    camera: Any = ...,
    *,
    depth: bool,
    context: Any = ...,
    **options: Unpack[SharedRenderOptions],
) -> Image | tuple[Image, NDArray[np.float32]]: ...
def render(
    vertices: Any,
    faces: Any = None,
    scene: Any = None,
    camera: Any = None,
    *,
    depth: bool = False,
    context: Any = None,
    **options: Unpack[SharedRenderOptions],
) -> Image | tuple[Image, NDArray[np.float32]]:
    """`gs.render` drawn by OpenGL with `raster_shaders`: the same arguments and result
    (float32), for comparing a GL rendering of the scene with glshade's (`gs.compare`).

    The model-view transform of positions and normals is applied here in float64 (the shaders
    get eye coordinates); flat shading gets unshared vertices carrying their face's normal, so
    that GL's provoking vertex lights each face with it, as `gs.render` does. Without a scene
    or a camera, `gs.render`'s defaults: ``gs.glsl.render(mesh)`` draws what
    ``gs.render(mesh)`` draws, at any `width` and `height`.

    Parameters
    ----------
    vertices : (n, 3) float, or a mesh
        As for `gs.render`: positions, or a ``trimesh.Trimesh``, ``trimesh.Scene`` or
        ``(vertices, faces)`` tuple with `faces` omitted.
    faces : (m, 3) int, optional
        As for `gs.render`.
    scene : Scene, optional
        As for `gs.render`; None (the default) is `gs.render`'s default scene: a key light and
        a dim fill fixed in the world, a light grey material.
    camera : Camera, optional
        As for `gs.render`; None (the default) is the camera `gs.render` frames the mesh's
        bounds with (placed by ``model``), for an image of ``width`` x ``height``.
    depth : bool
        As for `gs.render`.
    context : moderngl.Context, optional
        Default: `context()`.
    **options
        `gs.render`'s options that GL's pipeline has, with `gs.render`'s defaults: `width`,
        `height`, `shading`, `normals`, `colors`, `color_material`, `color_material_face`,
        `model`, `normalize`, `rescale_normal`, `cull`, `background`, `lights_in` and
        `transfer` (the encoding of the image's RGB, applied to GL's float32 result). Any
        other name is a TypeError.

    Returns
    -------
    Image, or (Image, depth) with ``depth=True``
        (height, width, 4) float32 RGBA, row 0 at the top; depth (height, width) in [0, 1].

    Raises
    ------
    ImportError
        Without moderngl.
    ValueError, TypeError
        As `gs.render` raises them: wrong shapes, dtypes, names, sizes or matrices, a colour
        given by name.

    Warns
    -----
    ColorRangeWarning
        As `gs.render`: for a `background` that looks like 0-255 bytes.
    """
    o = shared_defaults(gs_render, options, "render")
    w = integer(o["width"], "width", 1, 16384)
    h = integer(o["height"], "height", 1, 16384)
    mode = one_of(o["shading"], "shading", ("flat", "gouraud", "phong"))
    encoding = transfer_name("linear" if o["transfer"] is None else o["transfer"])
    m = transform(o["model"], "model")
    mesh = {name: o[name] for name in ("normals", "colors", "color_material", "lights_in")}
    given = render_input(
        vertices, faces, scene, camera, shading=mode, model=m, width=w, height=h, texture=False,
        **mesh,
    )  # fmt: skip
    if not isinstance(given.scene, Scene):
        raise TypeError(
            f"glsl.render draws GL's lighting equation; a {type(given.scene).__module__}."
            f"{type(given.scene).__name__} has no GLSL counterpart here yet: use glshade.render"
        )
    scene = given.scene
    warn_if_bytes(color(o["background"], "background"), "background", "render")
    v = given.vertices.astype(np.float64)
    f = given.faces
    modelview = given.camera.view @ m
    linear = modelview[:3, :3]
    normal_matrix = np.linalg.inv(linear).T
    if o["rescale_normal"]:
        normal_matrix = normal_matrix / np.linalg.norm(np.linalg.inv(linear)[2])
    eye = v @ linear.T + modelview[:3, 3]
    colors_given = given.colors
    from .._normals import face_normals, vertex_normals

    if mode == "flat":
        n = face_normals(v, f) if given.normals is None else given.normals
        eye, n = eye[f].reshape(-1, 3), np.repeat(n, 3, axis=0)
        if colors_given is not None:
            colors_given = colors_given[f].reshape(-1, colors_given.shape[1])
        f = np.arange(len(eye), dtype=np.int64).reshape(-1, 3)
    else:
        n = vertex_normals(v, f) if given.normals is None else given.normals
    targets = rasterize(
        eye,
        np.asarray(n, np.float64) @ normal_matrix.T,
        f,
        given.camera.projection_matrix(w, h),
        w,
        h,
        scene,
        shading=cast(Shading, mode),
        normalize=o["normalize"],
        colors=colors_given,
        color_material=given.color_material,
        color_material_face=o["color_material_face"],
        cull=o["cull"],
        background=o["background"],
        context=context,
    )
    image = apply_transfer(targets.color, encoding).view(Image)
    return (image, targets.depth) if depth else image
