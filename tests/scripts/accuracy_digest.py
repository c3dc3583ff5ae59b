"""The SHA-256 of `gs.shade` over 3·10⁵ vertices (some NaN) under 20 lights, in both dtypes and
every accuracy: run under different RAYON_NUM_THREADS, it prints the same digest.

Usage: RAYON_NUM_THREADS=N python tests/scripts/accuracy_digest.py
"""

from __future__ import annotations

import hashlib

import numpy as np

import glshade as gs


def main() -> None:
    rng = np.random.default_rng(3)
    n = 300_000
    p = rng.normal(size=(n, 3)) * 3
    nrm = rng.normal(size=(n, 3))
    p[::9973] = np.nan
    lights = gs.Lights(
        position=np.c_[rng.normal(size=(20, 3)) * 4, rng.integers(0, 2, 20)],
        diffuse=rng.uniform(0, 0.2, (20, 3)),
        specular=rng.uniform(0, 0.2, (20, 3)),
        linear_attenuation=rng.uniform(0, 1, 20),
    )
    scene = gs.Scene(
        lights,
        material=gs.Material(specular=(0.5, 0.5, 0.5), shininess=40),
        viewer=(0, 0, 0, 1),
        two_side=True,
    )
    digest = hashlib.sha256()
    for dtype in (np.float32, np.float64):
        for accuracy in ("fast", "exact"):
            rgba = gs.shade(p.astype(dtype), nrm.astype(dtype), scene, accuracy=accuracy)
            digest.update(rgba.tobytes())
    print(digest.hexdigest())


if __name__ == "__main__":
    main()
