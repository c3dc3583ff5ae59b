"""Equality by value and pickling for the frozen records that hold arrays and read-only
mappings (`presets.Preset`, `Comparison`, `glsl.Shaders`, `glsl.Targets`)."""

from __future__ import annotations

import dataclasses
from collections.abc import Mapping
from types import MappingProxyType
from typing import Any

import numpy as np

__all__ = ["ValueRecord", "same", "set_field"]


def same(a: Any, b: Any) -> bool:
    """Equal by value: arrays element by element (shape and dtype kind too, NaN equal to NaN),
    mappings by keys and values, lists and tuples item by item, anything else by ``==``."""
    if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        x, y = np.asarray(a), np.asarray(b)
        if x.shape != y.shape or x.dtype.kind != y.dtype.kind:
            return False
        return bool(np.array_equal(x, y, equal_nan=x.dtype.kind in "fc"))
    if isinstance(a, Mapping) and isinstance(b, Mapping):
        return a.keys() == b.keys() and all(same(a[k], b[k]) for k in a)
    if isinstance(a, (list, tuple)) and isinstance(b, (list, tuple)):
        return type(a) is type(b) and len(a) == len(b) and all(map(same, a, b))
    return bool(a == b)


def set_field(record: Any, name: str, value: Any) -> None:
    """Stores a field of a frozen dataclass from its ``__init__`` (normalised values)."""
    object.__setattr__(record, name, value)


def _plain(value: Any) -> Any:
    """A read-only mapping as a dict, which pickles; anything else as it is."""
    return dict(value) if isinstance(value, MappingProxyType) else value


class ValueRecord:
    """For dataclasses (``eq=False``): equal when of one type with fields equal by `same`, and
    pickled through their constructor, read-only mappings as dicts (``__post_init__`` makes
    them read-only again where a record wants that)."""

    def __eq__(self, other: object) -> bool:
        if type(other) is not type(self):
            return NotImplemented
        return all(
            same(getattr(self, f.name), getattr(other, f.name))
            for f in dataclasses.fields(self)  # type: ignore[arg-type]
        )

    __hash__ = None  # type: ignore[assignment]  # equal by value, holding arrays

    def __reduce__(self) -> tuple[Any, tuple[Any, ...]]:
        fields = dataclasses.fields(self)  # type: ignore[arg-type]
        return (type(self), tuple(_plain(getattr(self, f.name)) for f in fields))
