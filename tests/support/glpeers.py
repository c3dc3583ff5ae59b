"""Headless OpenGL for the cross-checks: Mesa's llvmpipe through EGL, on the CPU.

- `moderngl_context()`: the session's standalone moderngl context (GL 4.3+ core).
- `compat_context()`: an EGL compatibility-profile context (GL 2.1 fixed function) for raw
  PyOpenGL calls, and `load_fixed_function(scene, ...)`, which sets a `gs.Scene` as GL's
  glLight/glMaterial/glLightModel state in it.
- `shade_compute(...)` and `rasterize(...)`: `glshade.glsl`'s compute shader and raster
  shaders on that context (`gs.glsl.shade`, `gs.glsl.rasterize`: lit colours, eye position,
  eye normal, depth in float32 targets).
- `pyrender_source` / `set_uniforms_gl`: `glshade.glsl`'s lighting library in pyrender's raw
  GL programs.

When a context cannot be made, the calling test fails under CI=true and is skipped elsewhere
(`conftest.unavailable`). Every context is created once per session and made current by the
accessor, so the contexts of moderngl, PyOpenGL and pyrender can take turns in one process.
"""

from __future__ import annotations

import ctypes
import functools
import os
import sys
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Literal

# PyOpenGL picks its platform when it is first imported; pyrender and the fixed-function oracle
# need EGL (no X server). LIBGL_ALWAYS_SOFTWARE keeps Mesa on llvmpipe even where a GPU driver
# exists, so the numbers are those of the CPU renderer these tests were measured with.
os.environ["PYOPENGL_PLATFORM"] = "egl"
os.environ.setdefault("LIBGL_ALWAYS_SOFTWARE", "1")
_platform = getattr(sys.modules.get("OpenGL.platform"), "PLATFORM", None)
if _platform is not None and "egl" not in type(_platform).__module__:
    raise RuntimeError("PyOpenGL was imported before glpeers could set PYOPENGL_PLATFORM=egl")

import numpy as np  # noqa: E402
from conftest import unavailable  # noqa: E402

import glshade as gs  # noqa: E402

GLSL_DIR = Path(__file__).parent.parent / "glsl"

# GL's limit on fixed-function lights in Mesa (GL_MAX_LIGHTS); glshade.glsl takes more.
GL_MAX_LIGHTS = 8
COLOR_MATERIAL_MODES = {
    None: 0,
    "ambient": 1,
    "diffuse": 2,
    "specular": 3,
    "emission": 4,
    "ambient_and_diffuse": 5,
}
COLOR_MATERIAL_FACES = {"front": 1, "back": 2, "front_and_back": 3}

_failures: dict[str, str] = {}


def gl_resource(what: str, make: Any) -> Any:
    """make() (a context, a renderer): on any error the calling test fails under CI=true and
    is skipped elsewhere, naming `what`; a failure is remembered, so later tests report it
    without retrying."""
    if what in _failures:
        unavailable(_failures[what])
    try:
        return make()
    except Exception as exc:  # any missing library, EGL or GL error means "no context"
        _failures[what] = f"{what}: {type(exc).__name__}: {exc}"
        unavailable(_failures[what])


@functools.cache
def pyrender_renderer(width: int, height: int) -> Any:
    """One stock pyrender OffscreenRenderer per size for the session, never deleted: its
    delete() calls eglTerminate on the EGL display moderngl's context shares, which would break
    every later GL test."""
    import pyrender

    return gl_resource(
        "pyrender OffscreenRenderer (EGL)", lambda: pyrender.OffscreenRenderer(width, height)
    )


# ---------------------------------------------------------------------------------------------
# moderngl


def moderngl_context() -> Any:
    """The session's standalone moderngl context (`gs.glsl.context`: EGL, GL >= 4.3 core,
    llvmpipe), made current."""
    return gl_resource("moderngl EGL context (require=430)", gs.glsl.context)


# ---------------------------------------------------------------------------------------------
# EGL compatibility profile for raw PyOpenGL


@dataclass
class CompatContext:
    """An EGL context with the compatibility profile and a 1x1 framebuffer (surfaceless EGL has
    no default one, and draws, even in feedback mode, need a complete framebuffer)."""

    display: Any
    context: Any
    renderer: str
    version: str

    def make_current(self) -> None:
        from OpenGL import EGL

        if not EGL.eglMakeCurrent(
            self.display, EGL.EGL_NO_SURFACE, EGL.EGL_NO_SURFACE, self.context
        ):
            raise RuntimeError("eglMakeCurrent failed")


def _egl_display() -> Any:
    """Mesa's surfaceless platform, else the first EGL device (as pyrender does)."""
    from OpenGL import EGL

    address = EGL.eglGetProcAddress(b"eglGetPlatformDisplayEXT")
    if not address:
        raise RuntimeError("EGL has no eglGetPlatformDisplayEXT")
    get_display = ctypes.CFUNCTYPE(EGL.EGLDisplay, ctypes.c_int, ctypes.c_void_p, ctypes.c_void_p)(
        address
    )
    client = (EGL.eglQueryString(EGL.EGL_NO_DISPLAY, EGL.EGL_EXTENSIONS) or b"").split()
    if b"EGL_MESA_platform_surfaceless" in client:
        return get_display(0x31DD, None, None)  # EGL_PLATFORM_SURFACELESS_MESA
    query = ctypes.CFUNCTYPE(
        EGL.EGLBoolean, EGL.EGLint, ctypes.c_void_p, ctypes.POINTER(EGL.EGLint)
    )(EGL.eglGetProcAddress(b"eglQueryDevicesEXT"))
    devices = (ctypes.c_void_p * 1)()
    count = EGL.EGLint()
    if not query(1, devices, ctypes.byref(count)) or count.value < 1:
        raise RuntimeError("EGL reports no device")
    return get_display(0x313F, devices[0], None)  # EGL_PLATFORM_DEVICE_EXT


@functools.cache
def _compat() -> CompatContext:
    from OpenGL import EGL, GL

    display = _egl_display()
    major, minor = EGL.EGLint(), EGL.EGLint()
    if not display or not EGL.eglInitialize(display, ctypes.byref(major), ctypes.byref(minor)):
        raise RuntimeError("eglInitialize failed")
    if not EGL.eglBindAPI(EGL.EGL_OPENGL_API):
        raise RuntimeError("eglBindAPI(EGL_OPENGL_API) failed")
    # No profile mask and version 2.1: the compatibility profile.
    attributes = (EGL.EGLint * 5)(
        EGL.EGL_CONTEXT_MAJOR_VERSION, 2, EGL.EGL_CONTEXT_MINOR_VERSION, 1, EGL.EGL_NONE
    )
    context = EGL.eglCreateContext(display, EGL.EGLConfig(), EGL.EGL_NO_CONTEXT, attributes)
    if not context:
        raise RuntimeError("eglCreateContext (compatibility profile, no config) failed")
    compat = CompatContext(display, context, "", "")
    compat.make_current()
    compat.renderer = GL.glGetString(GL.GL_RENDERER).decode()
    compat.version = GL.glGetString(GL.GL_VERSION).decode()
    if "Compatibility" not in compat.version:
        raise RuntimeError(f"got {compat.version}, not a compatibility profile")
    framebuffer = GL.glGenFramebuffers(1)
    GL.glBindFramebuffer(GL.GL_FRAMEBUFFER, framebuffer)
    renderbuffer = GL.glGenRenderbuffers(1)
    GL.glBindRenderbuffer(GL.GL_RENDERBUFFER, renderbuffer)
    GL.glRenderbufferStorage(GL.GL_RENDERBUFFER, GL.GL_RGBA8, 1, 1)
    GL.glFramebufferRenderbuffer(
        GL.GL_FRAMEBUFFER, GL.GL_COLOR_ATTACHMENT0, GL.GL_RENDERBUFFER, renderbuffer
    )
    if GL.glCheckFramebufferStatus(GL.GL_FRAMEBUFFER) != GL.GL_FRAMEBUFFER_COMPLETE:
        raise RuntimeError("incomplete framebuffer")
    return compat


def compat_context() -> CompatContext:
    """The session's EGL compatibility-profile context (fixed-function GL), made current."""
    compat: CompatContext = gl_resource("EGL OpenGL compatibility-profile context", _compat)
    compat.make_current()
    return compat


def load_fixed_function(
    scene: gs.Scene,
    *,
    normalize: bool = False,
    rescale_normal: bool = False,
    color_material: str | None = None,
    color_material_face: str = "front_and_back",
) -> None:
    """Sets `scene` as the fixed-function lighting state of the current compatibility context.

    Lights are specified under an identity modelview (glshade's lights are in eye space), all
    of GL's lights are set (unused ones disabled), materials are set with COLOR_MATERIAL off
    (GL makes colour-material replacements permanent), then COLOR_MATERIAL is enabled if asked.
    The modelview is left at identity. Only GL's features are accepted: at most GL_MAX_LIGHTS
    lights, Blinn's halfway vector, the infinite viewer (0, 0, 1, 0) or the local one (0, 0, 0, 1).
    """
    from OpenGL import GL

    lights = scene.lights
    if len(lights) > GL_MAX_LIGHTS:
        raise ValueError(f"fixed-function GL has {GL_MAX_LIGHTS} lights, the scene {len(lights)}")
    if scene.specular != "blinn":
        raise ValueError("fixed-function GL has only the halfway vector (specular='blinn')")
    if not scene.specular_gate:
        raise ValueError("fixed-function GL always has the specular gate f_i (eq. 2.2)")
    viewer = tuple(float(x) for x in scene.viewer)
    if viewer not in ((0.0, 0.0, 1.0, 0.0), (0.0, 0.0, 0.0, 1.0)):
        raise ValueError(f"GL's viewer is (0, 0, 1, 0) or (0, 0, 0, 1), got {viewer}")
    exponents = [scene.material.shininess, scene.back_material.shininess]
    exponents += [float(e) for e in np.atleast_1d(lights.spot_exponent)]
    if max(exponents) > 128:  # glMaterial/glLight would raise GL_INVALID_VALUE
        raise ValueError(f"GL's shininess and spot exponents are at most 128, got {max(exponents)}")

    GL.glMatrixMode(GL.GL_MODELVIEW)
    GL.glLoadIdentity()
    GL.glEnable(GL.GL_LIGHTING)
    GL.glDisable(GL.GL_COLOR_MATERIAL)
    for i in range(GL_MAX_LIGHTS):
        gl_light = GL.GL_LIGHT0 + i
        if i >= len(lights):
            GL.glDisable(gl_light)
            continue
        light = lights[i]
        GL.glEnable(gl_light)
        for pname, value in (
            (GL.GL_POSITION, light.position),
            (GL.GL_AMBIENT, light.ambient),
            (GL.GL_DIFFUSE, light.diffuse),
            (GL.GL_SPECULAR, light.specular),
            (GL.GL_SPOT_DIRECTION, light.spot_direction),
        ):
            GL.glLightfv(gl_light, pname, np.asarray(value, np.float32))
        for pname, scalar in (
            (GL.GL_SPOT_EXPONENT, light.spot_exponent),
            (GL.GL_SPOT_CUTOFF, light.spot_cutoff),
            (GL.GL_CONSTANT_ATTENUATION, light.constant_attenuation),
            (GL.GL_LINEAR_ATTENUATION, light.linear_attenuation),
            (GL.GL_QUADRATIC_ATTENUATION, light.quadratic_attenuation),
        ):
            GL.glLightf(gl_light, pname, float(scalar))
    for face, material in ((GL.GL_FRONT, scene.material), (GL.GL_BACK, scene.back_material)):
        for pname, value in (
            (GL.GL_AMBIENT, material.ambient),
            (GL.GL_DIFFUSE, material.diffuse),
            (GL.GL_SPECULAR, material.specular),
            (GL.GL_EMISSION, material.emission),
        ):
            GL.glMaterialfv(face, pname, np.asarray(value, np.float32))
        GL.glMaterialf(face, GL.GL_SHININESS, material.shininess)
    GL.glLightModelfv(GL.GL_LIGHT_MODEL_AMBIENT, np.asarray(scene.global_ambient, np.float32))
    GL.glLightModeli(GL.GL_LIGHT_MODEL_LOCAL_VIEWER, int(viewer[3] == 1.0))
    GL.glLightModeli(GL.GL_LIGHT_MODEL_TWO_SIDE, int(scene.two_side))
    GL.glLightModeli(
        GL.GL_LIGHT_MODEL_COLOR_CONTROL,
        GL.GL_SEPARATE_SPECULAR_COLOR if scene.separate_specular else GL.GL_SINGLE_COLOR,
    )
    for cap, on in ((GL.GL_NORMALIZE, normalize), (GL.GL_RESCALE_NORMAL, rescale_normal)):
        (GL.glEnable if on else GL.glDisable)(cap)
    if color_material is not None:
        faces = {"front": GL.GL_FRONT, "back": GL.GL_BACK, "front_and_back": GL.GL_FRONT_AND_BACK}
        modes = {
            "ambient": GL.GL_AMBIENT,
            "diffuse": GL.GL_DIFFUSE,
            "specular": GL.GL_SPECULAR,
            "emission": GL.GL_EMISSION,
            "ambient_and_diffuse": GL.GL_AMBIENT_AND_DIFFUSE,
        }
        GL.glColorMaterial(faces[color_material_face], modes[color_material])
        GL.glEnable(GL.GL_COLOR_MATERIAL)


# ---------------------------------------------------------------------------------------------
# glshade.glsl's shaders in raw GL programs (pyrender's)


def pyrender_source(shaders: gs.glsl.Shaders, file_name: str, **defines: int) -> str:
    """``#version 330 core``, `defines`, GS_TWO_SIDE and GS_NORMALIZE from the shaders' plan,
    ``shaders.library``, then the file ``glsl/<file_name>``."""
    plan = shaders.plan
    defines = {**defines, "GS_TWO_SIDE": int(len(plan.sides) == 2),
               "GS_NORMALIZE": int(plan.normalize)}  # fmt: skip
    head = ["#version 330 core", *[f"#define {k} {v}" for k, v in defines.items()]]
    body = (GLSL_DIR / file_name).read_text()
    return "\n".join([*head, shaders.library, body])


def set_uniforms_gl(program: int, shaders: gs.glsl.Shaders, ints: dict[str, int]) -> None:
    """Writes `shaders.uniforms` (and the int uniforms `ints`) into the current raw GL program
    `program` (e.g. one of pyrender's)."""
    from OpenGL import GL

    setters = {"float": GL.glUniform1fv, "vec3": GL.glUniform3fv, "vec4": GL.glUniform4fv}
    for name, value in ints.items():
        location = GL.glGetUniformLocation(program, name)
        if location >= 0:
            GL.glUniform1i(location, value)
    for name, value in shaders.uniforms.items():
        location = GL.glGetUniformLocation(program, name)
        if location < 0:
            continue
        glsl_type = shaders.types[name]
        v = np.ascontiguousarray(value)
        if glsl_type == "mat4":
            GL.glUniformMatrix4fv(location, 1, GL.GL_TRUE, v)
        elif glsl_type == "mat3":
            GL.glUniformMatrix3fv(location, 1, GL.GL_TRUE, v)
        else:
            base, _, count = glsl_type.partition("[")
            setters[base](location, int(count[:-1]) if count else 1, v)


# ---------------------------------------------------------------------------------------------
# How close two float32 evaluations of the equation must be


@dataclass
class Float32Tolerance:
    """Per vertex: may it be compared, and how far may two float32 evaluations be apart.

    bound : (n,)
        ``tol * max(1, sum |terms|)`` (glshade's float32 bound: 1e-5 for unit normals and
        colours in [0, 1]) ``+ 16 u sum s tan(theta) |specular|`` (glshade's conditioning term;
        both on the documentation's Accuracy page, docs/pages/guide/accuracy.md)
        ``+ 2 u sum s |specular|``: the evaluation GL implementations use,
        ``pow(n.h, s)`` of a float32 dot product rounded to about u, multiplies that rounding by
        the exponent s (measured on Mesa: at most 0.35 u s |specular| beyond the first term).
        Without `gl_pow` the first term alone.
    comparable : (n,) bool
        Not within `margin` of a discontinuity (n.VP = 0, a cone edge, a point light), and no
        specular power above float32's range (a power of a non-unit normal, e.g. (5 n.h)^128,
        is inf in float32, and 0 * inf is NaN where att * spot = 0; the exact value is finite).
    reference : gl_reference.Reference
        The float64 oracle's result for the same inputs.
    """

    bound: np.ndarray
    comparable: np.ndarray
    reference: Any


def float32_tolerance(
    ref: Any,
    positions: np.ndarray,
    normals: np.ndarray,
    tol: float = 1e-5,
    margin: float = 2e-5,
    *,
    gl_pow: bool = True,
) -> Float32Tolerance:
    """The `Float32Tolerance` of the inputs `gl_reference.gl_lighting` sees as `ref`; without
    `gl_pow` (a peer that forms the powers as glshade's careful path does, glshade.glsl) the
    bound is ``tol * max(1, sum |terms|)`` and the plain power's 4u s |specular term| of
    glshade's own float32 fast mode."""
    import copy

    from support.gl_reference import gl_lighting

    reference = gl_lighting(positions, normals, ref)
    u = float(np.finfo(np.float32).eps) / 2
    power_sum = np.zeros(len(positions))
    largest_power = np.zeros(len(positions))
    sides = 2 if ref.two_side else 1
    for light in ref.lights:
        # The light's specular terms alone, as the secondary colour of each side.
        alone = copy.copy(ref)
        alone.lights = [light]
        alone.separate_specular = True
        terms = gl_lighting(positions, normals, alone).unclamped
        # Its bare power f (n.h)^s: white, unattenuated, no spot, white specular material.
        bare = copy.copy(alone)
        bare.lights = [
            {
                **light,
                "ambient": (0, 0, 0),
                "diffuse": (0, 0, 0),
                "specular": (1, 1, 1),
                "spot_cutoff": 180.0,
                "constant_attenuation": 1.0,
                "linear_attenuation": 0.0,
                "quadratic_attenuation": 0.0,
            }
        ]
        bare.material = {**ref.material, "specular": (1, 1, 1)}
        back = ref.back_material or ref.material
        bare.back_material = {**back, "specular": (1, 1, 1)}
        bare.colors = None
        powers = gl_lighting(positions, normals, bare).unclamped
        for side, material in enumerate((ref.material, back)[:sides]):
            spec = np.abs(terms[2 * side + 1][:, :3]).max(axis=1)
            power_sum += float(material["shininess"]) * spec
            largest_power = np.maximum(largest_power, powers[2 * side + 1][:, 0])
    # glshade's own float32 fast mode forms the power plainly where it can (its lean
    # arithmetic): 4u s |specular term| of its bound (the Accuracy page).
    bound = tol * np.maximum(1.0, reference.magnitude) + 4 * u * power_sum
    if gl_pow:
        bound = bound + 16 * u * reference.sensitivity + 2 * u * power_sum
    comparable = (reference.margin > margin) & (largest_power < np.finfo(np.float32).max / 64)
    return Float32Tolerance(bound, comparable, reference)


def assert_agree(
    tolerance: Float32Tolerance,
    ours: np.ndarray,
    theirs: np.ndarray,
    compared: np.ndarray,
    peer: str,
    context: object = "",
) -> int:
    """Fails the test at the worst of the `compared` rows where glshade's colours `ours` and a
    peer's `theirs` ((n, 4) or (k, n, 4) alike) differ by more than ``tolerance.bound`` in any
    channel of any output; returns the number of rows compared."""
    n = len(compared)
    a, b = ours.reshape(-1, n, 4).astype(np.float64), theirs.reshape(-1, n, 4)
    assert a.shape == b.shape, (a.shape, b.shape)
    assert np.isfinite(b[:, compared]).all(), f"{peer} gave a colour for every compared row"
    err = np.abs(a - b).max(axis=(0, 2))
    bad = np.flatnonzero(compared & (err > tolerance.bound))
    if bad.size:
        i = bad[np.argmax(err[bad] / tolerance.bound[bad])]
        spec = [out[i] for out in tolerance.reference.outputs]
        import pytest

        pytest.fail(
            f"row {i}: |glshade - {peer}| = {err[i]:.3g} > {tolerance.bound[i]:.3g}\n"
            f"glshade {a[:, i]}\n{peer:7} {b[:, i]}\nspec    {spec}\n{context}"
        )
    return int(compared.sum())


# ---------------------------------------------------------------------------------------------
# Per vertex and per pixel: glshade.glsl's shaders through its moderngl helper


def shade_compute(positions: Any, normals: Any, scene: gs.Scene, **kwargs: Any) -> np.ndarray:
    """`gs.shade` evaluated by glshade.glsl's compute shader on llvmpipe, in float32: the same
    arguments and output layout as `gs.shade`."""
    return gs.glsl.shade(positions, normals, scene, context=moderngl_context(), **kwargs)


def rasterize(
    positions: Any,
    normals: Any,
    faces: Any,
    projection: Any,
    width: int,
    height: int,
    scene: gs.Scene | None = None,
    *,
    shading: Literal["phong", "gouraud", "flat"] = "phong",
    normalize: bool = False,
    **kwargs: Any,
) -> gs.glsl.Targets:
    """An eye-space mesh drawn by glshade.glsl's shaders on llvmpipe (`gs.glsl.rasterize`);
    without a scene, lit by none (emission and ambient only), for the geometry targets."""
    lit = scene if scene is not None else gs.Scene(lights=[])
    return gs.glsl.rasterize(
        positions, normals, faces, projection, width, height, lit, shading=shading,
        normalize=normalize, context=moderngl_context(), **kwargs,
    )  # fmt: skip
