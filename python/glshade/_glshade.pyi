"""Type stub of the native module. Use the `glshade` package: it coerces the arguments."""

from typing import Any

import numpy as np
from numpy.typing import NDArray

__all__ = [
    "LIGHT_LAYOUT",
    "MATERIAL_LAYOUT",
    "__version__",
    "check_lights",
    "check_material",
    "check_scene",
    "describe",
    "face_normals",
    "look_at",
    "orthographic",
    "output_names",
    "perspective",
    "render",
    "shade",
    "vertex_normals",
]

__version__: str
LIGHT_LAYOUT: list[tuple[str, int]]
MATERIAL_LAYOUT: list[tuple[str, int]]

def check_lights(lights: NDArray[np.float64]) -> None: ...
def check_material(material: NDArray[np.float64], name: str) -> None: ...
def check_scene(
    lights: NDArray[np.float64],
    material: NDArray[np.float64],
    back_material: NDArray[np.float64],
    global_ambient: NDArray[np.float64],
    viewer: NDArray[np.float64],
    specular: str,
    specular_gate: bool,
) -> None: ...
def output_names(two_side: bool, separate_specular: bool) -> list[str]: ...
def shade(
    positions: NDArray[np.floating[Any]],
    normals: NDArray[np.floating[Any]],
    lights: NDArray[np.float64],
    material: NDArray[np.float64],
    back_material: NDArray[np.float64],
    global_ambient: NDArray[np.float64],
    viewer: NDArray[np.float64],
    two_side: bool,
    separate_specular: bool,
    specular: str,
    specular_gate: bool,
    modelview: NDArray[np.float64] | None,
    normalize: bool,
    rescale_normal: bool,
    colors: NDArray[np.floating[Any]] | None,
    color_material: str | None,
    color_material_face: str,
    accuracy: str,
    strict: bool,
    out: NDArray[np.floating[Any]] | None,
) -> NDArray[np.floating[Any]]: ...
def describe(
    lights: NDArray[np.float64],
    material: NDArray[np.float64],
    back_material: NDArray[np.float64],
    global_ambient: NDArray[np.float64],
    viewer: NDArray[np.float64],
    two_side: bool,
    separate_specular: bool,
    specular: str,
    specular_gate: bool,
    modelview: NDArray[np.float64] | None,
    normalize: bool,
    rescale_normal: bool,
    color_material: str | None,
    color_material_face: str,
    accuracy: str,
    strict: bool,
    dtype: str,
) -> str: ...
def face_normals(
    vertices: NDArray[np.floating[Any]], faces: NDArray[np.int64]
) -> NDArray[np.floating[Any]]: ...
def vertex_normals(
    vertices: NDArray[np.floating[Any]], faces: NDArray[np.int64], weighting: str
) -> NDArray[np.floating[Any]]: ...
def look_at(
    eye: NDArray[np.float64], target: NDArray[np.float64], up: NDArray[np.float64]
) -> NDArray[np.float64]: ...
def perspective(fovy: float, aspect: float, near: float, far: float) -> NDArray[np.float64]: ...
def orthographic(
    left: float, right: float, bottom: float, top: float, near: float, far: float
) -> NDArray[np.float64]: ...
def render(
    vertices: NDArray[np.floating[Any]],
    faces: NDArray[np.int64],
    lights: NDArray[np.float64],
    material: NDArray[np.float64],
    back_material: NDArray[np.float64],
    global_ambient: NDArray[np.float64],
    viewer: NDArray[np.float64],
    two_side: bool,
    separate_specular: bool,
    specular: str,
    specular_gate: bool,
    view: NDArray[np.float64],
    projection: NDArray[np.float64],
    model: NDArray[np.float64],
    width: int,
    height: int,
    shading: str,
    normals: NDArray[np.floating[Any]] | None,
    colors: NDArray[np.floating[Any]] | None,
    color_material: str | None,
    color_material_face: str,
    normalize: bool,
    rescale_normal: bool,
    cull: str,
    background: NDArray[np.float64],
) -> tuple[NDArray[np.floating[Any]], NDArray[np.floating[Any]]]: ...
