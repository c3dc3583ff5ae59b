"""Headless OpenGL for the cross-checks: Mesa's llvmpipe through EGL, on the CPU.

- `moderngl_context()`: the session's standalone moderngl context (GL 4.3+ core).
- `compat_context()`: an EGL compatibility-profile context (GL 2.1 fixed function) for raw
  PyOpenGL calls, and `load_fixed_function(scene, ...)`, which sets a `gs.Scene` as GL's
  glLight/glMaterial/glLightModel state in it.
- `LIGHTING_GLSL` (``glsl/ff_lighting.glsl``): the GL 2.1 lighting equation as one GLSL function,
  written from the spec; `pack_scene` turns a `gs.Scene` into its uniform values and
  `set_uniforms` (moderngl) / `set_uniforms_gl` (raw GL program) load them.
- `shade_compute(...)`: `gs.shade`'s signature and output layout, evaluated per vertex by that
  GLSL in a compute shader.
- `rasterize(...)`: an eye-space triangle mesh rasterised into float32 targets (lit colour,
  secondary colour, eye position, eye normal, depth).

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
from typing import Any, Literal, NamedTuple

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

GLSL_DIR = Path(__file__).parent / "glsl"
LIGHTING_GLSL = (GLSL_DIR / "ff_lighting.glsl").read_text()

# GL's limit on fixed-function lights in Mesa (GL_MAX_LIGHTS); the GLSL port takes more.
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
SHADING_MODES = {"phong": 0, "gouraud": 1, "flat": 2}

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


# ---------------------------------------------------------------------------------------------
# moderngl


@functools.cache
def _moderngl() -> Any:
    import moderngl

    return moderngl.create_standalone_context(backend="egl", require=430)


def moderngl_context() -> Any:
    """The session's standalone EGL moderngl context (GL >= 4.3 core, llvmpipe), made current."""
    ctx = gl_resource("moderngl EGL context (require=430)", _moderngl)
    ctx.__enter__()  # make it current: another context (pyrender, PyOpenGL) may have been
    return ctx


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
# The GLSL port and its uniforms


class UniformValue(NamedTuple):
    """A uniform's GLSL type ("int", "uint", "float", "vec3", "vec4", "mat3", "mat4") and its
    value: shape () or (count,) for scalars, (count, k) for vectors, (k, k) row-major matrices."""

    glsl_type: str
    value: np.ndarray


def max_lights_for(scene: gs.Scene) -> int:
    """The FF_MAX_LIGHTS a shader needs for `scene`: its light count rounded up to 8. The
    light arrays are uniforms, about 36 components per light: llvmpipe's 16384 components per
    stage hold some 400 lights."""
    return max(8, -(-len(scene.lights) // 8) * 8)


def pack_scene(
    scene: gs.Scene,
    *,
    modelview: Any = None,
    normalize: bool = False,
    rescale_normal: bool = False,
    color_material: str | None = None,
    color_material_face: str = "front_and_back",
    max_lights: int | None = None,
) -> dict[str, UniformValue]:
    """The uniforms of ``ff_lighting.glsl`` for `scene` and `gs.shade`'s options.

    Parameters are read from the scene in float64; the per-light constants (unit spot
    direction, cos of the cutoff, exactly 0 at 90 degrees) and the normal matrix are computed in
    float64 and rounded once to float32. Arrays are padded to `max_lights` (default
    `max_lights_for(scene)`), which must equal the shader's FF_MAX_LIGHTS.
    """
    lights = scene.lights
    count = len(lights)
    size = max_lights_for(scene) if max_lights is None else max_lights
    if count > size:
        raise ValueError(f"{count} lights do not fit FF_MAX_LIGHTS = {size}")

    def padded(rows: np.ndarray, width: int, fill: float = 0.0) -> np.ndarray:
        out = np.full((size, width), fill)
        out[:count] = np.asarray(rows, np.float64).reshape(count, width)
        return out if width > 1 else out[:, 0]

    direction = np.asarray(lights.spot_direction, np.float64).reshape(count, 3)
    length = np.linalg.norm(direction, axis=1, keepdims=True)
    direction = np.divide(direction, length, out=np.zeros_like(direction), where=length > 0)
    cutoff = np.asarray(lights.spot_cutoff, np.float64).reshape(count)
    cos_cutoff = np.where(cutoff == 90.0, 0.0, np.cos(np.radians(cutoff)))
    attenuation = np.stack(
        [
            np.asarray(getattr(lights, k), np.float64).reshape(count)
            for k in ("constant_attenuation", "linear_attenuation", "quadratic_attenuation")
        ],
        axis=1,
    )
    materials = (scene.material, scene.back_material)
    m = np.eye(4) if modelview is None else np.asarray(modelview, np.float64)
    m3_inverse = np.linalg.inv(m[:3, :3])
    scale = 1.0 / float(np.linalg.norm(m3_inverse[2])) if rescale_normal else 1.0

    def f4(glsl_type: str, value: Any) -> UniformValue:
        return UniformValue(glsl_type, np.asarray(value, np.float64).astype(np.float32))

    def i4(value: int) -> UniformValue:
        return UniformValue("int", np.asarray(value, np.int32))

    return {
        "ff_light_count": i4(count),
        "ff_light_position": f4("vec4", padded(lights.position, 4)),
        "ff_light_ambient": f4("vec3", padded(np.asarray(lights.ambient)[..., :3], 3)),
        "ff_light_diffuse": f4("vec3", padded(np.asarray(lights.diffuse)[..., :3], 3)),
        "ff_light_specular": f4("vec3", padded(np.asarray(lights.specular)[..., :3], 3)),
        "ff_light_attenuation": f4("vec3", padded(attenuation, 3)),
        "ff_spot_direction": f4("vec3", padded(direction, 3)),
        "ff_spot_exponent": f4("float", padded(lights.spot_exponent, 1)),
        "ff_spot_cutoff": f4("float", padded(cutoff, 1, 180.0)),
        "ff_spot_cos_cutoff": f4("float", padded(cos_cutoff, 1, -1.0)),
        "ff_material_ambient": f4("vec4", [mat.ambient for mat in materials]),
        "ff_material_diffuse": f4("vec4", [mat.diffuse for mat in materials]),
        "ff_material_specular": f4("vec4", [mat.specular for mat in materials]),
        "ff_material_emission": f4("vec4", [mat.emission for mat in materials]),
        "ff_material_shininess": f4("float", [mat.shininess for mat in materials]),
        "ff_global_ambient": f4("vec4", scene.global_ambient),
        "ff_viewer": f4("vec4", scene.viewer),
        "ff_two_side": i4(int(scene.two_side)),
        "ff_separate_specular": i4(int(scene.separate_specular)),
        "ff_phong": i4(int(scene.specular == "phong")),
        "ff_specular_gate": i4(int(scene.specular_gate)),
        "ff_color_material": i4(COLOR_MATERIAL_MODES[color_material]),
        "ff_color_material_faces": i4(
            COLOR_MATERIAL_FACES[color_material_face] if color_material else 0
        ),
        "ff_modelview": f4("mat4", m),
        "ff_normal_matrix": f4("mat3", m3_inverse.T),
        "ff_normal_scale": f4("float", scale),
        "ff_normalize": i4(int(normalize)),
    }


def _column_major(u: UniformValue) -> np.ndarray:
    return np.ascontiguousarray(u.value.T) if u.glsl_type.startswith("mat") else u.value


def set_uniforms(program: Any, uniforms: dict[str, UniformValue]) -> None:
    """Writes `uniforms` into a moderngl program; names the compiler removed are skipped."""
    for name, u in uniforms.items():
        member = program.get(name, None)
        if member is not None:
            member.write(np.ascontiguousarray(_column_major(u)).tobytes())


def set_uniforms_gl(program: int, uniforms: dict[str, UniformValue]) -> None:
    """Writes `uniforms` into the current raw GL program `program` (e.g. one of pyrender's)."""
    from OpenGL import GL

    setters = {
        "int": GL.glUniform1iv,
        "uint": GL.glUniform1uiv,
        "float": GL.glUniform1fv,
        "vec3": GL.glUniform3fv,
        "vec4": GL.glUniform4fv,
    }
    for name, u in uniforms.items():
        location = GL.glGetUniformLocation(program, name)
        if location < 0:
            continue
        value = np.ascontiguousarray(u.value)
        if u.glsl_type == "mat4":
            GL.glUniformMatrix4fv(location, 1, GL.GL_TRUE, value)
        elif u.glsl_type == "mat3":
            GL.glUniformMatrix3fv(location, 1, GL.GL_TRUE, value)
        else:
            rows = 2 if u.glsl_type.startswith("vec") else 1
            count = len(value) if value.ndim == rows else 1
            setters[u.glsl_type](location, count, value)


def glsl_source(version: int | str, *parts: str, max_lights: int = 8, **defines: int) -> str:
    """``#version``, FF_MAX_LIGHTS and `defines`, ``ff_lighting.glsl``, then `parts` (file names
    under ``glsl/``)."""
    head = [f"#version {version}", f"#define FF_MAX_LIGHTS {max_lights}"]
    head += [f"#define {k} {v}" for k, v in defines.items()]
    body = [(GLSL_DIR / p).read_text() for p in parts]
    return "\n".join(
        [*head, "#line 1 1", LIGHTING_GLSL, *[f"#line 1 {i + 2}\n{b}" for i, b in enumerate(body)]]
    )


# ---------------------------------------------------------------------------------------------
# How close two float32 evaluations of the equation must be


@dataclass
class Float32Tolerance:
    """Per vertex: may it be compared, and how far may two float32 evaluations be apart.

    bound : (n,)
        ``tol * max(1, sum |terms|)`` (the README's float32 bound: 1e-5 for unit normals and
        colours in [0, 1]) ``+ 16 u sum s tan(theta) |specular|`` (glshade's conditioning term,
        README "Accuracy") ``+ 2 u sum s |specular|``: the evaluation GL implementations use,
        ``pow(n.h, s)`` of a float32 dot product rounded to about u, multiplies that rounding by
        the exponent s (measured on Mesa: at most 0.35 u s |specular| beyond the first term).
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
    ref: Any, positions: np.ndarray, normals: np.ndarray, tol: float = 1e-5, margin: float = 2e-5
) -> Float32Tolerance:
    """The `Float32Tolerance` of the inputs `gl_reference.gl_lighting` sees as `ref`."""
    import copy

    from gl_reference import gl_lighting

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
    bound = (
        tol * np.maximum(1.0, reference.magnitude)
        + 16 * u * reference.sensitivity
        + 2 * u * power_sum
    )
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
# Per vertex: the compute shader


@functools.cache
def _compute_program(max_lights: int) -> Any:
    return _moderngl().compute_shader(glsl_source(430, "shade.comp", max_lights=max_lights))


def shade_compute(
    positions: Any,
    normals: Any,
    scene: gs.Scene,
    *,
    modelview: Any = None,
    normalize: bool = False,
    rescale_normal: bool = False,
    colors: Any = None,
    color_material: str | None = None,
    color_material_face: str = "front_and_back",
) -> np.ndarray:
    """`gs.shade` evaluated by ``ff_lighting.glsl`` in a compute shader, in float32.

    Same arguments and output layout as `gs.shade`: (n, 4), or (k, n, 4) for the k colours
    ``scene.outputs`` names.
    """
    ctx = moderngl_context()
    p = np.ascontiguousarray(positions, np.float32).reshape(-1, 3)
    n = np.ascontiguousarray(normals, np.float32).reshape(-1, 3)
    count = len(p)
    c = np.ones((count, 4), np.float32)
    if colors is not None:
        given = np.asarray(colors, np.float32)
        c[:, : given.shape[1]] = given
        color_material = color_material or "ambient_and_diffuse"
    uniforms = pack_scene(
        scene,
        modelview=modelview,
        normalize=normalize,
        rescale_normal=rescale_normal,
        color_material=color_material,
        color_material_face=color_material_face,
    )
    program = _compute_program(max_lights_for(scene))
    set_uniforms(program, uniforms)
    program["ff_count"].value = count
    planes = len(scene.outputs)
    groups = -(-count // 64)
    if groups > 65535:
        raise ValueError(f"at most {65535 * 64} vertices per call, got {count}")
    buffers = [ctx.buffer(a.tobytes() or b"\0" * 16) for a in (p, n, c)]
    result = ctx.buffer(reserve=max(16, planes * count * 16))
    for binding, buffer in enumerate([*buffers, result]):
        buffer.bind_to_storage_buffer(binding)
    program.run(group_x=max(groups, 1))
    out = np.frombuffer(result.read(), np.float32)[: planes * count * 4].reshape(planes, count, 4)
    for buffer in [*buffers, result]:
        buffer.release()
    return out[0].copy() if planes == 1 else out.copy()


# ---------------------------------------------------------------------------------------------
# Per pixel: rasterisation into float targets


@dataclass
class Targets:
    """Float32 images of `rasterize`, in image convention: row 0 is the top row, and pixel
    (row r, column c) has its centre at window coordinates (c + 0.5, height - r - 0.5).

    color, secondary : (height, width, 4)
        The lit primary and secondary colour (front or back by the facing), clamped; 0 where
        no triangle covers the pixel centre.
    position : (height, width, 4)
        The interpolated eye-space position; w = 1 where covered, 0 elsewhere.
    normal : (height, width, 4)
        The interpolated eye-space normal (before any normalisation); w = +1 where the
        covering triangle is front-facing (counter-clockwise), -1 back-facing, 0 uncovered.
    depth : (height, width)
        Window depth in [0, 1] of the depth buffer (24-bit), 1 where uncovered.
    """

    color: np.ndarray
    secondary: np.ndarray
    position: np.ndarray
    normal: np.ndarray
    depth: np.ndarray

    @property
    def covered(self) -> np.ndarray:
        """(height, width) bool: a triangle covers the pixel centre."""
        return self.position[..., 3] == 1.0


@functools.cache
def _raster_program(max_lights: int, shading: str) -> Any:
    defines = {"FF_SHADING": SHADING_MODES[shading]}
    return _moderngl().program(
        vertex_shader=glsl_source(330, "raster.vert", max_lights=max_lights, **defines),
        fragment_shader=glsl_source(330, "raster.frag", max_lights=max_lights, **defines),
    )


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
    colors: Any = None,
    color_material: str | None = None,
    color_material_face: str = "front_and_back",
) -> Targets:
    """Rasterises an eye-space triangle mesh with GL (llvmpipe) into float32 targets.

    Parameters
    ----------
    positions, normals : (n, 3) float
        Eye-space vertex positions and normals (cast to float32).
    faces : (m, 3) int
        Vertex indices; counter-clockwise in window space is front-facing.
    projection : (4, 4) float
        Row-major projection matrix: clip = projection @ (position, 1).
    width, height : int
        The viewport, in pixels.
    scene : gs.Scene, optional
        Lit with ``ff_lighting.glsl``: `shading` "phong" per fragment (interpolated position
        and normal, normalised when `normalize`), "gouraud" per vertex and interpolated,
        "flat" per vertex from the provoking (last) vertex. Without a scene the colour targets
        stay 0.
    colors, color_material, color_material_face
        As in `gs.shade` (the colour is interpolated like the normal).

    The depth test is on (less), culling and blending are off, no multisampling.
    """
    import moderngl

    ctx = moderngl_context()
    p = np.asarray(positions, np.float32).reshape(-1, 3)
    count = len(p)
    vertices = np.ones((count, 10), np.float32)
    vertices[:, 0:3] = p
    vertices[:, 3:6] = np.asarray(normals, np.float32).reshape(-1, 3)
    if colors is not None:
        given = np.asarray(colors, np.float32)
        vertices[:, 6 : 6 + given.shape[1]] = given
        color_material = color_material or "ambient_and_diffuse"
    lit = scene if scene is not None else gs.Scene(lights=[])
    program = _raster_program(max_lights_for(lit), shading)
    set_uniforms(
        program,
        pack_scene(
            lit,
            normalize=normalize,
            color_material=color_material,
            color_material_face=color_material_face,
        ),
    )
    program["ff_projection"].write(np.asarray(projection, np.float32).T.copy().tobytes())
    vbo = ctx.buffer(vertices.tobytes())
    ibo = ctx.buffer(np.ascontiguousarray(faces, np.uint32).tobytes())
    vao = ctx.vertex_array(
        program,
        [(vbo, "3f 3f 4f", "in_position", "in_normal", "in_color")],
        index_buffer=ibo,
        index_element_size=4,
        skip_errors=True,
    )
    size = (int(width), int(height))
    textures = [ctx.texture(size, 4, dtype="f4") for _ in range(4)]
    depth = ctx.depth_texture(size)
    fbo = ctx.framebuffer(color_attachments=textures, depth_attachment=depth)
    fbo.use()
    ctx.enable_only(moderngl.DEPTH_TEST)
    ctx.depth_func = "<"
    ctx.provoking_vertex = moderngl.LAST_VERTEX_CONVENTION
    fbo.clear(0.0, 0.0, 0.0, 0.0, depth=1.0)
    vao.render(moderngl.TRIANGLES)
    images = [
        np.frombuffer(t.read(), np.float32).reshape(size[1], size[0], 4)[::-1].copy()
        for t in textures
    ]
    z = np.frombuffer(depth.read(), np.float32).reshape(size[1], size[0])[::-1].copy()
    for obj in (vao, fbo, depth, *textures, vbo, ibo):
        obj.release()
    if scene is None:
        images[0][:] = 0.0
        images[1][:] = 0.0
    return Targets(images[0], images[1], images[2], images[3], z)
