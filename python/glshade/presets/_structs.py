"""Shader structs given as mappings from member names to values, checked member by member so
that an error names the struct and member the user wrote (``spot_light["cutOff"]``)."""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from typing import Any, Literal

from .._params import rgb, scalar, vector3
from .._typing import Float64Array

# What a struct member holds: a colour, a 3-vector, a nonzero direction, or a number.
Kind = Literal["rgb", "rgba", "vector", "direction", "number"]


def struct(value: Any, name: str, members: Mapping[str, Kind]) -> dict[str, Any]:
    """`value`'s members checked by kind, each named ``name["member"]`` in errors."""
    if not isinstance(value, Mapping):
        raise TypeError(
            f"{name} must be a mapping of its struct's members ({', '.join(members)}), "
            f"got {type(value).__name__}"
        )
    missing = [m for m in members if m not in value]
    unknown = [m for m in value if m not in members]
    if missing or unknown:
        found = "; ".join(
            f"{what} {names}"
            for what, names in (("missing", missing), ("unknown", unknown))
            if names
        )
        raise TypeError(f"{name} must have exactly the members {list(members)}: {found}")
    out: dict[str, Any] = {}
    for member, kind in members.items():
        label = f'{name}["{member}"]'
        item = value[member]
        if kind in ("rgb", "rgba"):
            out[member] = rgb(item, label, alpha=kind == "rgba")
        elif kind == "number":
            out[member] = scalar(item, label)
        else:
            out[member] = vector3(item, label, nonzero=kind == "direction")
    return out


def structs(values: Iterable[Any], name: str, members: Mapping[str, Kind]) -> list[dict[str, Any]]:
    if isinstance(values, Mapping):
        raise TypeError(f"{name} must be a sequence of structs (mappings), got one mapping")
    return [struct(v, f"{name}[{i}]", members) for i, v in enumerate(values)]


def attenuation(k: Float64Array, names: tuple[str, str, str], owner: str) -> dict[str, float]:
    """GL's k0, k1, k2 as `Light`'s keywords, from a shader's three coefficients `k` (named
    `names` in `owner`): each >= 0 (GL refuses negative ones), not all 0."""
    if (k < 0).any() or not k.any():
        given = ", ".join(f"{n}={x:g}" for n, x in zip(names, k, strict=True))
        raise ValueError(f"{owner}'s {', '.join(names)} must be >= 0, not all 0, got {given}")
    return {
        "constant_attenuation": float(k[0]),
        "linear_attenuation": float(k[1]),
        "quadratic_attenuation": float(k[2]),
    }


def colors_of(
    structs: list[dict[str, Any]], name: str, members: Iterable[str], *, single: bool = False
) -> dict[str, Any]:
    """The structs' colours by their user names (``name[i]["member"]``, or ``name["member"]``
    for the one struct of a `single` argument), for `warn_bytes`."""
    return {
        f'{name if single else f"{name}[{i}]"}["{m}"]': s[m]
        for i, s in enumerate(structs)
        for m in members
    }
