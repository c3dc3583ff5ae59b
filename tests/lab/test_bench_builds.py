"""``python -m glshade bench builds`` runs each build in a child interpreter that imports it and
not the installed core, in alternating rounds, and saves what the docs' tables render; bad
arguments are named. The timing itself is never a test."""

import importlib.util
import json
import shutil
from pathlib import Path
from types import ModuleType

import pytest

from glshade import __main__ as cli
from glshade import _glshade
from glshade.lab.bench_builds import bench_builds, time_scenes

pytestmark = [pytest.mark.lab, pytest.mark.subprocess]

INSTALLED = Path(_glshade.__file__).resolve()
SCENES = ["1 directional", "8 mixed"]


def _builds(folder: Path, *names: str) -> list[Path]:
    """Copies of the installed extension module under `names`: builds that import."""
    paths = [folder / name for name in names]
    for path in paths:
        shutil.copyfile(INSTALLED, path)
    return paths


def _tables() -> ModuleType:
    """docs/hooks/tables.py, which renders the saved JSON in the docs."""
    path = Path(__file__).parents[2] / "docs" / "hooks" / "tables.py"
    spec = importlib.util.spec_from_file_location("tables", path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_each_build_runs_in_turn_from_its_own_copy(tmp_path: Path) -> None:
    a, b = _builds(tmp_path, "a.so", "b.so")
    out = tmp_path / "builds.json"
    kwargs = {"vertices": 2_000, "scenes": SCENES, "seconds": 0.01}
    assert bench_builds([a, b], rounds=2, json_path=out, **kwargs) == 0  # type: ignore[arg-type]
    data = json.loads(out.read_text())
    assert data["bench"] == "builds"
    rows = data["results"]["rows"]
    assert [(r["build"], r["round"]) for r in rows] == [
        ("a.so", 1),
        ("b.so", 1),
        ("a.so", 2),
        ("b.so", 2),
    ]
    modules = {Path(r["module"]) for r in rows}
    # Each child imported a copy of its build of its own, never the installed core.
    assert len(modules) == len(rows)
    assert all(m.name == INSTALLED.name and m.parent != INSTALLED.parent for m in modules)
    assert all(r["mvert_s"][s] > 0 for r in rows for s in SCENES)
    assert set(data["results"]["ratios"]) == {"b.so"}
    assert set(data["results"]["ratios"]["b.so"]) == set(SCENES)
    settings = data["settings"]
    assert settings["labels"] == ["a.so", "b.so"] and settings["threads"] == 1
    assert settings["sha256"]["a.so"] == settings["sha256"]["b.so"]  # the same file twice

    # The docs render the file: a row per build and round, the ratios under it, the command.
    tables = _tables()
    text = tables.table(out, out.name)
    assert "| build | round | 1 directional | 8 mixed |" in text
    assert "b.so over a.so (medians of per-round ratios): 1 directional" in text
    assert "python -m glshade bench builds a.so b.so --labels 'a.so,b.so' --repeat 2" in text
    assert "1 threads" in text


def test_a_file_that_is_not_a_build_is_named(tmp_path: Path) -> None:
    (a,) = _builds(tmp_path, "a.so")
    not_a_build = tmp_path / "notes.so"
    not_a_build.write_text("not an extension module")
    with pytest.raises(RuntimeError, match=r"build 'notes\.so' did not run"):
        bench_builds([a, not_a_build], rounds=1, vertices=100, scenes=SCENES, seconds=0.01)


def test_the_command_names_a_build_that_does_not_run(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    _builds(tmp_path, "a.so")
    (tmp_path / "empty.so").write_bytes(b"")
    monkeypatch.chdir(tmp_path)
    with pytest.raises(SystemExit) as stop:
        cli.main(["bench", "builds", "a.so", "empty.so", "--vertices", "100", "--seconds", "0.01"])
    assert stop.value.code == 2
    assert "build 'empty.so' did not run (exit status 1)" in capsys.readouterr().err


def test_the_child_refuses_a_core_from_elsewhere(tmp_path: Path) -> None:
    # This process imports the installed core, not one from tmp_path.
    with pytest.raises(RuntimeError, match="not from the build in"):
        time_scenes(str(tmp_path), SCENES, 100, "float32", 0.01)


@pytest.mark.parametrize(
    ("extra", "message"),
    [
        ([], "builds: expected two or more extension modules, got 1"),
        (["missing.so"], "builds: expected a built extension module file, got"),
        (["b.so", "--labels", "one"], "--labels: expected one label per build (2), got 1"),
        (["b.so", "--labels", "x,x"], "--labels: expected different labels"),
        (
            ["b.so", "--labels", "x,"],
            "argument --labels: expected names separated by commas, got 'x,'",
        ),
        (
            ["b.so", "--seconds", "0"],
            "argument --seconds: must be a positive number of seconds, got 0",
        ),
        (["b.so", "--scenes", "9 mixed"], "--scenes"),
    ],
)
def test_bad_arguments_are_named(
    tmp_path: Path,
    capsys: pytest.CaptureFixture[str],
    monkeypatch: pytest.MonkeyPatch,
    extra: list[str],
    message: str,
) -> None:
    _builds(tmp_path, "a.so", "b.so")
    monkeypatch.chdir(tmp_path)
    with pytest.raises(SystemExit) as stop:
        cli.main(["bench", "builds", "a.so", *extra])
    assert stop.value.code == 2
    assert message in capsys.readouterr().err
