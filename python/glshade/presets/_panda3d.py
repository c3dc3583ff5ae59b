"""Panda3D's shader generator (``setShaderAuto``) as a preset."""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from .._intake import colors_checked
from .._params import rgb, scalar, warn_bytes
from .._scene import Light, Material, Scene
from ._preset import BLACK, Preset
from ._structs import Kind, attenuation, colors_of, struct, structs

_LIGHT: dict[str, Kind] = {"color": "rgba", "specular_color": "rgba"}
_DIRECTIONAL: dict[str, Kind] = {**_LIGHT, "direction": "direction"}
_POINT: dict[str, Kind] = {**_LIGHT, "point": "vector", "attenuation": "vector"}
_SPOT: dict[str, Kind] = {**_POINT, "direction": "direction", "exponent": "number", "fov": "number"}
_MATERIAL: dict[str, Kind] = {
    "ambient": "rgba",
    "diffuse": "rgba",
    "emission": "rgba",
    "specular": "rgba",
    "shininess": "number",
}
_WHITE = (1.0, 1.0, 1.0, 1.0)
# Panda3D's view space is Y-forward, Z-up: the infinite viewer looks along +y.
_INFINITE_VIEWER = (0.0, -1.0, 0.0, 0.0)


def panda3d(
    *,
    material: Mapping[str, Any] | None = None,
    local: bool = False,
    ambient_lights: Iterable[ArrayLike] = (),
    directional_lights: Iterable[Mapping[str, Any]] = (),
    point_lights: Iterable[Mapping[str, Any]] = (),
    spotlights: Iterable[Mapping[str, Any]] = (),
) -> Preset:
    """Panda3D's per-pixel lighting from its shader generator, in Panda3D's view space.

    Read from panda3d/panda3d, ``panda/src/pgraphnodes/shaderGenerator.cxx`` (commit
    0224c144), the Cg it writes for ``AmbientLight``, ``DirectionalLight``, ``PointLight`` and
    ``Spotlight``::

        tot_ambient = sum of the ambient lights' colours
        lattenv = 1 / (latten.x + latten.y * ldist + latten.z * ldist^2)     (point, spot)
        lattenv *= pow(langle, exponent); 0 where langle < cos(cutoff)       (spot)
        tot_diffuse += color * lattenv * saturate(dot(N, lvec))
        tot_specular += specular_color * lattenv * pow(saturate(dot(N, lhalf)), shininess)
        result = saturate(emission + tot_ambient * ambient + tot_diffuse * diffuse)
        result.a = 1 (or the vertex colour's alpha)
        result.rgb += tot_specular.rgb * specular                  (after the clamp)
        o_color = result * 1.000001

    with ``lhalf = normalize(lvec - (0, 1, 0))``, or ``normalize(lvec - normalize(P))`` for a
    local material, and ``langle = saturate(dot(-axis, lvec))``. In GL's terms: lights without
    ambient colour, the ambient lights' sum as the global ambient, Blinn's halfway vector with
    the infinite viewer along Panda's +y, and **no gate** (``specular_gate=False``: a highlight
    where the light is behind the surface). The specular term comes after the clamp, but with
    colours >= 0 every term is too, so once the framebuffer clamps the sum the colour is GL's
    single clamped sum. (A float framebuffer keeps ``min(primary, 1) + specular``:
    ``Scene(separate_specular=True)`` with ``clamp=False`` gives the two.) The shader's
    ``* 1.000001`` (a workaround for an old Radeon driver) is left out: it changes a value by
    at most 1e-6.

    Positions, normals and lights are in Panda3D's view (camera) space, Y forward and Z up;
    `shade`'s ``modelview=`` moves positions and normals there.

    Parameters
    ----------
    material : mapping, optional
        ``Material``: ``"ambient"``, ``"diffuse"``, ``"emission"``, ``"specular"`` (3,) or
        (4,) colours and ``"shininess"`` (>= 0). Panda3D then ignores the vertex colours' RGB,
        so give such a preset no ``colors=`` (`shade` would light them as GL's colour material).
        None (the default) is no material: the vertex colours (``colors=``) are the ambient and
        diffuse colour (white without them) and there is no specular term.
    local : bool, default: False
        ``Material.local``: the viewer at the camera instead of infinitely far.
    ambient_lights : sequence of (3,) or (4,) colours
        Each ``AmbientLight``'s colour; they add up.
    directional_lights : sequence of mappings
        ``DirectionalLight`` each: ``"color"``, ``"specular_color"`` and ``"direction"``, where
        the light shines (normalised here).
    point_lights : sequence of mappings
        ``PointLight`` each: ``"color"``, ``"specular_color"``, ``"point"`` and
        ``"attenuation"`` (constant, linear, quadratic), >= 0, not all 0.
    spotlights : sequence of mappings
        ``Spotlight`` each: the point light's members, ``"direction"`` (its lens' view vector,
        normalised here: Panda3D's is a unit vector unless the light's node is scaled),
        ``"exponent"`` (>= 0) and ``"fov"``, its lens' field of view in degrees, in [0, 180]:
        the cone's half-angle is half of it.

    Returns
    -------
    Preset
        The scene (``specular="blinn"``, ``specular_gate=False``) and ``normalize=True``.

    Raises
    ------
    TypeError
        For a struct that is not a mapping, lacks a member or has one Panda3D's light does not,
        or a colour given by name; each names the light and member.
    ValueError
        For no light at all, a wrong shape, a negative shininess, exponent or attenuation, or a
        field of view outside [0, 180] degrees.

    Warns
    -----
    ColorRangeWarning
        For a colour that looks like 0-255 bytes, under its light's name.
    """
    if not isinstance(local, (bool, np.bool_)):
        raise TypeError(f"local must be True or False, got {local!r}")
    mat = None if material is None else struct(material, "material", _MATERIAL)
    if mat is not None and mat["shininess"] < 0:
        raise ValueError(f'material["shininess"] must be >= 0, got {mat["shininess"]:g}')
    ambients = [rgb(c, f"ambient_lights[{i}]", alpha=True) for i, c in enumerate(ambient_lights)]
    suns = structs(directional_lights, "directional_lights", _DIRECTIONAL)
    points = structs(point_lights, "point_lights", _POINT)
    spots = structs(spotlights, "spotlights", _SPOT)
    if not (ambients or suns or points or spots):
        raise ValueError(
            "panda3d needs a light: without one Panda3D turns lighting off and writes the "
            "vertex colour"
        )
    with colors_checked():
        lights = [
            Light(position=(*-d["direction"], 0.0), ambient=BLACK, **_colors(d)) for d in suns
        ]
        for i, p in enumerate(points):
            lights.append(_positional(p, f"point_lights[{i}]", {}))
        for i, s in enumerate(spots):
            name = f"spotlights[{i}]"
            exponent = scalar(s["exponent"], f'{name}["exponent"]', minimum=0.0)
            fov = s["fov"]
            if not 0.0 <= fov <= 180.0:
                raise ValueError(f'{name}["fov"] must be in [0, 180] degrees, got {fov:g}')
            cone = {
                "spot_direction": s["direction"],
                "spot_exponent": exponent,
                "spot_cutoff": fov / 2.0,
            }
            lights.append(_positional(s, name, cone))
        total = sum((a[:3] for a in ambients), np.zeros(3))
        if mat is None:
            surface = Material(ambient=_WHITE, diffuse=_WHITE, specular=BLACK, emission=BLACK)
        else:
            surface = Material(
                ambient=mat["ambient"],
                diffuse=(*mat["diffuse"][:3], 1.0),  # the shader writes alpha 1
                specular=mat["specular"],
                emission=mat["emission"],
                shininess=mat["shininess"],
            )
        scene = Scene(
            lights=lights,
            material=surface,
            global_ambient=(*total, 1.0),
            viewer=(0.0, 0.0, 0.0, 1.0) if local else _INFINITE_VIEWER,
            specular="blinn",
            specular_gate=False,
        )
    colors = {f"ambient_lights[{i}]": a for i, a in enumerate(ambients)}
    if mat is not None:
        colors |= {f'material["{m}"]': mat[m] for m in ("ambient", "diffuse", "specular")}
    for found, name in (
        (suns, "directional_lights"),
        (points, "point_lights"),
        (spots, "spotlights"),
    ):
        colors |= colors_of(found, name, _LIGHT)
    warn_bytes(colors, "panda3d")
    return Preset(scene, {"normalize": True})


def _colors(light: Mapping[str, Any]) -> dict[str, Any]:
    return {"diffuse": light["color"], "specular": light["specular_color"]}


def _positional(light: Mapping[str, Any], name: str, cone: dict[str, Any]) -> Light:
    names = ("constant", "linear", "quadratic")
    k = attenuation(light["attenuation"], names, f'{name}["attenuation"]')
    return Light(
        position=(*light["point"], 1.0),
        ambient=BLACK,
        **k,
        **cone,
        **_colors(light),
    )
