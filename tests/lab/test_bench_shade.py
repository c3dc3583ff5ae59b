"""The baselines and peers of ``python -m glshade bench shade`` compute the equation glshade
computes, so the benchmark compares like with like (checked here; the timing itself is never a
test); a method that does not is reported as FAILED and not timed; each bench accepts only its
own flags and saves its results as JSON with the machine (``bench shade`` also as CSV)."""

import csv
import json
import os
import types
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from conftest import require

import glshade as gs
from glshade import __main__ as cli
from glshade import _glshade
from glshade.lab import bench_shade, c_loop, timing
from glshade.lab.baselines import numba_shade, numpy_shade
from glshade.lab.bench_shade import CSV_COLUMNS, GRAZING, TOLERANCE, smooth_set, world_smooth_set
from glshade.lab.c_loop import c_shade
from glshade.lab.machine import identity, machine
from glshade.lab.peers import drjit_shade, jax_shade, versions
from glshade.lab.scenes import (
    bench_scenes,
    bench_vertices,
    extra_bench_scenes,
    scene_names,
    shade_scenes,
    world_scenes,
)
from glshade.lab.timing import Timing, ratio, time_calibrated, time_rounds
from glshade.lab.world_peers import drjit_world, numba_world
from support import gltf_reference, threejs_reference

pytestmark = pytest.mark.lab

SCENES = bench_scenes()
GL = {**SCENES, **extra_bench_scenes()}  # the three and the extra four
WORLD = world_scenes()  # three of glTF's model, three of three.js'
EVERY = shade_scenes()


def _reference(name: str, n: int = 4_000) -> tuple[Any, Any, Any]:
    """The bench's float32 vertices and `gs.shade`'s float64 exact result on them."""
    p, normals = bench_vertices(n)
    exact = gs.shade(
        p.astype(np.float64), normals.astype(np.float64), EVERY[name], accuracy="exact"
    )
    return p, normals, exact


@pytest.mark.parametrize("name", GL)
def test_numpy_baseline_is_the_gl_equation(name: str) -> None:
    p, n, reference = _reference(name)
    got = numpy_shade(p, n, EVERY[name])
    assert got.dtype == np.float32
    # float32 arithmetic: a few ulp of the largest term.
    np.testing.assert_allclose(got, reference, rtol=0, atol=2e-6)
    # The scene lights the vertices: the comparison is not of zeros.
    assert (reference[:, :3] > 0.05).mean() > 0.9


@pytest.mark.parametrize("name", GL)
def test_numba_baseline_is_the_gl_equation(name: str) -> None:
    _check_compiled("numba", numba_shade, name)


@pytest.mark.parametrize("name", GL)
def test_the_drjit_peer_is_the_gl_equation(name: str) -> None:
    _check_compiled("drjit", drjit_shade, name)


@pytest.mark.parametrize("name", GL)
def test_the_jax_peer_is_the_gl_equation(name: str) -> None:
    _check_compiled("jax", jax_shade, name)


@pytest.mark.parametrize("name", GL)
def test_the_c_loop_is_the_gl_equation(name: str) -> None:
    shade = c_shade(1)
    # A C compiler is what building glshade from source needs (Rust links with it).
    if isinstance(shade, str) and not os.environ.get("CI"):
        pytest.skip(shade)
    assert not isinstance(shade, str), shade
    p, n, reference = _reference(name)
    got = shade(p, n, EVERY[name])
    assert got.shape == (4_000, 4) and got.dtype == np.float32
    # -ffast-math's reciprocal square roots and vector powf: within the bench's tolerance.
    np.testing.assert_allclose(got, reference, rtol=0, atol=TOLERANCE)
    assert np.abs(got - reference).max() > 0  # the loop ran, not a copy of the reference


def test_the_c_loop_reads_the_columns_of_the_light_table() -> None:
    # The source names the columns; their numbers come from `baselines` as macros.
    for column in ("COS_CUTOFF", "SPOT_EXPONENT", "K2", "VIEWER", "SHININESS", "COLUMNS"):
        assert column in c_loop.SOURCE
    assert {"-O3", "-ffast-math", "-fopenmp"} <= set(c_loop.FLAGS)


def _check_compiled(module: str, make: Any, name: str) -> None:
    """The peer `make` builds (it needs `module`) computes the equation on scene `name`."""
    require(module)
    shade = make()
    assert not isinstance(shade, str), shade
    p, n, reference = _reference(name)
    got = shade(p, n, EVERY[name])
    assert got.shape == (4_000, 4) and got.dtype == np.float32
    np.testing.assert_allclose(got, reference, rtol=0, atol=2e-6)


@pytest.mark.parametrize("peer", ["numba", "drjit"])
@pytest.mark.parametrize("name", WORLD)
def test_the_world_peers_are_the_models(name: str, peer: str) -> None:
    """Dr.Jit's and numba's glTF and three.js models agree with `gs.shade`'s float64 exact
    result off grazing views (|n·v| > GRAZING, where the bench checks them), three.js' within
    float32's few ulp, glTF's within the 3e-5 that pyrender's GGX denominator costs in float32
    near the highlight; the check is of something: the vertices are lit."""
    require(peer)
    shade = {"numba": numba_world, "drjit": drjit_world}[peer]()
    assert not isinstance(shade, str), shade
    p, n, reference = _reference(name)
    got = shade(p, n, WORLD[name])
    assert got.shape == (4_000, 4) and got.dtype == np.float32
    smooth = world_smooth_set(p, n, WORLD[name])
    assert smooth.mean() > 0.98
    atol = 5e-5 if name.startswith("gltf") else 4e-6
    np.testing.assert_allclose(got[smooth], reference[smooth], rtol=0, atol=atol)
    assert (reference[:, :3] > 0.02).mean() > 0.8


@pytest.mark.parametrize("name", WORLD)
def test_glshade_is_within_its_fast_bound_on_the_benchs_world_scenes(name: str) -> None:
    """The fast mode's error on the bench's vertices (every one, grazing views included) is
    within the bound the Accuracy page states, written in float64 in the tests' support."""
    scene = WORLD[name]
    p, n = bench_vertices(4_000)
    fast = gs.shade(p, n, scene, clamp=False)
    exact = gs.shade(p.astype(np.float64), n.astype(np.float64), scene, clamp=False)
    bound = (gltf_reference if name.startswith("gltf") else threejs_reference).fast_bound(
        p.astype(np.float64), n.astype(np.float64), scene
    )
    assert (np.abs(fast[:, :3] - exact[:, :3]) <= bound).all()


def test_the_world_peers_take_only_the_lights_they_model() -> None:
    """A light a peer does not write (three.js' hemisphere light, a light with a reach) is
    refused, so the bench reports it FAILED rather than timing another equation."""
    require("numba")
    p, n = bench_vertices(16)
    for scene in (
        gs.threejs.Scene([gs.threejs.HemisphereLight()]),
        gs.threejs.Scene([gs.threejs.PointLight(distance=5.0)]),
    ):
        with pytest.raises(NotImplementedError, match="no peer"):
            numba_world()(p, n, scene)  # type: ignore[operator]


def test_the_world_smooth_set_leaves_out_grazing_views() -> None:
    scene = WORLD["gltf directional"]
    p = np.array([[0.0, 0.0, -3.0]] * 3)
    n = np.array([[1.0, 0.0, 0.0], [1.0, 0.0, 2 * GRAZING], [0.0, 0.0, 0.0]])
    assert world_smooth_set(p, n, scene).tolist() == [False, True, False]


def test_the_peers_name_their_versions() -> None:
    found = versions()
    assert {"numba", "drjit", "jax", "jaxlib"} <= set(found)
    assert all(isinstance(v, str) and v for v in found.values())


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


def test_the_extra_scenes_are_those_of_the_issue() -> None:
    extra = extra_bench_scenes()
    assert list(extra) == ["16 mixed", "2 directional", "spot 2.5", "32 point"]
    mixed = extra["16 mixed"].lights
    assert len(mixed) == 16 and extra["16 mixed"].viewer[3] == 1
    kinds = {
        ("directional" if light.position[3] == 0 else "point")
        + (" spot" if light.spot_cutoff != 180 else "")
        for light in mixed
    }
    assert kinds == {"directional", "point", "point spot"}
    two = extra["2 directional"]
    assert [light.position[3] for light in two.lights] == [0, 0] and two.viewer[3] == 0
    spot = extra["spot 2.5"]
    assert [light.spot_exponent for light in spot.lights if light.spot_cutoff != 180] == [2.5]
    assert [light.position[3] for light in spot.lights] == [1, 1] and spot.viewer[3] == 1
    points = extra["32 point"].lights
    assert len(points) == 32
    assert all(light.position[3] == 1 and light.spot_cutoff == 180 for light in points)
    assert all(light.linear_attenuation + light.quadratic_attenuation > 0 for light in points)


def test_the_world_scenes_are_those_of_the_issue() -> None:
    """Per model: a directional light; a point, a directional and a spot light; the three with
    an ambient light."""
    for model, module in (("gltf", gs.gltf), ("threejs", gs.threejs)):
        kinds = [
            sorted(type(light).__name__ for light in WORLD[f"{model} {name}"].lights)
            for name in ("directional", "3 lights", "3 lights, ambient")
        ]
        three = ["DirectionalLight", "PointLight", "SpotLight"]
        assert kinds[:2] == [["DirectionalLight"], three]
        with_ambient = WORLD[f"{model} 3 lights, ambient"]
        assert isinstance(with_ambient, module.Scene)
        if model == "gltf":
            assert kinds[2] == three and max(with_ambient.ambient_light) > 0
        else:
            assert kinds[2] == ["AmbientLight", *three]


def test_scenes_are_chosen_by_name_and_group(monkeypatch: pytest.MonkeyPatch) -> None:
    assert scene_names("all") == list(EVERY) == [*GL, *WORLD]
    assert scene_names("bench") == list(SCENES)
    assert scene_names("gl") == list(GL)
    assert scene_names("world") == list(WORLD)
    # A name's own comma stays in it; a name given twice counts once.
    assert scene_names("1 point, local viewer,spot 2.5, 8 mixed,spot 2.5") == [
        "1 point, local viewer",
        "spot 2.5",
        "8 mixed",
    ]
    assert scene_names("extra,bench")[:4] == list(extra_bench_scenes())
    for wrong in ("", "1 point", "8 mixed,nine mixed"):
        with pytest.raises(ValueError, match="no scene"):
            scene_names(wrong)
    given: list[dict[str, Any]] = []
    monkeypatch.setattr(bench_shade, "bench_shade", lambda *args, **kw: given.append(kw) or 0)
    assert cli.main(["bench", "shade"]) == 0
    assert cli.main(["bench", "shade", "--scenes", "bench", "--no-threads-check"]) == 0
    assert given == [
        {"scenes": list(EVERY), "threads_check": True},
        {"scenes": list(SCENES), "threads_check": False},
    ]


@pytest.mark.parametrize("name", GL)
def test_the_smooth_set_holds_most_vertices(name: str) -> None:
    p, n = bench_vertices(4_000)
    assert smooth_set(p, n, EVERY[name]).mean() > 0.98


def test_the_smooth_set_leaves_out_vertices_on_a_kink() -> None:
    # One vertex on the gate of the point light (n . VP = 0), one on the spot's cone, one that
    # is well inside both; and a zero normal.
    point = gs.Scene([gs.Light(position=(1.0, 2.0, 3.0, 1.0))], viewer=(0, 0, 0, 1))
    p = np.array([[0.0, 0.0, -3.0], [0.0, 0.0, -3.0], [0.0, 0.0, -3.0]])
    to_light = np.array([1.0, 2.0, 6.0])
    n = np.array([[2.0, -1.0, 0.0], [0.0, 0.0, 1.0], [0.0, 0.0, 0.0]])
    assert n[0] @ to_light == 0
    assert smooth_set(p, n, point).tolist() == [False, True, False]
    spot = extra_bench_scenes()["spot 2.5"]
    light = spot.lights[0]
    axis = np.asarray(light.spot_direction) / np.linalg.norm(light.spot_direction)
    side = np.cross(axis, [1.0, 0.0, 0.0])
    side /= np.linalg.norm(side)
    edge = np.radians(light.spot_cutoff)
    on_cone = np.asarray(light.position[:3]) + 2.0 * (np.cos(edge) * axis + np.sin(edge) * side)
    inside = np.asarray(light.position[:3]) + 2.0 * axis
    normals = np.array([[0.0, 0.0, 1.0], [0.0, 0.0, 1.0]])
    assert smooth_set(np.array([on_cone, inside]), normals, spot).tolist() == [False, True]


def test_bench_shade_runs_prints_every_scene_and_saves_json_and_csv(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    path = tmp_path / "b.json"
    args = ["bench", "shade", "--sizes", "100,200", "--repeat", "2", "--json", str(path)]
    assert cli.main([*args, "--scenes", "bench"]) == 0
    out = capsys.readouterr().out
    for name in SCENES:
        assert f"\n{name}: fast: float32" in out
    assert "per-call overhead" in out and f"wrote {path}" in out
    cpu = machine()
    assert f"CPU: {cpu['cpu']}; glshade's instruction set: {cpu['instruction_set']}" in out
    assert "of stream f64 exact" in out  # the header: no display column between them
    assert "x drjit" in out and "x c" in out and "max |error| on the smooth set" in out
    assert "C loop: " in out and "-O3 -march=native -ffast-math -fopenmp" in out
    found = versions()
    assert f"numba {found['numba']}, drjit {found['drjit']}" in out
    assert f"jax {found['jax']}, jaxlib {found['jaxlib']}" in out
    assert "FAILED (" not in out and "not timed\n" not in out
    # The thread scaling: glshade in two child processes, 1 and 2 threads, the largest size.
    assert "threads: glshade on 8 mixed, 200 vertices" in out and "2 threads: " in out
    saved = json.loads(path.read_text())
    assert saved["bench"] == "shade" and saved["settings"]["sizes"] == [100, 200]
    assert saved["settings"]["versions"] == found
    assert saved["settings"]["scenes"] == list(SCENES)
    threads = saved["results"]["threads"]
    assert threads["vertices"] == 200 and set(threads["mvert_s"]) == {"1", "2"}
    assert len(threads["ms"]["2"]["rounds"]) == 2 and set(threads["speedup"]) == {"2"}
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
        assert {"stream", "exact64"} <= set(r["ms"])
        checked = {"glshade", "exact64", "numpy", "numba", "c", "drjit", "jax"}
        assert set(r["error_smooth"]) == checked and r["failed"] == {}
        assert all(e <= TOLERANCE for e in r["error_smooth"].values())
        assert set(r["mvert_s"]) == {*checked, "stream"} and r["smooth_vertices"] > 0
    with path.with_suffix(".csv").open(newline="") as file:
        rows = list(csv.reader(file))
    assert tuple(rows[0]) == CSV_COLUMNS
    table = [dict(zip(CSV_COLUMNS, row, strict=True)) for row in rows[1:]]
    assert len(table) == 3 * 2 * 8  # scenes, sizes, methods
    first = saved["results"]["scenes"][0]
    numba = next(row for row in table if row["method"] == "numba")
    assert (numba["scene"], numba["vertices"]) == ("1 directional", "100")
    assert float(numba["mvert_s"]) == pytest.approx(first["mvert_s"]["numba"])
    assert float(numba["ratio_glshade_over_method"]) == first["speedup"]["numba"]["median"]
    assert float(numba["err_smooth"]) == first["error_smooth"]["numba"]
    stream = next(row for row in table if row["method"] == "stream")
    assert stream["err_smooth"] == "" and float(stream["ms_median"]) > 0


def test_a_method_off_the_equation_is_failed_and_not_timed(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    calls = []

    def off(p: Any, n: Any, scene: gs.Scene) -> Any:
        calls.append(len(p))
        return numpy_shade(p, n, scene) * np.float32(0.99)  # 1% off

    monkeypatch.setattr(bench_shade, "drjit_shade", lambda: off)
    monkeypatch.setattr(bench_shade, "jax_shade", lambda: "JAX is away: no JAX peer")
    path = tmp_path / "f.json"
    code = bench_shade.bench_shade((300,), 1, str(path), ["1 directional"], threads_check=False)
    assert code == 0 and calls == [300]  # checked once, never timed
    out = capsys.readouterr().out
    assert "drjit FAILED (error " in out and "not timed" in out
    assert "JAX is away: no JAX peer" in out and "threads:" not in out
    row = json.loads(path.read_text())["results"]["scenes"][0]
    assert row["failed"]["drjit"].startswith("error ") and row["error_smooth"]["drjit"] > 1e-3
    assert "drjit" not in row["mvert_s"] and "drjit" not in row["speedup"]
    assert "jax" not in row["error_smooth"] and "jax" not in row["mvert_s"]
    with path.with_suffix(".csv").open(newline="") as file:
        drjit = [r for r in csv.DictReader(file) if r["method"] == "drjit"]
    assert len(drjit) == 1 and drjit[0]["mvert_s"] == drjit[0]["ratio_glshade_over_method"] == ""
    assert float(drjit[0]["err_smooth"]) > 1e-3


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
        ["bench", "shade", "--scenes", "9 mixed"],
        ["bench", "shade", "--scenes", ""],
        ["bench", "normals", "--scenes", "bench"],
        ["bench", "render", "--no-threads-check"],
        ["bench", "normals", "--sizes", "100"],
        ["bench", "render", "--settle", "0"],
        ["bench", "normals", "--faces", "1"],
        ["bench", "normals", "--settle", "-1"],
        ["bench", "render", "--size", "0"],
        ["bench", "render", "--scenes", "torus,sphere"],
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
