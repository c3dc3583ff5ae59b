"""Type stub of the native module. Use the `glshade` package: its intake prepares the arrays."""

from typing import Any, TypeAlias, final

import numpy as np
from numpy.typing import NDArray

__all__ = [
    "MAX_SIZE",
    "GltfScene",
    "Lights",
    "Material",
    "Scene",
    "ThreejsScene",
    "__version__",
    "blend",
    "crease_normals",
    "describe",
    "encode",
    "face_normals",
    "hillshade",
    "look_at",
    "orthographic",
    "perspective",
    "render",
    "render_draws",
    "render_points",
    "shade",
    "shade_normals",
    "stream",
    "vertex_normals",
]

__version__: str
MAX_SIZE: int

@final
class Lights:
    PARAMETERS: list[str]
    DEFAULTS: dict[str, Any]
    def __new__(cls, parameters: list[NDArray[np.float64]], count: int | None = None) -> Lights: ...
    def __len__(self) -> int: ...
    def column(self, name: str) -> NDArray[np.float64]: ...
    def take(self, indices: list[int]) -> Lights: ...
    @staticmethod
    def concatenate(parts: list[Lights]) -> Lights: ...
    def __getnewargs__(self) -> tuple[list[NDArray[np.float64]], int]: ...

@final
class Material:
    PARAMETERS: list[str]
    DEFAULTS: dict[str, Any]
    def __new__(cls, parameters: list[NDArray[np.float64]]) -> Material: ...
    def get(self, name: str) -> Any: ...
    def __getnewargs__(self) -> tuple[list[Any]]: ...

@final
class Scene:
    DEFAULTS: dict[str, Any]
    def __new__(
        cls,
        lights: Lights,
        material: Material,
        *,
        back_material: Material | None,
        global_ambient: tuple[float, float, float, float],
        viewer: tuple[float, ...],
        two_side: bool,
        separate_specular: bool,
        specular: str,
        specular_gate: bool,
    ) -> Scene: ...
    @property
    def outputs(self) -> list[str]: ...
    @property
    def lights(self) -> Lights: ...
    @property
    def material(self) -> Material: ...
    @property
    def back_material(self) -> Material | None: ...
    @property
    def global_ambient(self) -> tuple[float, float, float, float]: ...
    @property
    def viewer(self) -> tuple[float, float, float, float]: ...
    @property
    def two_side(self) -> bool: ...
    @property
    def separate_specular(self) -> bool: ...
    @property
    def specular(self) -> str: ...
    @property
    def specular_gate(self) -> bool: ...
    def __getnewargs_ex__(self) -> tuple[tuple[Lights, Material], dict[str, Any]]: ...

_AnyScene: TypeAlias = Scene | GltfScene | ThreejsScene

def shade(
    positions: NDArray[np.floating[Any]],
    normals: NDArray[np.floating[Any]],
    scene: _AnyScene,
    *,
    colors: NDArray[np.floating[Any]] | None,
    accuracy: str,
    clamp: bool,
    out: NDArray[np.floating[Any]] | None,
    modelview: NDArray[np.float64] | None = None,
    normalize: bool = False,
    rescale_normal: bool = False,
    color_material: str | None = None,
    color_material_face: str = "front_and_back",
    strict: bool = False,
) -> NDArray[np.floating[Any]]: ...
def stream(
    positions: NDArray[np.floating[Any]],
    normals: NDArray[np.floating[Any]],
    read_positions: bool,
) -> NDArray[np.floating[Any]]: ...
def describe(
    scene: _AnyScene,
    *,
    dtype: str,
    accuracy: str,
    clamp: bool,
    modelview: NDArray[np.float64] | None = None,
    normalize: bool = False,
    rescale_normal: bool = False,
    color_material: str | None = None,
    color_material_face: str = "front_and_back",
    strict: bool = False,
) -> str: ...
def face_normals(
    vertices: NDArray[np.floating[Any]], faces: NDArray[np.int64]
) -> NDArray[np.floating[Any]]: ...
def vertex_normals(
    vertices: NDArray[np.floating[Any]], faces: NDArray[np.int64], weighting: str
) -> NDArray[np.floating[Any]]: ...
def look_at(
    eye: tuple[float, float, float],
    target: tuple[float, float, float],
    up: tuple[float, float, float],
) -> NDArray[np.float64]: ...
def perspective(fovy: float, aspect: float, near: float, far: float) -> NDArray[np.float64]: ...
def orthographic(
    left: float, right: float, bottom: float, top: float, near: float, far: float
) -> NDArray[np.float64]: ...
def render(
    vertices: NDArray[np.floating[Any]],
    faces: NDArray[np.int64],
    scene: _AnyScene,
    *,
    view: NDArray[np.float64],
    projection: NDArray[np.float64],
    model: NDArray[np.float64],
    width: int,
    height: int,
    shading: str,
    provoking_vertex: str,
    normals: NDArray[np.floating[Any]] | None,
    colors: NDArray[np.floating[Any]] | None,
    cull: str,
    background: NDArray[np.float64],
    transfer: str,
    clamp: bool,
    texture: NDArray[Any] | None,
    uv: NDArray[np.floating[Any]] | None,
    texture_filter: str,
    texture_wrap: tuple[str, str],
    color_material: str | None = None,
    color_material_face: str = "front_and_back",
    normalize: bool = True,
    rescale_normal: bool = False,
) -> tuple[NDArray[np.floating[Any]], NDArray[np.floating[Any]]]: ...
def render_points(
    vertices: NDArray[np.floating[Any]],
    scene: _AnyScene,
    *,
    view: NDArray[np.float64],
    projection: NDArray[np.float64],
    model: NDArray[np.float64],
    width: int,
    height: int,
    normals: NDArray[np.floating[Any]] | None,
    colors: NDArray[np.floating[Any]] | None,
    point_size: float,
    point_shape: str,
    background: NDArray[np.float64],
    transfer: str,
    clamp: bool,
    color_material: str | None = None,
    color_material_face: str = "front_and_back",
    normalize: bool = True,
    rescale_normal: bool = False,
) -> tuple[NDArray[np.floating[Any]], NDArray[np.floating[Any]]]: ...
def render_draws(
    draws: list[
        tuple[
            NDArray[np.floating[Any]],
            NDArray[np.int64],
            _AnyScene,
            NDArray[np.float64],
            str,
            NDArray[np.floating[Any]] | None,
            NDArray[np.floating[Any]] | None,
            NDArray[Any] | None,
            NDArray[np.floating[Any]] | None,
            str,
            tuple[str, str],
        ]
    ],
    *,
    view: NDArray[np.float64],
    projection: NDArray[np.float64],
    width: int,
    height: int,
    shading: str,
    provoking_vertex: str,
    background: NDArray[np.float64],
    transfer: str,
    clamp: bool,
    placement: str = "model",
) -> tuple[NDArray[np.floating[Any]], NDArray[np.floating[Any]]]: ...

@final
class GltfScene:
    def __new__(
        cls,
        *,
        lights: list[
            tuple[
                str,
                tuple[float, ...],
                float,
                tuple[float, ...],
                tuple[float, ...],
                float,
                float,
            ]
        ],
        base_color: tuple[float, ...],
        metallic: float,
        roughness: float,
        emissive: tuple[float, ...],
        ambient_light: tuple[float, ...],
        camera_position: tuple[float, ...],
    ) -> GltfScene: ...

@final
class ThreejsScene:
    def __new__(
        cls,
        *,
        lights: list[tuple[Any, ...]],
        color: tuple[float, ...],
        specular: tuple[float, ...],
        shininess: float,
        emissive: tuple[float, ...],
        emissive_intensity: float,
        opacity: float,
        side: str,
        camera_position: tuple[float, ...],
        view_direction: tuple[float, ...] | None,
        physically_correct_lights: bool,
    ) -> ThreejsScene: ...

def encode(values: NDArray[np.floating[Any]], transfer: str, *, rgba: bool) -> None: ...
def crease_normals(
    vertices: NDArray[np.floating[Any]],
    faces: NDArray[np.int64],
    weighting: str,
    angle: float,
) -> NDArray[np.floating[Any]]: ...
def hillshade(
    elevation: NDArray[np.float64],
    *,
    vert_exag: float,
    dx: float,
    dy: float,
    direction: tuple[float, ...],
    fraction: float,
) -> NDArray[np.float64]: ...
def shade_normals(
    normals: NDArray[np.float64], *, direction: tuple[float, ...], fraction: float
) -> NDArray[np.float64]: ...
def blend(
    rgb: NDArray[np.float64],
    intensity: NDArray[np.float64],
    *,
    mode: str,
    hsv: tuple[float, ...],
) -> NDArray[np.float64]: ...
