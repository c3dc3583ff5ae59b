"""glshade: OpenGL fixed-function, Phong and Blinn-Phong lighting over numpy arrays.

>>> import numpy as np, glshade as gs
>>> scene = gs.Scene(lights=[gs.Light(position=(1, 2, 3, 1))], material=gs.Material(shininess=32))
>>> rgba = gs.shade(np.random.rand(1000, 3), np.tile([0, 0, 1.0], (1000, 1)), scene)
>>> rgba.shape
(1000, 4)
"""

from . import glsl, presets
from ._area_lights import disc_light, rectangle_light
from ._camera import Camera
from ._compare import Comparison, compare
from ._glshade import __version__
from ._normals import face_normals, vertex_normals
from ._render import Image, render
from ._scene import Light, Lights, Material, Scene
from ._shade import shade
from ._shade_mesh import shade_mesh
from ._tools.report import Report, report  # last: the tools use the names above

__all__ = [
    "Camera",
    "Comparison",
    "Image",
    "Light",
    "Lights",
    "Material",
    "Report",
    "Scene",
    "__version__",
    "compare",
    "disc_light",
    "face_normals",
    "glsl",
    "presets",
    "rectangle_light",
    "render",
    "report",
    "shade",
    "shade_mesh",
    "vertex_normals",
]
