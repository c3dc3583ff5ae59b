"""The one dispatch on a scene's shading model.

Every scene type is a `Model`: `glshade.Scene` (GL's fixed-function equation),
`glshade.gltf.Scene` (glTF's metallic-roughness model) and `glshade.threejs.Scene` (three.js'
``MeshPhongMaterial``). A scene holds its native scene, which the binding's one `shade`,
`describe` and `render` take whatever the model, and answers for itself what differs between
the models: which of GL's options it takes, the scene a render lights with, the faces a
render culls by default. `shade`, `shade_mesh`, `render` and `dask` ask the scene and never
test its type; `glsl`, which writes GL's equation alone, refuses the others, and `explain`
converts a scene from one model to another (`_model_conversion`).

The names of each model, in Python, in the binding and in the Rust crate (its state and its
model)::

    glshade.Scene          _glshade.Scene         gl / fixed_function
    glshade.gltf.Scene     _glshade.GltfScene     gltf / metallic_roughness
    glshade.threejs.Scene  _glshade.ThreejsScene  threejs / mesh_phong
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from numpy.typing import ArrayLike

__all__ = ["SCENES", "Model", "at_default", "is_scene"]

SCENES = "a glshade.Scene, glshade.gltf.Scene or glshade.threejs.Scene"
"""The scene types, as error messages name them."""


class Model:
    """The base of every model's scene type: what `shade`, `render` and the rest ask of a
    scene, whatever its model."""

    __slots__ = ()

    _native: Any
    """The native scene (``_glshade.Scene``, ``GltfScene`` or ``ThreejsScene``)."""

    @property
    def outputs(self) -> tuple[str, ...]:
        """The names of the colours `shade` returns, in the order of its leading axis."""
        raise NotImplementedError

    def _gl_options(self, given: Mapping[str, tuple[Any, Any]], *, colors: bool) -> dict[str, Any]:
        """GL's options of a call as the binding takes them: `given` maps each option's name
        to its value and the calling function's default; `colors` says whether the call has
        vertex colours. A scene of another model refuses any option not at its default
        (TypeError) and returns none."""
        raise NotImplementedError

    def _lit_scene(self, view: ArrayLike, lights_in: str) -> Model:
        """The scene a render with this `view` lights with, its lights given in `lights_in`
        coordinates ("eye" or "world")."""
        raise NotImplementedError

    def _default_cull(self) -> str | None:
        """The faces a render culls when the call names none: none (GL's default)."""
        return None


def is_scene(obj: object) -> bool:
    """A scene of one of glshade's models."""
    return isinstance(obj, Model)


def at_default(value: Any, default: Any) -> bool:
    """`value` is the calling function's `default`: the same object, or an equal bool or
    name."""
    return value is default or (isinstance(value, (bool, str)) and value == default)
