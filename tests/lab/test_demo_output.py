"""`python -m glshade demo --output` makes a missing folder before its work, and names the
path when a folder cannot be made."""

from __future__ import annotations

from pathlib import Path

import pytest

from glshade.lab.cli import main

pytestmark = pytest.mark.lab


def test_the_demo_makes_its_output_folder(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    output = tmp_path / "new" / "deeper" / "demo.png"
    assert main(["demo", "--size", "16", "--repeat", "1", "--output", str(output)]) == 0
    for name in ("demo.png", "demo-flat.png", "demo-gouraud.png", "demo-phong.png"):
        assert (output.parent / name).read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert f"wrote {output}" in capsys.readouterr().out


def test_a_folder_that_cannot_be_made_is_named_before_the_work(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    blocker = tmp_path / "a-file"
    blocker.write_text("")
    with pytest.raises(SystemExit) as exit_info:
        main(["demo", "--size", "16", "--repeat", "1", "--output", str(blocker / "demo.png")])
    assert exit_info.value.code == 2
    captured = capsys.readouterr()
    assert "--output: cannot create the folder" in captured.err
    assert f"(a file is in the way: {blocker})" in captured.err
    assert "gs.shade" not in captured.out  # failed before the first part ran
