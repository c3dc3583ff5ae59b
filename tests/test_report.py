"""``python -m glshade report``: its reference is the GL equation, its rows hold the README's
per-mode bounds, and it writes the Markdown table and the PNG plot."""

import inspect
from pathlib import Path

import numpy as np
import pytest

import glshade as gs
from gl_reference import RefScene, gl_lighting
from glshade import __main__ as cli
from glshade._report import MODES, measure, reference_shade, report_scenes, report_vertices

BOUNDS = {  # the README's per-mode bounds on unit normals and colours in [0, 1]
    ("float32", "fast"): 1e-5,
    ("float32", "exact"): 2.0**-24 + 1e-12,
    ("float64", "fast"): 1e-12,
    ("float64", "exact"): 1e-12,
}


@pytest.mark.parametrize("name", list(report_scenes()))
def test_the_long_double_reference_is_the_gl_equation(name: str) -> None:
    scene = report_scenes()[name]
    p, n = report_vertices(name, 3_000)
    lights = [
        {key: getattr(scene.lights, key)[i] for key in inspect.signature(gs.Light).parameters}
        for i in range(len(scene.lights))
    ]
    m = scene.material
    ref = RefScene(
        lights=lights,
        material={
            "ambient": m.ambient,
            "diffuse": m.diffuse,
            "specular": m.specular,
            "emission": m.emission,
            "shininess": m.shininess,
        },
        global_ambient=tuple(scene.global_ambient),
        viewer=tuple(scene.viewer),
    )
    expected = gl_lighting(p, n, ref).outputs[0][:, :3]
    # float64's naive pow loses s * 1e-16 near the highlight; long double keeps it.
    np.testing.assert_allclose(reference_shade(p, n, scene), expected, rtol=0, atol=1e-11)


def test_every_row_is_within_its_modes_bound() -> None:
    rows = measure(4_000, repeat=1)
    assert len(rows) == len(report_scenes()) * len(MODES)
    for row in rows:
        assert row["max_error"] <= BOUNDS[(row["dtype"], row["accuracy"])], row
        assert row["mvert_s"] > 0
    # exact float32 is the float64 result rounded once: half an ulp at most.
    assert max(r["max_error"] for r in rows if r["accuracy"] == "exact") <= 2.0**-24 + 1e-12


def test_report_writes_markdown_and_png(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    output = tmp_path / "r.md"
    args = ["report", "--vertices", "1000", "--repeat", "1", "--output", str(output)]
    assert cli.main(args) == 0
    text = output.read_text()
    assert text.count("| float32 | fast |") == len(report_scenes())
    assert "Area light sampled by k points" in text and "Gouraud against per-pixel Phong" in text
    assert output.with_suffix(".png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    captured = capsys.readouterr()
    assert "[16/16]" in captured.err, "progress goes to stderr"
