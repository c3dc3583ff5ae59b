"""OpenGL lighting state as Python objects: lights, materials and the light model.

Each object holds its native counterpart (``glshade._glshade.Lights``, ``Material``, ``Scene``),
checked once, by the Rust code that shades, when it is built; `shade` and `render` hand that
object to the core as it is. GL's defaults are the core's, read from the native classes.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Mapping
from typing import Any, Literal

import numpy as np
from numpy.typing import ArrayLike

from . import _glshade
from ._intake import (
    accuracy_choice,
    choice,
    color,
    colors_checked,
    flag,
    integer,
    matrix,
    optional_choice,
    real,
    rgba,
    warn_if_bytes,
)
from ._model import Model
from ._typing import Accuracy, Float64Array

__all__ = ["Light", "Lights", "Material", "Scene"]

_LIGHT = _glshade.Lights.DEFAULTS
_MATERIAL = _glshade.Material.DEFAULTS
_SCENE = _glshade.Scene.DEFAULTS


# The colour parameters of a light, and of a material.
_LIGHT_COLORS = ("ambient", "diffuse", "specular")
_MATERIAL_COLORS = ("ambient", "diffuse", "specular", "emission")


def _light_parameters(given: dict[str, Any], single: bool) -> dict[str, Float64Array]:
    """The parameters of `Lights` (or of one `Light`, `single`) by name, checked: colours
    through `color` (names refused, uint8 divided by 255), a 3-vector position refused with the
    two ways of adding w."""
    parameters = {
        name: color(given[name], name) if name in _LIGHT_COLORS else real(given[name], name)
        for name in _glshade.Lights.PARAMETERS
    }
    position = parameters["position"]
    if position.ndim in ((1,) if single else (1, 2)) and position.shape[-1] == 3:
        if position.ndim == 1:
            xyz = _format(position)
            raise ValueError(
                f"position must have shape (4,), (x, y, z, w), got {xyz} of shape (3,): add w, "
                f"{xyz[:-1]}, 1) for a point light at {xyz}, or {xyz[:-1]}, 0) for a "
                f"directional light shining from direction {xyz}"
            )
        count = len(position)
        raise ValueError(
            f"position must have shape (L, 4), got shape {position.shape}: add a column of w, "
            f"np.c_[position, np.ones({count})] for point lights, or "
            f"np.c_[position, np.zeros({count})] for directional lights"
        )
    return parameters


def _warn_light_bytes(
    parameters: dict[str, Float64Array], native: _glshade.Lights, owner: str
) -> None:
    """`warn_if_bytes` on the colours given for the unattenuated lights: an attenuated light's
    large colour is its intensity (1 / d^2 brings it down), not bytes."""
    count = len(native)
    plain = (
        (native.column("constant_attenuation").reshape(count) == 1.0)
        & (native.column("linear_attenuation").reshape(count) == 0.0)
        & (native.column("quadratic_attenuation").reshape(count) == 0.0)
    )
    if not plain.any():
        return
    for name in _LIGHT_COLORS:
        values = parameters[name]
        warn_if_bytes(values[plain] if values.ndim == 2 else values, name, owner)


def _format(value: Any) -> str:
    if np.ndim(value) == 0:
        return f"{float(value):g}"
    return "(" + ", ".join(f"{float(x):g}" for x in value) + ")"


class Lights:
    """Any number of OpenGL lights, one row per light, in eye coordinates.

    Every parameter takes either one value shared by all lights or one row per light (a
    leading axis of length L), so a scene of 10,000 lights is built from arrays without a
    Python loop. Defaults are GL's ``GL_LIGHT0`` (diffuse and specular white).

    Parameters
    ----------
    position : (4,) or (L, 4) float, default: (0.0, 0.0, 1.0, 0.0)
        Homogeneous ``GL_POSITION``: ``w = 0`` is a directional light shining from direction
        ``(x, y, z)``; otherwise a point light at ``(x, y, z) / w``.
    diffuse : (3,), (4,), (L, 3) or (L, 4) float, default: (1.0, 1.0, 1.0, 1.0)
        ``GL_DIFFUSE``; a missing alpha is 1. Negative values are legal, as in GL. Numbers in
        [0, 1] (above 1 for a brighter light); uint8 is divided by 255; a name such as
        ``"red"`` is refused.
    specular : (3,), (4,), (L, 3) or (L, 4) float, default: (1.0, 1.0, 1.0, 1.0)
        ``GL_SPECULAR``, as `diffuse`.
    constant_attenuation : float or (L,) float, default: 1.0
        k0 >= 0; attenuation is ``1 / (k0 + k1 d + k2 d^2)`` for positional lights.
    linear_attenuation : float or (L,) float, default: 0.0
        k1 >= 0.
    quadratic_attenuation : float or (L,) float, default: 0.0
        k2 >= 0.
    spot_direction : (3,) or (L, 3) float, default: (0.0, 0.0, -1.0)
        ``GL_SPOT_DIRECTION``, any nonzero length.
    spot_exponent : float or (L,) float, default: 0.0
        ``GL_SPOT_EXPONENT`` >= 0.
    spot_cutoff : float or (L,) float, default: 180.0
        ``GL_SPOT_CUTOFF`` in degrees: in [0, 90], or 180 for no spot.
    ambient : (3,), (4,), (L, 3) or (L, 4) float, default: (0.0, 0.0, 0.0, 1.0)
        ``GL_AMBIENT``, as `diffuse`.
    spot_inner_cutoff : float or (L,) float, default: 180.0
        A soft spot edge (not GL's): the inner cone in degrees, in [0, `spot_cutoff`]; the spot
        factor is scaled by ``clamp((cos t - cos spot_cutoff) / (cos inner - cos spot_cutoff),
        0, 1)``, learnopengl's ``cutOff``. 180 (or `spot_cutoff` itself) is GL's hard edge.
    range : float or (L,) float, default: inf
        A positional light adds nothing, not even its ambient term, at a distance beyond
        `range` (> 0): Direct3D 11's ``Range`` in Luna's ``LightHelper.fx``; inf is GL.
    count : int, optional
        The number of lights when every parameter is a single value; None (the default) makes
        it 1, or the length of the parameters' leading axis.

    Raises
    ------
    ValueError
        For a wrong shape or a parameter outside GL's range, naming it and the light; a
        position of 3 components, saying which w to add (1: a point light, 0: a direction).
    TypeError
        For a non-numeric parameter, or a colour given by name (the message gives its numbers).

    Warns
    -----
    ColorRangeWarning
        For a colour of unattenuated lights that looks like 0-255 bytes: every value a whole
        number in [0, 255], the largest 16 or more.

    Examples
    --------
    >>> import numpy as np, glshade as gs
    >>> pos = np.c_[np.random.rand(10_000, 3), np.ones(10_000)]
    >>> lights = gs.Lights(position=pos, diffuse=(0.01, 0.01, 0.01), linear_attenuation=0.5)
    >>> len(lights)
    10000
    """

    __slots__ = ("_native",)
    _native: _glshade.Lights
    # The parameters, as read-only properties made from the native PARAMETERS below (one row
    # per light, or the one light's value for a `Light`); declared here for type checkers.
    position: Any
    ambient: Any
    diffuse: Any
    specular: Any
    spot_direction: Any
    spot_exponent: Any
    spot_cutoff: Any
    constant_attenuation: Any
    linear_attenuation: Any
    quadratic_attenuation: Any
    spot_inner_cutoff: Any
    range: Any

    def __init__(
        self,
        position: ArrayLike = _LIGHT["position"],
        diffuse: ArrayLike = _LIGHT["diffuse"],
        specular: ArrayLike = _LIGHT["specular"],
        constant_attenuation: ArrayLike = _LIGHT["constant_attenuation"],
        linear_attenuation: ArrayLike = _LIGHT["linear_attenuation"],
        quadratic_attenuation: ArrayLike = _LIGHT["quadratic_attenuation"],
        spot_direction: ArrayLike = _LIGHT["spot_direction"],
        spot_exponent: ArrayLike = _LIGHT["spot_exponent"],
        spot_cutoff: ArrayLike = _LIGHT["spot_cutoff"],
        ambient: ArrayLike = _LIGHT["ambient"],
        spot_inner_cutoff: ArrayLike = _LIGHT["spot_inner_cutoff"],
        range: ArrayLike = _LIGHT["range"],
        *,
        count: int | None = None,
    ) -> None:
        given = locals()
        n = None if count is None else integer(count, "count", 0, 2**62)
        parameters = _light_parameters(given, single=False)
        self._native = _glshade.Lights([parameters[k] for k in _glshade.Lights.PARAMETERS], n)
        _warn_light_bytes(parameters, self._native, "Lights")

    @classmethod
    def _wrap(cls, native: _glshade.Lights) -> Lights:
        obj = Lights.__new__(Light if cls is Light and len(native) == 1 else Lights)
        obj._native = native
        return obj

    @classmethod
    def concatenate(cls, lights: Iterable[Lights]) -> Lights:
        """All lights of several `Lights` (or `Light`) objects, in order.

        Parameters
        ----------
        lights : iterable of Lights or Light
            The objects whose lights are joined, in order.

        Returns
        -------
        Lights
            One object holding every light.

        Raises
        ------
        TypeError
            For an item that is not a `Light` or `Lights`, naming its index.
        """
        parts = []
        for i, item in enumerate(lights):
            if not isinstance(item, Lights):
                raise TypeError(f"lights[{i}] must be a Light or Lights, got {type(item)!r}")
            parts.append(item._native)
        return Lights._wrap(_glshade.Lights.concatenate(parts))

    def __len__(self) -> int:
        return len(self._native)

    def __getitem__(self, index: Any) -> Lights:
        """``lights[i]`` is a `Light`; a slice, integer array or boolean mask gives `Lights`."""
        try:
            picked = np.arange(len(self))[index]
        except IndexError as e:
            if "out of bounds" in str(e):
                raise IndexError(
                    f"light index {index!r} is out of range for {len(self)} lights"
                ) from None
            raise TypeError(
                f"lights are indexed by an integer, a slice, an integer array or a boolean "
                f"mask, got {index!r}"
            ) from None
        if np.ndim(picked) == 0:
            return Light._wrap(self._native.take([int(picked)]))
        return Lights._wrap(self._native.take(np.asarray(picked).tolist()))

    def _column(self, name: str) -> Float64Array:
        column: Float64Array = self._native.column(name)
        return column

    def __repr__(self) -> str:
        kinds = self._column("position")[:, 3] == 0
        spots = int(np.count_nonzero(self._column("spot_cutoff") != 180))
        n_dir = int(np.count_nonzero(kinds))
        return (
            f"Lights({len(self)} lights: {n_dir} directional, {len(self) - n_dir} positional, "
            f"{spots} spot)"
        )

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Lights):
            return NotImplemented
        return bool(self._native == other._native)

    __hash__ = None  # type: ignore[assignment]


def _light_property(name: str) -> property:
    def get(self: Lights) -> Any:
        value = self._column(name)
        return value[0] if isinstance(self, Light) else value

    get.__doc__ = f"``{name}``, one row per light (read-only)."
    return property(get)


for _name in _glshade.Lights.PARAMETERS:
    setattr(Lights, _name, _light_property(_name))


class Light(Lights):
    """One OpenGL light (``GL_LIGHTi`` state), in eye coordinates.

    Takes the parameters of `Lights` except `count`, each a single value. Attributes
    return that light's values (``light.position`` is a (4,) array, ``light.spot_cutoff`` a
    float).

    Parameters
    ----------
    position : (4,) float, default: (0.0, 0.0, 1.0, 0.0)
        Homogeneous ``GL_POSITION``: ``w = 0`` is a directional light shining from direction
        ``(x, y, z)``; otherwise a point light at ``(x, y, z) / w``.
    diffuse : (3,) or (4,) float, default: (1.0, 1.0, 1.0, 1.0)
        ``GL_DIFFUSE``; a missing alpha is 1. Negative values are legal, as in GL. Numbers, as
        for `Lights`: uint8 is divided by 255, a name is refused.
    specular : (3,) or (4,) float, default: (1.0, 1.0, 1.0, 1.0)
        ``GL_SPECULAR``, as `diffuse`.
    constant_attenuation : float, default: 1.0
        k0 >= 0; attenuation is ``1 / (k0 + k1 d + k2 d^2)`` for positional lights.
    linear_attenuation : float, default: 0.0
        k1 >= 0.
    quadratic_attenuation : float, default: 0.0
        k2 >= 0.
    spot_direction : (3,) float, default: (0.0, 0.0, -1.0)
        ``GL_SPOT_DIRECTION``, any nonzero length.
    spot_exponent : float, default: 0.0
        ``GL_SPOT_EXPONENT`` >= 0.
    spot_cutoff : float, default: 180.0
        ``GL_SPOT_CUTOFF`` in degrees: in [0, 90], or 180 for no spot.
    ambient : (3,) or (4,) float, default: (0.0, 0.0, 0.0, 1.0)
        ``GL_AMBIENT``, as `diffuse`.
    spot_inner_cutoff : float, default: 180.0
        A soft spot edge (not GL's): the inner cone in degrees, in [0, `spot_cutoff`]; the spot
        factor ramps linearly in the cosine from 0 at `spot_cutoff` to 1 there (learnopengl's
        ``cutOff``). 180 (or `spot_cutoff` itself) is GL's hard edge.
    range : float, default: inf
        A positional light adds nothing, not even its ambient term, beyond this distance
        (> 0): Luna's Direct3D 11 ``Range``. inf is GL.

    Raises
    ------
    ValueError
        For a wrong shape (more than one value for a parameter) or a parameter outside GL's
        range, naming it; a position of 3 components, saying which w to add.
    TypeError
        For a non-numeric parameter, or a colour given by name.

    Warns
    -----
    ColorRangeWarning
        For a colour that looks like 0-255 bytes, unless the light is attenuated.

    Examples
    --------
    >>> import glshade as gs
    >>> sun = gs.Light(position=(1, 1, 1, 0))                      # directional
    >>> bulb = gs.Light(position=(0, 2, -3, 1), quadratic_attenuation=0.1)
    >>> spot = gs.Light(position=(0, 0, 0, 1), spot_cutoff=20, spot_exponent=8)
    """

    __slots__ = ()

    def __init__(
        self,
        position: ArrayLike = _LIGHT["position"],
        diffuse: ArrayLike = _LIGHT["diffuse"],
        specular: ArrayLike = _LIGHT["specular"],
        constant_attenuation: float = _LIGHT["constant_attenuation"],
        linear_attenuation: float = _LIGHT["linear_attenuation"],
        quadratic_attenuation: float = _LIGHT["quadratic_attenuation"],
        spot_direction: ArrayLike = _LIGHT["spot_direction"],
        spot_exponent: float = _LIGHT["spot_exponent"],
        spot_cutoff: float = _LIGHT["spot_cutoff"],
        ambient: ArrayLike = _LIGHT["ambient"],
        spot_inner_cutoff: float = _LIGHT["spot_inner_cutoff"],
        range: float = _LIGHT["range"],
    ) -> None:
        given = locals()
        parameters = _light_parameters(given, single=True)
        for name, value in parameters.items():
            if value.ndim > (0 if np.ndim(_LIGHT[name]) == 0 else 1):
                raise ValueError(
                    f"a Light takes one value per parameter, got {name} of shape {value.shape}: "
                    "use glshade.Lights for many lights"
                )
        self._native = _glshade.Lights([parameters[k] for k in _glshade.Lights.PARAMETERS], None)
        _warn_light_bytes(parameters, self._native, "Light")

    def __repr__(self) -> str:
        fields = ", ".join(
            f"{name}={_format(getattr(self, name))}" for name in _glshade.Lights.PARAMETERS
        )
        return f"Light({fields})"


class Material:
    """The material of one face, with GL's defaults (Table 2.10).

    Parameters
    ----------
    ambient : (3,) or (4,) float, default: (0.2, 0.2, 0.2, 1.0)
        ``GL_AMBIENT``; a missing alpha is 1.
    diffuse : (3,) or (4,) float, default: (0.8, 0.8, 0.8, 1.0)
        ``GL_DIFFUSE``; a missing alpha is 1. Only the diffuse alpha reaches the output, as in
        GL.
    specular : (3,) or (4,) float, default: (0.0, 0.0, 0.0, 1.0)
        ``GL_SPECULAR``; a missing alpha is 1.
    emission : (3,) or (4,) float, default: (0.0, 0.0, 0.0, 1.0)
        ``GL_EMISSION``; a missing alpha is 1.
    shininess : float, default: 0.0
        ``GL_SHININESS`` >= 0. GL limits it to 128; glshade accepts larger exponents too.

    Raises
    ------
    TypeError
        For a non-numeric parameter, or a colour given by name (``diffuse="red"``): the
        message gives the numbers to write instead.
    ValueError
        For a wrong shape or a parameter outside GL's range.

    Warns
    -----
    ColorRangeWarning
        For a colour that looks like 0-255 bytes (every value a whole number in [0, 255], the
        largest 16 or more): divide it by 255, or give it as uint8.

    Notes
    -----
    Colours are numbers in [0, 1] (values above 1 are legal, as in GL); a uint8 colour is
    divided by 255, as vertex colours are.
    """

    __slots__ = ("_native",)
    _native: _glshade.Material

    def __init__(
        self,
        ambient: ArrayLike = _MATERIAL["ambient"],
        diffuse: ArrayLike = _MATERIAL["diffuse"],
        specular: ArrayLike = _MATERIAL["specular"],
        emission: ArrayLike = _MATERIAL["emission"],
        shininess: float = _MATERIAL["shininess"],
    ) -> None:
        given = locals()
        parameters = {
            name: color(given[name], name) if name in _MATERIAL_COLORS else real(given[name], name)
            for name in _glshade.Material.PARAMETERS
        }
        self._native = _glshade.Material(list(parameters.values()))
        for name in _MATERIAL_COLORS:
            warn_if_bytes(parameters[name], name, "Material")

    ambient = property(lambda self: self._native.get("ambient"), doc="(4,) ``GL_AMBIENT``.")
    diffuse = property(lambda self: self._native.get("diffuse"), doc="(4,) ``GL_DIFFUSE``.")
    specular = property(lambda self: self._native.get("specular"), doc="(4,) ``GL_SPECULAR``.")
    emission = property(lambda self: self._native.get("emission"), doc="(4,) ``GL_EMISSION``.")
    shininess = property(lambda self: float(self._native.get("shininess")), doc="``GL_SHININESS``.")

    def __repr__(self) -> str:
        return (
            f"Material(ambient={_format(self.ambient)}, diffuse={_format(self.diffuse)}, "
            f"specular={_format(self.specular)}, emission={_format(self.emission)}, "
            f"shininess={self.shininess:g})"
        )

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Material):
            return NotImplemented
        return bool(self._native == other._native)

    __hash__ = None  # type: ignore[assignment]


class Scene(Model):
    """Lights, materials and the light model (``glLightModel``) of one lit scene.

    Parameters
    ----------
    lights : Lights, Light, or a sequence of them
        The enabled lights, summed in order. Default: none (emission and global ambient only).
    material : Material, optional
        The front material (default: GL's).
    back_material : Material, optional
        The back material for two-sided lighting (default: the front material).
    global_ambient : (3,) or (4,) float, default: (0.2, 0.2, 0.2, 1.0)
        ``GL_LIGHT_MODEL_AMBIENT``: numbers (uint8 divided by 255), no colour name; one that
        looks like 0-255 bytes warns (`ColorRangeWarning`).
    viewer : (4,) float, default: (0.0, 0.0, 1.0, 0.0)
        The viewer, homogeneous: ``(0, 0, 1, 0)`` (default) is GL's infinite viewer,
        ``(0, 0, 0, 1)`` GL's local viewer at the eye, any ``(x, y, z, 1)`` a viewer at that point
        (learnopengl's ``viewPos``), any ``(x, y, z, 0)`` a viewer infinitely far that way.
    two_side : bool, default: False
        ``GL_LIGHT_MODEL_TWO_SIDE``: `shade` also returns the back colour, lit with the back
        material and the negated normal.
    separate_specular : bool, default: False
        ``GL_SEPARATE_SPECULAR_COLOR``: `shade` returns the specular sum as a secondary colour.
    specular : {"blinn", "phong"}
        GL's halfway vector ``(n . h)^s`` or the reflection vector ``(R . V)^s``; any case.
    specular_gate : bool, default: True
        GL's ``f_i`` (eq. 2.2): a light adds no specular unless ``n . VP > 0``.
        False drops the gate, as learnopengl's shaders do: the specular term is added wherever
        its cosine is positive, even where ``n . VP <= 0`` (the diffuse term is still
        ``max(n . VP, 0)``). A zero normal or a light at the vertex still gives no specular.

    Attributes
    ----------
    outputs : tuple of str
        The colours `shade` returns for this scene, in order: ``("color",)``, or with
        ``two_side`` ``("front", "back")``, with ``separate_specular``
        ``("primary", "secondary")``, with both ``("front_primary", "front_secondary",
        "back_primary", "back_secondary")``.
    """

    __slots__ = ("_lights", "_native", "back_material", "material")

    _native: _glshade.Scene

    def __init__(
        self,
        lights: Lights | Iterable[Lights] = (),
        material: Material | None = None,
        back_material: Material | None = None,
        global_ambient: ArrayLike = _SCENE["global_ambient"],
        viewer: ArrayLike = _SCENE["viewer"],
        two_side: bool = _SCENE["two_side"],
        separate_specular: bool = _SCENE["separate_specular"],
        specular: Literal["blinn", "phong"] = _SCENE["specular"],
        specular_gate: bool = _SCENE["specular_gate"],
    ) -> None:
        if isinstance(lights, Lights):
            self._lights = lights
        elif isinstance(lights, Iterable) and not isinstance(lights, (str, bytes)):
            self._lights = Lights.concatenate(lights)
        else:
            raise TypeError(
                f"lights must be a Light, a Lights or a sequence of them, got {lights!r}"
            )
        for name, m in (("material", material), ("back_material", back_material)):
            if m is not None and not isinstance(m, Material):
                raise TypeError(f"{name} must be a Material or None, got {type(m)!r}")
        self.material = Material() if material is None else material
        self.back_material = self.material if back_material is None else back_material
        ambient = rgba(global_ambient, "global_ambient")
        warn_if_bytes(color(global_ambient, "global_ambient"), "global_ambient", "Scene")
        viewer_array = real(viewer, "viewer")
        if viewer_array.shape != (4,):
            raise ValueError(f"viewer must have shape (4,), got shape {viewer_array.shape}")
        self._native = _glshade.Scene(
            self._lights._native,
            self.material._native,
            back_material=None if back_material is None else back_material._native,
            global_ambient=ambient,
            viewer=tuple(viewer_array.tolist()),
            two_side=flag(two_side, "two_side"),
            separate_specular=flag(separate_specular, "separate_specular"),
            specular=choice(specular, "specular"),
            specular_gate=flag(specular_gate, "specular_gate"),
        )

    @property
    def lights(self) -> Lights:
        """All lights of the scene, as one `Lights`."""
        return self._lights

    @property
    def global_ambient(self) -> Float64Array:
        """(4,) float64 ``GL_LIGHT_MODEL_AMBIENT``."""
        return _frozen(np.array(self._native.global_ambient))

    @property
    def viewer(self) -> Float64Array:
        """(4,) float64 homogeneous viewer."""
        return _frozen(np.array(self._native.viewer))

    @property
    def two_side(self) -> bool:
        """``GL_LIGHT_MODEL_TWO_SIDE``."""
        return self._native.two_side

    @property
    def separate_specular(self) -> bool:
        """``GL_SEPARATE_SPECULAR_COLOR``."""
        return self._native.separate_specular

    @property
    def specular(self) -> str:
        """``"blinn"`` or ``"phong"``."""
        return self._native.specular

    @property
    def specular_gate(self) -> bool:
        """GL's ``f_i`` gate on the specular term."""
        return self._native.specular_gate

    @property
    def outputs(self) -> tuple[str, ...]:
        return tuple(self._native.outputs)

    def plan(
        self,
        dtype: Any = np.float32,
        *,
        modelview: ArrayLike | None = None,
        normalize: bool = False,
        rescale_normal: bool = False,
        color_material: str | None = None,
        color_material_face: str = "front_and_back",
        accuracy: Accuracy = "fast",
        strict: bool = False,
        clamp: bool = True,
    ) -> str:
        """What `shade` computes for this scene, in one line.

        The keywords are those of `shade` (``color_material`` stands for the presence of
        per-vertex colours). The line names the arithmetic and instruction set, whether
        positions are read at all, and for each light which terms are evaluated: a term the
        scene does not need (a zero colour, shininess 0, no attenuation, no spot cone, a
        directional light's constant direction and halfway vector) is left out, with the same
        results bit for bit. In float32 it also says when the lights are grey (r = g = b) and the
        kernel sums one colour channel for the three, again with the same results, and which
        path the fast mode runs first: lean float32 blocks (plain float32 arithmetic, the
        careful path only where a vertex needs a safeguard) or, for a shininess above 128 or a
        constant attenuation below 2⁻⁶⁰ alone, the careful path throughout.

        Parameters
        ----------
        dtype : dtype-like
            The computation dtype: float32 (float16 counts as float32) or float64.
        modelview : (4, 4) float, optional
            As for `shade`.
        normalize : bool
            As for `shade`.
        rescale_normal : bool
            As for `shade`.
        color_material : {None, "ambient", "diffuse", "specular", "emission", "ambient_and_diffuse"}
            As for `shade`; None (the default) plans a call without per-vertex colours.
        color_material_face : {"front_and_back", "front", "back"}
            As for `shade`.
        accuracy : {"fast", "exact"}
            As for `shade`: ``"display"`` is a deprecated alias of ``"fast"`` (it warns).
        strict : bool
            As for `shade`.
        clamp : bool
            As for `shade`: without the clamp the line ends "unclamped (high dynamic range)".

        Returns
        -------
        str
            The plan, one line.

        Raises
        ------
        TypeError
            For a dtype other than float16, float32 or float64.

        Examples
        --------
        >>> import glshade as gs
        >>> print(gs.Scene(lights=[gs.Light()]).plan())  # doctest: +ELLIPSIS
        fast: float32 arithmetic, ...; light 0 directional (VP, ĥ constant): diffuse; lean ...
        """
        name = np.dtype(dtype).name
        if name not in ("float16", "float32", "float64"):
            raise TypeError(f"dtype must be float32 or float64, got {name}")
        options = {
            "modelview": modelview, "normalize": normalize, "rescale_normal": rescale_normal,
            "color_material": color_material, "color_material_face": color_material_face,
            "strict": strict,
        }  # fmt: skip
        return _glshade.describe(
            self._native,
            dtype="float64" if name == "float64" else "float32",
            accuracy=accuracy_choice(accuracy),
            clamp=flag(clamp, "clamp"),
            **_native_gl_options(options),
        )

    def _gl_options(self, given: Mapping[str, tuple[Any, Any]], *, colors: bool) -> dict[str, Any]:
        values = {name: value for name, (value, _) in given.items()}
        if colors and "color_material" in values:
            # Colours without a mode track GL's default, GL_AMBIENT_AND_DIFFUSE.
            values["color_material"] = values["color_material"] or "ambient_and_diffuse"
        return _native_gl_options(values)

    def _lit_scene(self, view: ArrayLike, lights_in: str) -> Scene:
        return self.in_eye_space(view) if lights_in == "world" else self

    def in_eye_space(self, view: ArrayLike) -> Scene:
        """This scene with its lights and viewer given in world coordinates, moved into eye
        coordinates by `view`: GL's order of calls, ``glLoadMatrix(view)`` before ``glLight``.

        Light positions (points and directions alike) become ``view @ position``, spot
        directions ``view[:3, :3] @ spot_direction`` (GL transforms both when glLight is
        called). The viewer moves too when it is a world point ``(x, y, z, 1)`` or direction
        ``(x, y, z, 0)``, except GL's two viewers, (0, 0, 1, 0) (infinite) and (0, 0, 0, 1)
        (at the eye), which belong to the eye and stay. Everything else is unchanged.

        Parameters
        ----------
        view : (4, 4) float
            World to eye coordinates (``camera.view``): affine and finite.

        Returns
        -------
        Scene
            A new scene; this one is unchanged.

        Examples
        --------
        >>> import glshade as gs
        >>> camera = gs.Camera.look_at(eye=(0, 0, 5))
        >>> scene = gs.Scene(lights=[gs.Light(position=(0, 0, 2, 1))]).in_eye_space(camera.view)
        >>> scene.lights.position
        array([[ 0.,  0., -3.,  1.]])
        """
        m = matrix(view, "view")
        if not np.isfinite(m).all() or not np.array_equal(m[3], [0.0, 0.0, 0.0, 1.0]):
            raise ValueError(f"view must be finite and affine (last row (0, 0, 0, 1)), got {m}")
        count = len(self._lights)
        columns: dict[str, Any] = {n: self._lights._column(n) for n in _glshade.Lights.PARAMETERS}
        columns["position"] = columns["position"].reshape(count, 4) @ m.T
        columns["spot_direction"] = columns["spot_direction"].reshape(count, 3) @ m[:3, :3].T
        # Built as the native class takes them: these colours were checked (and any warning
        # given) when the scene was made, so moving it into eye space warns no second time.
        parameters = [real(columns[n], n) for n in _glshade.Lights.PARAMETERS]
        lights = Lights._wrap(_glshade.Lights(parameters, None)) if count else Lights(count=0)
        viewer = self.viewer
        if tuple(viewer) not in ((0.0, 0.0, 1.0, 0.0), (0.0, 0.0, 0.0, 1.0)):
            viewer = m @ viewer
        with colors_checked():  # the global ambient warned, if at all, when the scene was made
            return Scene(
                lights=lights,
                material=self.material,
                back_material=None if self.back_material is self.material else self.back_material,
                global_ambient=self.global_ambient,
                viewer=viewer,
                two_side=self.two_side,
                separate_specular=self.separate_specular,
                specular=self.specular,  # type: ignore[arg-type]
                specular_gate=self.specular_gate,
            )

    def __repr__(self) -> str:
        return (
            f"Scene({self._lights!r}, material={self.material!r}, "
            f"global_ambient={_format(self.global_ambient)}, viewer={_format(self.viewer)}, "
            f"two_side={self.two_side}, separate_specular={self.separate_specular}, "
            f"specular={self.specular!r}, specular_gate={self.specular_gate})"
        )

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Scene):
            return NotImplemented
        return bool(self._native == other._native)

    __hash__ = None  # type: ignore[assignment]


def _frozen(values: Any) -> Float64Array:
    a = np.array(values, dtype=np.float64)
    a.flags.writeable = False
    return a


# GL's options as the binding takes them, each checked and converted by its name.
_GL_OPTIONS: dict[str, Callable[[Any], Any]] = {
    "modelview": lambda m: None if m is None else matrix(m, "modelview"),
    "normalize": lambda v: flag(v, "normalize"),
    "rescale_normal": lambda v: flag(v, "rescale_normal"),
    "color_material": lambda v: optional_choice(v, "color_material"),
    "color_material_face": lambda v: choice(v, "color_material_face"),
    "strict": lambda v: flag(v, "strict"),
}


def _native_gl_options(values: Mapping[str, Any]) -> dict[str, Any]:
    """`values` of GL's options (any of `_GL_OPTIONS`), checked and converted."""
    return {name: _GL_OPTIONS[name](value) for name, value in values.items()}
