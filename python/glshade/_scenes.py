"""The scene types of glshade's models as one type, for annotations: what `shade`, `shade_mesh`
and `render` take. Adding a model adds its scene here."""

from __future__ import annotations

from typing import TypeAlias

from ._scene import Scene
from .gltf import Scene as GltfScene
from .threejs import Scene as ThreejsScene

__all__ = ["AnyScene"]

AnyScene: TypeAlias = Scene | GltfScene | ThreejsScene
"""A `glshade.Scene`, `glshade.gltf.Scene` or `glshade.threejs.Scene`."""
