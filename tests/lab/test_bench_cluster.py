"""`python -m glshade bench cluster`: the lab's cluster benchmark runs on a local cluster, finds
the outputs bit-identical to the local call's, saves its JSON and removes its scratch files."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from conftest import require

from glshade import __main__ as cli

pytestmark = [pytest.mark.lab, pytest.mark.cluster]


def test_the_cluster_bench_runs_and_finds_the_outputs_bit_identical(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    require("dask.array")
    require("distributed")
    path = tmp_path / "cluster.json"
    args = ["bench", "cluster", "--vertices", "300000", "--chunk", "70000", "--repeat", "1"]
    assert cli.main([*args, "--json", str(path), "--dir", str(tmp_path)]) == 0
    out = capsys.readouterr().out
    assert "bit-identical to the local call's: True" in out and "Mvert/s" in out
    saved = json.loads(path.read_text())
    assert saved["bench"] == "cluster" and saved["results"]["bit_identical"] is True
    assert saved["settings"] == {"vertices": 300_000, "chunk": 70_000, "workers": 2, "repeat": 1}
    assert "cpu" in saved["machine"]
    assert list(tmp_path.iterdir()) == [path]  # the scratch files are gone
