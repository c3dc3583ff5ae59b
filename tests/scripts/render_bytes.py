"""A 150 x 120 float32 render of a torus in each shading, image and depth, as raw bytes on stdout:
run under different RAYON_NUM_THREADS, it writes the same bytes.

Usage: RAYON_NUM_THREADS=N python tests/scripts/render_bytes.py > out.bin
"""

from __future__ import annotations

import sys

import numpy as np

import glshade as gs
from glshade.meshes import torus


def main() -> None:
    v, f = torus(60, 40)
    cam = gs.Camera.look_at((0, -2.5, 2), (0, 0, 0), (0, 0, 1))
    scene = gs.Scene(lights=[gs.Light(position=(1, 1, 1, 0))], two_side=True)
    for mode in ("flat", "gouraud", "phong"):
        img, z = gs.render(
            v.astype(np.float32), f, scene, cam, width=150, height=120, shading=mode, depth=True
        )
        sys.stdout.buffer.write(img.tobytes() + z.tobytes())


if __name__ == "__main__":
    main()
