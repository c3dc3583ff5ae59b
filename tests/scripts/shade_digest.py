"""The SHA-256 of `gs.shade` over 5·10⁴ random vertices under six spot lights, two-sided, with
normalize: run under different RAYON_NUM_THREADS, it prints the same digest.

Usage: RAYON_NUM_THREADS=N python tests/scripts/shade_digest.py
"""

from __future__ import annotations

import hashlib

import numpy as np

import glshade as gs


def main() -> None:
    rng = np.random.default_rng(3)
    p = rng.uniform(-1, 1, (50_000, 3)).astype(np.float32)
    n = rng.normal(size=(50_000, 3)).astype(np.float32)
    pos = np.c_[rng.normal(size=(6, 3)), np.ones(6)]
    lights = gs.Lights(position=pos, spot_cutoff=60, linear_attenuation=0.2)
    material = gs.Material(specular=(1, 1, 1), shininess=50)
    scene = gs.Scene(lights=lights, material=material, two_side=True)
    print(hashlib.sha256(gs.shade(p, n, scene, normalize=True).tobytes()).hexdigest())


if __name__ == "__main__":
    main()
