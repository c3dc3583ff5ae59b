"""glTF 2.0's metallic-roughness model, as pyrender evaluates it: a material, punctual lights and
a scene that `glshade.shade` and `glshade.render` take in place of a `glshade.Scene`.

>>> import numpy as np, glshade as gs
>>> scene = gs.gltf.Scene(
...     lights=[gs.gltf.DirectionalLight(intensity=3.0, direction=(0, 0, -1))],
...     material=gs.gltf.Material(base_color=(0.8, 0.2, 0.2, 1.0), metallic=0.0, roughness=0.5),
...     camera_position=(0, 0, 5),
... )
>>> gs.shade(np.zeros((1, 3)), np.array([[0, 0, 1.0]]), scene).round(4)
array([[0.8568, 0.3288, 0.3288, 1.    ]])

The model is pyrender 0.1.45's ``shaders/mesh.frag`` for a metallic-roughness material without
textures, term by term: GGX's distribution, Smith-Schlick occlusion with k = (r + 1)²/8,
Schlick's Fresnel, the diffuse (1 - F)·c_diff/π, its clamps (n·l and |n·v| at least 0.001,
roughness at least 0.04) and constants, its lights and units, base colour times ambient light,
and
a vertex colour that multiplies the result. The result is linear, as the lighting sums are;
pyrender's final ``pow(c, 1/2.2)`` is ``transfer="gamma2.2"`` in `glshade.render` (or
``c ** (1 / 2.2)`` on `shade`'s result). The documentation's page "glTF metallic-roughness"
(docs/pages/guide/gltf.md) lists every term and where glshade and pyrender differ.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Iterable
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from . import _glshade
from ._intake import color, refuse_bytes, vector
from ._records import ValueRecord, set_field
from ._typing import Float64Array
from ._world import Color, WorldScene, record_fields, set_fields

__all__ = ["DirectionalLight", "Material", "PointLight", "Scene", "SpotLight"]


@dataclasses.dataclass(frozen=True, eq=False, init=False)
class Material(ValueRecord):
    """A metallic-roughness material (glTF's ``pbrMetallicRoughness`` factors and
    ``emissiveFactor``), with glTF's defaults.

    Parameters
    ----------
    base_color : (3,) or (4,) float, default (1, 1, 1, 1)
        ``baseColorFactor``: linear RGBA in [0, 1] (a missing alpha is 1). The output's alpha is
        its alpha (times a vertex colour's).
    metallic : float in [0, 1], default 1
        ``metallicFactor``.
    roughness : float in [0, 1], default 1
        ``roughnessFactor``, perceptual roughness; the model uses at least 0.04.
    emissive : (3,) float >= 0, default (0, 0, 0)
        The emitted linear RGB, added as it is (glTF's meaning of ``emissiveFactor``; pyrender's
        shader adds the square of its factor, which `glshade.render` of a pyrender scene
        accounts for).

    Raises
    ------
    TypeError
        For a non-numeric value.
    ValueError
        For a base colour of another shape than (3,) or (4,), a factor outside [0, 1] or a
        negative emission.
    """

    base_color: tuple[float, float, float, float]
    metallic: float
    roughness: float
    emissive: Color

    def __init__(
        self,
        base_color: ArrayLike = (1.0, 1.0, 1.0, 1.0),
        metallic: float = 1.0,
        roughness: float = 1.0,
        emissive: ArrayLike = (0.0, 0.0, 0.0),
    ) -> None:
        base = color(base_color, "base_color")
        if base.shape not in ((3,), (4,)):
            raise ValueError(f"base_color must have shape (3,) or (4,), got shape {base.shape}")
        refuse_bytes(base, "base_color", "gltf.Material")  # glTF's factors lie in [0, 1]
        set_field(self, "base_color", (*(float(x) for x in base), 1.0)[:4])
        set_fields(self, locals())  # the others
        # The native scene checks ranges; checking here too names the value at its source.
        _native_scene([], self, (0.0, 0.0, 0.0), (0.0, 0.0, 0.0))


@dataclasses.dataclass(frozen=True, eq=False, init=False)
class DirectionalLight(ValueRecord):
    """Light travelling along `direction` (pyrender's ``DirectionalLight`` at a node whose -z
    axis is `direction`).

    Parameters
    ----------
    color : (3,) float >= 0, default (1, 1, 1)
        Linear RGB.
    intensity : float >= 0, default 1
        Illuminance (lux): the radiance is ``color * intensity``.
    direction : (3,) float, default (0, 0, -1)
        The way the light travels, any nonzero length (normalised).
    """

    color: Color
    intensity: float
    direction: tuple[float, ...]

    def __init__(
        self,
        color: ArrayLike = (1.0, 1.0, 1.0),
        intensity: float = 1.0,
        direction: ArrayLike = (0.0, 0.0, -1.0),
    ) -> None:
        set_fields(self, locals())
        _native_scene([self], Material(), (0.0, 0.0, 0.0), (0.0, 0.0, 0.0))


@dataclasses.dataclass(frozen=True, eq=False, init=False)
class PointLight(ValueRecord):
    """Light from a point, falling off as 1/d² (pyrender's ``PointLight``; its ``range`` is not
    used by pyrender's shader, so there is none here).

    Parameters
    ----------
    color : (3,) float >= 0, default (1, 1, 1)
        Linear RGB.
    intensity : float >= 0, default 1
        Luminous intensity (candela): the radiance at distance d is ``color * intensity / d²``.
    position : (3,) float, default (0, 0, 0)
        Where the light is, in the coordinates of the vertices.
    """

    color: Color
    intensity: float
    position: tuple[float, ...]

    def __init__(
        self,
        color: ArrayLike = (1.0, 1.0, 1.0),
        intensity: float = 1.0,
        position: ArrayLike = (0.0, 0.0, 0.0),
    ) -> None:
        set_fields(self, locals())
        _native_scene([self], Material(), (0.0, 0.0, 0.0), (0.0, 0.0, 0.0))


@dataclasses.dataclass(frozen=True, eq=False, init=False)
class SpotLight(ValueRecord):
    """A point light within a cone (pyrender's ``SpotLight``, glTF's spot): full intensity
    within `inner_cone_angle` of the axis, none beyond `outer_cone_angle`, and
    ``clamp((cos θ - cos outer) / (cos inner - cos outer), 0, 1)²`` between (the width below
    at least 0.001, as pyrender has it).

    Parameters
    ----------
    color : (3,) float >= 0, default (1, 1, 1)
        Linear RGB.
    intensity : float >= 0, default 1
        Luminous intensity (candela) on the axis, over d².
    position : (3,) float, default (0, 0, 0)
        Where the light is.
    direction : (3,) float, default (0, 0, -1)
        The cone's axis, the way the light travels (normalised).
    inner_cone_angle : float, default 0
        Radians, ``0 <= inner_cone_angle <= outer_cone_angle``.
    outer_cone_angle : float, default pi/4
        Radians, at most pi/2.
    """

    color: Color
    intensity: float
    position: tuple[float, ...]
    direction: tuple[float, ...]
    inner_cone_angle: float
    outer_cone_angle: float

    def __init__(
        self,
        color: ArrayLike = (1.0, 1.0, 1.0),
        intensity: float = 1.0,
        position: ArrayLike = (0.0, 0.0, 0.0),
        direction: ArrayLike = (0.0, 0.0, -1.0),
        inner_cone_angle: float = 0.0,
        outer_cone_angle: float = math.pi / 4,
    ) -> None:
        set_fields(self, locals())
        _native_scene([self], Material(), (0.0, 0.0, 0.0), (0.0, 0.0, 0.0))


Light = DirectionalLight | PointLight | SpotLight
_ZERO = (0.0, 0.0, 0.0)


def _row(light: Light) -> tuple[Any, ...]:
    """A light as the native scene takes it."""
    if isinstance(light, DirectionalLight):
        return ("directional", light.color, light.intensity, _ZERO, light.direction, 0.0, 0.0)
    if isinstance(light, PointLight):
        return ("point", light.color, light.intensity, light.position, _ZERO, 0.0, 0.0)
    return (
        "spot", light.color, light.intensity, light.position, light.direction,
        light.inner_cone_angle, light.outer_cone_angle,
    )  # fmt: skip


def _native_scene(
    lights: list[Light], material: Material, ambient: tuple[float, ...], camera: tuple[float, ...]
) -> _glshade.GltfScene:
    """The native scene, which checks every value (the material's fields are its keywords)."""
    rows = [_row(light) for light in lights]
    return _glshade.GltfScene(
        lights=rows, ambient_light=ambient, camera_position=camera, **record_fields(material)
    )


class Scene(WorldScene[Light, Material]):
    """Lights, one material, the ambient light and the camera, in world coordinates: what
    pyrender's shader reads for one mesh.

    Parameters
    ----------
    lights : DirectionalLight, PointLight or SpotLight, or an iterable of them
        Summed in order.
    material : Material, optional
        Default: glTF's default material (white, metallic 1, roughness 1).
    ambient_light : (3,) float >= 0, default (0, 0, 0)
        pyrender's ``Scene.ambient_light``: adds ``base_color * ambient_light``.
    camera_position : (3,) float, default (0, 0, 0)
        Where the camera is (the view vector points there). `glshade.render` takes it from the
        camera instead.

    Raises
    ------
    TypeError
        For a light or material of another type, or a non-numeric value.
    ValueError
        For a negative or non-finite ambient light, or a camera position that is not finite.
    """

    __slots__ = ("_ambient_light",)

    _native: _glshade.GltfScene

    _LIGHTS = (DirectionalLight, PointLight, SpotLight)
    _MATERIAL = Material

    def __init__(
        self,
        lights: Iterable[Light] | Light = (),
        material: Material | None = None,
        *,
        ambient_light: ArrayLike = (0.0, 0.0, 0.0),
        camera_position: ArrayLike = (0.0, 0.0, 0.0),
    ) -> None:
        self._take(lights, material)
        self._ambient_light = vector(ambient_light, "ambient_light")
        self._camera_position = vector(camera_position, "camera_position")
        self._native = _native_scene(
            list(self._lights), self.material, self._ambient_light, self._camera_position
        )

    @property
    def ambient_light(self) -> Float64Array:
        """(3,) The ambient light."""
        return np.array(self._ambient_light)

    def with_camera(self, camera_position: ArrayLike) -> Scene:
        """The same scene seen from `camera_position`."""
        return Scene(**{**self._fields(), "camera_position": camera_position})

    def _model_fields(self) -> dict[str, Any]:
        return {"ambient_light": self._ambient_light, "camera_position": self._camera_position}
