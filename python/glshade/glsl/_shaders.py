"""`Shaders`: the GLSL of one scene with the values to bind; `compute_shader` and
`raster_shaders` make them."""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._intake import one_of
from .._records import ValueRecord
from .._scene import Scene
from .._typing import Shading
from . import _source
from ._plan import Plan, make_plan
from ._values import values


@dataclass(frozen=True, eq=False)
class Shaders(ValueRecord):
    """GLSL for one scene, specialised like the CPU kernel, and the uniform values to bind.

    Attributes
    ----------
    library : str
        The uniforms and functions alone (no ``#version``, no ``main``), to paste into shaders
        of your own: ``GSColor gs_lighting_front(vec3 V, vec3 n, vec4 color)`` (and
        ``gs_lighting_back``, called with ``-n``, with two-sided lighting) light one eye-space
        vertex, returning the clamped primary and secondary colours; ``gs_eye_space`` applies
        the modelview; ``gs_dot``, ``gs_transform``, ``gs_unit``, ``gs_direction`` and (when a
        power is needed) ``gs_cos_pow`` are the helpers they use, selects only, and ``precise``
        from GLSL 4.00 on (the macro ``GS_PRECISE``).
    compute : str or None
        ``#version 430`` compute shader (`compute_shader`): SSBOs of tightly packed float
        positions (binding 0, only when the scene reads them) and normals (binding 1), vec4
        colours (binding 2, with colour material), vec4 results (binding 3) in `gs.shade`'s
        layout, ``(len(scene.outputs), count)`` planes; ``uniform uint gs_count``; local size
        64, dispatched as ``(x, y)`` groups covering ``x * y * 64 >= count`` vertices.
    vertex, fragment : str or None
        ``#version 330 core`` pair (`raster_shaders`): attributes ``gs_position`` (location 0),
        ``gs_normal`` (1), ``gs_color`` (2, with colour material); ``uniform mat4
        gs_projection``; fragment outputs ``gs_frag_color`` (location 0, GL's colour sum),
        ``gs_frag_primary``, ``gs_frag_secondary``, ``gs_frag_position`` (eye space, w = 1) and
        ``gs_frag_normal`` (w = +1 front-facing, -1 back-facing) at 1 to 4, which a renderer may
        leave unattached.
    uniforms : Mapping[str, ndarray]
        float32 values by uniform name: shape () for a scalar, (k,) for a vector or an array of
        k floats, (count, k) for an array of vectors; matrices (4, 4) and (3, 3) **row-major**,
        as numpy prints them (GL reads the transpose: ``glUniformMatrix4fv(..., GL_TRUE, m)``,
        or moderngl's ``write(m.T.tobytes())``; `bind` does it). ``gs_projection`` and
        ``gs_count`` are not included: they belong to the draw or dispatch.
    types : Mapping[str, str]
        The GLSL type of each uniform (``"vec3[2]"`` for an array of two).
    outputs : tuple of str
        ``scene.outputs``: the planes of the compute shader's result.
    plan : Plan
        What the source computes (light groups, sides); it decides the code, so a scene with
        other zero/non-zero colours, shininess, attenuation or cutoffs needs new shaders.
    """

    library: str
    compute: str | None
    vertex: str | None
    fragment: str | None
    uniforms: Mapping[str, NDArray[Any]]
    types: Mapping[str, str]
    outputs: tuple[str, ...]
    plan: Plan = field(repr=False)

    def __post_init__(self) -> None:
        # Read-only views, also after unpickling (which hands the mappings over as dicts).
        for name in ("uniforms", "types"):
            object.__setattr__(self, name, MappingProxyType(dict(getattr(self, name))))

    @property
    def sources(self) -> dict[str, str]:
        """The stage sources by moderngl's keyword: ``compute_shader`` or ``vertex_shader`` and
        ``fragment_shader``."""
        if self.compute is not None:
            return {"compute_shader": self.compute}
        assert self.vertex is not None and self.fragment is not None
        return {"vertex_shader": self.vertex, "fragment_shader": self.fragment}

    def bind(self, program: Any) -> None:
        """Writes `uniforms` into a moderngl program (matrices transposed for GL); names the
        GLSL compiler removed as unused are skipped.

        Parameters
        ----------
        program : moderngl.Program or moderngl.ComputeShader
            A program built from these sources (`sources`); anything whose
            ``get(name, None)`` returns an object with ``write(bytes)`` will do.
        """
        for name, value in self.uniforms.items():
            member = program.get(name, None)
            if member is not None:
                data = value.T if self.types[name].startswith("mat") else value
                member.write(np.ascontiguousarray(data, np.float32).tobytes())


def _shaders(
    scene: Scene,
    plan: Plan,
    raw: dict[str, NDArray[np.float64]],
    makers: dict[str, Callable[[str], str]],
) -> Shaders:
    lib = _source.library(plan, {name: len(v) if v.ndim else 0 for name, v in raw.items()})
    stages = {stage: make(lib) for stage, make in makers.items()}
    uniforms = {name: np.asarray(v, np.float64).astype(np.float32) for name, v in raw.items()}
    for value in uniforms.values():
        value.flags.writeable = False
    types = {
        name: _source.uniform_type(name, len(v) if v.ndim >= 1 else 0)
        for name, v in uniforms.items()
    }
    return Shaders(
        lib,
        stages.get("compute"),
        stages.get("vertex"),
        stages.get("fragment"),
        MappingProxyType(uniforms),
        MappingProxyType(types),
        scene.outputs,
        plan,
    )


def compute_shader(
    scene: Scene,
    *,
    modelview: ArrayLike | None = None,
    normalize: bool = False,
    rescale_normal: bool = False,
    color_material: str | None = None,
    color_material_face: str = "front_and_back",
) -> Shaders:
    """The GLSL 430 compute shader computing `gs.shade(positions, normals, scene, ...)` per
    vertex, with its uniforms.

    Parameters
    ----------
    scene : Scene
        Lights, materials and light model.
    modelview : (4, 4) float, optional
        As for `gs.shade`.
    normalize : bool
        As for `gs.shade`.
    rescale_normal : bool
        As for `gs.shade`.
    color_material : {None, "ambient", "diffuse", "specular", "emission", "ambient_and_diffuse"}
        As for `gs.shade`; None (the default) is off, any other value means vertex colours are
        bound.
    color_material_face : {"front_and_back", "front", "back"}
        As for `gs.shade`.

    Returns
    -------
    Shaders
        ``compute`` set, ``vertex`` and ``fragment`` None.

    Raises
    ------
    TypeError, ValueError
        For a scene that is not a `gs.Scene`, or a bad option, naming it.

    Examples
    --------
    >>> import glshade as gs
    >>> shaders = gs.glsl.compute_shader(gs.Scene(lights=[gs.Light()]))
    >>> "spot" in shaders.compute, sorted(shaders.uniforms)[:2]
    (False, ['gs_front_ambient', 'gs_front_diffuse'])
    """
    plan = make_plan(
        scene,
        modelview=modelview,
        normalize=normalize,
        rescale_normal=rescale_normal,
        color_material=color_material,
        color_material_face=color_material_face,
    )
    return _shaders(
        scene, plan, values(scene, plan), {"compute": lambda lib: _source.compute(plan, lib)}
    )


def raster_shaders(
    scene: Scene,
    shading: Shading = "phong",
    *,
    modelview: ArrayLike | None = None,
    normalize: bool = True,
    rescale_normal: bool = False,
    color_material: str | None = None,
    color_material_face: str = "front_and_back",
) -> Shaders:
    """The GLSL 330 core vertex + fragment pair that draws a mesh as `gs.render` does.

    Parameters
    ----------
    scene : Scene
        Lights and viewer in eye coordinates, materials, light model.
    shading : {"phong", "gouraud", "flat"}
        Per fragment (the interpolated eye position and normal), per vertex with the colours
        interpolated, or per vertex with the provoking vertex's colour (``flat`` varyings; GL's
        last vertex unless the renderer changes the convention).
    modelview : (4, 4) float, optional
        Applied in the vertex shader (``gs_modelview``, ``gs_normal_matrix``); None: the
        attributes are in eye coordinates already (transform them in float64 for the closest
        agreement with `gs.render`).
    normalize : bool
        GL_NORMALIZE wherever the equation is evaluated (on by default, as in `gs.render`).
    rescale_normal : bool
        As for `gs.shade`.
    color_material : {None, "ambient", "diffuse", "specular", "emission", "ambient_and_diffuse"}
        As for `gs.shade`; None (the default) is off, any other value means vertex colours are
        bound.
    color_material_face : {"front_and_back", "front", "back"}
        As for `gs.shade`.

    Returns
    -------
    Shaders
        ``vertex`` and ``fragment`` set, ``compute`` None.
    """
    mode = one_of(shading, "shading", ("phong", "gouraud", "flat"))
    plan = make_plan(
        scene,
        modelview=modelview,
        normalize=normalize,
        rescale_normal=rescale_normal,
        color_material=color_material,
        color_material_face=color_material_face,
    )
    stages = {
        "vertex": lambda lib: _source.vertex(plan, mode, lib),
        "fragment": lambda lib: _source.fragment(plan, mode, lib),
    }
    return _shaders(scene, plan, values(scene, plan), stages)
