"""What the scenes of the world models share: `glshade.gltf.Scene` and `glshade.threejs.Scene`
hold lights and one material in world coordinates, take none of GL's options, are lit by
`render` as they are, and compare, print and pickle by their constructor's keywords."""

from __future__ import annotations

import dataclasses
from collections.abc import Callable, Iterable, Mapping
from typing import Any, ClassVar, Generic, TypeVar, cast

import numpy as np

from . import _glshade
from ._intake import accuracy_choice, number, vector, warn_if_bytes
from ._model import Model, at_default
from ._records import set_field
from ._typing import Accuracy, Float64Array

__all__ = ["Color", "WorldScene", "record_fields", "set_fields"]

Color = tuple[float, ...]
"""The annotation of a colour field of a light or material: `set_fields` converts it by the
model's colour rule and warns when it looks like 0-255 bytes."""

LightT = TypeVar("LightT")
MaterialT = TypeVar("MaterialT")


class WorldScene(Model, Generic[LightT, MaterialT]):
    """A scene of a model in world coordinates: its lights (instances of `_LIGHTS`), its
    material (a `_MATERIAL`), the camera, what else its model reads (`_model_fields`) and its
    native scene."""

    __slots__ = ("_camera_position", "_lights", "_material", "_native")

    _lights: tuple[LightT, ...]
    _material: MaterialT
    _camera_position: tuple[float, ...]

    _LIGHTS: ClassVar[tuple[type, ...]]
    """The light types the model takes."""
    _MATERIAL: ClassVar[type[Any]]
    """The material type, whose defaults are the model's default material."""

    def _take(self, lights: Iterable[LightT] | LightT, material: MaterialT | None) -> None:
        """Stores `lights` (one light, or an iterable of them) and `material` (None: the
        default one), checked: a TypeError names the first of another type."""
        module = self._module()
        try:
            # One light, as `glshade.Scene` takes it, or an iterable of them.
            self._lights = (
                (cast(LightT, lights),)
                if isinstance(lights, self._LIGHTS)
                else tuple(cast(Iterable[LightT], lights))
            )
        except TypeError:
            raise TypeError(
                f"lights must be a glshade.{module} light or an iterable of them (a list), got "
                f"{type(lights)!r}"
            ) from None
        for i, light in enumerate(self._lights):
            if not isinstance(light, self._LIGHTS):
                names = [kind.__name__ for kind in self._LIGHTS]
                raise TypeError(
                    f"lights[{i}] must be a glshade.{module} {', '.join(names[:-1])} or "
                    f"{names[-1]}, got {type(light)!r}"
                )
        if material is None:
            material = self._MATERIAL()
        if not isinstance(material, self._MATERIAL):
            raise TypeError(
                f"material must be a glshade.{module}.{self._MATERIAL.__name__}, got "
                f"{type(material)!r}"
            )
        self._material = material

    @classmethod
    def _module(cls) -> str:
        """The model's module under glshade: ``gltf`` or ``threejs``."""
        return cls.__module__.rsplit(".", 1)[-1]

    def _fields(self) -> dict[str, Any]:
        """The scene as its constructor's keywords."""
        return {"lights": self._lights, "material": self._material, **self._model_fields()}

    def _model_fields(self) -> dict[str, Any]:
        """The constructor's keywords for what the model reads besides lights and material."""
        raise NotImplementedError

    @property
    def lights(self) -> tuple[LightT, ...]:
        """The lights, as given (each model sums them in its order)."""
        return self._lights

    @property
    def material(self) -> MaterialT:
        """The material."""
        return self._material

    @property
    def camera_position(self) -> Float64Array:
        """(3,) Where the camera is: the view vector points there."""
        return np.array(self._camera_position)

    @property
    def outputs(self) -> tuple[str, ...]:
        """The names of the colours `shade` returns: one, linear RGBA."""
        return ("color",)

    def plan(
        self, dtype: Any = np.float32, *, accuracy: Accuracy = "fast", clamp: bool = True
    ) -> str:
        """One line saying what `glshade.shade` computes for this scene with arrays of `dtype`:
        the accuracy, the arithmetic (float32 or float64; "float32 arrays widened" for exact
        accuracy on float32 arrays), the instruction set, the lanes per block, and which lights
        and terms run (a light of zero intensity or colour is skipped, so is a term the
        material cannot have, and positions are read only where a light or the camera needs
        them).
        """
        name = np.dtype(dtype).name
        if name not in ("float32", "float64"):
            raise ValueError(f"dtype must be float32 or float64, got {name}")
        mode = accuracy_choice(accuracy)
        return str(_glshade.describe(self._native, dtype=name, accuracy=mode, clamp=clamp))

    def _gl_options(self, given: Mapping[str, tuple[Any, Any]], *, colors: bool) -> dict[str, Any]:
        for name, (value, default) in given.items():
            if not at_default(value, default):
                raise TypeError(
                    f"{name} applies to the GL model (glshade.Scene), not to a "
                    f"glshade.{self._module()}.Scene (normals are always normalised, positions "
                    f"are in world coordinates and vertex colours multiply a colour of the "
                    f"model), got {name}={value!r}"
                )
        return {}

    def _lit_scene(self, view: Any, lights_in: str) -> WorldScene[LightT, MaterialT]:
        # In world coordinates always; the native render puts the camera at the view's eye.
        return self

    def __repr__(self) -> str:
        fields = self._fields()
        fields["lights"] = list(fields["lights"])
        shown = ", ".join(f"{k}={v!r}" for k, v in fields.items() if v is not None)
        return f"{self._module()}.Scene({shown})"

    def __eq__(self, other: object) -> bool:
        if type(other) is not type(self):
            return NotImplemented
        return self._fields() == other._fields()

    __hash__ = None  # type: ignore[assignment]

    def __reduce__(self) -> tuple[Any, ...]:
        return (_rebuilt, (type(self), self._fields()))


def _rebuilt(kind: type[WorldScene[Any, Any]], fields: dict[str, Any]) -> WorldScene[Any, Any]:
    """A pickled scene, rebuilt by its constructor."""
    return kind(**fields)


def record_fields(record: Any) -> dict[str, Any]:
    """A record's fields (a material's) by name: the keywords of its model's native scene."""
    return {f.name: getattr(record, f.name) for f in dataclasses.fields(record)}


def set_fields(
    record: Any,
    arguments: Mapping[str, Any],
    color: Callable[[Any, str], tuple[float, ...]] = vector,
) -> None:
    """Stores the fields of a light or material of a world model from its constructor's
    `arguments` (its ``locals()``), in the order of the fields, each converted by its
    annotation: ``tuple[float, ...]`` by `vector` (a 3-vector of numbers), `Color` by `color`
    (the model's colour rule; then `warn_if_bytes` under the record's name), ``float`` by
    `number`. A field of another type is the constructor's to store."""
    convert: dict[object, Callable[[Any, str], Any]] = {
        "tuple[float, ...]": vector,
        "Color": color,
        "float": number,
    }
    for field in dataclasses.fields(record):
        if field.type in convert:
            set_field(record, field.name, convert[field.type](arguments[field.name], field.name))
    owner = f"{type(record).__module__.rsplit('.', 1)[-1]}.{type(record).__name__}"
    for field in dataclasses.fields(record):
        if field.type == "Color":
            warn_if_bytes(np.array(getattr(record, field.name)), field.name, owner)
