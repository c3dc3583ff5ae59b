"""The lighting models of glshade's source documents, each one call in that model's own terms.

Each function takes the parameters a document names (``l_a``, ``m_d`` and ``p`` for the
DirectX 11 tutorial; ``ambientStrength``, ``objectColor`` and ``viewPos`` for learnopengl; ``k_a``,
``I_l`` and ``n`` for the lecture's Phong model) and returns a `Preset`: the `Scene` and the
`shade` keywords that make glshade compute exactly that model. Nothing here is a new equation:
each model is GL state (lights, materials, global ambient, viewer, ``specular="phong"``,
``specular_gate``, ``normalize``, ``modelview``), so it runs in the same kernel as everything else.

>>> import numpy as np, glshade as gs
>>> model = gs.presets.learnopengl(light_pos=(1.2, 1.0, 2.0), view_pos=(0.0, 0.0, 3.0))
>>> model.shade(np.zeros((1, 3)), np.array([[0.0, 0.0, 1.0]])).round(4)
array([[0.8884, 0.4442, 0.2754, 1.    ]])
"""

from ._documents import directx11, learnopengl, opengl, phong_illumination
from ._panda3d import panda3d
from ._preset import Preset
from ._pytorch3d import pytorch3d
from ._shader_lights import directx11_lights, learnopengl_lights

__all__ = [
    "Preset",
    "directx11",
    "directx11_lights",
    "learnopengl",
    "learnopengl_lights",
    "opengl",
    "panda3d",
    "phong_illumination",
    "pytorch3d",
]
