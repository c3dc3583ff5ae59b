"""The SHA-256 of every normal of a 10⁵-face grid with scattered faces, both dtypes, every
weighting: run under different RAYON_NUM_THREADS, it prints the same digest.

Usage: RAYON_NUM_THREADS=N python tests/scripts/normals_digest.py
"""

from __future__ import annotations

import hashlib

import numpy as np

import glshade as gs
from glshade.meshes import grid


def main() -> None:
    v, f = grid(100_000)
    f = np.random.default_rng(0).permutation(f)  # scattered faces: long adjacency lists
    digest = hashlib.sha256()
    for vertices in (v, v.astype(np.float32)):
        for weighting in ("angle", "area", "uniform"):
            digest.update(gs.vertex_normals(vertices, f, weighting).tobytes())
        digest.update(gs.face_normals(vertices, f).tobytes())
    print(digest.hexdigest())


if __name__ == "__main__":
    main()
