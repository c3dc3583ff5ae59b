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
from ._intake import color, number, vector
from ._records import ValueRecord, set_field
from ._typing import Float64Array

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
        For a wrong shape or a value outside its range.
    """

    base_color: tuple[float, ...]
    metallic: float
    roughness: float
    emissive: tuple[float, ...]

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
        set_field(self, "base_color", (*(float(x) for x in base), 1.0)[:4])
        set_field(self, "metallic", number(metallic, "metallic"))
        set_field(self, "roughness", number(roughness, "roughness"))
        set_field(self, "emissive", vector(emissive, "emissive"))
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

    color: tuple[float, ...]
    intensity: float
    direction: tuple[float, ...]

    def __init__(
        self,
        color: ArrayLike = (1.0, 1.0, 1.0),
        intensity: float = 1.0,
        direction: ArrayLike = (0.0, 0.0, -1.0),
    ) -> None:
        set_field(self, "color", vector(color, "color"))
        set_field(self, "intensity", number(intensity, "intensity"))
        set_field(self, "direction", vector(direction, "direction"))
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

    color: tuple[float, ...]
    intensity: float
    position: tuple[float, ...]

    def __init__(
        self,
        color: ArrayLike = (1.0, 1.0, 1.0),
        intensity: float = 1.0,
        position: ArrayLike = (0.0, 0.0, 0.0),
    ) -> None:
        set_field(self, "color", vector(color, "color"))
        set_field(self, "intensity", number(intensity, "intensity"))
        set_field(self, "position", vector(position, "position"))
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

    color: tuple[float, ...]
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
        set_field(self, "color", vector(color, "color"))
        set_field(self, "intensity", number(intensity, "intensity"))
        set_field(self, "position", vector(position, "position"))
        set_field(self, "direction", vector(direction, "direction"))
        set_field(self, "inner_cone_angle", number(inner_cone_angle, "inner_cone_angle"))
        set_field(self, "outer_cone_angle", number(outer_cone_angle, "outer_cone_angle"))
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
    return _glshade.GltfScene(
        lights=[_row(light) for light in lights],
        base_color=material.base_color,
        metallic=material.metallic,
        roughness=material.roughness,
        emissive=material.emissive,
        ambient_light=ambient,
        camera_position=camera,
    )


class Scene:
    """Lights, one material, the ambient light and the camera, in world coordinates: what
    pyrender's shader reads for one mesh.

    Parameters
    ----------
    lights : iterable of DirectionalLight, PointLight or SpotLight
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
        For a value outside its range.
    """

    __slots__ = ("_ambient_light", "_camera_position", "_lights", "_material", "_native")

    outputs: tuple[str, ...] = ("color",)
    """The names of the colours `shade` returns: one, linear RGBA."""

    def __init__(
        self,
        lights: Iterable[Light] = (),
        material: Material | None = None,
        *,
        ambient_light: ArrayLike = (0.0, 0.0, 0.0),
        camera_position: ArrayLike = (0.0, 0.0, 0.0),
    ) -> None:
        self._lights = tuple(lights)
        for i, light in enumerate(self._lights):
            if not isinstance(light, (DirectionalLight, PointLight, SpotLight)):
                raise TypeError(
                    f"lights[{i}] must be a glshade.gltf DirectionalLight, PointLight or "
                    f"SpotLight, got {type(light)!r}"
                )
        material = Material() if material is None else material
        if not isinstance(material, Material):
            raise TypeError(f"material must be a glshade.gltf.Material, got {type(material)!r}")
        self._material = material
        self._ambient_light = vector(ambient_light, "ambient_light")
        self._camera_position = vector(camera_position, "camera_position")
        self._native = _native_scene(
            list(self._lights), material, self._ambient_light, self._camera_position
        )

    @property
    def lights(self) -> tuple[Light, ...]:
        """The lights, in summation order."""
        return self._lights

    @property
    def material(self) -> Material:
        """The material."""
        return self._material

    @property
    def ambient_light(self) -> Float64Array:
        """(3,) The ambient light."""
        return np.array(self._ambient_light)

    @property
    def camera_position(self) -> Float64Array:
        """(3,) Where the camera is."""
        return np.array(self._camera_position)

    def with_camera(self, camera_position: ArrayLike) -> Scene:
        """The same scene seen from `camera_position`."""
        return Scene(
            self._lights,
            self._material,
            ambient_light=self._ambient_light,
            camera_position=camera_position,
        )

    def plan(self, dtype: Any = np.float32, *, clamp: bool = True) -> str:
        """One line saying what `glshade.shade` computes for this scene with arrays of `dtype`:
        the arithmetic (float64, float32 arrays widened), the instruction set, the lanes per
        block, and which lights and terms run
        (a light of zero intensity or colour is skipped; the diffuse part runs only for
        metallic < 1 and a base colour that is not black).
        """
        name = np.dtype(dtype).name
        if name not in ("float32", "float64"):
            raise ValueError(f"dtype must be float32 or float64, got {name}")
        return str(_glshade.describe_gltf(self._native, model=None, clamp=clamp, dtype=name))

    def __repr__(self) -> str:
        return (
            f"gltf.Scene(lights={list(self._lights)!r}, material={self._material!r}, "
            f"ambient_light={self._ambient_light}, camera_position={self._camera_position})"
        )

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Scene):
            return NotImplemented
        return (
            self._lights == other._lights
            and self._material == other._material
            and self._ambient_light == other._ambient_light
            and self._camera_position == other._camera_position
        )

    __hash__ = None  # type: ignore[assignment]

    def __reduce__(self) -> tuple[Any, ...]:
        return (
            _rebuilt,
            (self._lights, self._material, self._ambient_light, self._camera_position),
        )


def _rebuilt(lights: tuple[Light, ...], material: Material, ambient: Any, camera: Any) -> Scene:
    """A pickled scene, rebuilt."""
    return Scene(lights, material, ambient_light=ambient, camera_position=camera)
