"""`accuracy="display"`, the removed display tier's name: a deprecated alias of ``"fast"`` that
warns (`DeprecationWarning`, at the caller's line, once per call) and computes ``"fast"``'s bits,
in `gs.shade` (in memory and over dask), `gs.shade_mesh` and `Scene.plan`, whatever its case
(names of options are case-insensitive). Unknown modes and non-strings are still refused."""

from __future__ import annotations

import importlib
import warnings
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from conftest import require

import glshade as gs
from glshade.lab.scenes import bench_scenes, bench_vertices

# The warning names the removed tier and the mode that runs instead.
REMOVED = r"(?s)display.*fast"
# Spellings a caller may have written: the intake lower-cases names.
SPELLINGS = ["display", "DISPLAY", "Display"]


def _with_shininess(scene: gs.Scene, shininess: float) -> gs.Scene:
    """`scene` with the material's shininess replaced (a non-integer one takes exp and ln, where
    the display tier ran its own polynomials)."""
    m = scene.material
    material = gs.Material(m.ambient, m.diffuse, m.specular, m.emission, shininess)
    return gs.Scene(scene.lights, material=material, viewer=scene.viewer)


def _same_bits(a: Any, b: Any) -> None:
    a, b = np.asarray(a), np.asarray(b)
    assert a.dtype == b.dtype and a.shape == b.shape
    assert a.tobytes() == b.tobytes()


def _warned_here(record: pytest.WarningsRecorder) -> None:
    """One DeprecationWarning, pointing at this file (the caller's line), not into glshade."""
    assert len(record) == 1, [str(w.message) for w in record]
    (warning,) = record
    assert warning.category is DeprecationWarning
    assert Path(warning.filename).resolve() == Path(__file__).resolve(), warning.filename
    message = str(warning.message)
    assert "removed" in message and "2^-10" in message and "will be removed" in message


@pytest.mark.parametrize("spelling", SPELLINGS)
@pytest.mark.parametrize("shininess", [None, 31.7])
@pytest.mark.parametrize("dtype", [np.float32, np.float64])
@pytest.mark.parametrize("name", list(bench_scenes()))
def test_shade_warns_and_gives_fasts_bits(
    name: str, dtype: type, shininess: float | None, spelling: str
) -> None:
    scene = bench_scenes()[name]
    if shininess is not None:
        scene = _with_shininess(scene, shininess)
    p, n = (a.astype(dtype) for a in bench_vertices(20_000, seed=3))
    fast = gs.shade(p, n, scene, accuracy="fast")
    with pytest.warns(DeprecationWarning, match=REMOVED) as record:
        got = gs.shade(p, n, scene, accuracy=spelling)  # type: ignore[arg-type]
    _warned_here(record)
    assert got.dtype == dtype
    _same_bits(got, fast)


@pytest.mark.parametrize("spelling", SPELLINGS)
def test_every_option_and_out_as_with_fast(spelling: str) -> None:
    scene = gs.Scene(
        lights=[gs.Light(position=(1, 2, 3, 1)), gs.Light(position=(0, 0, 1, 0))],
        material=gs.Material(specular=(0.5, 0.5, 0.5), shininess=20.5),
        two_side=True,
        separate_specular=True,
    )
    rng = np.random.default_rng(8)
    p = rng.normal(size=(1000, 3)).astype(np.float32)
    n = rng.normal(size=(1000, 3)).astype(np.float32) * 3
    colors = rng.uniform(size=(1000, 4)).astype(np.float32)
    options: dict[str, Any] = {"normalize": True, "colors": colors, "clamp": False}
    fast = gs.shade(p, n, scene, accuracy="fast", **options)
    out = np.empty_like(fast)
    with pytest.warns(DeprecationWarning, match=REMOVED) as record:
        got = gs.shade(p, n, scene, accuracy=spelling, out=out, **options)  # type: ignore[arg-type]
    _warned_here(record)
    assert got is out
    _same_bits(got, fast)


@pytest.mark.parametrize("spelling", SPELLINGS)
@pytest.mark.parametrize("dtype", [np.float32, np.float64])
def test_the_plan_warns_and_is_fasts(dtype: type, spelling: str) -> None:
    scene = bench_scenes()["8 mixed"]
    with pytest.warns(DeprecationWarning, match=REMOVED) as record:
        plan = scene.plan(dtype, accuracy=spelling)  # type: ignore[arg-type]
    _warned_here(record)
    assert plan == scene.plan(dtype, accuracy="fast")
    assert plan.startswith(f"fast: {np.dtype(dtype).name} arithmetic")


def test_shade_mesh_warns_at_the_callers_line() -> None:
    vertices = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], np.float32)
    faces = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
    scene = bench_scenes()["8 mixed"]
    fast = gs.shade_mesh(vertices, faces, scene=scene, accuracy="fast")
    with pytest.warns(DeprecationWarning, match=REMOVED) as record:
        got = gs.shade_mesh(vertices, faces, scene=scene, accuracy="display")
    _warned_here(record)
    _same_bits(got, fast)


def test_over_dask_it_warns_once_here_and_the_tasks_run_fast() -> None:
    da: Any = require("dask.array")
    gsd = importlib.import_module("glshade.dask")
    scene = bench_scenes()["8 mixed"]
    p, n = bench_vertices(3_000, seed=4)
    fast = gs.shade(p, n, scene)
    for call in (gs.shade, gsd.shade):
        with pytest.warns(DeprecationWarning, match=REMOVED) as record:
            lazy = call(da.from_array(p, chunks=1_000), n, scene, accuracy="display")
        _warned_here(record)
        # The graph holds "fast": computing it warns no more (warnings are errors here).
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            got = lazy.compute(scheduler="synchronous")
        _same_bits(got, fast)


def test_fast_and_exact_do_not_warn_and_bad_modes_are_refused() -> None:
    scene = bench_scenes()["8 mixed"]
    p, n = bench_vertices(4)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        gs.shade(p, n, scene, accuracy="FAST")
        gs.shade(p, n, scene, accuracy="exact")
        scene.plan(accuracy="exact")
    # The native module's message lists the two modes; "display" never reaches it.
    with pytest.raises(ValueError, match="accuracy must be 'fast' or 'exact', got 'draft'"):
        gs.shade(p, n, scene, accuracy="draft")  # type: ignore[arg-type]
    with pytest.raises(ValueError, match="accuracy must be 'fast' or 'exact', got 'draft'"):
        scene.plan(accuracy="draft")  # type: ignore[arg-type]
    with pytest.raises(TypeError, match="accuracy must be a string"):
        gs.shade(p, n, scene, accuracy=1)  # type: ignore[arg-type]
