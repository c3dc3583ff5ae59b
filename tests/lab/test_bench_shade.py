"""The baselines of ``python -m glshade bench shade`` compute the equation glshade computes, so
the benchmark compares like with like (checked here; the timing itself is never a test); each
bench accepts only its own flags and saves its results as JSON with the machine."""

import json
import types
from pathlib import Path

import numpy as np
import pytest
from conftest import require

import glshade as gs
from glshade import __main__ as cli
from glshade import _glshade
from glshade.lab import timing
from glshade.lab.baselines import numba_shade, numpy_shade
from glshade.lab.machine import identity, machine
from glshade.lab.scenes import bench_scenes, bench_vertices
from glshade.lab.timing import Timing, ratio, time_calibrated, time_rounds

pytestmark = pytest.mark.lab

SCENES = bench_scenes()


@pytest.mark.parametrize("name", SCENES)
def test_numpy_baseline_is_the_gl_equation(name: str) -> None:
    p, n = bench_vertices(4_000)
    reference = gs.shade(p.astype(np.float64), n.astype(np.float64), SCENES[name])
    got = numpy_shade(p, n, SCENES[name])
    assert got.dtype == np.float32
    # float32 arithmetic: a few ulp of the largest term.
    np.testing.assert_allclose(got, reference, rtol=0, atol=2e-6)
    # The scene lights the vertices: the comparison is not of zeros.
    assert (reference[:, :3] > 0.05).mean() > 0.9


@pytest.mark.parametrize("name", SCENES)
def test_numba_baseline_is_the_gl_equation(name: str) -> None:
    require("numba")
    shade = numba_shade()
    assert not isinstance(shade, str), shade
    p, n = bench_vertices(4_000)
    reference = gs.shade(p.astype(np.float64), n.astype(np.float64), SCENES[name])
    np.testing.assert_allclose(shade(p, n, SCENES[name]), reference, rtol=0, atol=2e-6)


def test_the_scenes_are_those_of_the_issue() -> None:
    kinds = [
        [
            ("directional" if light.position[3] == 0 else "point")
            + (" spot" if light.spot_cutoff != 180 else "")
            + (" attenuated" if light.linear_attenuation + light.quadratic_attenuation > 0 else "")
            for light in scene.lights
        ]
        for scene in SCENES.values()
    ]
    assert kinds[0] == ["directional"]
    assert kinds[1] == ["point"] and SCENES["1 point, local viewer"].viewer[3] == 1
    assert len(kinds[2]) == 8
    assert {"directional", "point attenuated", "point spot"} <= set(kinds[2])


def test_bench_shade_runs_prints_every_scene_and_saves_json(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    path = tmp_path / "b.json"
    args = ["bench", "shade", "--sizes", "100", "200", "--repeat", "2", "--json", str(path)]
    assert cli.main(args) == 0
    out = capsys.readouterr().out
    for name in SCENES:
        assert f"\n{name}: fast: float32" in out
    assert "per-call overhead" in out and f"wrote {path}" in out
    cpu = machine()
    assert f"CPU: {cpu['cpu']}; glshade's instruction set: {cpu['instruction_set']}" in out
    assert "of stream" in out and "display" in out and "f64 exact" in out
    saved = json.loads(path.read_text())
    assert saved["bench"] == "shade" and saved["settings"]["sizes"] == [100, 200]
    assert {"cpu", "instruction_set", "threads", "glshade", "numpy", "python"} <= set(
        saved["machine"]
    )
    assert [(r["scene"], r["vertices"]) for r in saved["results"]["scenes"]] == [
        (name, n) for name in SCENES for n in (100, 200)
    ]
    for r in saved["results"]["scenes"]:
        glshade = r["ms"]["glshade"]
        assert len(glshade["rounds"]) == 2
        assert glshade["low"] <= glshade["median"] <= glshade["high"]
        # The speed-up is the median of the per-round ratios of the saved times.
        per_round = [
            b / o for b, o in zip(r["ms"]["numpy"]["rounds"], glshade["rounds"], strict=True)
        ]
        assert r["speedup"]["numpy"]["median"] == pytest.approx(np.median(per_round))
        assert {"stream", "display", "exact64"} <= set(r["ms"])


def test_the_cpu_is_named_by_family_and_model_where_its_name_does_not_say() -> None:
    def named(vendor: str, family: int, model: int) -> str:
        return identity({"vendor_id": vendor, "cpu family": str(family), "model": str(model)})

    # Under KVM this project's AMD machine calls itself "AMD EPYC".
    assert named("AuthenticAMD", 25, 17) == "AuthenticAMD family 25 model 17: Zen 4"
    assert named("AuthenticAMD", 26, 2).endswith(": Zen 5")
    assert named("GenuineIntel", 6, 143).endswith(": Sapphire Rapids")
    assert named("GenuineIntel", 6, 151) == "GenuineIntel family 6 model 151"
    assert identity({"model name": "ARMv8"}) == ""
    assert machine()["cpu"]


@pytest.mark.parametrize("dtype", [np.float32, np.float64])
def test_the_streaming_floor_reads_and_writes_what_shade_does(dtype: type) -> None:
    p, n = (a.astype(dtype) for a in bench_vertices(1_000))
    for read in (False, True):
        got = _glshade.stream(p, n, read)
        assert got.shape == (1_000, 4) and got.dtype == dtype
        np.testing.assert_array_equal(got[:, :3], n)
        w = (p[:, 0] + p[:, 1]) + p[:, 2] if read else np.ones(1_000, dtype)
        np.testing.assert_array_equal(got[:, 3], w)


@pytest.mark.parametrize(
    "args",
    [
        ["bench", "shade", "--sizes", "0"],
        ["bench", "shade", "--faces", "100"],  # another bench's flag
        ["bench", "shade", "--settle", "0"],
        ["bench", "normals", "--sizes", "100"],
        ["bench", "render", "--settle", "0"],
        ["bench", "normals", "--faces", "1"],
        ["bench", "normals", "--settle", "-1"],
        ["bench", "render", "--size", "0"],
        ["report", "--vertices", "0"],
        ["report", "--isa", "sse"],
        ["report", "--compare", "one.json"],  # two files
        ["bench", "cluster", "--chunk", "0"],
        ["bench", "cluster", "--sizes", "100"],
    ],
)
def test_each_command_accepts_only_its_own_valid_flags(
    args: list[str], capsys: pytest.CaptureFixture[str]
) -> None:
    with pytest.raises(SystemExit) as stop:
        cli.main(args)
    assert stop.value.code == 2
    assert "error:" in capsys.readouterr().err


def test_time_rounds_rotates_the_order_and_reports_median_and_spread() -> None:
    calls: list[str] = []
    methods = {name: (lambda name=name: calls.append(name)) for name in "abc"}
    times = time_rounds(methods, 4)
    assert calls[:3] == ["a", "b", "c"]  # the warm-up
    rounds = [calls[3 + 3 * r : 6 + 3 * r] for r in range(4)]
    assert rounds == [list("abc"), list("acb"), list("cab"), list("cba")]
    assert all(len(t.seconds) == 4 for t in times.values())
    t = Timing((3.0, 1.0, 2.0, 10.0))
    assert (t.median, t.low, t.high) == (2.5, 1.0, 10.0)
    assert ratio(Timing((2.0, 6.0)), Timing((1.0, 2.0))).seconds == (2.0, 3.0)
    with pytest.raises(ValueError, match="rounds and burst must be >= 1, got 0 and 1"):
        time_rounds(methods, 0)


def test_time_calibrated_times_each_call_beside_its_kernel_and_cancels_a_drift(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    clock = [0.0]
    monkeypatch.setattr(timing, "time", types.SimpleNamespace(perf_counter=lambda: clock[0]))
    calls: list[str] = []
    cost = {"a": 2.0, "a/k": 1.0, "b": 6.0, "b/k": 2.0}
    slowness = [1.0]  # the shared machine, twice as slow every round

    def call(name: str) -> None:
        calls.append(name)
        clock[0] += cost[name] * slowness[0]

    def slow_down() -> None:
        slowness[0] *= 2

    methods = {n: (lambda n=n: call(n), lambda n=n: call(f"{n}/k")) for n in "ab"}
    times = time_calibrated(methods, 3, burst=2, on_round=slow_down)
    assert calls[:4] == ["a", "a/k", "b", "b/k"]  # the warm-up
    turns = [calls[4 + 8 * r : 12 + 8 * r : 2] for r in range(3)]  # one call of each burst
    assert calls[4:6] == ["a", "a"]  # a burst: the same call twice in a row
    # The method then its kernel, then (rotated and reversed) the kernel first.
    assert turns == [["a", "a/k", "b", "b/k"], ["a/k", "a", "b/k", "b"], ["a", "a/k", "b", "b/k"]]
    assert times["a"].own.seconds == (2.0, 4.0, 8.0)
    assert times["a"].calibration.seconds == (1.0, 2.0, 4.0)
    assert times["a"].relative.seconds == (2.0, 2.0, 2.0)  # the drift cancels
    assert times["b"].relative.seconds == (3.0, 3.0, 3.0)
    with pytest.raises(ValueError, match="rounds and burst must be >= 1, got 2 and 0"):
        time_calibrated(methods, 2, burst=0)
