"""glshade: OpenGL fixed-function, Phong and Blinn-Phong lighting over numpy arrays.

>>> import numpy as np, glshade as gs
>>> scene = gs.Scene(lights=[gs.Light(position=(1, 2, 3, 1))], material=gs.Material(shininess=32))
>>> rgba = gs.shade(np.random.rand(1000, 3), np.tile([0, 0, 1.0], (1000, 1)), scene)
>>> rgba.shape
(1000, 4)
"""

from typing import TYPE_CHECKING, Any

from . import glsl, gltf, meshes, presets, relief, threejs
from ._area_lights import disc_light, rectangle_light
from ._camera import Camera
from ._compare import Comparison, compare
from ._explain import Explanation, explain
from ._glshade import __version__
from ._image import Image
from ._intake import ColorRangeWarning
from ._normals import crease_normals, face_normals, vertex_normals
from ._render import render
from ._scene import Light, Lights, Material, Scene
from ._shade import shade
from ._shade_mesh import shade_mesh
from ._transfer import srgb_decode, srgb_encode

if TYPE_CHECKING:
    from .lab.report import Report, report

__all__ = [
    "Camera",
    "ColorRangeWarning",
    "Comparison",
    "Explanation",
    "Image",
    "Light",
    "Lights",
    "Material",
    "Report",
    "Scene",
    "__version__",
    "compare",
    "crease_normals",
    "disc_light",
    "explain",
    "face_normals",
    "glsl",
    "gltf",
    "meshes",
    "presets",
    "rectangle_light",
    "relief",
    "render",
    "report",
    "shade",
    "shade_mesh",
    "srgb_decode",
    "srgb_encode",
    "threejs",
    "vertex_normals",
]


def __getattr__(name: str) -> Any:
    """`report` and `Report` from the lab, imported on first use: `import glshade` leaves the
    lab (bench, report and demo code, matplotlib's figures) unimported."""
    if name in ("report", "Report"):
        # The package's one runtime import of the lab, on first use: the lab is its client.
        from .lab import report as lab_report

        return getattr(lab_report, name)
    raise AttributeError(f"module 'glshade' has no attribute {name!r}")


def __dir__() -> list[str]:
    """The module's names with the two the lab gives on first use, so completion offers them."""
    return sorted({*globals(), "report", "Report"})
