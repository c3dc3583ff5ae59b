"""OpenGL lighting state as Python objects: lights, materials and the light model.

Each object packs itself into the float64 row layout the native module reads
(``_glshade.LIGHT_LAYOUT`` and ``_glshade.MATERIAL_LAYOUT``) and is checked by the same Rust code
that shades, so a bad parameter is reported when the object is built.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any, Literal, TypeVar

import numpy as np
from numpy.typing import ArrayLike, NDArray

from . import _glshade
from ._arrays import choice, matrix, optional_choice

__all__ = ["Light", "Lights", "Material", "Scene"]

Float64Array = NDArray[np.float64]
_L = TypeVar("_L", bound="Lights")

_LIGHT_COLUMNS: dict[str, slice] = {}
_start = 0
for _name, _width in _glshade.LIGHT_LAYOUT:
    _LIGHT_COLUMNS[_name] = slice(_start, _start + _width)
    _start += _width
_LIGHT_ROW_LEN = _start


def _frozen(a: Float64Array) -> Float64Array:
    a.flags.writeable = False
    return a


def _vector(value: ArrayLike, name: str, widths: tuple[int, ...]) -> Float64Array:
    """One parameter as a float64 array of shape (k,) or (L, k); a colour of 3 gets alpha 1."""
    a = np.asarray(value)
    if a.dtype.kind not in "fiu" and a.dtype != np.bool_:
        raise TypeError(f"{name} must be real numbers, got dtype {a.dtype}")
    a = a.astype(np.float64)
    if a.ndim not in (1, 2) or a.shape[-1] not in widths:
        expected = " or ".join(f"({w},) or (L, {w})" for w in widths)
        raise ValueError(f"{name} must have shape {expected}, got {a.shape}")
    if a.shape[-1] == 3 and 4 in widths:
        a = np.concatenate([a, np.ones((*a.shape[:-1], 1))], axis=-1)
    return a


def _scalar(value: ArrayLike, name: str) -> Float64Array:
    """One scalar parameter as a float64 array of shape () or (L,)."""
    a = np.asarray(value)
    if a.dtype.kind not in "fiu":
        raise TypeError(f"{name} must be real numbers, got dtype {a.dtype}")
    if a.ndim > 1:
        raise ValueError(f"{name} must be a number or have shape (L,), got {a.shape}")
    return a.astype(np.float64)


class Lights:
    """Any number of OpenGL lights, one row per light, in eye coordinates.

    Every parameter takes either one value shared by all lights or one row per light (a
    leading axis of length L), so a scene of 10,000 lights is built from arrays without a
    Python loop. Defaults are GL's ``GL_LIGHT0`` (diffuse and specular white).

    Parameters
    ----------
    position : (4,) or (L, 4) float
        Homogeneous ``GL_POSITION``: ``w = 0`` is a directional light shining from direction
        ``(x, y, z)``; otherwise a point light at ``(x, y, z) / w``.
    diffuse, specular, ambient : (3,), (4,), (L, 3) or (L, 4) float
        Light colours; a missing alpha is 1. Negative values are legal, as in GL.
    constant_attenuation, linear_attenuation, quadratic_attenuation : float or (L,) float
        k0, k1, k2 >= 0; attenuation is ``1 / (k0 + k1 d + k2 d^2)`` for positional lights.
    spot_direction : (3,) or (L, 3) float
        ``GL_SPOT_DIRECTION``, any nonzero length.
    spot_exponent : float or (L,) float
        ``GL_SPOT_EXPONENT`` >= 0.
    spot_cutoff : float or (L,) float
        ``GL_SPOT_CUTOFF`` in degrees: in [0, 90], or 180 for no spot.
    count : int, optional
        The number of lights when every parameter is a single value (default 1).

    Raises
    ------
    ValueError
        For a wrong shape or a parameter outside GL's range, naming it and the light.
    TypeError
        For a non-numeric parameter.

    Examples
    --------
    >>> import numpy as np, glshade as gs
    >>> pos = np.c_[np.random.rand(10_000, 3), np.ones(10_000)]
    >>> lights = gs.Lights(position=pos, diffuse=(0.01, 0.01, 0.01), linear_attenuation=0.5)
    >>> len(lights)
    10000
    """

    __slots__ = ("_table",)
    _table: Float64Array
    # The parameters, as read-only properties made from LIGHT_LAYOUT below (one row per light,
    # or the one light's value for a `Light`); declared here for type checkers.
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

    def __init__(
        self,
        position: ArrayLike = (0.0, 0.0, 1.0, 0.0),
        diffuse: ArrayLike = (1.0, 1.0, 1.0, 1.0),
        specular: ArrayLike = (1.0, 1.0, 1.0, 1.0),
        constant_attenuation: ArrayLike = 1.0,
        linear_attenuation: ArrayLike = 0.0,
        quadratic_attenuation: ArrayLike = 0.0,
        spot_direction: ArrayLike = (0.0, 0.0, -1.0),
        spot_exponent: ArrayLike = 0.0,
        spot_cutoff: ArrayLike = 180.0,
        ambient: ArrayLike = (0.0, 0.0, 0.0, 1.0),
        *,
        count: int | None = None,
    ) -> None:
        values = {
            "position": _vector(position, "position", (4,)),
            "ambient": _vector(ambient, "ambient", (3, 4)),
            "diffuse": _vector(diffuse, "diffuse", (3, 4)),
            "specular": _vector(specular, "specular", (3, 4)),
            "spot_direction": _vector(spot_direction, "spot_direction", (3,)),
            "spot_exponent": _scalar(spot_exponent, "spot_exponent"),
            "spot_cutoff": _scalar(spot_cutoff, "spot_cutoff"),
            "constant_attenuation": _scalar(constant_attenuation, "constant_attenuation"),
            "linear_attenuation": _scalar(linear_attenuation, "linear_attenuation"),
            "quadratic_attenuation": _scalar(quadratic_attenuation, "quadratic_attenuation"),
        }
        per_light = {
            name: len(v)
            for name, v in values.items()
            if v.ndim == (2 if _LIGHT_COLUMNS[name].stop - _LIGHT_COLUMNS[name].start > 1 else 1)
        }
        counts = set(per_light.values()) | ({count} if count is not None else set())
        if len(counts) > 1:
            found = ", ".join(f"{k}: {n}" for k, n in per_light.items())
            raise ValueError(
                f"per-light parameters must all have the same number of rows, got {found}"
                + (f" and count={count}" if count is not None else "")
            )
        n = counts.pop() if counts else 1
        if n < 0:
            raise ValueError(f"count must be >= 0, got {n}")
        table = np.zeros((n, _LIGHT_ROW_LEN))
        for name, v in values.items():
            column = _LIGHT_COLUMNS[name]
            table[:, column] = v.reshape(-1, column.stop - column.start) if v.ndim else v
        _glshade.check_lights(table)
        self._table = _frozen(table)

    @classmethod
    def _from_table(cls: type[_L], table: Float64Array) -> _L:
        obj = cls.__new__(cls)
        obj._table = _frozen(np.ascontiguousarray(table, dtype=np.float64))
        return obj

    @classmethod
    def concatenate(cls, lights: Iterable[Lights]) -> Lights:
        """All lights of several `Lights` (or `Light`) objects, in order."""
        tables = [lt._table for lt in lights]
        if not tables:
            return Lights._from_table(np.zeros((0, _LIGHT_ROW_LEN)))
        return Lights._from_table(np.concatenate(tables))

    def __len__(self) -> int:
        return len(self._table)

    def __getitem__(self, index: int) -> Light:
        row = self._table[index]
        return Light._from_table(row[None, :])

    def _column(self, name: str) -> Float64Array:
        return self._table[:, _LIGHT_COLUMNS[name]]

    @property
    def table(self) -> Float64Array:
        """(L, 24) float64: the packed rows, columns as ``glshade._glshade.LIGHT_LAYOUT``."""
        return self._table

    def __repr__(self) -> str:
        kinds = np.where(self._column("position")[:, 3] == 0, "directional", "positional")
        spots = int(np.count_nonzero(self._column("spot_cutoff")[:, 0] != 180))
        n_dir = int(np.count_nonzero(kinds == "directional"))
        return (
            f"Lights({len(self)} lights: {n_dir} directional, {len(self) - n_dir} positional, "
            f"{spots} spot)"
        )

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Lights):
            return NotImplemented
        return np.array_equal(self._table, other._table)

    __hash__ = None  # type: ignore[assignment]


def _light_property(name: str, width: int) -> property:
    def get(self: Lights) -> Any:
        col = self._column(name)
        value = col[:, 0] if width == 1 else col
        return value[0] if isinstance(self, Light) else value

    get.__doc__ = f"``{name}``, one row per light."
    return property(get)


for _name, _width in _glshade.LIGHT_LAYOUT:
    setattr(Lights, _name, _light_property(_name, _width))


class Light(Lights):
    """One OpenGL light (``GL_LIGHTi`` state), in eye coordinates.

    Takes the same parameters as `Lights`, each a single value; see there. Attributes
    return that light's values (``light.position`` is a (4,) array, ``light.spot_cutoff`` a
    float).

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
        position: ArrayLike = (0.0, 0.0, 1.0, 0.0),
        diffuse: ArrayLike = (1.0, 1.0, 1.0, 1.0),
        specular: ArrayLike = (1.0, 1.0, 1.0, 1.0),
        constant_attenuation: float = 1.0,
        linear_attenuation: float = 0.0,
        quadratic_attenuation: float = 0.0,
        spot_direction: ArrayLike = (0.0, 0.0, -1.0),
        spot_exponent: float = 0.0,
        spot_cutoff: float = 180.0,
        ambient: ArrayLike = (0.0, 0.0, 0.0, 1.0),
    ) -> None:
        super().__init__(
            position,
            diffuse,
            specular,
            constant_attenuation,
            linear_attenuation,
            quadratic_attenuation,
            spot_direction,
            spot_exponent,
            spot_cutoff,
            ambient,
        )
        if len(self) != 1:
            raise ValueError(
                f"a Light takes one value per parameter, got {len(self)} rows: "
                "use glshade.Lights for many lights"
            )

    def __repr__(self) -> str:
        fields = ", ".join(
            f"{name}={self._format(getattr(self, name))}" for name, _ in _glshade.LIGHT_LAYOUT
        )
        return f"Light({fields})"

    @staticmethod
    def _format(value: Any) -> str:
        if np.ndim(value) == 0:
            return f"{float(value):g}"
        return "(" + ", ".join(f"{float(x):g}" for x in value) + ")"


def _rgba(value: ArrayLike, name: str) -> Float64Array:
    a = _vector(value, name, (3, 4))
    if a.ndim != 1:
        raise ValueError(f"{name} must have shape (3,) or (4,), got {a.shape}")
    return a


class Material:
    """The material of one face, with GL's defaults (Table 2.10).

    Parameters
    ----------
    ambient, diffuse, specular, emission : (3,) or (4,) float
        ``GL_AMBIENT``, ``GL_DIFFUSE``, ``GL_SPECULAR``, ``GL_EMISSION``; a missing alpha is 1.
        Only the diffuse alpha reaches the output, as in GL.
    shininess : float
        ``GL_SHININESS`` >= 0. GL limits it to 128; glshade accepts larger exponents too.
    """

    __slots__ = ("_row",)
    _row: Float64Array

    def __init__(
        self,
        ambient: ArrayLike = (0.2, 0.2, 0.2, 1.0),
        diffuse: ArrayLike = (0.8, 0.8, 0.8, 1.0),
        specular: ArrayLike = (0.0, 0.0, 0.0, 1.0),
        emission: ArrayLike = (0.0, 0.0, 0.0, 1.0),
        shininess: float = 0.0,
    ) -> None:
        if np.ndim(shininess) != 0:
            raise ValueError(f"shininess must be a number, got shape {np.shape(shininess)}")
        row = np.concatenate(
            [
                _rgba(ambient, "ambient"),
                _rgba(diffuse, "diffuse"),
                _rgba(specular, "specular"),
                _rgba(emission, "emission"),
                _scalar(shininess, "shininess").reshape(1),
            ]
        )
        _glshade.check_material(row, "material")
        self._row = _frozen(row)

    ambient = property(lambda self: self._row[0:4], doc="(4,) float64 ``GL_AMBIENT``.")
    diffuse = property(lambda self: self._row[4:8], doc="(4,) float64 ``GL_DIFFUSE``.")
    specular = property(lambda self: self._row[8:12], doc="(4,) float64 ``GL_SPECULAR``.")
    emission = property(lambda self: self._row[12:16], doc="(4,) float64 ``GL_EMISSION``.")
    shininess = property(lambda self: float(self._row[16]), doc="``GL_SHININESS``.")

    @property
    def row(self) -> Float64Array:
        """(17,) float64: the packed row, as ``glshade._glshade.MATERIAL_LAYOUT``."""
        return self._row

    def __repr__(self) -> str:
        f = Light._format
        return (
            f"Material(ambient={f(self.ambient)}, diffuse={f(self.diffuse)}, "
            f"specular={f(self.specular)}, emission={f(self.emission)}, "
            f"shininess={self.shininess:g})"
        )

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Material):
            return NotImplemented
        return np.array_equal(self._row, other._row)

    __hash__ = None  # type: ignore[assignment]


class Scene:
    """Lights, materials and the light model (``glLightModel``) of one lit scene.

    Parameters
    ----------
    lights : Lights, Light, or a sequence of them
        The enabled lights, summed in order. Default: none (emission and global ambient only).
    material : Material, optional
        The front material (default: GL's).
    back_material : Material, optional
        The back material for two-sided lighting (default: the front material).
    global_ambient : (3,) or (4,) float
        ``GL_LIGHT_MODEL_AMBIENT``.
    viewer : (4,) float
        The viewer, homogeneous: ``(0, 0, 1, 0)`` (default) is GL's infinite viewer,
        ``(0, 0, 0, 1)`` GL's local viewer at the eye, any ``(x, y, z, 1)`` a viewer at that point
        (learnopengl's ``viewPos``), any ``(x, y, z, 0)`` a viewer infinitely far that way.
    two_side : bool
        ``GL_LIGHT_MODEL_TWO_SIDE``: `shade` also returns the back colour, lit with the back
        material and the negated normal.
    separate_specular : bool
        ``GL_SEPARATE_SPECULAR_COLOR``: `shade` returns the specular sum as a secondary colour.
    specular : {"blinn", "phong"}
        GL's halfway vector ``(n . h)^s`` or the reflection vector ``(R . V)^s``.
    specular_gate : bool
        GL's ``f_i`` (eq. 2.2, default True): a light adds no specular unless ``n . VP > 0``.
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

    __slots__ = (
        "_global_ambient",
        "_lights",
        "_viewer",
        "back_material",
        "material",
        "separate_specular",
        "specular",
        "specular_gate",
        "two_side",
    )

    def __init__(
        self,
        lights: Lights | Iterable[Lights] = (),
        material: Material | None = None,
        back_material: Material | None = None,
        global_ambient: ArrayLike = (0.2, 0.2, 0.2, 1.0),
        viewer: ArrayLike = (0.0, 0.0, 1.0, 0.0),
        two_side: bool = False,
        separate_specular: bool = False,
        specular: Literal["blinn", "phong"] = "blinn",
        specular_gate: bool = True,
    ) -> None:
        if isinstance(lights, Lights):
            self._lights = lights
        else:
            items = list(lights)
            for i, item in enumerate(items):
                if not isinstance(item, Lights):
                    raise TypeError(f"lights[{i}] must be a Light or Lights, got {type(item)!r}")
            self._lights = Lights.concatenate(items)
        material = Material() if material is None else material
        for name, m in (("material", material), ("back_material", back_material)):
            if m is not None and not isinstance(m, Material):
                raise TypeError(f"{name} must be a Material or None, got {type(m)!r}")
        self.material = material
        self.back_material = material if back_material is None else back_material
        self._global_ambient = _frozen(_rgba(global_ambient, "global_ambient"))
        self._viewer = _frozen(_vector(viewer, "viewer", (4,)))
        if self._viewer.ndim != 1:
            raise ValueError(f"viewer must have shape (4,), got {self._viewer.shape}")
        self.two_side = bool(two_side)
        self.separate_specular = bool(separate_specular)
        if not isinstance(specular, str):
            raise TypeError(f"specular must be 'blinn' or 'phong', got {specular!r}")
        self.specular = specular
        if not isinstance(specular_gate, (bool, np.bool_)):
            raise TypeError(f"specular_gate must be True or False, got {specular_gate!r}")
        self.specular_gate = bool(specular_gate)
        _glshade.check_scene(
            self._lights.table,
            self.material.row,
            self.back_material.row,
            self._global_ambient,
            self._viewer,
            self.specular,
            self.specular_gate,
        )

    @property
    def lights(self) -> Lights:
        """All lights of the scene, as one `Lights`."""
        return self._lights

    @property
    def global_ambient(self) -> Float64Array:
        """(4,) float64 ``GL_LIGHT_MODEL_AMBIENT``."""
        return self._global_ambient

    @property
    def viewer(self) -> Float64Array:
        """(4,) float64 homogeneous viewer."""
        return self._viewer

    @property
    def outputs(self) -> tuple[str, ...]:
        return tuple(_glshade.output_names(self.two_side, self.separate_specular))

    def _native(
        self,
    ) -> tuple[
        Float64Array, Float64Array, Float64Array, Float64Array, Float64Array, bool, bool, str, bool
    ]:
        """The scene as the native functions take it: lights, material, back_material,
        global_ambient, viewer, two_side, separate_specular, specular, specular_gate."""
        return (
            self._lights.table,
            self.material.row,
            self.back_material.row,
            self._global_ambient,
            self._viewer,
            self.two_side,
            self.separate_specular,
            self.specular,
            self.specular_gate,
        )

    def plan(
        self,
        dtype: Any = np.float32,
        *,
        modelview: ArrayLike | None = None,
        normalize: bool = False,
        rescale_normal: bool = False,
        color_material: str | None = None,
        color_material_face: str = "front_and_back",
        accuracy: Literal["fast", "exact"] = "fast",
        strict: bool = False,
    ) -> str:
        """What `shade` computes for this scene, in one line.

        The keywords are those of `shade` (``color_material`` stands for the presence of
        per-vertex colours). The line names the arithmetic and instruction set, whether
        positions are read at all, and for each light which terms are evaluated: a term the
        scene does not need (a zero colour, shininess 0, no attenuation, no spot cone, a
        directional light's constant direction and halfway vector) is left out, with the same
        results bit for bit.

        Examples
        --------
        >>> import glshade as gs
        >>> print(gs.Scene(lights=[gs.Light()]).plan())  # doctest: +ELLIPSIS
        fast: float32 arithmetic, ...; light 0 directional (VP, ĥ constant): diffuse
        """
        name = np.dtype(dtype).name
        if name not in ("float16", "float32", "float64"):
            raise TypeError(f"dtype must be float32 or float64, got {name}")
        return _glshade.describe(
            *self._native(),
            None if modelview is None else matrix(modelview, "modelview"),
            bool(normalize),
            bool(rescale_normal),
            optional_choice(color_material, "color_material"),
            choice(color_material_face, "color_material_face"),
            choice(accuracy, "accuracy"),
            bool(strict),
            "float64" if name == "float64" else "float32",
        )

    def __repr__(self) -> str:
        f = Light._format
        return (
            f"Scene({self._lights!r}, material={self.material!r}, "
            f"global_ambient={f(self._global_ambient)}, viewer={f(self._viewer)}, "
            f"two_side={self.two_side}, separate_specular={self.separate_specular}, "
            f"specular={self.specular!r}, specular_gate={self.specular_gate})"
        )

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Scene):
            return NotImplemented
        return (
            self._lights == other._lights
            and self.material == other.material
            and self.back_material == other.back_material
            and np.array_equal(self._global_ambient, other._global_ambient)
            and np.array_equal(self._viewer, other._viewer)
            and (self.two_side, self.separate_specular, self.specular, self.specular_gate)
            == (other.two_side, other.separate_specular, other.specular, other.specular_gate)
        )

    __hash__ = None  # type: ignore[assignment]
