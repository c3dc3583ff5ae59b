"""`bench render`'s pyrender and texture parts: what they time, and that their records hold
what the performance page's table reads."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest
from conftest import require

from glshade.lab.bench_pyrender import PYRENDER_SCENES, bench_pyrender, pyrender_scene
from support import glpeers  # noqa: F401 (it sets PYOPENGL_PLATFORM=egl before OpenGL loads)


def test_the_texture_part_times_each_texture_size(tmp_path: Path) -> None:
    path = tmp_path / "render.json"
    args = ["bench", "render", "--scenes", "texture", "--repeat", "1", "--json", str(path)]
    run = subprocess.run(
        [sys.executable, "-m", "glshade", *args], cwd=tmp_path, capture_output=True, text=True,
        check=True,
    )  # fmt: skip
    assert "8192x8192" in run.stdout
    results = json.loads(path.read_text())["results"]
    assert list(results) == ["texture"]
    sizes = ["1024x1024", "4096x4096", "8192x8192"]
    assert list(results["texture"]["ms"]) == sizes
    assert results["texture"]["over_first"]["1024x1024"]["median"] == 1.0


def test_the_scenes_hold_what_their_names_say() -> None:
    require("pyrender")
    for name, (per_side, subdivisions) in PYRENDER_SCENES.items():
        if subdivisions > 5:  # the large spheres: their counts follow from 20 * 4^s
            assert f"{20 * 4**subdivisions:,} faces" in name
            continue
        scene = pyrender_scene(per_side, subdivisions)
        meshes = [n.mesh for n in scene.mesh_nodes]
        assert len(meshes) == per_side**2
        faces = {len(m.primitives[0].indices) for m in meshes}
        assert faces == {20 * 4**subdivisions}
        assert str(per_side**2) in name or per_side == 1
        materials = {id(m.primitives[0].material) for m in meshes}
        assert len(materials) == len(meshes)  # a material each
        kinds = sorted(type(n.light).__name__ for n in scene.light_nodes)
        assert kinds == ["DirectionalLight", "PointLight"]


@pytest.mark.gl
def test_the_pyrender_part_agrees_with_pyrender_before_timing() -> None:
    require("pyrender")
    names = ["1 mesh, 20,480 faces", "64 meshes of 1,280 faces"]
    results = bench_pyrender(256, 1, names)
    assert list(results) == names
    for result in results.values():
        # Interior pixels: pyrender's 8-bit rounding, and MSAA where a pixel straddles two
        # small triangles of a highlight (2/255 at 1024², up to 5/255 at 256²); a scene read
        # wrongly (a light, a pose, a material) differs by tens.
        assert result["interior_pixels"] > 1000
        assert result["max_interior_difference_255"] < 8.0
        assert result["speedup_over_pyrender"]["median"] > 0
