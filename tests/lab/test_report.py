"""`gs.report` and ``python -m glshade report``: its reference is the GL equation (against the
tests' float64 transcription and the 50-digit oracle), report.json follows its schema, every row
is within its mode's bound, the SVG figures hold the axis labels, the legend and one point
per row, and ``report --compare`` counts the rows on which two runs agree (on made-up rows:
the timing itself is never a test)."""

from __future__ import annotations

import copy
import csv
import doctest
import inspect
import io
import json
import pickle
import statistics
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from conftest import require

import glshade as gs
from glshade import __main__ as cli
from glshade.lab import report as report_module
from glshade.lab import report_compare
from glshade.lab.baselines import equation, stable_power
from glshade.lab.bounds import BOUNDS
from glshade.lab.progress import Progress
from glshade.lab.scenes import report_classes
from support.gl_reference import RefScene, gl_lighting

pytestmark = pytest.mark.lab

CLASSES = {c.name: c for c in report_classes()}
SCHEMA = Path(report_module.__file__).with_name("report.schema.json")
SVG = "{http://www.w3.org/2000/svg}"


def _lights(scene: gs.Scene) -> list[dict[str, Any]]:
    keys = inspect.signature(gs.Light).parameters
    return [{k: getattr(scene.lights, k)[i] for k in keys} for i in range(len(scene.lights))]


def _material(scene: gs.Scene) -> dict[str, Any]:
    m = scene.material
    keys = ("ambient", "diffuse", "specular", "emission", "shininess")
    return {k: getattr(m, k) for k in keys}


def _reference(p: np.ndarray, n: np.ndarray, scene: gs.Scene) -> np.ndarray:
    with np.errstate(over="ignore", invalid="ignore"):
        ev = equation(p.astype(np.longdouble), n.astype(np.longdouble), scene, stable_power)
    return ev.rgb.astype(np.float64)


@pytest.mark.parametrize("name", [c.name for c in report_classes() if c.kind == "typical"])
def test_the_long_double_reference_is_the_gl_equation(name: str) -> None:
    cls = CLASSES[name]
    p, n = cls.vertices(3_000, np.random.default_rng(0))
    s = cls.scene
    ref = RefScene(
        lights=_lights(s),
        material=_material(s),
        global_ambient=tuple(s.global_ambient),
        viewer=tuple(s.viewer),
    )
    expected = gl_lighting(p, n, ref).outputs[0][:, :3]
    # float64's naive pow loses s * 1e-16 near the highlight; long double keeps it.
    got = np.clip(_reference(p, n, s), 0, 1)
    np.testing.assert_allclose(got, expected, rtol=0, atol=1e-11)


@pytest.mark.parametrize("name", list(CLASSES))
def test_the_reference_agrees_with_the_50_digit_oracle_on_every_class(name: str) -> None:
    require("mpmath")
    from support.mp_reference import mp_vertex

    cls = CLASSES[name]
    count = 3 if len(cls.scene.lights) > 100 else 24
    p, n = cls.vertices(200, np.random.default_rng(3))
    picks = np.r_[0:count]  # every class puts its hardest vertices among the first rows
    s = cls.scene
    got = _reference(p[picks], n[picks], s)
    finite = np.isfinite(p[picks]).all(axis=1) & np.isfinite(n[picks]).all(axis=1)
    assert np.isnan(got[~finite]).all(), "a non-finite input that is read makes the row NaN"
    for i in np.flatnonzero(finite):
        exact = mp_vertex(
            p[picks][i],
            n[picks][i],
            _lights(s),
            _material(s),
            global_ambient=s.global_ambient,
            viewer=s.viewer,
        )
        if not np.isfinite(exact.magnitude):
            assert np.clip(got[i], 0, 1).tolist() == [1.0, 1.0, 1.0]
            continue
        scale = max(1.0, exact.magnitude)
        np.testing.assert_allclose(got[i], exact.rgb, rtol=0, atol=1e-15 * scale, err_msg=name)


# gs.report runs a worker process per instruction set, ~7 s: its users are subprocess and slow.
@pytest.fixture(scope="module")
def small(tmp_path_factory: pytest.TempPathFactory) -> tuple[gs.Report, Path]:
    result = gs.report(vertices=3_000, rounds=2, progress=False)
    folder = tmp_path_factory.mktemp("report")
    result.write(folder)
    return result, folder


@pytest.mark.slow
@pytest.mark.subprocess
def test_one_row_per_class_dtype_mode_and_instruction_set(small: tuple[gs.Report, Path]) -> None:
    result, _ = small
    isas = sorted({r.isa for r in result.rows})
    assert "baseline" in isas and set(isas) <= {"avx512", "avx2", "baseline"}
    keys = [(r.scene, r.dtype, r.accuracy, r.isa) for r in result.rows]
    # Two dtypes, two modes ("fast", "exact").
    assert len(set(keys)) == len(keys) == len(CLASSES) * 4 * len(isas)
    assert {r.kind for r in result.rows} == {"typical", "stiff"}
    m = result.machine
    assert m["instruction_set"] in isas and m["glshade"] == gs.__version__
    assert m["numpy"] == np.__version__ and m["python"] == sys.version.split()[0]
    assert result.area_lights and result.gouraud_phong
    # Every instruction set computes the same bits: the same errors, row for row.
    by_isa: dict[str, list[tuple[float, float]]] = {}
    for r in result.rows:
        by_isa.setdefault(r.isa, []).append((r.max_error, r.mean_error))
    assert all(v == by_isa["baseline"] for v in by_isa.values())


@pytest.mark.slow
@pytest.mark.subprocess
def test_report_json_follows_its_schema_and_every_row_is_within_its_bound(
    small: tuple[gs.Report, Path],
) -> None:
    jsonschema = require("jsonschema")
    _, folder = small
    data = json.loads((folder / "report.json").read_text())
    jsonschema.validate(data, json.loads(SCHEMA.read_text()))  # type: ignore[attr-defined]
    for row in data["rows"]:
        mode = BOUNDS[(row["dtype"], row["accuracy"])]
        assert row["bound"] == mode.unit
        assert row["max_error_over_bound"] is not None, row
        assert row["max_error_over_bound"] <= 1.0, row
        if row["kind"] == "typical":  # unit normals and colours in [0, 1]: the plain bound
            assert row["max_error"] <= mode.unit, row
        assert row["time_low_ns"] <= row["time_ns"] <= row["time_high_ns"]
        low, high = row["time_over_kernel_low"], row["time_over_kernel_high"]
        assert low <= row["time_over_kernel"] <= high
        assert row["kernel_low_ns"] <= row["kernel_ns"] <= row["kernel_high_ns"]
        # Each round's ratio is that round's time over its kernel's, per vertex of each.
        assert row["time_low_ns"] / row["kernel_high_ns"] <= low * (1 + 1e-12), row
        assert high <= row["time_high_ns"] / row["kernel_low_ns"] * (1 + 1e-12), row
        assert row["mvert_s"] == pytest.approx(1e3 / row["time_ns"])
        assert row["p999_error"] <= row["max_error"] and row["mean_error"] <= row["max_error"]
    # Only float32's arithmetic lands on the other side of a cone's edge, within 1e-6 rad of it.
    flipped = {(r["scene"], r["dtype"], r["accuracy"]) for r in data["rows"] if r["flipped"]}
    edge = "spot cutoff 90, cone edge"
    assert flipped <= {(edge, "float32", "fast")}
    # Exact float32 is the float64 result rounded once: half an ulp at most.
    exact = [r for r in data["rows"] if r["accuracy"] == "exact" and r["dtype"] == "float32"]
    assert max(r["max_ulps"] for r in exact) <= 0.5 + 1e-9


@pytest.mark.slow
@pytest.mark.subprocess
def test_the_data_files_say_the_same(small: tuple[gs.Report, Path]) -> None:
    result, folder = small
    rows = list(csv.DictReader(io.StringIO((folder / "report.csv").read_text())))
    dicts = result.to_dicts()
    assert len(rows) == len(dicts)
    for read, row in zip(rows, dicts, strict=True):
        assert read["scene"] == row["scene"] and read["isa"] == row["isa"]
        assert float(read["max_error"]) == row["max_error"]
        assert float(read["time_ns"]) == row["time_ns"]
        assert float(read["time_over_kernel"]) == row["time_over_kernel"]
    assert json.loads(result.to_json())["rows"] == json.loads(json.dumps(dicts))
    text = (folder / "report.md").read_text()
    assert result.machine["cpu"] in text and result.settings["kernel"] in text
    assert "| x kernel | spread | ns/vertex | spread |" in text
    assert text.count(" | float32 | fast | ") == len(CLASSES) * len({r.isa for r in result.rows})
    assert "Area light sampled by k points" in text and "Gouraud against per-pixel Phong" in text


@pytest.mark.slow
@pytest.mark.subprocess
def test_the_report_pickles_and_deepcopies_to_an_equal_one(small: tuple[gs.Report, Path]) -> None:
    result, _ = small
    assert pickle.loads(pickle.dumps(result)) == result
    assert copy.deepcopy(result) == result


def _svg(path: Path) -> tuple[list[str], set[str]]:
    root = ET.parse(path).getroot()
    texts = ["".join(t.itertext()) for t in root.iter(f"{SVG}text")]
    ids = {e.get("id", "") for e in root.iter()}
    return texts, ids


@pytest.mark.slow
@pytest.mark.subprocess
def test_the_svg_figures_have_labels_legends_and_one_point_per_row(
    small: tuple[gs.Report, Path],
) -> None:
    require("matplotlib")
    result, folder = small
    for name in ("error-time", "gouraud-phong", "area-lights"):
        assert (folder / f"{name}.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    texts, ids = _svg(folder / "error-time.svg")
    assert "time per vertex (ns, median of the rounds)" in texts
    assert any(t.startswith("max error against the long-double reference") for t in texts)
    assert {"float32", "float64"} <= set(texts)  # the panels
    assert set(CLASSES) <= set(texts) and "Pareto front" in texts
    assert {r.isa for r in result.rows} <= set(texts)
    assert {f"row-{i}" for i in range(len(result.rows))} <= ids
    assert f"row-{len(result.rows)}" not in ids
    assert {"legend", "pareto-float32", "pareto-float64"} <= ids
    texts, ids = _svg(folder / "gouraud-phong.svg")
    assert "triangles of the icosphere" in texts and "time per call (ms, median)" in texts
    assert {"Gouraud time", "Phong time", "max |Gouraud - Phong|"} <= set(texts)
    assert {f"gouraud-{i}" for i in range(len(result.gouraud_phong))} <= ids
    texts, ids = _svg(folder / "area-lights.svg")
    assert "k, points sampling the area light" in texts and "max error" in texts
    assert {f"area-{i}" for i in range(len(result.area_lights))} <= ids


@pytest.mark.slow
@pytest.mark.subprocess
def test_without_matplotlib_the_data_files_and_one_line(
    small: tuple[gs.Report, Path],
    tmp_path: Path,
    monkeypatch: pytest.MonkeyPatch,
    capsys: pytest.CaptureFixture[str],
) -> None:
    result, _ = small
    monkeypatch.delitem(sys.modules, "glshade.lab.figures", raising=False)
    monkeypatch.setitem(sys.modules, "matplotlib", None)  # import fails
    written = result.write(tmp_path)
    assert sorted(p.name for p in written) == ["report.csv", "report.json", "report.md"]
    assert capsys.readouterr().out == (
        "no figures: matplotlib is not installed (pip install 'glshade[plot]')\n"
    )


@pytest.mark.subprocess
def test_the_command_writes_every_file(tmp_path: Path) -> None:
    out = tmp_path / "d"
    args = ["report", "--out", str(out), "--vertices", "300", "--rounds", "1", "--isa"]
    run = subprocess.run(
        [sys.executable, "-m", "glshade", *args, "baseline", "--no-studies"],
        capture_output=True,
        text=True,
        check=True,
    )
    names = {"report.md", "report.json", "report.csv", "error-time.png", "error-time.svg"}
    assert names <= {p.name for p in out.iterdir()}
    assert f"wrote {out / 'report.json'}" in run.stdout
    assert "glshade report" in run.stderr  # the progress bar
    data = json.loads((out / "report.json").read_text())
    assert {r["isa"] for r in data["rows"]} == {"baseline"}
    assert data["studies"] == {"area_lights": [], "gouraud_phong": []}


def test_the_progress_line_without_tqdm(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setitem(sys.modules, "tqdm", None)
    monkeypatch.setitem(sys.modules, "tqdm.auto", None)
    stream = io.StringIO()
    with Progress(3, "work", stream=stream) as bar:
        bar.step("one")
        bar.step("two", n=2)
    text = stream.getvalue()
    assert text.count("\n") == 1 and text.endswith("\n")  # one line, rewritten in place
    assert [part.split("(")[0].strip() for part in text.split("\r")[1:]] == [
        "work: 0/3",
        "work: 1/3",
        "work: 3/3",
    ]


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        ({"vertices": 0}, "vertices must be a positive integer, got 0"),
        ({"rounds": 2.5}, "rounds must be a positive integer, got 2.5"),
        ({"isas": ["sse4"]}, "isas must name some of avx512, avx2, baseline, got \\['sse4'\\]"),
        ({"scenes": ["nothing"]}, "scenes must be among .*got \\['nothing'\\]"),
    ],
)
def test_bad_arguments_name_themselves(kwargs: dict[str, Any], message: str) -> None:
    with pytest.raises(ValueError, match=message):
        gs.report(**kwargs)


def test_the_docstring_example_runs() -> None:
    result = doctest.testmod(report_module, optionflags=doctest.ELLIPSIS)
    assert result.attempted >= 2 and result.failed == 0


def _row(
    scene: str, isa: str, kernel: tuple[float, float, float], ns: tuple[float, float, float]
) -> dict[str, Any]:
    names = (*report_compare.FIGURES["time_over_kernel"], *report_compare.FIGURES["time_ns"])
    keys = {"scene": scene, "dtype": "float32", "accuracy": "fast", "isa": isa}
    return {**keys, **dict(zip(names, (*kernel, *ns), strict=True))}


# Made-up runs: B is 20% slower in seconds on every row, its calibrated figure moves little.
RUN_A = [
    _row("one", "avx2", (2.0, 1.9, 2.2), (10.0, 9.0, 11.0)),
    _row("two", "avx2", (4.0, 3.0, 4.5), (20.0, 19.0, 21.0)),
    _row("three", "avx2", (6.0, 5.0, 6.5), (30.0, 25.0, 31.0)),
    _row("four", "avx2", (8.0, 7.9, 8.1), (40.0, 39.0, 41.0)),
    _row("only in A", "avx2", (1.0, 1.0, 1.0), (1.0, 1.0, 1.0)),
]
RUN_B = [  # calibrated: which way B agrees with A; seconds: which way
    _row("one", "avx2", (2.1, 2.0, 2.3), (12.0, 9.5, 13.0)),  # both; A in B only
    _row("two", "avx2", (4.4, 4.2, 4.6), (24.0, 20.0, 25.0)),  # B in A only; A in B only
    _row("three", "avx2", (5.8, 5.4, 6.0), (36.0, 35.0, 37.0)),  # both (the ends count); neither
    _row("four", "avx2", (9.0, 8.5, 9.5), (48.0, 47.0, 49.0)),  # neither; neither
    _row("one", "baseline", (1.0, 1.0, 1.0), (1.0, 1.0, 1.0)),
]


def test_compare_counts_the_rows_whose_medians_lie_within_the_other_runs_spread() -> None:
    calibrated = report_compare.agreement(RUN_A, RUN_B, "time_over_kernel")
    assert (calibrated.rows, calibrated.b_in_a, calibrated.a_in_b, calibrated.both) == (4, 3, 2, 2)
    assert calibrated.share(calibrated.both) == 0.5
    assert calibrated.drift == pytest.approx(statistics.median([1.05, 1.1, 5.8 / 6, 9 / 8]))
    assert calibrated.width_a == pytest.approx(statistics.median([0.15, 0.375, 0.25, 0.025]))
    absolute = report_compare.agreement(RUN_A, RUN_B, "time_ns")
    assert (absolute.b_in_a, absolute.a_in_b, absolute.both) == (0, 2, 0)
    assert absolute.drift == pytest.approx(1.2)
    # Swapping the runs swaps the one-way counts.
    swapped = report_compare.agreement(RUN_B, RUN_A, "time_over_kernel")
    assert (swapped.b_in_a, swapped.a_in_b, swapped.both) == (2, 3, 2)


def test_compare_rejects_reports_that_cannot_be_compared() -> None:
    with pytest.raises(ValueError, match="a and b share no row"):
        report_compare.agreement(RUN_A[:1], RUN_B[1:2], "time_ns")
    with pytest.raises(ValueError, match=r"b has the row .*'two'.* twice"):
        report_compare.agreement(RUN_A, RUN_B + RUN_B[1:2], "time_ns")
    with pytest.raises(
        ValueError, match="figure must be one of time_over_kernel, time_ns, got 'ms'"
    ):
        report_compare.agreement(RUN_A, RUN_B, "ms")


def test_a_report_without_the_calibrated_figure_compares_on_seconds_only() -> None:
    old = [{k: v for k, v in row.items() if "kernel" not in k} for row in RUN_A]
    result = report_compare.compare({"rows": old}, {"rows": RUN_B})
    assert result["time_over_kernel"] is None
    assert result["time_ns"] == report_compare.agreement(RUN_A, RUN_B, "time_ns")


def test_the_compare_option_prints_both_figures_and_names_a_bad_file(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    a, b, bad = tmp_path / "a.json", tmp_path / "b.json", tmp_path / "bad.json"
    a.write_text(json.dumps({"schema": "glshade-report/2", "rows": RUN_A}))
    b.write_text(json.dumps({"schema": "glshade-report/2", "rows": RUN_B}))
    assert cli.main(["report", "--compare", str(a), str(b)]) == 0
    out = capsys.readouterr().out
    assert "time_over_kernel (4 rows in both): B's median within A's spread 3 (75.0%), " in out
    assert "A's within B's 2 (50.0%), both ways 2 (50.0%); B / A 1.075 (median row)" in out
    assert "time_ns (4 rows in both): B's median within A's spread 0 (0.0%)" in out
    bad.write_text(json.dumps({"schema": "glshade-report/2", "rows": []}))
    with pytest.raises(SystemExit) as stop:
        cli.main(["report", "--compare", str(a), str(bad)])
    assert stop.value.code == 2
    assert f"--compare: B: {bad} is not a glshade report.json (no rows)" in capsys.readouterr().err
