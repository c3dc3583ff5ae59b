"""`glshade.glsl`: the GLSL of a scene, specialised like the CPU kernel, with the values to bind.

For cross-checking a GPU renderer, shader or figure against glshade: the same equation with the
same conventions (0^0 = 1, the specular gate f_i, the spot factor on directional lights,
two-sided lighting, separate specular, colour material, one clamp at the end), as

- `compute_shader`: a GLSL 430 compute shader computing `gs.shade` per vertex;
- `raster_shaders`: a GLSL 330 core vertex + fragment pair drawing flat, Gouraud or Phong
  shading as `gs.render` does;
- each with ``Shaders.uniforms``, the float32 values to bind by uniform name, and
  ``Shaders.library``, the lighting functions alone for shaders of your own.

The source holds only what the scene needs (no attenuation code for lights without it, no cone
for cutoff 180, no power for shininess 0, ...): it depends on which values are zero, so make new
shaders for another scene. With moderngl installed (``pip install moderngl``), `shade`,
`rasterize` and `render` run them on an OpenGL context: Mesa's llvmpipe headless, or a GPU.

Examples
--------
>>> import glshade as gs
>>> scene = gs.Scene(lights=[gs.Light(position=(1, 1, 1, 0))])
>>> shaders = gs.glsl.raster_shaders(scene, "gouraud")
>>> shaders.vertex.splitlines()[0], shaders.types["gs_light0_vp"]
('#version 330 core', 'vec3[1]')
"""

from ._moderngl import Targets, context, rasterize, render, shade
from ._plan import LightGroup, Plan, Side
from ._shaders import Shaders, compute_shader, raster_shaders

__all__ = [
    "LightGroup",
    "Plan",
    "Shaders",
    "Side",
    "Targets",
    "compute_shader",
    "context",
    "raster_shaders",
    "rasterize",
    "render",
    "shade",
]
