"""three.js' ``MeshPhongMaterial`` and its lights, as three.js' shaders evaluate them: a
material, lights and a scene that `glshade.shade` and `glshade.render` take in place of a
`glshade.Scene`.

>>> import numpy as np, glshade as gs
>>> scene = gs.threejs.Scene(
...     lights=[gs.threejs.DirectionalLight(intensity=2.0, position=(0, 0, 1))],
...     material=gs.threejs.MeshPhongMaterial(color=(0.8, 0.2, 0.2)),
...     camera_position=(0, 0, 5),
... )
>>> gs.shade(np.zeros((1, 3)), np.array([[0, 0, 1.0]]), scene).round(4)
array([[0.6795, 0.2975, 0.2975, 1.    ]])

The model is release 111's ``meshphong_frag`` (Debian's ``libjs-three``) without maps, term
by term: Lambert's diffuse ``color / π``, the normalised Blinn-Phong specular
``(shininess/2 + 1)/(4π) · (n·h)^shininess`` times Schlick's Fresnel on the ``specular``
colour, every direct light weighted by ``saturate(n·l)``, three.js' distance falloff and
penumbra smoothstep, ambient and hemisphere lights, emission. With
``physically_correct_lights=True`` (the default) it is also the current release's model;
``False`` is r111's default "legacy" lights (every irradiance times π, a decay only within a
finite ``distance``). The result is linear; three.js' sRGB output is
``transfer="srgb"`` in `glshade.render`. The documentation's page "three.js MeshPhongMaterial"
(docs/pages/guide/threejs.md) lists every term and its source line.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Iterable
from typing import Any, Literal

import numpy as np
from numpy.typing import ArrayLike

from . import _glshade
from ._intake import one_of, vector
from ._records import ValueRecord, set_field
from ._transfer import srgb_decode
from ._typing import Float64Array
from ._world import Color, WorldScene, record_fields, set_fields

__all__ = [
    "AmbientLight",
    "DirectionalLight",
    "HemisphereLight",
    "MeshPhongMaterial",
    "PointLight",
    "Scene",
    "SpotLight",
]

Side = Literal["front", "back", "double"]
ColorLike = ArrayLike | int | str
"""A three.js colour: (3,) linear RGB numbers, a hex integer (0xff8800) or a '#rrggbb' string."""
_WHITE = (1.0, 1.0, 1.0)
_ZERO = (0.0, 0.0, 0.0)
_UP = (0.0, 1.0, 0.0)


def _color(value: ColorLike, name: str) -> tuple[float, ...]:
    """A colour as three.js' ``Color`` takes it, in linear RGB: three numbers as they are (the
    working colour space, as ``new Color(r, g, b)``); a hex integer ``0xrrggbb`` or a
    ``'#rrggbb'`` or ``'#rgb'`` string as sRGB, decoded as current three.js' colour management
    decodes them (``setHex`` and ``setStyle`` read sRGB)."""
    if isinstance(value, (int, np.integer)) and not isinstance(value, (bool, np.bool_)):
        if not 0 <= value <= 0xFFFFFF:
            raise ValueError(f"{name} as a hex integer must be in [0, 0xffffff], got {value:#x}")
        encoded = [(int(value) >> shift & 255) / 255 for shift in (16, 8, 0)]
    elif isinstance(value, str):
        encoded = _hex_string(value, name)
    else:
        a = np.asarray(value) if not isinstance(value, np.ndarray) else value
        if a.ndim == 0 and a.dtype.kind in "fiub":
            raise TypeError(
                f"{name} must be three numbers (r, g, b) in [0, 1], linear, a hex integer such as "
                f"0xff8800 or a '#rrggbb' string, got {value!r}"
            )
        return vector(value, name)
    return tuple(float(x) for x in srgb_decode(np.array(encoded)))


def _hex_string(text: str, name: str) -> list[float]:
    """The sRGB components of a CSS hex colour, '#rrggbb' or '#rgb' (each digit doubled)."""
    digits = text.strip().lstrip("#")
    if text.strip().startswith("#") and len(digits) in (3, 6):
        try:
            if len(digits) == 3:
                return [int(d, 16) / 15 for d in digits]
            return [int(digits[i : i + 2], 16) / 255 for i in (0, 2, 4)]
        except ValueError:
            pass
    raise ValueError(
        f"{name} as a string must be a hex colour, '#rrggbb' or '#rgb' (sRGB, as three.js reads "
        f"it), got {text!r}: write, say, '#ff8800', 0xff8800, or linear numbers (1.0, 0.25, 0.0)"
    )


@dataclasses.dataclass(frozen=True, eq=False, init=False)
class MeshPhongMaterial(ValueRecord):
    """three.js' ``MeshPhongMaterial`` without maps, with its defaults.

    Parameters
    ----------
    color : (3,) float >= 0, int or str, default (1, 1, 1)
        The diffuse colour (three.js' ``color``): three numbers are linear RGB; a hex integer
        (``0xff8800``) or a ``'#rrggbb'`` / ``'#rgb'`` string is sRGB and is decoded, as
        current three.js' colour management decodes ``new Color(0xff8800)``. Every colour
        parameter of this module takes the same three forms. Vertex colours and `render`'s
        texture multiply it.
    specular : (3,) float >= 0, int or str, default (17/255, 17/255, 17/255)
        Schlick's f0 (three.js' ``specular``): the default is 0x111111 as r111 reads it,
        undecoded; ``specular=0x111111`` is decoded from sRGB as current releases decode it,
        0.0056.
    shininess : float >= 0, default 30
        The Blinn-Phong exponent; at least 1e-4, as three.js passes it to its shader (so
        ``(n·h)^shininess`` is 0 at n·h = 0).
    emissive : (3,) float >= 0, int or str, default (0, 0, 0)
        Emitted linear RGB (or a hex colour, decoded).
    emissive_intensity : float >= 0, default 1
        ``emissiveIntensity``, multiplies `emissive`.
    opacity : float in [0, 1], default 1
        The output's alpha (times a vertex colour's alpha).
    side : {"front", "back", "double"}, default "front"
        three.js' ``side``: "back" lights the negated normal; "double" gives two colours, the
        back with the negated normal (`shade` returns (2, ..., 4), front then back; `render`
        picks by facing). `render` culls by it unless given ``cull=``.

    Raises
    ------
    TypeError
        For a non-numeric value, or a single number as a colour.
    ValueError
        For a colour of another shape than (3,), a hex integer beyond 0xffffff or a string not
        '#rrggbb' or '#rgb', a negative colour, shininess or intensity, an opacity outside
        [0, 1] or an unknown side.
    ColorRangeWarning
        For a colour given as numbers that look like 0-255 bytes (every value in [0, 255], the
        largest 16 or more): write it as a hex colour or divide by 255.
    """

    color: Color
    specular: Color
    shininess: float
    emissive: Color
    emissive_intensity: float
    opacity: float
    side: Side

    def __init__(
        self,
        color: ColorLike = _WHITE,
        specular: ColorLike = (17 / 255, 17 / 255, 17 / 255),
        shininess: float = 30.0,
        emissive: ColorLike = _ZERO,
        emissive_intensity: float = 1.0,
        opacity: float = 1.0,
        side: Side = "front",
    ) -> None:
        set_fields(self, locals(), _color)
        set_field(self, "side", one_of(side, "side", ("front", "back", "double")))
        # The native scene checks ranges; checking here too names the value at its source.
        _native_scene([], self, _ZERO, None, True)


@dataclasses.dataclass(frozen=True, eq=False, init=False)
class AmbientLight(ValueRecord):
    """three.js' ``AmbientLight``: irradiance ``color * intensity`` from everywhere (times π
    with legacy lights), lighting the diffuse colour only.

    Parameters
    ----------
    color : (3,) float >= 0, int or str, default (1, 1, 1)
        Linear RGB, or a hex colour (sRGB, decoded; see `MeshPhongMaterial`).
    intensity : float >= 0, default 1
    """

    color: Color
    intensity: float

    def __init__(self, color: ColorLike = _WHITE, intensity: float = 1.0) -> None:
        set_fields(self, locals(), _color)
        _native_scene([self], MeshPhongMaterial(), _ZERO, None, True)


@dataclasses.dataclass(frozen=True, eq=False, init=False)
class HemisphereLight(ValueRecord):
    """three.js' ``HemisphereLight``: irradiance ``mix(ground_color, sky_color, 0.5·n·d +
    0.5) * intensity`` with d the unit `position` (times π with legacy lights), lighting the
    diffuse colour only.

    Parameters
    ----------
    sky_color : (3,) float >= 0, int or str, default (1, 1, 1)
        The light's ``color`` (the constructor's ``skyColor``), linear RGB or a hex colour.
    ground_color : (3,) float >= 0, int or str, default (1, 1, 1)
        ``groundColor``, linear RGB or a hex colour.
    intensity : float >= 0, default 1
    position : (3,) float, default (0, 1, 0)
        Towards the sky, nonzero (three.js normalises the light's position).
    """

    sky_color: Color
    ground_color: Color
    intensity: float
    position: tuple[float, ...]

    def __init__(
        self,
        sky_color: ColorLike = _WHITE,
        ground_color: ColorLike = _WHITE,
        intensity: float = 1.0,
        position: ArrayLike = _UP,
    ) -> None:
        set_fields(self, locals(), _color)
        _native_scene([self], MeshPhongMaterial(), _ZERO, None, True)


@dataclasses.dataclass(frozen=True, eq=False, init=False)
class DirectionalLight(ValueRecord):
    """three.js' ``DirectionalLight``: parallel light from `position` towards `target`.

    Parameters
    ----------
    color : (3,) float >= 0, int or str, default (1, 1, 1)
        Linear RGB, or a hex colour (sRGB, decoded; see `MeshPhongMaterial`).
    intensity : float >= 0, default 1
    position : (3,) float, default (0, 1, 0)
        The light's position; only ``position - target`` matters (nonzero).
    target : (3,) float, default (0, 0, 0)
        ``target.position``.
    """

    color: Color
    intensity: float
    position: tuple[float, ...]
    target: tuple[float, ...]

    def __init__(
        self,
        color: ColorLike = _WHITE,
        intensity: float = 1.0,
        position: ArrayLike = _UP,
        target: ArrayLike = _ZERO,
    ) -> None:
        set_fields(self, locals(), _color)
        _native_scene([self], MeshPhongMaterial(), _ZERO, None, True)


@dataclasses.dataclass(frozen=True, eq=False, init=False)
class PointLight(ValueRecord):
    """three.js' ``PointLight``.

    Parameters
    ----------
    color : (3,) float >= 0, int or str, default (1, 1, 1)
        Linear RGB, or a hex colour (sRGB, decoded; see `MeshPhongMaterial`).
    intensity : float >= 0, default 1
    distance : float >= 0, default 0
        The reach: physically correct lights fade as ``saturate(1 - (d/distance)^4)^2``,
        legacy lights as ``saturate(1 - d/distance)^decay``; 0 is unlimited.
    decay : float >= 0, default 2
        Physically correct lights fall off as ``1 / max(d^decay, 0.01)`` (the current
        release's default 2; r111's default was 1).
    position : (3,) float, default (0, 0, 0)
    """

    color: Color
    intensity: float
    distance: float
    decay: float
    position: tuple[float, ...]

    def __init__(
        self,
        color: ColorLike = _WHITE,
        intensity: float = 1.0,
        distance: float = 0.0,
        decay: float = 2.0,
        position: ArrayLike = _ZERO,
    ) -> None:
        set_fields(self, locals(), _color)
        _native_scene([self], MeshPhongMaterial(), _ZERO, None, True)


@dataclasses.dataclass(frozen=True, eq=False, init=False)
class SpotLight(ValueRecord):
    """three.js' ``SpotLight``: a point light within the cone from `position` towards `target`:
    0 unless cos θ > cos(angle), then ``smoothstep(cos(angle), cos(angle·(1 - penumbra)),
    cos θ)`` (a step for penumbra 0).

    Parameters
    ----------
    color : (3,) float >= 0, int or str, default (1, 1, 1)
        Linear RGB, or a hex colour (sRGB, decoded; see `MeshPhongMaterial`).
    intensity : float >= 0, default 1
    distance : float >= 0, default 0
        As `PointLight`'s.
    angle : float, default pi/3
        Radians in (0, pi/2].
    penumbra : float in [0, 1], default 0
    decay : float >= 0, default 2
        As `PointLight`'s.
    position : (3,) float, default (0, 1, 0)
    target : (3,) float, default (0, 0, 0)
        The cone's axis is ``target - position`` (nonzero).
    """

    color: Color
    intensity: float
    distance: float
    angle: float
    penumbra: float
    decay: float
    position: tuple[float, ...]
    target: tuple[float, ...]

    def __init__(
        self,
        color: ColorLike = _WHITE,
        intensity: float = 1.0,
        distance: float = 0.0,
        angle: float = math.pi / 3,
        penumbra: float = 0.0,
        decay: float = 2.0,
        position: ArrayLike = _UP,
        target: ArrayLike = _ZERO,
    ) -> None:
        set_fields(self, locals(), _color)
        _native_scene([self], MeshPhongMaterial(), _ZERO, None, True)


Light = AmbientLight | HemisphereLight | DirectionalLight | PointLight | SpotLight
_KINDS = (AmbientLight, HemisphereLight, DirectionalLight, PointLight, SpotLight)


def _away(position: tuple[float, ...], target: tuple[float, ...]) -> tuple[float, ...]:
    """``position - target``, the direction `WebGLLights` gives directional and spot lights."""
    return tuple(p - t for p, t in zip(position, target, strict=True))


def _row(light: Light) -> tuple[Any, ...]:
    """A light as the native scene takes it: kind, colour, intensity, position, direction,
    ground colour, distance, decay, angle, penumbra."""
    if isinstance(light, AmbientLight):
        return ("ambient", light.color, light.intensity, _ZERO, _ZERO, _ZERO, 0.0, 0.0, 0.0, 0.0)
    if isinstance(light, HemisphereLight):
        return (
            "hemisphere", light.sky_color, light.intensity, _ZERO, light.position,
            light.ground_color, 0.0, 0.0, 0.0, 0.0,
        )  # fmt: skip
    if isinstance(light, DirectionalLight):
        away = _away(light.position, light.target)
        return ("directional", light.color, light.intensity, _ZERO, away, _ZERO, 0.0, 0.0, 0.0, 0.0)
    if isinstance(light, PointLight):
        return (
            "point", light.color, light.intensity, light.position, _ZERO, _ZERO,
            light.distance, light.decay, 0.0, 0.0,
        )  # fmt: skip
    return (
        "spot", light.color, light.intensity, light.position,
        _away(light.position, light.target), _ZERO, light.distance, light.decay, light.angle,
        light.penumbra,
    )  # fmt: skip


def _native_scene(
    lights: list[Light],
    material: MeshPhongMaterial,
    camera: tuple[float, ...],
    view_direction: tuple[float, ...] | None,
    physical: bool,
) -> _glshade.ThreejsScene:
    """The native scene, which checks every value (the material's fields are its keywords)."""
    return _glshade.ThreejsScene(
        lights=[_row(light) for light in lights],
        camera_position=camera,
        view_direction=view_direction,
        physically_correct_lights=physical,
        **record_fields(material),
    )


class Scene(WorldScene[Light, MeshPhongMaterial]):
    """Lights, one ``MeshPhongMaterial``, the camera and the renderer's light convention, in
    world coordinates: what three.js' shader reads for one mesh.

    Parameters
    ----------
    lights : a light or an iterable of AmbientLight, HemisphereLight, DirectionalLight, PointLight
        or SpotLight
        three.js sums point, spot and directional lights (in that order), then the ambient
        and hemisphere lights.
    material : MeshPhongMaterial, optional
        Default: three.js' default material.
    camera_position : (3,) float, default (0, 0, 0)
        Where a perspective camera is (the view vector points there). `glshade.render` takes
        it from the camera instead.
    view_direction : (3,) float, optional
        For an orthographic camera: the view vector of every vertex, the camera's +z axis
        (towards the viewer), as the shader's ``isOrthographic`` branch has it; replaces
        `camera_position`. `glshade.render` sets it from an orthographic camera.
    physically_correct_lights : bool, default True
        ``WebGLRenderer.physicallyCorrectLights``: True is the current release's only
        convention; False is r111's default (every irradiance times π; decay only within a
        finite distance).

    Raises
    ------
    TypeError
        For a light or material of another type, a non-numeric value, or a
        `physically_correct_lights` that is not a bool.
    ValueError
        For a camera position that is not finite, or a view direction that is zero or not
        finite.
    """

    __slots__ = ("_physical", "_view")

    _native: _glshade.ThreejsScene

    _LIGHTS = _KINDS
    _MATERIAL = MeshPhongMaterial

    def __init__(
        self,
        lights: Iterable[Light] | Light = (),
        material: MeshPhongMaterial | None = None,
        *,
        camera_position: ArrayLike = _ZERO,
        view_direction: ArrayLike | None = None,
        physically_correct_lights: bool = True,
    ) -> None:
        self._take(lights, material)
        if not isinstance(physically_correct_lights, (bool, np.bool_)):
            raise TypeError(
                f"physically_correct_lights must be True or False, got "
                f"{physically_correct_lights!r}"
            )
        self._camera_position = vector(camera_position, "camera_position")
        self._view = None if view_direction is None else vector(view_direction, "view_direction")
        self._physical = bool(physically_correct_lights)
        self._native = _native_scene(
            list(self._lights), self.material, self._camera_position, self._view, self._physical
        )

    @property
    def outputs(self) -> tuple[str, ...]:
        """The names of the colours `shade` returns: ("color",), or ("front", "back") for a
        double-sided material."""
        return ("front", "back") if self.material.side == "double" else ("color",)

    @property
    def view_direction(self) -> Float64Array | None:
        """(3,) The orthographic view direction, or None for a perspective camera."""
        return None if self._view is None else np.array(self._view)

    @property
    def physically_correct_lights(self) -> bool:
        """three.js' ``physicallyCorrectLights``."""
        return self._physical

    def _default_cull(self) -> str | None:
        # The triangles three.js discards for the material's side (its face culling).
        return {"front": "back", "back": "front", "double": None}[self.material.side]

    def _model_fields(self) -> dict[str, Any]:
        return {
            "camera_position": self._camera_position,
            "view_direction": self._view,
            "physically_correct_lights": self._physical,
        }
