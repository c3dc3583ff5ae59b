"""`python -m glshade bench relief`: it checks glshade against matplotlib before timing, and
writes its results with the machine."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from conftest import require

from glshade.lab.cli import main

pytestmark = pytest.mark.lab


def test_the_relief_bench_runs_and_agrees(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    require("matplotlib")
    out = tmp_path / "relief.json"
    assert main(["bench", "relief", "--size", "64", "--repeat", "2", "--json", str(out)]) == 0
    data = json.loads(out.read_text())
    assert data["bench"] == "relief" and data["settings"] == {"size": 64, "rounds": 2}
    assert set(data["results"]) == {"hillshade", "shade_rgb hsv", "shade_rgb overlay"}
    for result in data["results"].values():
        assert result["max_difference"] <= 1e-12
        assert len(result["speedup"]["rounds"]) == 2
    assert "matplotlib 3." in capsys.readouterr().out
