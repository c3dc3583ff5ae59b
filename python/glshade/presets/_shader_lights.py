"""The seeds' shaders with several lights: learnopengl's Light casters (5.4) and Multiple lights
(6), and Luna's ``LightHelper.fx`` (DirectX 11), each light given as its shader struct.

A struct is a mapping from the shader's member names (``"outerCutOff"``, ``"Att"``) to values,
as the tutorial's C++ sets the uniforms. Every model is GL state: a soft spot edge is
`Light`'s ``spot_inner_cutoff``, a Direct3D range its ``range``, and where a shader attenuates
the ambient term differently from the diffuse and specular ones (GL scales all three alike) a
light becomes two GL lights at the same place, one for the ambient term and one for the rest.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping
from typing import Any, Literal

import numpy as np
from numpy.typing import ArrayLike

from .._intake import colors_checked
from .._params import scalar, vector3, warn_bytes
from .._scene import Light, Material, Scene
from ._preset import BLACK, Preset, model_matrix, world_kwargs
from ._structs import Kind, attenuation, colors_of, struct, structs

_GLSL_DIR: dict[str, Kind] = {
    "direction": "direction",
    "ambient": "rgb",
    "diffuse": "rgb",
    "specular": "rgb",
}
_GLSL_POINT: dict[str, Kind] = {
    "position": "vector",
    "constant": "number",
    "linear": "number",
    "quadratic": "number",
    "ambient": "rgb",
    "diffuse": "rgb",
    "specular": "rgb",
}
_GLSL_SPOT: dict[str, Kind] = {
    **_GLSL_POINT,
    "direction": "direction",
    "cutOff": "number",
    "outerCutOff": "number",
}
_GLSL_MATERIAL: dict[str, Kind] = {"diffuse": "rgb", "specular": "rgb", "shininess": "number"}

_HLSL_COLORS: dict[str, Kind] = {"Ambient": "rgba", "Diffuse": "rgba", "Specular": "rgba"}
_HLSL_DIR: dict[str, Kind] = {**_HLSL_COLORS, "Direction": "direction"}
_HLSL_POINT: dict[str, Kind] = {
    **_HLSL_COLORS,
    "Position": "vector",
    "Range": "number",
    "Att": "vector",
}
_HLSL_SPOT: dict[str, Kind] = {**_HLSL_POINT, "Direction": "direction", "Spot": "number"}


def learnopengl_lights(
    *,
    view_pos: ArrayLike,
    material: Mapping[str, Any],
    dir_light: Mapping[str, Any] | None = None,
    point_lights: Iterable[Mapping[str, Any]] = (),
    spot_light: Mapping[str, Any] | None = None,
    chapter: Literal["6", "5.4"] = "6",
    model: ArrayLike | None = None,
) -> Preset:
    """learnopengl's Multiple lights (chapter 6) or soft spot light (chapter 5.4), per vertex.

    Read from JoeyDeVries/LearnOpenGL, ``src/2.lighting/6.multiple_lights/6.multiple_lights.fs``
    and ``src/2.lighting/5.4.light_casters_spot_soft/5.4.light_casters.fs`` (commit d99731d7)::

        result = CalcDirLight(dirLight) + sum CalcPointLight(pointLights[i])
                 + CalcSpotLight(spotLight)
        each: ambient + diff * diffuse + spec * specular, times the light's factors
        diff = max(dot(norm, lightDir), 0)
        spec = pow(max(dot(viewDir, reflect(-lightDir, norm)), 0), material.shininess)
        attenuation = 1 / (constant + linear * d + quadratic * d^2)
        intensity = clamp((theta - outerCutOff) / (cutOff - outerCutOff), 0, 1),
                    theta = dot(lightDir, normalize(-direction))

    A point light scales all three terms by ``attenuation``; chapter 6's spot light by
    ``attenuation * intensity``; chapter 5.4's scales its ambient by ``attenuation`` only (two GL
    lights: an ambient-only point light and a soft spot without ambient). The colours multiply
    the material's maps, here constant colours: ``material["diffuse"]`` for ambient and
    diffuse, ``material["specular"]`` for specular (a diffuse map is `shade`'s ``colors=``,
    which replaces the ambient and diffuse colour as the shader's texture does). No gate
    (``specular_gate=False``), no clamp in the shader (the framebuffer clamps, and so does
    glshade), alpha 1.

    Parameters
    ----------
    view_pos : (3,) float
        ``viewPos``, world space.
    material : mapping
        ``Material``: ``"diffuse"`` and ``"specular"`` (3,) colours (the maps' texel), and
        ``"shininess"`` (>= 0).
    dir_light : mapping, optional
        ``DirLight``: ``"direction"`` (from the light, normalised here), ``"ambient"``,
        ``"diffuse"``, ``"specular"`` (3,) colours. Chapter 6 only.
    point_lights : sequence of mappings
        ``PointLight`` each: ``"position"``, ``"constant"``, ``"linear"``, ``"quadratic"``
        (>= 0, not all 0), ``"ambient"``, ``"diffuse"``, ``"specular"``. Chapter 6 only (its
        ``NR_POINT_LIGHTS`` is 4; any number will do here).
    spot_light : mapping, optional
        ``SpotLight`` (chapter 5.4: ``Light``): the point light's members plus ``"direction"``
        and the cosines ``"cutOff"`` (inner) and ``"outerCutOff"``, with
        ``0 <= outerCutOff <= cutOff <= 1`` (``cutOff == outerCutOff``, where the shader divides
        by zero, is GL's hard edge; at 0 both, GL's clamped cosine lets the 90-degree cone light
        what is behind the light, where the shader's ``-inf`` clamps to 0).
    chapter : {"6", "5.4"}, default: "6"
        Which shader: chapter 5.4 has one light, `spot_light`, whose ambient term its spot
        intensity does not scale.
    model : (4, 4) float, optional
        The model matrix, as for `learnopengl`; default: the identity.

    Returns
    -------
    Preset
        GL lights in the order dirLight, pointLights, spotLight; every light colour as given;
        material ambient and diffuse ``material["diffuse"]``, specular ``material["specular"]``;
        no global ambient or emission; a viewer at `view_pos`; ``specular="phong"``,
        ``specular_gate=False``; ``normalize=True`` and ``modelview=model``.

    Raises
    ------
    TypeError
        For a struct that is not a mapping, lacks a member or has one the shader does not, or a
        colour given by name; each names the struct and member (``spot_light["cutOff"]``).
    ValueError
        For a wrong shape, a negative shininess or attenuation, cosines out of order, an unknown
        `chapter`, or chapter 5.4 with `dir_light` or `point_lights`.

    Warns
    -----
    ColorRangeWarning
        For a colour that looks like 0-255 bytes, under its struct's name.
    """
    if chapter not in ("6", "5.4"):
        raise ValueError(f'chapter must be "6" or "5.4", got {chapter!r}')
    viewer = vector3(view_pos, "view_pos")
    mat = struct(material, "material", _GLSL_MATERIAL)
    if mat["shininess"] < 0:
        raise ValueError(f'material["shininess"] must be >= 0, got {mat["shininess"]:g}')
    dirs = [] if dir_light is None else [struct(dir_light, "dir_light", _GLSL_DIR)]
    points = structs(point_lights, "point_lights", _GLSL_POINT)
    spots = [] if spot_light is None else [struct(spot_light, "spot_light", _GLSL_SPOT)]
    if chapter == "5.4" and (dirs or points):
        raise ValueError(
            "chapter 5.4's shader has one light, spot_light; dir_light and point_lights are "
            "chapter 6's"
        )
    matrix = model_matrix(model)
    with colors_checked():
        lights = [Light(position=(*-d["direction"], 0.0), **_glsl_colors(d)) for d in dirs]
        for i, p in enumerate(points):
            k = _glsl_attenuation(p, f"point_lights[{i}]")
            lights.append(Light(position=(*p["position"], 1.0), **k, **_glsl_colors(p)))
        for s in spots:
            lights.extend(_glsl_spot(s, chapter))
        scene = Scene(
            lights=lights,
            material=Material(
                ambient=mat["diffuse"],
                diffuse=mat["diffuse"],
                specular=mat["specular"],
                emission=BLACK,
                shininess=mat["shininess"],
            ),
            global_ambient=BLACK,
            viewer=(*viewer, 1.0),
            specular="phong",
            specular_gate=False,
        )
    colors = {'material["diffuse"]': mat["diffuse"], 'material["specular"]': mat["specular"]}
    terms = ("ambient", "diffuse", "specular")
    colors |= colors_of(dirs, "dir_light", terms, single=True)
    colors |= colors_of(points, "point_lights", terms)
    colors |= colors_of(spots, "spot_light", terms, single=True)
    warn_bytes(colors, "learnopengl_lights")
    return Preset(scene, world_kwargs(matrix))


def _glsl_colors(light: Mapping[str, Any]) -> dict[str, Any]:
    return {"ambient": light["ambient"], "diffuse": light["diffuse"], "specular": light["specular"]}


def _glsl_attenuation(light: Mapping[str, Any], name: str) -> dict[str, float]:
    names = ("constant", "linear", "quadratic")
    return attenuation(np.array([light[n] for n in names]), names, name)


def _degrees(cosine: float) -> float:
    """The angle of a cosine in [0, 1], exactly 90 at 0 (GL's cutoff is in degrees)."""
    return 90.0 if cosine == 0.0 else math.degrees(math.acos(cosine))


def _glsl_spot(spot: Mapping[str, Any], chapter: str) -> list[Light]:
    inner, outer = spot["cutOff"], spot["outerCutOff"]
    if not 0.0 <= outer <= inner <= 1.0:
        raise ValueError(
            'spot_light must have 0 <= "outerCutOff" <= "cutOff" <= 1 (cosines of the outer and '
            f"inner cones; GL's cone is at most 90 degrees), got outerCutOff={outer:g}, "
            f"cutOff={inner:g}"
        )
    where = (*spot["position"], 1.0)
    k = _glsl_attenuation(spot, "spot_light")
    cone = {
        "spot_direction": spot["direction"],
        "spot_cutoff": _degrees(outer),
        "spot_inner_cutoff": _degrees(inner),
        "spot_exponent": 0.0,
    }
    if chapter == "6":
        return [Light(position=where, **k, **cone, **_glsl_colors(spot))]
    # 5.4: ambient *= attenuation, but diffuse and specular *= intensity too.
    return [
        Light(position=where, **k, ambient=spot["ambient"], diffuse=BLACK, specular=BLACK),
        Light(
            position=where,
            **k,
            **cone,
            ambient=BLACK,
            diffuse=spot["diffuse"],
            specular=spot["specular"],
        ),
    ]


def directx11_lights(
    *,
    material: Mapping[str, Any],
    eye_position: ArrayLike,
    dir_lights: Iterable[Mapping[str, Any]] = (),
    point_lights: Iterable[Mapping[str, Any]] = (),
    spot_lights: Iterable[Mapping[str, Any]] = (),
    world: ArrayLike | None = None,
) -> Preset:
    """Luna's DirectX 11 lighting with directional, point and spot lights, Range included.

    Read from Frank Luna, *Introduction to 3D Game Programming with DirectX 11* (2012),
    chapter 7, ``LightHelper.fx``: ``ComputeDirectionalLight``, ``ComputePointLight`` and
    ``ComputeSpotLight``, summed as its ``Basic.fx`` sums them::

        litColor = sum (ambient + diffuse + spec),   litColor.a = gMaterial.Diffuse.a
        ambient = mat.Ambient * L.Ambient
        diffuse = diffuseFactor * mat.Diffuse * L.Diffuse             where diffuseFactor > 0
        spec = pow(max(dot(reflect(-lightVec, normal), toEye), 0), mat.Specular.w)
               * mat.Specular * L.Specular                             where diffuseFactor > 0
        point, spot: nothing at all where d > L.Range
        point: diffuse, spec *= 1 / dot(L.Att, (1, d, d^2))
        spot:  spot = pow(max(dot(-lightVec, L.Direction), 0), L.Spot)
               ambient *= spot;  diffuse, spec *= spot / dot(L.Att, (1, d, d^2))

    with ``diffuseFactor = dot(lightVec, normal)``, ``normal`` the normalised world normal and
    ``toEye = normalize(gEyePosW - posW)``. GL attenuates the ambient term with the others,
    so a point or spot light whose ``Att`` is not (1, 0, 0) becomes two GL lights with the
    same range: one ambient-only, unattenuated (but scaled by the spot factor, a GL cone of
    90 degrees with exponent ``Spot``), one with the rest. `directx11` is the one-light case.

    Parameters
    ----------
    material : mapping
        ``Material``: ``"Ambient"``, ``"Diffuse"`` (3,) or (4,) colours (the output alpha is
        Diffuse's, 1 for RGB) and ``"Specular"`` (4,), whose w is the specular power (>= 0).
    eye_position : (3,) float
        ``gEyePosW``, world space.
    dir_lights : sequence of mappings
        ``DirectionalLight`` each: ``"Ambient"``, ``"Diffuse"``, ``"Specular"`` (3,) or (4,)
        colours (alpha unused) and ``"Direction"`` (the light's rays, normalised here as the
        book's demos set them).
    point_lights : sequence of mappings
        ``PointLight`` each: the colours, ``"Position"``, ``"Range"`` (> 0; lit where
        ``d <= Range``) and ``"Att"`` (a0, a1, a2), >= 0, not all 0.
    spot_lights : sequence of mappings
        ``SpotLight`` each: the point light's members, ``"Direction"`` (normalised here) and
        ``"Spot"`` (the exponent, >= 0).
    world : (4, 4) float, optional
        ``gWorld`` as numpy prints it (``world @ (x, y, z, 1)``), affine and invertible:
        positions by it, normals by its inverse transpose (``gWorldInvTranspose``). Default:
        the identity (positions are world space).

    Returns
    -------
    Preset
        GL lights in the order given (directional, point, spot), each point or spot light one
        or two; material as given, no emission, no global ambient; a viewer at
        `eye_position`; ``specular="phong"`` with GL's gate; ``normalize=True``, and
        ``modelview=world``.

    Raises
    ------
    TypeError
        For a struct that is not a mapping, lacks a member or has one the shader does not, or a
        colour given by name; each names the struct and member (``point_lights[0]["Att"]``).
    ValueError
        For a wrong shape, a negative power, exponent or attenuation, or a Range that is not
        positive.

    Notes
    -----
    At ``Spot = 0`` the shader raises 0 to the power 0 behind the light, which HLSL leaves
    undefined; glshade follows GL's eq. 2.5, whose clamped cosine makes it 0^0 = 1 there (the
    light shines behind itself, as numpy's ``0.0 ** 0`` has it).

    Warns
    -----
    ColorRangeWarning
        For a colour that looks like 0-255 bytes, under its struct's name.
    """
    mat = struct(material, "material", {**_HLSL_COLORS, "Specular": "rgba"})
    if mat["Specular"].shape != (4,):
        raise ValueError(
            'material["Specular"] must have shape (4,): its w is the specular power, '
            f"got {mat['Specular'].shape}"
        )
    power = float(mat["Specular"][3])
    if power < 0:
        raise ValueError(
            f'material["Specular"]\'s w, the specular power, must be >= 0, got {power:g}'
        )
    eye = vector3(eye_position, "eye_position")
    dirs = structs(dir_lights, "dir_lights", _HLSL_DIR)
    points = structs(point_lights, "point_lights", _HLSL_POINT)
    spots = structs(spot_lights, "spot_lights", _HLSL_SPOT)
    matrix = model_matrix(world, "world")
    with colors_checked():
        lights = [Light(position=(*-d["Direction"], 0.0), **_hlsl_colors(d)) for d in dirs]
        for i, p in enumerate(points):
            lights.extend(_hlsl_positional(p, f"point_lights[{i}]", {}))
        for i, s in enumerate(spots):
            name = f"spot_lights[{i}]"
            spot = scalar(s["Spot"], f'{name}["Spot"]', minimum=0.0)
            cone = {"spot_direction": s["Direction"], "spot_cutoff": 90.0, "spot_exponent": spot}
            lights.extend(_hlsl_positional(s, name, cone))
        scene = Scene(
            lights=lights,
            material=Material(
                ambient=mat["Ambient"],
                diffuse=mat["Diffuse"],
                specular=mat["Specular"][:3],
                emission=BLACK,
                shininess=power,
            ),
            global_ambient=BLACK,
            viewer=(*eye, 1.0),
            specular="phong",
        )
    colors = {f'material["{m}"]': mat[m] for m in ("Ambient", "Diffuse")}
    colors['material["Specular"]'] = mat["Specular"][:3]
    for found, name in ((dirs, "dir_lights"), (points, "point_lights"), (spots, "spot_lights")):
        colors |= colors_of(found, name, _HLSL_COLORS)
    warn_bytes(colors, "directx11_lights")
    return Preset(scene, world_kwargs(matrix))


def _hlsl_colors(light: Mapping[str, Any]) -> dict[str, Any]:
    return {"ambient": light["Ambient"], "diffuse": light["Diffuse"], "specular": light["Specular"]}


def _hlsl_positional(light: Mapping[str, Any], name: str, cone: dict[str, Any]) -> list[Light]:
    """A point light (no `cone`) or spot light: one GL light, or two when GL's attenuation of
    the ambient term would differ from Luna's (none)."""
    k = attenuation(light["Att"], ("a0", "a1", "a2"), f'{name}["Att"]')
    reach = light["Range"]
    if reach <= 0:
        raise ValueError(f'{name}["Range"] must be > 0, got {reach:g}')
    where = {"position": (*light["Position"], 1.0), "range": reach, **cone}
    if tuple(k.values()) == (1.0, 0.0, 0.0):
        return [Light(**where, **_hlsl_colors(light))]
    parts = []
    if light["Ambient"][:3].any():
        parts.append(Light(**where, ambient=light["Ambient"], diffuse=BLACK, specular=BLACK))
    if not (light["Diffuse"][:3].any() or light["Specular"][:3].any()):
        return parts
    rest = Light(
        **where,
        ambient=BLACK,
        diffuse=light["Diffuse"],
        specular=light["Specular"],
        **k,
    )
    return [*parts, rest]
