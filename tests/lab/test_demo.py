"""`python -m glshade demo` runs, prints what it computed, and writes valid PNGs; the benchmarks
run beside their baselines."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

pytestmark = [pytest.mark.lab, pytest.mark.subprocess]


def test_demo_runs_and_writes_the_image(tmp_path: Path) -> None:
    output = tmp_path / "demo.png"
    run = subprocess.run(
        [
            sys.executable,
            "-m",
            "glshade",
            "demo",
            "--size",
            "96",
            "--repeat",
            "2",
            "--output",
            str(output),
        ],
        capture_output=True,
        text=True,
        check=True,
    )
    assert "Mvertices/s" in run.stdout and "float32" in run.stdout and "float64" in run.stdout
    max_diff = float(run.stdout.split("max |float32 - float64|")[1].split(":")[1].split()[0])
    assert max_diff < 1e-5
    for shading in ("flat", "gouraud", "phong"):
        assert run.stdout.count(f"\n{shading} ") == 1  # its timing line
    # Gouraud misses and smears the highlights Phong shading shows on the coarse torus.
    gouraud_error = float(
        run.stdout.split("Gouraud against Phong: max |difference|")[1].split(",")[0]
    )
    assert 0.05 < gouraud_error < 1
    for name in ("demo.png", "demo-flat.png", "demo-gouraud.png", "demo-phong.png"):
        assert f"wrote {tmp_path / name}" in run.stdout
        assert (tmp_path / name).read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_bench_normals_runs_beside_trimesh(tmp_path: Path) -> None:
    from conftest import require

    require("trimesh")
    path = tmp_path / "normals.json"
    run = subprocess.run(
        [
            sys.executable,
            "-m",
            "glshade",
            *"bench normals --faces 2000 --repeat 2 --settle 0 --json".split(),
            str(path),
        ],
        capture_output=True,
        text=True,
        check=True,
    )
    assert "trimesh vertex_normals" in run.stdout
    assert "speed-up over trimesh" in run.stdout
    difference = float(run.stdout.split("angle weighting, float64:")[1].split()[0])
    assert difference < 1e-12
    saved = json.loads(path.read_text())
    assert saved["bench"] == "normals" and saved["machine"]["cpu"]
    assert saved["results"]["max_difference_from_trimesh"] < 1e-12
    speedup = saved["results"]["speedup_over_trimesh"]["face normals, float64"]
    assert len(speedup["rounds"]) == 2 and speedup["low"] <= speedup["median"] <= speedup["high"]


@pytest.mark.gl
def test_bench_render_runs_beside_llvmpipe(tmp_path: Path) -> None:
    from conftest import require

    require("moderngl")
    path = tmp_path / "render.json"
    args = ["bench", "render", "--faces", "2000", "--size", "96", "--repeat", "2", "--scenes"]
    args += ["torus", "--json"]
    args.append(str(path))
    run = subprocess.run(
        [sys.executable, "-m", "glshade", *args],
        cwd=tmp_path,  # anywhere: the baseline is glshade.glsl's, not the tests' (no pytest)
        capture_output=True,
        text=True,
        check=True,
    )
    for shading in ("flat", "gouraud", "phong"):
        assert f"glshade {shading}" in run.stdout and f"llvmpipe {shading}" in run.stdout
        line = run.stdout.split("speed-up")[1].split(f"\n  {shading}")[1].split()
        assert float(line[0].rstrip("%")) > 99.0, line  # the same picture, pixel for pixel
    saved = json.loads(path.read_text())
    assert saved["bench"] == "render" and saved["settings"]["size"] == 96
    assert saved["settings"]["scenes"] == ["torus"] and list(saved["results"]) == ["torus"]
    assert min(saved["results"]["torus"]["agreeing_pixels"].values()) > 0.99
