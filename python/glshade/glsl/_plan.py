"""Which terms a scene's GLSL computes: the CPU kernel's plan (``Scene.plan``), decided in Python.

The rules are those of ``src/lighting/fixed_function/plan.rs``: a light term is left out where
its colour is zero, a side's specular where its material (and no tracked vertex colour) has
none, the power where the shininess is 0 (0^0 = 1), attenuation where (k0, k1, k2) = (1, 0, 0),
the cone where the cutoff is 180, a directional light's VP, spot factor and (infinite viewer,
Blinn) halfway vector are per-light constants. Lights that need the same terms share one loop
over uniform arrays.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray

from .._intake import choice, flag, optional_choice, transform
from .._scene import Scene
from .._typing import Float64Array

COLOR_MATERIAL_MODES = ("ambient", "diffuse", "specular", "emission", "ambient_and_diffuse")
COLOR_MATERIAL_FACES = {"front": (0,), "back": (1,), "front_and_back": (0, 1)}


@dataclass(frozen=True)
class LightGroup:
    """Lights that need the same terms (one GLSL loop); `indices` in summation order.

    Attributes
    ----------
    directional : bool
        The lights are directional (``w = 0``): VP and the spot factor are per-light constants.
    ambient : bool
        Their ambient colour is nonzero: the ambient term is computed.
    diffuse : bool
        Their diffuse colour is nonzero: the diffuse term is computed.
    specular : bool
        Their specular colour is nonzero and a side has a specular term: it is computed.
    attenuated : bool
        Positional lights whose (k0, k1, k2) is not (1, 0, 0): attenuation is computed.
    spot : bool
        Their cutoff is not 180: the spot cone is computed.
    soft : bool
        Positional spot lights with a soft edge (``spot_inner_cutoff < spot_cutoff``): the
        cone's linear ramp is computed (a directional light's is in its constant spot factor).
    ranged : bool
        Positional lights with a finite ``range``: nothing is added beyond it.
    halfway : bool
        The halfway vector is a per-light constant (directional lights, an infinite viewer,
        Blinn's specular), bound as a uniform rather than computed per vertex.
    indices : tuple of int
        The lights of the group, as indices into ``scene.lights``, in summation order.
    """

    directional: bool
    ambient: bool
    diffuse: bool
    specular: bool
    attenuated: bool
    spot: bool
    soft: bool
    ranged: bool
    halfway: bool
    indices: tuple[int, ...]

    @property
    def key(self) -> tuple[bool, ...]:
        return (self.directional, self.ambient, self.diffuse, self.specular, self.attenuated,
                self.spot, self.soft, self.ranged, self.halfway)  # fmt: skip


@dataclass(frozen=True)
class Side:
    """What one side (0 front, 1 back) computes, and which material parameters the vertex
    colour replaces there (GL_COLOR_MATERIAL).

    Attributes
    ----------
    specular : bool
        The side has a specular term: its material's specular colour is nonzero, or the vertex
        colour replaces it.
    power : bool
        The specular term raises to the shininess (it is not 0, where 0^0 = 1).
    tracked : frozenset of str
        The material parameters the vertex colour replaces on this side: some of
        ``"ambient"``, ``"diffuse"``, ``"specular"`` and ``"emission"``; empty without colour
        material.
    """

    specular: bool
    power: bool
    tracked: frozenset[str]


@dataclass(frozen=True)
class Plan:
    """Everything that chooses code; the values to bind come from `uniforms.values`.

    Attributes
    ----------
    groups : tuple of LightGroup
        The lights by the terms they need; a light that adds nothing (zero ambient and
        diffuse colours, no specular term) is in none.
    sides : tuple of Side
        The front side and, with two-sided lighting, the back.
    positions : bool
        Vertex positions are read: a positional light or a viewer that is not infinite.
    view : bool
        The direction to a viewer at a point is computed per vertex (for a specular power).
    viewer_direction : bool
        An infinite viewer's direction is needed (for a specular power whose halfway vector is
        not a per-light constant).
    separate_specular : bool
        ``scene.separate_specular``.
    phong : bool
        The reflection vector (``specular="phong"``) instead of Blinn's halfway vector.
    gate : bool
        ``scene.specular_gate``, GL's ``f_i``.
    modelview : (4, 4) float64 ndarray or None
        The modelview matrix the shaders apply, or None for eye-space input.
    normalize : bool
        ``GL_NORMALIZE``.
    rescale_normal : bool
        ``GL_RESCALE_NORMAL``.
    color_material : str or None
        The ``color_material`` mode, or None without vertex colours.
    """

    groups: tuple[LightGroup, ...]
    sides: tuple[Side, ...]
    positions: bool
    view: bool
    viewer_direction: bool
    separate_specular: bool
    phong: bool
    gate: bool
    modelview: Float64Array | None
    normalize: bool
    rescale_normal: bool
    color_material: str | None


def _nonzero(rows: Any) -> NDArray[np.bool_]:
    result: NDArray[np.bool_] = np.any(np.asarray(rows, np.float64)[..., :3] != 0, axis=-1)
    return result


def make_plan(
    scene: Scene,
    *,
    modelview: Any = None,
    normalize: bool = False,
    rescale_normal: bool = False,
    color_material: str | None = None,
    color_material_face: str = "front_and_back",
) -> Plan:
    """The plan of `scene` with `shade`'s options (`color_material`: per-vertex colours are
    bound and replace that material parameter)."""
    if not isinstance(scene, Scene):
        raise TypeError(f"scene must be a glshade.Scene, got {type(scene)!r}")
    m = None if modelview is None else transform(modelview, "modelview")
    if m is not None and not np.array_equal(m[3], [0.0, 0.0, 0.0, 1.0]):
        raise ValueError(f"modelview must be affine (last row (0, 0, 0, 1)), got last row {m[3]}")
    if m is not None and np.linalg.det(m[:3, :3]) == 0:
        raise ValueError(
            "modelview must be invertible (its normal matrix is the inverse transpose)"
        )
    cm = optional_choice(color_material, "color_material")
    if cm is not None and cm not in COLOR_MATERIAL_MODES:
        raise ValueError(
            f"color_material must be one of {COLOR_MATERIAL_MODES} or None, got {cm!r}"
        )
    face = choice(color_material_face, "color_material_face")
    if face not in COLOR_MATERIAL_FACES:
        raise ValueError(
            f"color_material_face must be one of {tuple(COLOR_MATERIAL_FACES)}, got {face!r}"
        )
    tracked_faces = COLOR_MATERIAL_FACES[face] if cm is not None else ()
    tracks = {
        "ambient": ("ambient",),
        "diffuse": ("diffuse",),
        "specular": ("specular",),
        "emission": ("emission",),
        "ambient_and_diffuse": ("ambient", "diffuse"),
    }
    sides = []
    for index, material in enumerate((scene.material, scene.back_material)[: 1 + scene.two_side]):
        tracked = (
            frozenset(tracks[cm]) if cm is not None and index in tracked_faces else frozenset()
        )
        specular = bool(_nonzero(material.specular)) or "specular" in tracked
        sides.append(Side(specular, specular and material.shininess != 0, tracked))
    any_specular = any(s.specular for s in sides)
    any_power = any(s.power for s in sides)

    lights = scene.lights
    count = len(lights)
    position = lights._column("position").reshape(count, 4)
    directional = position[:, 3] == 0
    attenuation = np.stack(
        [lights._column(k).reshape(count) for k in ("constant_attenuation",
         "linear_attenuation", "quadratic_attenuation")], axis=1)  # fmt: skip
    attenuated = ~directional & np.any(attenuation != [1.0, 0.0, 0.0], axis=1)
    cutoff = lights._column("spot_cutoff").reshape(count)
    spot = cutoff != 180.0
    soft = ~directional & spot & (lights._column("spot_inner_cutoff").reshape(count) < cutoff)
    ranged = ~directional & (lights._column("range").reshape(count) != np.inf)
    ambient = _nonzero(lights._column("ambient").reshape(count, 4))
    diffuse = _nonzero(lights._column("diffuse").reshape(count, 4))
    lit = any_specular & _nonzero(lights._column("specular").reshape(count, 4))
    infinite_viewer = scene.viewer[3] == 0
    blinn = scene.specular == "blinn"
    power_lit = bool(any_power and lit.any())

    keys: dict[tuple[bool, ...], list[int]] = {}
    for i in range(count):
        if not (ambient[i] or diffuse[i] or lit[i]):
            continue  # a light that adds nothing has no code
        halfway = bool(directional[i] and infinite_viewer and blinn and lit[i] and any_power)
        key = (bool(directional[i]), bool(ambient[i]), bool(diffuse[i]), bool(lit[i]),
               bool(attenuated[i]), bool(spot[i]), bool(soft[i]), bool(ranged[i]),
               halfway)  # fmt: skip
        keys.setdefault(key, []).append(i)
    groups = tuple(
        LightGroup(
            directional=k[0],
            ambient=k[1],
            diffuse=k[2],
            specular=k[3],
            attenuated=k[4],
            spot=k[5],
            soft=k[6],
            ranged=k[7],
            halfway=k[8],
            indices=tuple(ix),
        )
        for k, ix in keys.items()
    )
    # VP_e is needed by every power that is not a per-light constant halfway vector.
    needs_view = any(g.specular and not g.halfway for g in groups) and any_power
    return Plan(
        groups=groups,
        sides=tuple(sides),
        positions=bool((~directional).any() or not infinite_viewer),
        view=bool(not infinite_viewer and power_lit),
        viewer_direction=bool(infinite_viewer and needs_view),
        separate_specular=scene.separate_specular,
        phong=not blinn,
        gate=scene.specular_gate,
        modelview=m,
        normalize=flag(normalize, "normalize"),
        rescale_normal=flag(rescale_normal, "rescale_normal"),
        color_material=cm,
    )
