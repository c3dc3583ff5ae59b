"""The baselines of ``python -m glshade bench shade`` compute the equation glshade computes, so
the benchmark compares like with like (checked here; the timing itself is never a test)."""

import numpy as np
import pytest
from conftest import require

import glshade as gs
from glshade import __main__ as cli
from glshade._bench_shade import bench_scenes, bench_vertices, numba_shade, numpy_shade

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


def test_bench_shade_runs_and_prints_every_scene(capsys: pytest.CaptureFixture[str]) -> None:
    assert cli.main(["bench", "shade", "--sizes", "100", "--repeat", "1"]) == 0
    out = capsys.readouterr().out
    for name in SCENES:
        assert f"\n{name}: fast: float32" in out
    assert "per-call overhead" in out


def test_bench_shade_rejects_bad_sizes() -> None:
    with pytest.raises(SystemExit):
        cli.main(["bench", "shade", "--sizes", "0"])
