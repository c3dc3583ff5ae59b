"""The type aliases that more than one module of glshade uses: arrays and the names of options."""

from __future__ import annotations

from typing import Any, Literal

import numpy as np
from numpy.typing import NDArray

__all__ = [
    "Accuracy",
    "ColorMaterialMode",
    "Cull",
    "Face",
    "Float64Array",
    "FloatArray",
    "Per",
    "Shading",
    "Space",
    "Weighting",
]

FloatArray = NDArray[np.floating[Any]]
Float64Array = NDArray[np.float64]

# "display" is the removed display tier's name, a deprecated alias of "fast" (it warns): kept
# here so that code which passes it still type-checks until the name goes.
Accuracy = Literal["fast", "exact", "display"]
ColorMaterialMode = Literal["ambient", "diffuse", "specular", "emission", "ambient_and_diffuse"]
Cull = Literal["back", "front", "front_and_back"]
# GL_FRONT, GL_BACK, GL_FRONT_AND_BACK: the material(s) a colour material replaces.
Face = Literal["front", "back", "front_and_back"]
# Where a mesh's colours (or normals) belong.
Per = Literal["vertex", "face"]
Shading = Literal["phong", "gouraud", "flat"]
# Where flat shading lights a face (glProvokingVertex, or the centroid).
ProvokingVertex = Literal["last", "first", "centroid"]
# The coordinates lights are given in.
Space = Literal["eye", "world"]
Weighting = Literal["angle", "area", "uniform"]
