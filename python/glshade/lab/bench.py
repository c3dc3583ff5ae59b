"""Benchmarks run beside their baselines in the same process: ``python -m glshade bench ...``.

Timings are medians of rounds (`timing.time_rounds`), quoted with the ratio to the baseline
measured in the same round; the machine's other load affects both sides alike. Each bench saves
its results as JSON with the machine description (`save`).
"""

from __future__ import annotations

import functools
import json
import os
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import NDArray

import glshade as gs

from ..meshes import grid
from .machine import describe, machine
from .timing import Timing, ratio, time_rounds


def numpy_area_normals(v: NDArray[np.float64], f: NDArray[np.int64]) -> NDArray[np.float64]:
    """The textbook numpy implementation: scatter-add the cross products, normalise."""
    cross = np.cross(v[f[:, 1]] - v[f[:, 0]], v[f[:, 2]] - v[f[:, 0]])
    summed = np.zeros_like(v)
    for corner in range(3):
        np.add.at(summed, f[:, corner], cross)
    length = np.linalg.norm(summed, axis=1, keepdims=True)
    unit: NDArray[np.float64] = np.divide(
        summed, length, out=np.zeros_like(summed), where=length > 0
    )
    return unit


def save(path: str | Path | None, bench: str, settings: dict[str, Any], results: Any) -> None:
    """Writes a bench's results as JSON at `path` (None: nowhere) with the machine description:
    ``{"bench", "machine", "settings", "results"}``, and says where."""
    if path is None:
        return
    data = {"bench": bench, "machine": machine(), "settings": settings, "results": results}
    target = Path(path)
    target.parent.mkdir(parents=True, exist_ok=True)
    target.write_text(json.dumps(data, indent=2) + "\n")
    print(f"\nwrote {target}")


def bench_normals(
    faces: int, repeat: int, settle: float = 0.25, json_path: str | None = None
) -> int:
    """Prints (and saves at `json_path`) the median time of glshade's normals, a numpy
    scatter-add and trimesh's on a mesh of about `faces` faces, with the per-round speed-ups."""
    v, f = grid(faces)
    v32 = v.astype(np.float32)
    methods: dict[str, Callable[[], Any]] = {
        "glshade vertex_normals angle, float64": lambda: gs.vertex_normals(v, f),
        "glshade vertex_normals angle, float32": lambda: gs.vertex_normals(v32, f),
        "glshade vertex_normals area, float64": lambda: gs.vertex_normals(v, f, "area"),
        "glshade vertex_normals uniform, float64": lambda: gs.vertex_normals(v, f, "uniform"),
        "glshade face_normals, float64": lambda: gs.face_normals(v, f),
        "numpy area-weighted (np.add.at)": lambda: numpy_area_normals(v, f),
    }
    try:
        import trimesh
    except ImportError:
        trimesh = None  # type: ignore[assignment]
    if trimesh is not None:
        # A fresh mesh per call: trimesh caches its normals on the object.
        methods["trimesh vertex_normals"] = lambda: (
            trimesh.Trimesh(v, f, process=False).vertex_normals
        )
        methods["trimesh face_normals"] = lambda: trimesh.Trimesh(v, f, process=False).face_normals
    print(describe(machine()))
    print(f"{len(f):,} faces, {len(v):,} vertices (a jittered height field, float64, int64)")
    print(f"{repeat} rounds, each method once per round in rotating order, {settle} s apart")
    if trimesh is not None:
        print(
            f"trimesh {trimesh.__version__}: trimesh.Trimesh(v, f, process=False).vertex_normals "
            "(and .face_normals) on a fresh mesh per call, so nothing is cached"
        )
    times = time_rounds(methods, repeat, settle=settle)
    print(f"\n  {'method':42} {'median':>10}")
    for name, t in times.items():
        print(f"  {name:42} {t.median * 1e3:7.1f} ms")
    settings = {"faces": len(f), "vertices": len(v), "rounds": repeat, "settle_s": settle}
    results: dict[str, Any] = {"ms": {k: t.as_dict(1e3) for k, t in times.items()}}
    if trimesh is None:
        print("\ntrimesh is not installed (pip install trimesh scipy): no trimesh baseline")
        save(json_path, "normals", settings, results)
        return 0
    reference = trimesh.Trimesh(v, f, process=False).vertex_normals
    difference = np.abs(gs.vertex_normals(v, f) - reference).max()
    print(f"\nmax |glshade - trimesh|, angle weighting, float64: {difference:.1e}")
    print("\nspeed-up over trimesh, per round (median, and the range over the rounds):")
    pairs = [
        (
            "vertex normals, angle, float64",
            "trimesh vertex_normals",
            "glshade vertex_normals angle, float64",
        ),
        (
            "vertex normals, angle, float32",
            "trimesh vertex_normals",
            "glshade vertex_normals angle, float32",
        ),
        ("face normals, float64", "trimesh face_normals", "glshade face_normals, float64"),
    ]
    speedups: dict[str, Timing] = {}
    for label, baseline, ours in pairs:
        speedups[label] = r = ratio(times[baseline], times[ours])
        print(f"  {label:42} {r.median:6.1f}x   ({r.low:.1f}x to {r.high:.1f}x)")
    results["max_difference_from_trimesh"] = float(difference)
    results["speedup_over_trimesh"] = {k: r.as_dict() for k, r in speedups.items()}
    save(json_path, "normals", settings, results)
    return 0


def _llvmpipe() -> Any:
    """glshade.glsl's moderngl context on Mesa's llvmpipe (``LIBGL_ALWAYS_SOFTWARE=1`` unless
    set otherwise), or None with the reason printed."""
    os.environ.setdefault("LIBGL_ALWAYS_SOFTWARE", "1")
    try:
        return gs.glsl.context()
    except (ImportError, RuntimeError) as exc:
        print(f"{exc}: no llvmpipe baseline")
        return None


class LlvmpipeRenderer:
    """The baseline: the same mesh drawn by Mesa's llvmpipe through moderngl, with
    `glshade.glsl`'s raster shaders of the scene (per fragment for Phong, per vertex otherwise)
    into an RGBA32F target.

    Programs, buffers and the framebuffer are made once; each call uploads the vertices, clears,
    draws and reads the image back into numpy (row 0 at the top), as `gs.render` returns it.
    """

    def __init__(
        self,
        ctx: Any,
        mesh: tuple[NDArray[np.float64], NDArray[np.int64]],
        shading: str,
        scene: gs.Scene,
        camera: gs.Camera,
        size: int,
    ) -> None:
        import moderngl

        self.ctx = ctx
        v, f = mesh
        view, normal_matrix = camera.view, np.linalg.inv(camera.view[:3, :3]).T
        eye = v @ view[:3, :3].T + view[:3, 3]
        if shading == "flat":
            normals = np.repeat(gs.face_normals(v, f) @ normal_matrix.T, 3, axis=0)
            eye, f = eye[f].reshape(-1, 3), np.arange(3 * len(f)).reshape(-1, 3)
        else:
            normals = gs.vertex_normals(v, f) @ normal_matrix.T
        self.vertices = np.ones((len(eye), 6), np.float32)
        self.vertices[:, :3], self.vertices[:, 3:6] = eye, normals
        shaders = gs.glsl.raster_shaders(scene, shading, normalize=True)  # type: ignore[arg-type]
        program = self.ctx.program(**shaders.sources)
        shaders.bind(program)
        projection = camera.projection_matrix(size, size)
        program["gs_projection"].write(projection.T.astype(np.float32).tobytes())
        self.vbo = self.ctx.buffer(reserve=self.vertices.nbytes)
        ibo = self.ctx.buffer(np.ascontiguousarray(f, np.uint32).tobytes())
        self.vao = self.ctx.vertex_array(
            program,
            [(self.vbo, "3f 3f", "gs_position", "gs_normal")],
            index_buffer=ibo,
            index_element_size=4,
            skip_errors=True,
        )
        self.texture = self.ctx.texture((size, size), 4, dtype="f4")
        depth = self.ctx.depth_texture((size, size))
        self.fbo = self.ctx.framebuffer(color_attachments=[self.texture], depth_attachment=depth)
        self.size = size
        self.moderngl = moderngl

    def __call__(self) -> NDArray[np.float32]:
        self.ctx.__enter__()
        self.vbo.write(self.vertices.tobytes())
        self.fbo.use()
        self.ctx.enable_only(self.moderngl.DEPTH_TEST)
        self.ctx.provoking_vertex = self.moderngl.LAST_VERTEX_CONVENTION
        self.fbo.clear(0.0, 0.0, 0.0, 0.0, depth=1.0)
        self.vao.render(self.moderngl.TRIANGLES)
        image = np.frombuffer(self.texture.read(), np.float32)
        return image.reshape(self.size, self.size, 4)[::-1]


RENDER_PARTS = ("torus", "pyrender", "texture")


def bench_render(
    faces: int,
    size: int,
    repeat: int,
    json_path: str | None = None,
    parts: tuple[str, ...] = RENDER_PARTS,
) -> int:
    """Prints (and saves at `json_path`) each part of the render bench: a torus beside
    moderngl on Mesa's llvmpipe (``torus``), pyrender scenes beside pyrender's own renderer
    (``pyrender``), and a small render with textures of growing size (``texture``)."""
    print(describe(machine()))
    results: dict[str, Any] = {}
    if "torus" in parts:
        results["torus"] = _bench_torus(faces, size, repeat)
    if "pyrender" in parts:
        from .bench_pyrender import bench_pyrender

        print()
        results["pyrender"] = bench_pyrender(size, repeat)
    if "texture" in parts:
        print()
        results["texture"] = bench_texture(repeat)
    settings = {"faces": faces, "size": size, "rounds": repeat, "scenes": list(parts)}
    save(json_path, "render", settings, results)
    return 0


# Texture sides of the texture part: the render is 64 x 64 whatever the texture's size.
TEXTURE_SIDES = (1024, 4096, 8192)
# Calls per turn of the texture part, the fastest counting: a call takes under a millisecond.
TEXTURE_BURST = 20


def bench_texture(repeat: int) -> dict[str, Any]:
    """The median time of a 64 x 64 render of a textured quad, uint8 RGBA textures of each
    side in `TEXTURE_SIDES` (after a first call of each), and the ratio of each to the first:
    a texture is read in place, so the time should grow with its size only as far as its
    texels fall out of the caches."""
    v = np.array([[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]], np.float64)
    f, uv = [[0, 1, 2], [0, 2, 3]], v[:, :2] * 0.5 + 0.5
    camera = gs.Camera.look_at((0, 0, 3), (0, 0, 0), (0, 1, 0))
    rng = np.random.default_rng(0)
    methods: dict[str, Callable[[], Any]] = {}
    for side in TEXTURE_SIDES:
        texture = rng.integers(0, 256, (side, side, 4), dtype=np.uint8)
        methods[f"{side}x{side}"] = functools.partial(
            gs.render, v, f, gs.Scene(), camera, width=64, height=64, texture=texture, uv=uv
        )
    times = time_rounds(methods, repeat, burst=TEXTURE_BURST)
    first = next(iter(times))
    print(
        f"a 64x64 render of a quad with a uint8 RGBA texture, {repeat} rounds, the fastest of "
        f"{TEXTURE_BURST} calls a turn"
    )
    print(f"\n  {'texture':12} {'median':>10} {'over ' + first:>16}")
    results: dict[str, Any] = {"ms": {}, "over_first": {}}
    for name, t in times.items():
        r = ratio(times[name], times[first])
        print(f"  {name:12} {t.median * 1e3:7.2f} ms {r.median:15.2f}x")
        results["ms"][name] = t.as_dict(1e3)
        results["over_first"][name] = r.as_dict()
    return results


def _bench_torus(faces: int, size: int, repeat: int) -> dict[str, Any]:
    """The median time of `gs.render` and of moderngl on Mesa's llvmpipe for each shading,
    with the per-round speed-ups and the pixels that agree."""
    from ..meshes import torus
    from .demo import demo_camera, demo_scene

    sides = max(3, round(np.sqrt(faces / 2 / 1.25)))  # 10^5 faces: 250 x 200 exactly
    rings = max(3, faces // (2 * sides))
    mesh = torus(rings, sides, 1.0, 0.45)
    v, f = mesh
    v32, normals = v.astype(np.float32), gs.vertex_normals(v, f).astype(np.float32)
    scene, camera = demo_scene(), demo_camera()
    print(
        f"a torus of {len(f):,} triangles ({len(v):,} vertices), {size}x{size}, float32; "
        f"{len(scene.lights)} lights; {repeat} rounds, each method once per round"
    )
    llvmpipe = _llvmpipe()
    methods: dict[str, Callable[[], Any]] = {}
    for shading in ("flat", "gouraud", "phong"):
        given = gs.face_normals(v32, f) if shading == "flat" else normals
        methods[f"glshade {shading}"] = functools.partial(
            gs.render,
            v32,
            f,
            scene,
            camera,
            width=size,
            height=size,
            shading=shading,
            normals=given,
        )
        if llvmpipe is not None:
            methods[f"llvmpipe {shading}"] = LlvmpipeRenderer(
                llvmpipe, mesh, shading, scene, camera, size
            )
    results = {name: np.asarray(call()) for name, call in methods.items()}
    times = time_rounds(methods, repeat)
    print(f"\n  {'method':24} {'median':>10}")
    for name, t in times.items():
        print(f"  {name:24} {t.median * 1e3:7.1f} ms")
    saved: dict[str, Any] = {
        "faces": len(f),
        "vertices": len(v),
        "ms": {k: t.as_dict(1e3) for k, t in times.items()},
    }
    if llvmpipe is None:
        return saved
    print("\n  shading   pixels within 1e-4 of llvmpipe   speed-up (median of per-round ratios)")
    saved["agreeing_pixels"], saved["speedup_over_llvmpipe"] = {}, {}
    for shading in ("flat", "gouraud", "phong"):
        ours, theirs = results[f"glshade {shading}"], results[f"llvmpipe {shading}"]
        both = (ours[..., 3] > 0) & (theirs[..., 3] > 0)
        agreeing = (np.abs(ours[both] - theirs[both]).max(axis=-1) <= 1e-4).mean()
        r = ratio(times[f"llvmpipe {shading}"], times[f"glshade {shading}"])
        print(f"  {shading:8} {agreeing:28.3%}   {r.median:10.2f}x")
        saved["agreeing_pixels"][shading] = float(agreeing)
        saved["speedup_over_llvmpipe"][shading] = r.as_dict()
    return saved
