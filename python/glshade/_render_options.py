"""The keyword options of `render`, declared once as types: `render`'s overloads take them as
``**options`` (PEP 692), mypy checks that `render`'s own signature, which holds their
defaults, takes every one, and `glsl.render` takes the ones it shares with `render`, with
`render`'s defaults (`shared_defaults`)."""

from __future__ import annotations

import inspect
from collections.abc import Callable, Mapping
from typing import Any, Literal, TypedDict

from numpy.typing import ArrayLike

from ._transfer import Transfer
from ._typing import ColorMaterialMode, Cull, Face, ProvokingVertex, Shading, Space

__all__ = ["RenderOptions", "SharedRenderOptions", "shared_defaults"]


class SharedRenderOptions(TypedDict, total=False):
    """The options of `render` that `glsl.render` takes too."""

    width: int
    height: int
    shading: Shading
    normals: ArrayLike | None
    colors: ArrayLike | Literal[False] | None
    color_material: ColorMaterialMode | None
    color_material_face: Face
    model: ArrayLike | None
    normalize: bool
    rescale_normal: bool
    cull: Cull | None
    background: ArrayLike
    lights_in: Space
    transfer: Transfer | None


class RenderOptions(SharedRenderOptions, total=False):
    """Every keyword option of `render` but `depth`, which picks its result's type."""

    provoking_vertex: ProvokingVertex
    clamp: bool
    texture: Any
    uv: ArrayLike | None
    texture_filter: str
    texture_wrap: str | tuple[str, str]
    point_size: float
    point_shape: str


def shared_defaults(
    render: Callable[..., Any], given: Mapping[str, Any], caller: str
) -> dict[str, Any]:
    """Every option of `SharedRenderOptions`: `given`, else `render`'s default. A name that is
    not one of them is a TypeError naming `caller`, as Python's own for a keyword."""
    names = SharedRenderOptions.__annotations__
    for name in given:
        if name not in names:
            raise TypeError(f"{caller}() got an unexpected keyword argument {name!r}")
    parameters = inspect.signature(render).parameters
    return {name: given.get(name, parameters[name].default) for name in names}
