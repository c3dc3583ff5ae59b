"""Random arguments to every public function and scene type (GL's, glTF's and three.js'
models, their lights and materials, textures, relief, `Image`, `compare`, `explain`, pyrender
scenes when pyrender is installed): nothing but the documented exceptions (TypeError,
ValueError, IndexError, MemoryError; FileNotFoundError for a string `render` takes as a path).
A `ColorRangeWarning` is a warning, not an outcome.
Prints the number of calls and the outcomes' counts, or "UNEXPECTED ..." and exits 1.

Usage: python tests/scripts/fuzz.py [ROUNDS]  (CALLS calls a round, and `explain` every
EXPLAIN_EVERY rounds; 600 rounds by default)
"""

from __future__ import annotations

import importlib
import os
import sys
import warnings
from collections.abc import Callable
from typing import Any

import numpy as np

import glshade as gs

# FileNotFoundError: `render` reads a string as a file's path.
ALLOWED = (TypeError, ValueError, IndexError, MemoryError, FileNotFoundError)
CALLS = 44  # 43 without pyrender
# explain renders a few dozen times a call: fuzzed every few rounds, on tiny pictures.
EXPLAIN_EVERY = 10


def _pyrender_scene() -> Any:
    """A pyrender scene of one mesh, a light and a camera, or None without pyrender."""
    os.environ.setdefault("PYOPENGL_PLATFORM", "egl")  # headless, as the tests' glpeers
    try:  # by name: pyrender ships no types
        pyrender: Any = importlib.import_module("pyrender")
        trimesh: Any = importlib.import_module("trimesh")
    except Exception:  # pyrender's import can fail in many ways without GL
        return None
    scene = pyrender.Scene(bg_color=(0.1, 0.1, 0.1, 1.0))
    scene.add(pyrender.Mesh.from_trimesh(trimesh.creation.icosphere(1)))
    pose = np.eye(4)
    pose[2, 3] = 3.0
    scene.add(pyrender.PerspectiveCamera(yfov=0.8), pose=pose)
    scene.add(pyrender.DirectionalLight(intensity=2.0), pose=pose)
    return scene


def main(rounds: int) -> None:
    rng = np.random.default_rng(20261201)
    arrays: list[Any] = [
        np.zeros((0, 3)), np.ones((1, 3)), rng.normal(size=(5, 3)), rng.normal(size=(5, 2)),
        rng.normal(size=3), np.float64(2.0), rng.normal(size=(2, 2, 3)), rng.normal(size=(5, 4)),
        np.full((5, 3), np.nan), np.full((5, 3), np.inf), np.full((5, 3), 1e300),
        np.full((5, 3), -0.0), np.full((5, 3), 3e38, np.float32),
        rng.normal(size=(5, 3)).astype(np.float16), rng.normal(size=(5, 3)).astype(">f4"),
        rng.integers(-3, 9, (5, 3)), rng.integers(0, 5, (4, 3)), np.ones((5, 3), bool),
        np.ones((5, 3), complex), np.array([["a"] * 3] * 5),
        np.array([[None] * 3] * 5, dtype=object), np.zeros((5, 3), np.uint64) + 2**63,
        [[0, 0, 1]] * 5, [[0, 0]], "text", None, 7, -1, 2.5, True, (), {}, object(),
    ]  # fmt: skip
    # Valid vertex arrays, weighted up so that most calls get past the intake into the core.
    valid = [a for a in arrays[:15] if isinstance(a, np.ndarray) and a.shape == (5, 3)] * 4
    faces = [rng.integers(0, 5, (4, 3)), rng.integers(0, 5, (9, 3)), np.zeros((0, 3), int)] * 4
    extra: list[Any] = [
        None, True, False, "phong", "flat", "front", 0, 2**64, np.eye(4), np.zeros((4, 4)),
        np.diag([1e300, 1e300, 1e300, 1]), np.diag([1e-300] * 3 + [1]), (1, 2, 3, 4),
    ]  # fmt: skip
    scenes: list[Any] = [
        gs.Scene(),
        gs.Scene(
            lights=[gs.Light(position=(1, 2, 3, 1), spot_cutoff=30)],
            two_side=True,
            separate_specular=True,
        ),
        gs.gltf.Scene(
            [gs.gltf.PointLight(position=(1, 2, 3)), gs.gltf.SpotLight(position=(0, 0, 2))],
            gs.gltf.Material(base_color=(0.8, 0.2, 0.2, 0.5), metallic=0.3, roughness=0.4),
        ),
        gs.threejs.Scene(
            [gs.threejs.PointLight(position=(1, 2, 3), distance=5), gs.threejs.AmbientLight()],
            gs.threejs.MeshPhongMaterial(color=0xFF8800, side="double"),
        ),
        "scene",
        None,
    ]
    pyrender_scene = _pyrender_scene()
    colours: list[Any] = [
        *arrays[:12], (1, 0.5, 0), (200, 80, 40), 0xFF8800, "#ff8800", "#f80", "red", -5,
        2**40, np.array([255, 128, 0], np.uint8), (1, 0.5, 0, 1), np.nan, 1.5,
    ]  # fmt: skip
    numbers: list[Any] = [0, 1, -1, 0.5, 2.5, 1e300, -1e300, np.nan, np.inf, "1", None, True, 90]
    pictures: list[Any] = [
        np.zeros((4, 5, 4)), rng.uniform(size=(4, 5, 3)), np.zeros((0, 0, 4)),
        rng.integers(0, 256, (4, 5, 4)).astype(np.uint8), np.full((4, 5, 4), np.nan),
        rng.uniform(size=(4, 5, 4)) * 255, np.zeros((4, 5, 4), np.uint16) + 65535,
        np.zeros((2, 4, 5, 4)), np.zeros((4, 5)), rng.integers(0, 9, (4, 5, 3)), "picture",
        np.zeros((4, 5, 4), complex), np.zeros((5, 4, 4)),
    ]  # fmt: skip
    grids: list[Any] = [
        rng.normal(size=(6, 7)), np.zeros((1, 7)), np.full((6, 7), np.nan), np.zeros((6, 7, 3)),
        np.ma.masked_array(np.zeros((4, 4)), mask=np.eye(4, dtype=bool)),
        rng.integers(0, 9, (5, 5)), "grid", np.zeros((0, 0)),
    ]  # fmt: skip
    counts: dict[str, int] = {}

    def attempt(name: str, call: Callable[..., object], *args: Any, **kwargs: Any) -> None:
        # The arguments are drawn by the caller, in the order the calls list them.
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", gs.ColorRangeWarning)
                call(*args, **kwargs)
            outcome = "ok"
        except ALLOWED as e:
            outcome = type(e).__name__
        except BaseException as e:
            print("UNEXPECTED", name, type(e).__module__, type(e).__name__, e)
            raise SystemExit(1) from e
        counts[outcome] = counts.get(outcome, 0) + 1

    def pick(pool: list[Any]) -> Any:
        return pool[rng.integers(len(pool))]

    rounds_done = [0]
    for _ in range(rounds):
        a, b = pick([*arrays, *valid]), pick([*arrays, *valid])
        c = pick([*arrays, *valid, *[None] * 20])
        f = pick([*arrays, *faces])
        scene, option = pick(scenes), pick(extra)
        attempt("shade", gs.shade, a, b, scene, colors=c)
        attempt("shade out", gs.shade, a, b, scene, out=pick(arrays))
        attempt("shade modelview", gs.shade, a, b, scene, modelview=option, normalize=True)
        attempt("shade accuracy", gs.shade, a, b, scene, accuracy=pick(["exact", option]))
        attempt("face_normals", gs.face_normals, a, f)
        attempt("vertex_normals", gs.vertex_normals, a, f, weighting=pick(["area", option]))
        attempt("shade_mesh", gs.shade_mesh, a, f, scene=scene)
        attempt("render", gs.render, a, f, scene, gs.Camera(), width=pick([1, 8, option]),
                height=8, shading=pick(["gouraud", "flat", option]))  # fmt: skip
        attempt("Light", gs.Light, position=pick([*arrays, *extra]),
                diffuse=pick([*arrays, *extra]))  # fmt: skip
        attempt("Lights", gs.Lights, spot_cutoff=pick([*arrays, *extra]), count=pick(extra))
        attempt("Material", gs.Material, shininess=pick([*arrays, *extra]), emission=option)
        attempt("Scene", gs.Scene, lights=pick([*arrays, *extra, *scenes]), viewer=pick(arrays),
                two_side=option, global_ambient=pick(arrays))  # fmt: skip
        attempt("Camera", gs.Camera.look_at, pick(arrays), near=option, fovy=pick(extra))
        # Cameras as other libraries give them, and many views in one render.
        attempt("Camera.from_pose", gs.Camera.from_pose, pick([*arrays, *extra]),
                fovy=pick(numbers), far=pick([None, *numbers]))  # fmt: skip
        attempt("Camera.from_opencv", gs.Camera.from_opencv, pick([np.eye(3), *arrays]),
                pick([np.eye(3), *arrays, *extra]), pick(arrays), pick([8, option]), 8,
                near=pick(numbers))  # fmt: skip
        attempt("Camera.orbit", gs.Camera.orbit, pick([1, 3, 0, option]),
                distance=pick(numbers), elevation=pick(numbers), up=pick(arrays))  # fmt: skip
        attempt("render points", gs.render, a, None, pick([None, scene]), gs.Camera(),
                width=8, height=8, normals=pick([None, b]), colors=c,
                point_size=pick([1, 3, *numbers]), point_shape=pick(["round", option]))  # fmt: skip
        views = [gs.Camera(), gs.Camera.look_at((0, 0, 3))]
        attempt("render views", gs.render, a, f, scene, pick([views, [], [gs.Camera(), "x"]]),
                width=8, height=8, lights_in=pick(["world", option]),
                depth=pick([True, False, option]))  # fmt: skip
        # The world models' records: colours (numbers, bytes, hex), numbers, vectors.
        three, gltf = gs.threejs, gs.gltf
        attempt("gltf.Material", gltf.Material, base_color=pick(colours), metallic=pick(numbers),
                roughness=pick(numbers), emissive=pick(colours))  # fmt: skip
        attempt("gltf.PointLight", gltf.PointLight, color=pick(colours),
                intensity=pick(numbers), position=pick([*arrays, *extra]))  # fmt: skip
        attempt("gltf.SpotLight", gltf.SpotLight, color=pick(colours), position=pick(arrays),
                direction=pick(arrays), inner_cone_angle=pick(numbers),
                outer_cone_angle=pick(numbers))  # fmt: skip
        attempt("gltf.Scene", gltf.Scene, pick([*scenes, *arrays, [gltf.PointLight()]]),
                pick([None, gltf.Material(), option]), ambient_light=pick(colours),
                camera_position=pick(arrays))  # fmt: skip
        attempt("threejs.MeshPhongMaterial", three.MeshPhongMaterial, color=pick(colours),
                specular=pick(colours), shininess=pick(numbers), opacity=pick(numbers),
                side=pick(["front", "double", option]))  # fmt: skip
        attempt("threejs.SpotLight", three.SpotLight, color=pick(colours), position=pick(arrays),
                angle=pick(numbers), penumbra=pick(numbers), decay=pick(numbers),
                distance=pick(numbers))  # fmt: skip
        attempt("threejs.HemisphereLight", three.HemisphereLight, sky_color=pick(colours),
                ground_color=pick(colours), position=pick(arrays))  # fmt: skip
        attempt("threejs.Scene", three.Scene, pick([*scenes, three.PointLight(), *arrays]),
                view_direction=pick([None, *arrays]),
                physically_correct_lights=pick([True, option]))  # fmt: skip
        attempt("shade transfer", gs.shade, a, b, scene, transfer=pick(["srgb", option]),
                clamp=pick([False, option]))  # fmt: skip
        # Textures and the other renders: every scene type, pyrender's too.
        attempt("render texture", gs.render, a, f, scene, gs.Camera(), width=8, height=8,
                texture=pick([*pictures, *grids]), uv=pick([*arrays, *valid]),
                texture_filter=pick(["linear", option]))  # fmt: skip
        attempt("render transfer", gs.render, a, f, scene, gs.Camera(), width=8, height=8,
                transfer=pick(["srgb", "gamma2.2", option]), background=pick(colours),
                depth=pick([True, option]))  # fmt: skip
        if pyrender_scene is not None:
            attempt("render pyrender", gs.render, pyrender_scene, width=pick([8, option]),
                    height=8, transfer=pick([None, option]))  # fmt: skip
        # Relief, pictures, comparisons.
        light = gs.relief.LightSource(azdeg=315, altdeg=45)
        attempt("relief.LightSource", gs.relief.LightSource, azdeg=pick(numbers),
                altdeg=pick(numbers), hsv_min_val=pick(numbers))  # fmt: skip
        attempt("relief.hillshade", light.hillshade, pick(grids), vert_exag=pick(numbers),
                dx=pick(numbers), dy=pick(numbers), fraction=pick(numbers))  # fmt: skip
        attempt("relief.shade", light.shade, pick(grids), pick([None, "viridis", option]),
                blend_mode=pick(["hsv", "overlay", "soft", option]))  # fmt: skip
        attempt("relief.shade_rgb", light.shade_rgb, pick(pictures), pick(grids),
                blend_mode=pick(["hsv", option]))  # fmt: skip
        attempt("Image", gs.Image, pick(pictures), display_width=pick([None, 3, option]))
        attempt("compare", gs.compare, pick(pictures), pick(pictures),
                tolerance=pick([None, *numbers]), background=pick([None, *colours]),
                depth=pick([None, *grids]), depth_convention=pick(["window", "linear", option]),
                near=pick([None, *numbers]), far=pick([None, *numbers]))  # fmt: skip
        # The rest of the package: crease normals, area lights, transfer functions, presets,
        # the GLSL generator.
        attempt("crease_normals", gs.crease_normals, a, f, angle=pick(numbers))
        attempt("rectangle_light", gs.rectangle_light, pick(arrays), pick(arrays), pick(arrays),
                pick([1, 4, 0, -1, 10**9, *numbers]), diffuse=pick(colours))  # fmt: skip
        emission = pick(["uniform", "lambertian", option])
        attempt("disc_light", gs.disc_light, pick(arrays), pick(arrays), pick(numbers),
                pick([1, 4, 0, *numbers]), emission=emission)  # fmt: skip
        attempt("srgb_encode", gs.srgb_encode, pick([*arrays, *pictures]))
        attempt("srgb_decode", gs.srgb_decode, pick([*arrays, *pictures]))
        attempt("presets.learnopengl", gs.presets.learnopengl, light_pos=pick(arrays),
                view_pos=pick(arrays), light_color=pick(colours),
                object_color=pick(colours))  # fmt: skip
        attempt("presets.pytorch3d", gs.presets.pytorch3d, location=pick(arrays),
                diffuse_color=pick(colours), shininess=pick(numbers))  # fmt: skip
        attempt("glsl.compute_shader", gs.glsl.compute_shader, pick(scenes),
                modelview=pick([None, option]), normalize=pick([True, option]))  # fmt: skip
        if rounds_done[0] % EXPLAIN_EVERY == 0:
            attempt("explain", gs.explain, pick(pictures), (pick(valid), pick(faces)),
                    pick([None, *scenes]), gs.Camera(), shading=pick(["flat", option]))  # fmt: skip
        rounds_done[0] += 1
    print(sum(counts.values()), sorted(counts.items()), f"pyrender={pyrender_scene is not None}")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 600)
