"""One wheel, every Python: shade, compute normals and render a fixed scene, and either save the
results (``--write FILE``, with the Python that ran the test suite) or check that they are
bit-identical to saved ones (``--check FILE``, with another Python and the same wheel)."""

from __future__ import annotations

import argparse
import sys

import numpy as np

import glshade as gs


def results() -> dict[str, np.ndarray]:
    """Every entry point over one seeded scene, float32 and float64, fast and exact."""
    rng = np.random.default_rng(2026)
    scene = gs.Scene(
        lights=[
            gs.Light(position=(1, 2, 3, 1), quadratic_attenuation=0.1),
            gs.Light(position=(0, 1, 1, 0), spot_direction=(0, -1, -1), spot_cutoff=35),
        ],
        material=gs.Material(specular=(1, 1, 1), shininess=50),
        back_material=gs.Material(diffuse=(0.2, 0.3, 1)),
        viewer=(0, 0, 0, 1),
        two_side=True,
    )
    positions = rng.standard_normal((5000, 3)) + np.array([0, 0, -4.0])
    normals = rng.standard_normal((5000, 3))
    out = {}
    for dtype in (np.float32, np.float64):
        p, n = positions.astype(dtype), normals.astype(dtype)
        for accuracy in ("fast", "exact"):
            out[f"shade-{dtype.__name__}-{accuracy}"] = gs.shade(p, n, scene, accuracy=accuracy)
    vertices = rng.standard_normal((200, 3))
    faces = rng.integers(0, 200, (300, 3))
    out["vertex_normals"] = gs.vertex_normals(vertices, faces)
    out["face_normals"] = gs.face_normals(vertices, faces)
    camera = gs.Camera.look_at((0.5, 1, 6))
    for shading in ("flat", "gouraud", "phong"):
        image = gs.render(vertices, faces, scene, camera, width=64, height=48, shading=shading)
        out[f"render-{shading}"] = np.asarray(image)
    return out


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__)
    mode = parser.add_mutually_exclusive_group(required=True)
    mode.add_argument("--write", metavar="FILE", help="save the results to FILE (.npz)")
    mode.add_argument("--check", metavar="FILE", help="compare the results with FILE (.npz)")
    arguments = parser.parse_args()
    mine = results()
    version = f"Python {sys.version.split()[0]}, glshade {gs.__version__}"
    if arguments.write:
        np.savez(arguments.write, **mine)
        print(f"{version}: wrote {len(mine)} results to {arguments.write}")
        return 0
    saved = np.load(arguments.check)
    differing = [
        k for k in mine if k not in saved or not np.array_equal(mine[k], saved[k], equal_nan=True)
    ]
    if differing or set(saved) != set(mine):
        print(f"{version}: differs from {arguments.check} in {differing or 'its names'}")
        return 1
    print(f"{version}: all {len(mine)} results bit-identical to {arguments.check}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
