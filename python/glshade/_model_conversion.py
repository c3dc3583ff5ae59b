"""A scene of one shading model as another model's scene: the scene a renderer of that model
would be given for the same lights and material, which `explain` renders when it asks whether
a picture comes from another model.

GL's scene in world coordinates is the hub: every model's scene converts to it and from it,
so each rule is written once. What a model cannot hold is dropped or approximated as the table
in docs/pages/guide/explain.md says (glTF has one light colour and no attenuation choice; GL
has one Blinn-Phong exponent where glTF has a roughness, converted by the rule trimesh and
pyrender apply to a Wavefront material's ``Ns``). Light units are carried as numbers: a
model's π (glTF and three.js divide the diffuse term by it) is left for the light scale.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterator
from typing import Any, NamedTuple

import numpy as np
from numpy.typing import NDArray

from . import _glshade, gltf, threejs
from ._intake import colors_checked
from ._scene import Lights, Material, Scene

__all__ = ["MODELS", "as_model", "model_of"]

AnyScene = Scene | gltf.Scene | threejs.Scene
# The shading models, by the names `explain` gives them: PyTorch3D's Phong is drawn as GL's
# equation with its conventions (`presets.pytorch3d`), so its scene is a `glshade.Scene`.
MODELS = ("gl", "gltf", "threejs", "pytorch3d")
# glTF's dielectric reflectance at normal incidence, its f0 for metallic 0.
DIELECTRIC_F0 = 0.04
# GL's largest shininess.
GL_SHININESS = 128.0


def model_of(scene: AnyScene) -> str:
    """The model of a scene as `MODELS` names it (a `glshade.Scene` is "gl")."""
    if isinstance(scene, gltf.Scene):
        return "gltf"
    return "threejs" if isinstance(scene, threejs.Scene) else "gl"


def as_model(scene: AnyScene, model: str, *, view: NDArray[Any], lights_in: str) -> AnyScene:
    """`scene` as `model`'s scene, in world coordinates; `scene` itself for its own model.

    Parameters
    ----------
    scene : Scene, gltf.Scene or threejs.Scene
        The scene as meant.
    model : {"gl", "gltf", "threejs", "pytorch3d"}
        The model to draw it with; "pytorch3d" gives a `glshade.Scene` drawn with its lights
        in world coordinates.
    view : (4, 4) float
        The camera's world-to-eye matrix, for a GL scene whose lights are in eye coordinates.
    lights_in : {"eye", "world"}
        Where a GL scene's lights are given.
    """
    if model == model_of(scene):
        return scene
    world = _gl_world(scene, view, lights_in)
    with colors_checked():  # every colour was checked when `scene` was made
        return _FROM_GL[model](world)


def _gl_world(scene: AnyScene, view: NDArray[Any], lights_in: str) -> Scene:
    """`scene` as a GL scene with its lights in world coordinates."""
    if isinstance(scene, Scene):
        return scene.in_eye_space(np.linalg.inv(view)) if lights_in == "eye" else scene
    with colors_checked():
        return _gltf_to_gl(scene) if isinstance(scene, gltf.Scene) else _threejs_to_gl(scene)


def _rgba(rgb: Any, alpha: float = 1.0) -> tuple[float, ...]:
    return (*(float(x) for x in rgb[:3]), float(alpha))


def _gl_light(
    kind: str,
    rgb: Any,
    *,
    position: Any = (0.0, 0.0, 0.0),
    direction: Any = (0.0, 0.0, -1.0),
    attenuation: tuple[float, float, float] = (1.0, 0.0, 0.0),
    cutoff: float = 180.0,
    inner: float = 180.0,
    reach: float = math.inf,
) -> dict[str, Any]:
    """One GL light's parameters: a light of colour `rgb` (diffuse and specular alike, no
    ambient of its own), travelling along `direction` ("directional") or from `position`."""
    k0, k1, k2 = attenuation
    travels = [-float(x) for x in direction]
    return {
        "position": (*travels, 0.0) if kind == "directional" else (*map(float, position), 1.0),
        "diffuse": _rgba(rgb),
        "specular": _rgba(rgb),
        "ambient": (0.0, 0.0, 0.0, 1.0),
        "constant_attenuation": k0,
        "linear_attenuation": k1,
        "quadratic_attenuation": k2,
        "spot_direction": tuple(map(float, direction)),
        "spot_cutoff": cutoff,
        "spot_inner_cutoff": inner,
        "range": reach,
    }


def _gl_scene(
    lights: list[dict[str, Any]], material: Material, ambient: Any, two_side: bool = False
) -> Scene:
    """A GL scene in world coordinates of `lights` (`_gl_light`'s dicts) and `material`, its
    viewer at the eye as the world models' cameras are."""
    columns: dict[str, Any] = (
        {name: [light[name] for light in lights] for name in lights[0]} if lights else {}
    )
    return Scene(
        lights=Lights(**columns) if lights else Lights(count=0),
        material=material,
        global_ambient=_rgba(ambient),
        viewer=(0.0, 0.0, 0.0, 1.0),
        two_side=two_side,
    )


def _gltf_to_gl(scene: gltf.Scene) -> Scene:
    """glTF's lights with their colour times intensity as diffuse and specular colours, points
    and spots falling off as 1/d² (GL's quadratic attenuation 1), a spot's outer cone as GL's
    cutoff and its inner cone as the soft edge's; the material's diffuse colour (and ambient,
    which the ambient light multiplies) its base colour times 1 - metallic, its specular
    colour f0 and its shininess trimesh's rule turned round, 2/r⁴ - 2 (at most 128)."""
    lights = []
    for light in scene.lights:
        rgb = np.multiply(light.color, light.intensity)
        if isinstance(light, gltf.DirectionalLight):
            lights.append(_gl_light("directional", rgb, direction=light.direction))
            continue
        spot: dict[str, Any] = {}
        if isinstance(light, gltf.SpotLight):
            outer, inner = (
                math.degrees(light.outer_cone_angle),
                math.degrees(light.inner_cone_angle),
            )
            spot = {
                "direction": light.direction, "cutoff": outer,
                "inner": inner if inner < outer else 180.0,
            }  # fmt: skip
        lights.append(
            _gl_light("point", rgb, position=light.position, attenuation=(0.0, 0.0, 1.0), **spot)
        )
    m = scene.material
    base = np.asarray(m.base_color)
    diffuse = _rgba(base[:3] * (1.0 - m.metallic), base[3])
    roughness = max(m.roughness, 0.04)  # the model's own floor
    material = Material(
        ambient=diffuse, diffuse=diffuse,
        specular=_rgba(DIELECTRIC_F0 + (base[:3] - DIELECTRIC_F0) * m.metallic),
        emission=_rgba(m.emissive),
        shininess=min(2.0 / roughness**4 - 2.0, GL_SHININESS),
    )  # fmt: skip
    return _gl_scene(lights, material, scene.ambient_light)


# three.js' decay as GL's attenuation (k0, k1, k2): none, 1/d, 1/d² (any other decay: 1/d²).
_DECAY = {0.0: (1.0, 0.0, 0.0), 1.0: (0.0, 1.0, 0.0)}


def _threejs_to_gl(scene: threejs.Scene) -> Scene:
    """three.js' direct lights with their colour times intensity as diffuse and specular
    colours, a point or spot light's decay as GL's attenuation, its distance as GL's range, a
    spot's angle as GL's cutoff and its penumbra as the soft edge; ambient and hemisphere
    lights (the mean of sky and ground) summed into the global ambient; the material's colour
    as diffuse and ambient colour, its specular colour, shininess (at most 128) and emission
    as they are, "double" side as GL's two-sided lighting."""
    lights = []
    ambient = np.zeros(3)
    for light in scene.lights:
        if isinstance(light, threejs.AmbientLight):
            ambient += np.multiply(light.color, light.intensity)
            continue
        if isinstance(light, threejs.HemisphereLight):
            sky, ground = np.asarray(light.sky_color), np.asarray(light.ground_color)
            ambient += (sky + ground) / 2 * light.intensity
            continue
        rgb = np.multiply(light.color, light.intensity)
        away = np.subtract(light.target, light.position) if hasattr(light, "target") else None
        if isinstance(light, threejs.DirectionalLight):
            lights.append(_gl_light("directional", rgb, direction=away))
            continue
        falloff: dict[str, Any] = {
            "attenuation": _DECAY.get(float(light.decay), (0.0, 0.0, 1.0)),
            "reach": light.distance if light.distance > 0 else math.inf,
        }
        if isinstance(light, threejs.SpotLight):
            cutoff = math.degrees(light.angle)
            falloff |= {
                "direction": away, "cutoff": cutoff,
                "inner": cutoff * (1.0 - light.penumbra) if light.penumbra > 0 else 180.0,
            }  # fmt: skip
        lights.append(_gl_light("point", rgb, position=light.position, **falloff))
    m = scene.material
    diffuse = _rgba(m.color, m.opacity)
    material = Material(
        ambient=diffuse, diffuse=diffuse, specular=_rgba(m.specular),
        emission=_rgba(np.multiply(m.emissive, m.emissive_intensity)),
        shininess=min(m.shininess, GL_SHININESS),
    )  # fmt: skip
    return _gl_scene(lights, material, ambient, two_side=m.side == "double")


def _light_rows(scene: Scene) -> list[dict[str, Any]]:
    """Each GL light's parameters, one dict a light (colours RGBA, positions homogeneous)."""
    lights = scene.lights
    count = len(lights)
    columns = {n: lights._column(n).reshape(count, -1) for n in _glshade.Lights.PARAMETERS}
    return [
        {n: c[i] if c.shape[1] > 1 else float(c[i, 0]) for n, c in columns.items()}
        for i in range(count)
    ]


def _ambient_sum(scene: Scene, rows: list[dict[str, Any]]) -> NDArray[Any]:
    """The global ambient and every light's own ambient colour, RGB, at least 0: the one
    ambient term of a model that has one."""
    total = scene.global_ambient[:3] + sum((row["ambient"][:3] for row in rows), np.zeros(3))
    return np.maximum(total, 0.0)


class _Emitter(NamedTuple):
    """A GL light that lights something, as the other models' lights are made from it."""

    row: dict[str, Any]
    """Its parameters (`_light_rows`)."""
    rgb: NDArray[Any]
    """Its diffuse colour, RGB, at least 0."""
    directional: bool
    where: NDArray[Any]
    """Towards the light (directional), or where it is."""
    cone: tuple[float, float] | None
    """A positional light's spot cone, (cutoff, inner cutoff) in degrees; None for none."""


def _emitters(rows: list[dict[str, Any]]) -> Iterator[_Emitter]:
    """The lights of `rows`, GL's (0, 0, 0, 0) left out (it lights nothing)."""
    for row in rows:
        position = row["position"]
        if not position.any():
            continue
        rgb = np.maximum(row["diffuse"][:3], 0.0)
        if position[3] == 0:
            yield _Emitter(row, rgb, True, position[:3], None)
            continue
        cutoff = float(row["spot_cutoff"])
        cone = None if cutoff >= 180.0 else (cutoff, min(float(row["spot_inner_cutoff"]), cutoff))
        yield _Emitter(row, rgb, False, position[:3] / position[3], cone)


def _to_gltf(scene: Scene) -> gltf.Scene:
    """GL's lights as glTF's, with their diffuse colour and intensity 1 (glTF has one colour
    a light, no ambient of its own and always 1/d²: GL's attenuation is dropped); the spot's
    cutoff as the outer cone and its soft edge as the inner one (a hard edge: both equal); the
    ambient colours summed into the ambient light; the material's diffuse colour as base
    colour, metallic 0, roughness (2/(s + 2))^(1/4) as trimesh and pyrender convert a Wavefront
    ``Ns``, its emission as it is (GL's specular colour is dropped: a dielectric's f0 is
    0.04)."""
    rows = _light_rows(scene)
    lights: list[gltf.Light] = []
    for light in _emitters(rows):
        rgb, where, cone = light.rgb, light.where, light.cone
        if light.directional:
            lights.append(gltf.DirectionalLight(color=rgb, direction=-where))
        elif cone is None:
            lights.append(gltf.PointLight(color=rgb, position=where))
        else:
            spot = gltf.SpotLight(
                color=rgb, position=where, direction=light.row["spot_direction"],
                outer_cone_angle=math.radians(cone[0]), inner_cone_angle=math.radians(cone[1]),
            )  # fmt: skip
            lights.append(spot)
    m = scene.material
    return gltf.Scene(
        lights,
        gltf.Material(
            base_color=np.clip(m.diffuse, 0.0, 1.0), metallic=0.0,
            roughness=(2.0 / (m.shininess + 2.0)) ** 0.25,
            emissive=np.maximum(m.emission[:3], 0.0),
        ),
        ambient_light=_ambient_sum(scene, rows),
    )  # fmt: skip


def _attenuation_as_decay(row: dict[str, Any]) -> tuple[float, float]:
    """GL's attenuation 1/(k0 + k1 d + k2 d²) as three.js' (decay, intensity): the highest
    power with a nonzero coefficient k, falling off as 1/(k d^power) (exact when only one
    coefficient is nonzero)."""
    for power in (2, 1, 0):
        k = float(row[("constant", "linear", "quadratic")[power] + "_attenuation"])
        if k > 0:
            return float(power), 1.0 / k
    return 0.0, 1.0


def _to_threejs(scene: Scene) -> threejs.Scene:
    """GL's lights as three.js', with their diffuse colour; a positional light's attenuation as
    its decay and intensity (`_attenuation_as_decay`), GL's range as its distance; a spot's
    cutoff as its angle and its soft edge as the penumbra; the ambient colours summed into an
    ``AmbientLight``; the material's diffuse, specular and emissive colours, shininess and
    alpha (as opacity) as ``MeshPhongMaterial``'s, two-sided lighting as ``side="double"``."""
    rows = _light_rows(scene)
    lights: list[threejs.Light] = []
    for light in _emitters(rows):
        rgb, where, cone, row = light.rgb, light.where, light.cone, light.row
        if light.directional:
            lights.append(threejs.DirectionalLight(color=rgb, position=where))
            continue
        decay, intensity = _attenuation_as_decay(row)
        reach = float(row["range"])
        falloff: dict[str, Any] = {
            "color": rgb, "intensity": intensity, "decay": decay, "position": where,
            "distance": reach if math.isfinite(reach) else 0.0,
        }  # fmt: skip
        if cone is None:
            lights.append(threejs.PointLight(**falloff))
            continue
        angle = max(math.radians(cone[0]), 1e-6)  # three.js' angle is above 0
        lights.append(
            threejs.SpotLight(
                angle=angle,
                penumbra=1.0 - cone[1] / cone[0] if cone[0] > 0 else 0.0,
                target=where + row["spot_direction"],
                **falloff,
            )
        )
    ambient = _ambient_sum(scene, rows)
    if ambient.any():
        lights.append(threejs.AmbientLight(color=ambient))
    m = scene.material
    return threejs.Scene(
        lights,
        threejs.MeshPhongMaterial(
            color=np.maximum(m.diffuse[:3], 0.0), specular=np.maximum(m.specular[:3], 0.0),
            shininess=m.shininess, emissive=np.maximum(m.emission[:3], 0.0),
            opacity=float(np.clip(m.diffuse[3], 0.0, 1.0)),
            side="double" if scene.two_side else "front",
        ),
    )  # fmt: skip


def _to_pytorch3d(scene: Scene) -> Scene:
    """GL's scene as PyTorch3D's Phong draws it (`presets.pytorch3d`): every light
    unattenuated and without a spot cone or range, no emission, Phong's reflection vector with
    GL's gate, the viewer at the camera; colours, positions, shininess and the ambient terms
    (global and per light: the same form as PyTorch3D's ``ambient_color`` products) as they
    are."""
    lights = scene.lights
    count = len(lights)
    plain = (
        Lights(
            position=lights.position,
            ambient=lights.ambient,
            diffuse=lights.diffuse,
            specular=lights.specular,
        )
        if count
        else Lights(count=0)
    )
    m = scene.material
    return Scene(
        lights=plain,
        material=Material(
            ambient=m.ambient,
            diffuse=m.diffuse,
            specular=m.specular,
            emission=(0.0, 0.0, 0.0, 1.0),
            shininess=m.shininess,
        ),
        global_ambient=scene.global_ambient,
        viewer=(0.0, 0.0, 0.0, 1.0),
        specular="phong",
        specular_gate=True,
    )


_FROM_GL: dict[str, Callable[[Scene], AnyScene]] = {
    "gl": lambda scene: scene,
    "gltf": _to_gltf,
    "threejs": _to_threejs,
    "pytorch3d": _to_pytorch3d,
}
