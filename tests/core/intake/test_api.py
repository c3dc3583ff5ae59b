"""The Python boundary: dtypes, memory layouts, `out=`, error messages, many lights, the GIL and
thread-count independence."""

from __future__ import annotations

import hashlib
import inspect
import time
from pathlib import Path
from typing import Any

import numpy as np
import pytest

import glshade as gs
from support.gil import count_while
from support.gl_reference import RefScene, gl_lighting
from support.processes import passes


def vertices(
    rng: np.random.Generator, n: int, dtype: Any = np.float64
) -> tuple[np.ndarray, np.ndarray]:
    return rng.uniform(-1, 1, (n, 3)).astype(dtype), rng.normal(size=(n, 3)).astype(dtype)


SCENE = gs.Scene(
    lights=[
        gs.Light(position=(1, 2, 3, 1), linear_attenuation=0.3),
        gs.Light(position=(0, 1, 0, 0)),
    ],
    material=gs.Material(specular=(1, 1, 1), shininess=20),
)


# --- dtypes and layouts ----------------------------------------------------------------------


@pytest.mark.parametrize(
    ("p_dtype", "n_dtype", "result"),
    [
        (np.float32, np.float32, np.float32),
        (np.float64, np.float64, np.float64),
        (np.float32, np.float64, np.float64),
        (np.float16, np.float16, np.float32),
    ],
)
def test_result_dtype_follows_the_inputs(
    p_dtype: Any, n_dtype: Any, result: Any, rng: np.random.Generator
) -> None:
    p, n = vertices(rng, 5)
    assert gs.shade(p.astype(p_dtype), n.astype(n_dtype), SCENE).dtype == result


def test_python_sequences_compute_in_float64() -> None:
    out = gs.shade([[0, 0, 0]], [[0, 0, 1]], gs.Scene(lights=[gs.Light()]))
    assert out.dtype == np.float64
    np.testing.assert_allclose(out, [[0.84, 0.84, 0.84, 1.0]], atol=1e-15)


@pytest.mark.parametrize("dtype", [np.float32, np.float64])
def test_fortran_and_strided_views_give_the_contiguous_result(
    dtype: Any, rng: np.random.Generator
) -> None:
    p, n = vertices(rng, 101, dtype)
    expected = gs.shade(p, n, SCENE)
    np.testing.assert_array_equal(
        gs.shade(np.asfortranarray(p), np.asfortranarray(n), SCENE), expected
    )
    wide_p = np.zeros((101, 7), dtype)
    wide_p[:, 2:5] = p
    strided_n = np.repeat(n, 2, axis=0)[::2]
    assert not wide_p[:, 2:5].flags.c_contiguous and not strided_n.flags.c_contiguous
    np.testing.assert_array_equal(gs.shade(wide_p[:, 2:5], strided_n, SCENE), expected)
    reversed_rows = gs.shade(p[::-1], n[::-1], SCENE)
    np.testing.assert_array_equal(reversed_rows, expected[::-1])


def test_empty_input_gives_an_empty_result() -> None:
    assert gs.shade(np.zeros((0, 3)), np.zeros((0, 3)), SCENE).shape == (0, 4)
    two = gs.Scene(lights=[gs.Light()], two_side=True)
    assert gs.shade(np.zeros((0, 3), np.float32), np.zeros((0, 3), np.float32), two).shape == (
        2,
        0,
        4,
    )


def test_output_shape_follows_the_light_model(rng: np.random.Generator) -> None:
    p, n = vertices(rng, 3)
    for two_side in (False, True):
        for separate in (False, True):
            scene = gs.Scene(lights=[gs.Light()], two_side=two_side, separate_specular=separate)
            out = gs.shade(p, n, scene)
            k = len(scene.outputs)
            assert out.shape == ((3, 4) if k == 1 else (k, 3, 4))
    assert gs.Scene(two_side=True, separate_specular=True).outputs == (
        "front_primary",
        "front_secondary",
        "back_primary",
        "back_secondary",
    )


@pytest.mark.parametrize("dtype", [np.float32, np.float64])
def test_out_is_filled_and_returned(dtype: Any, rng: np.random.Generator) -> None:
    p, n = vertices(rng, 50, dtype)
    scene = gs.Scene(lights=SCENE.lights, two_side=True)
    out = np.full((2, 50, 4), -1.0, dtype)
    result = gs.shade(p, n, scene, out=out)
    assert result is out
    np.testing.assert_array_equal(out, gs.shade(p, n, scene))


@pytest.mark.parametrize("dtype", [np.float32, np.float64])
@pytest.mark.parametrize("n", [1, 63, 64, 65, 200, 20_000])
@pytest.mark.parametrize("two_side,separate", [(False, False), (True, False), (True, True)])
def test_new_outputs_are_written_everywhere(
    dtype: Any, n: int, two_side: bool, separate: bool, rng: np.random.Generator
) -> None:
    # New results start uninitialised (as numpy's ufunc outputs do): memory just freed full of
    # a sentinel is what the allocator hands out next, so an unwritten element would show.
    p, normals = vertices(rng, n, dtype)
    scene = gs.Scene(lights=SCENE.lights, two_side=two_side, separate_specular=separate)
    planes = len(scene.outputs)
    shape = (n, 4) if planes == 1 else (planes, n, 4)
    expected = gs.shade(p, normals, scene, out=np.full(shape, 7.0, dtype))
    for _ in range(3):
        sentinel = np.full(shape, 7.0, dtype)
        del sentinel
        result = gs.shade(p, normals, scene)
        assert result.shape == shape and result.dtype == dtype
        np.testing.assert_array_equal(result, expected)
        assert (result <= 1).all()


# --- bad input -------------------------------------------------------------------------------

P, N = vertices(np.random.default_rng(2024), 4)  # fixed: the cases below are built once


@pytest.mark.parametrize(
    ("call", "exception", "words"),
    [
        (lambda: gs.shade(P[:, :2], N, SCENE), ValueError, ["positions", "(..., 3)", "(4, 2)"]),
        (lambda: gs.shade(P[:, 0], N, SCENE), ValueError, ["positions", "(4,)"]),
        (
            lambda: gs.shade(P[None, :3], N, SCENE),
            ValueError,
            ["broadcast", "positions (1, 3, 3)", "normals (4, 3)"],
        ),
        (lambda: gs.shade(P, N[:3], SCENE), ValueError, ["broadcast", "normals (3, 3)"]),
        (lambda: gs.shade(P, N.astype(np.complex128), SCENE), TypeError, ["normals", "complex128"]),
        (lambda: gs.shade(P.astype(np.longdouble), N, SCENE), TypeError, ["positions", "float"]),
        (lambda: gs.shade([["a", "b", "c"]], [[0, 0, 1]], SCENE), TypeError, ["positions"]),
        (lambda: gs.shade(P, N, "scene"), TypeError, ["scene", "Scene"]),
        (
            lambda: gs.shade(P, N, SCENE, colors=np.ones((4, 2))),
            ValueError,
            ["colors", "(..., 3) or (..., 4)", "(4, 2)"],
        ),
        (
            lambda: gs.shade(P, N, SCENE, colors=np.ones((5, 3))),
            ValueError,
            ["broadcast", "colors (5, 3)"],
        ),
        (
            lambda: gs.shade(P, N, SCENE, color_material="diffuse"),
            ValueError,
            ["color_material", "colors"],
        ),
        (
            lambda: gs.shade(P, N, SCENE, colors=np.ones((4, 3)), color_material="shiny"),
            ValueError,
            ["color_material", "'shiny'"],
        ),
        (
            lambda: gs.shade(P, N, SCENE, colors=np.ones((4, 3)), color_material_face="both"),
            ValueError,
            ["color_material_face", "'both'"],
        ),
        (
            lambda: gs.shade(P, N, SCENE, modelview=np.eye(3)),
            ValueError,
            ["modelview", "(4, 4)", "(3, 3)"],
        ),
        (
            lambda: gs.shade(P, N, SCENE, modelview=np.diag([1, 0, 1, 1])),
            ValueError,
            ["modelview", "invertible"],
        ),
        (
            lambda: gs.shade(P, N, SCENE, modelview=np.ones((4, 4))),
            ValueError,
            ["modelview", "affine"],
        ),
        (
            lambda: gs.shade(P, N, SCENE, modelview=np.full((4, 4), np.nan)),
            ValueError,
            ["modelview", "finite"],
        ),
        (
            lambda: gs.shade(P, N, SCENE, out=np.zeros((4, 3))),
            ValueError,
            ["out", "(4, 4)", "(4, 3)"],
        ),
        (
            lambda: gs.shade(P, N, SCENE, out=np.zeros((4, 4), np.float32)),
            TypeError,
            ["out", "float64", "float32"],
        ),
        (
            lambda: gs.shade(P, N, SCENE, out=np.zeros((4, 8))[:, ::2]),
            ValueError,
            ["out", "contiguous"],
        ),
        (lambda: gs.shade(P, N, SCENE, out=[[0.0] * 4] * 4), TypeError, ["out", "numpy array"]),
        (lambda: gs.Light(spot_cutoff=95), ValueError, ["spot_cutoff", "[0, 90]", "180", "95"]),
        (lambda: gs.Light(spot_cutoff=-1), ValueError, ["spot_cutoff", "-1"]),
        (lambda: gs.Light(spot_cutoff=179.9), ValueError, ["spot_cutoff", "179.9"]),
        (lambda: gs.Light(spot_exponent=-2), ValueError, ["spot_exponent", ">= 0", "-2"]),
        (
            lambda: gs.Light(constant_attenuation=-1),
            ValueError,
            ["constant_attenuation", ">= 0", "-1"],
        ),
        (lambda: gs.Light(linear_attenuation=-0.1), ValueError, ["linear_attenuation", "-0.1"]),
        (
            lambda: gs.Light(quadratic_attenuation=float("nan")),
            ValueError,
            ["quadratic_attenuation", "NaN"],
        ),
        (lambda: gs.Light(position=(1, 2, 3)), ValueError, ["position", "(4,)", "(3,)"]),
        (lambda: gs.Light(position=(0, 0, 0, 0)), ValueError, ["position", "direction"]),
        (lambda: gs.Light(diffuse=(1, 1)), ValueError, ["diffuse", "(3,)", "(2,)"]),
        (lambda: gs.Light(specular=(np.inf, 0, 0)), ValueError, ["specular", "finite", "inf"]),
        (
            lambda: gs.Light(position=(0, 0, 1, 1), constant_attenuation=0),
            ValueError,
            ["attenuation", "positional"],
        ),
        (
            lambda: gs.Light(spot_cutoff=10, spot_direction=(0, 0, 0)),
            ValueError,
            ["spot_direction", "nonzero"],
        ),
        (lambda: gs.Light(position="above"), TypeError, ["position"]),
        (
            lambda: gs.Lights(position=np.ones((3, 4)), diffuse=np.ones((2, 3))),
            ValueError,
            ["same number of rows", "position: 3", "diffuse: 2"],
        ),
        (lambda: gs.Lights(spot_cutoff=[10, 200]), ValueError, ["spot_cutoff of light 1", "200"]),
        (lambda: gs.Material(shininess=-1), ValueError, ["shininess", ">= 0", "-1"]),
        (lambda: gs.Material(emission=(0, 0, np.nan)), ValueError, ["emission", "finite"]),
        (
            lambda: gs.Material(ambient=np.ones((2, 3))),
            ValueError,
            ["ambient", "(3,) or (4,)", "(2, 3)"],
        ),
        (
            lambda: gs.Scene(specular="cook-torrance"),
            ValueError,
            ["specular", "'blinn' or 'phong'", "cook-torrance"],
        ),
        (lambda: gs.Scene(viewer=(0, 0, 1)), ValueError, ["viewer", "(4,)", "(3,)"]),
        (lambda: gs.Scene(viewer=(0, 0, 0, 0)), ValueError, ["viewer"]),
        (lambda: gs.Scene(global_ambient=(0, np.nan, 0)), ValueError, ["global_ambient", "finite"]),
        (lambda: gs.Scene(lights=[gs.Light(), "sun"]), TypeError, ["lights[1]"]),
        (lambda: gs.Scene(material="gold"), TypeError, ["material"]),
        (lambda: gs.Lights(count=3)[3], IndexError, ["3"]),
    ],
)
def test_bad_input_raises_a_clear_error(call: Any, exception: type, words: list[str]) -> None:
    with pytest.raises(exception) as info:
        call()
    message = str(info.value)
    for word in words:
        assert word in message, f"{word!r} not in {message!r}"


def test_native_module_rejects_bad_arrays_without_crashing() -> None:
    from glshade import _glshade

    native = SCENE._native
    tail: dict[str, Any] = {
        "modelview": None,
        "normalize": False,
        "rescale_normal": False,
        "colors": None,
        "color_material": None,
        "color_material_face": "front_and_back",
        "accuracy": "fast",
        "strict": False,
        "clamp": True,
        "out": None,
    }
    with pytest.raises(TypeError, match="positions must be float32 or float64"):
        _glshade.shade(P.astype(np.int32), N, native, **tail)
    with pytest.raises(TypeError, match="normals"):
        _glshade.shade(P, N.astype(np.float32), native, **tail)
    with pytest.raises(ValueError, match="C-contiguous"):
        _glshade.shade(np.asfortranarray(P), N, native, **tail)
    with pytest.raises(TypeError, match="Scene"):
        _glshade.shade(P, N, SCENE, **tail)
    with pytest.raises(ValueError, match="position must be"):
        _glshade.Lights([np.zeros(5)] + [np.zeros(())] * 11)
    with pytest.raises(TypeError, match="expected 5 parameters"):
        _glshade.Material([np.zeros(4)])


# --- many lights -----------------------------------------------------------------------------


def test_ten_thousand_lights_from_arrays() -> None:
    count = 10_000
    rng = np.random.default_rng(5)
    positions = np.c_[rng.uniform(-5, 5, (count, 3)), np.where(rng.random(count) < 0.3, 0.0, 1.0)]
    lights = gs.Lights(
        position=positions,
        diffuse=rng.uniform(0, 2e-4, (count, 3)),
        specular=rng.uniform(0, 2e-4, (count, 4)),
        ambient=(1e-5, 1e-5, 1e-5),
        linear_attenuation=rng.uniform(0, 1, count),
        spot_cutoff=np.where(rng.random(count) < 0.5, 180.0, rng.uniform(10, 90, count)),
        spot_exponent=rng.uniform(0, 10, count),
        spot_direction=rng.normal(size=(count, 3)),
    )
    assert len(lights) == count
    material = {
        "ambient": (0.2, 0.2, 0.2),
        "diffuse": (0.8, 0.7, 0.6),
        "specular": (1, 1, 1),
        "emission": (0, 0, 0),
        "shininess": 16.0,
    }
    scene = gs.Scene(lights=lights, material=gs.Material(**material), viewer=(0, 0, 0, 1))
    p, n = vertices(rng, 8)
    n /= np.linalg.norm(n, axis=1, keepdims=True)
    got = gs.shade(p, n, scene)
    columns = {name: getattr(lights, name) for name in inspect.signature(gs.Light).parameters}
    ref_lights = [{name: column[i] for name, column in columns.items()} for i in range(count)]
    ref = gl_lighting(p, n, RefScene(lights=ref_lights, material=material, viewer=(0, 0, 0, 1)))
    np.testing.assert_allclose(got, ref.outputs[0], atol=1e-12 * max(1, ref.magnitude.max()))
    got32 = gs.shade(p.astype(np.float32), n.astype(np.float32), scene)
    ref32 = gl_lighting(
        p.astype(np.float32),
        n.astype(np.float32),
        RefScene(lights=ref_lights, material=material, viewer=(0, 0, 0, 1)),
    )
    np.testing.assert_allclose(got32, ref32.outputs[0], atol=1e-5)


def test_lights_can_be_mixed_and_indexed() -> None:
    many = gs.Lights(position=[(0, 0, 1, 0), (1, 1, 1, 1)], diffuse=(0.5, 0.5, 0.5))
    scene = gs.Scene(lights=[gs.Light(), many])
    assert len(scene.lights) == 3
    assert scene.lights[2].position.tolist() == [1, 1, 1, 1]
    assert scene.lights[1].diffuse.tolist() == [0.5, 0.5, 0.5, 1.0]
    assert many.spot_cutoff.tolist() == [180, 180]
    assert gs.Light(spot_cutoff=45).spot_cutoff == 45
    assert gs.Light() == gs.Lights()
    assert "directional" in repr(many)


# --- the GIL and threads ---------------------------------------------------------------------


def test_shade_releases_the_gil(rng: np.random.Generator) -> None:
    p, n = vertices(rng, 1_000_000, np.float32)
    lights = gs.Lights(
        position=np.c_[rng.normal(size=(16, 3)), np.ones(16)], linear_attenuation=0.1
    )
    scene = gs.Scene(
        lights=lights, material=gs.Material(specular=(1, 1, 1), shininess=30), viewer=(0, 0, 0, 1)
    )
    free = count_while(lambda: time.sleep(0.3))
    during = count_while(lambda: gs.shade(p, n, scene))
    # Measured on 2 cores: ~0.3-0.6 of the free rate with the GIL released, ~0.03 without it.
    assert during > 0.15 * free, f"counter ran at {during / free:.3f} of its free rate"


@pytest.mark.subprocess
def test_results_do_not_depend_on_the_thread_count() -> None:
    # rayon's pool size is fixed per process: one process per count, the same bits from each.
    digests = {passes("shade_digest", threads=threads).strip() for threads in (1, 2, 5)}
    assert len(digests) == 1


# --- packaging -------------------------------------------------------------------------------


def test_typing_files_are_shipped() -> None:
    package = Path(gs.__file__).parent
    assert (package / "py.typed").exists()
    assert (package / "_glshade.pyi").exists()
    assert hashlib.sha256((package / "_glshade.pyi").read_bytes()).hexdigest()


def test_specular_gate_is_part_of_the_scene() -> None:
    scene = gs.Scene()
    assert scene.specular_gate is True
    off = gs.Scene(specular_gate=False)
    assert "specular_gate=False" in repr(off)
    assert off != scene
    assert gs.Scene(specular_gate=False) == off
    assert gs.Scene(specular="phong") != scene
    with pytest.raises(TypeError, match="specular_gate must be True or False, got 'no'"):
        gs.Scene(specular_gate="no")  # type: ignore[arg-type]


# --- documentation -----------------------------------------------------------------------------


@pytest.mark.shapes  # Scene.plan's example prints the shape of its kernel
def test_the_docstring_examples_print_what_they_say() -> None:
    import doctest
    import importlib
    import pkgutil

    attempted = doctest.testmod(gs, optionflags=doctest.ELLIPSIS).attempted
    for info in pkgutil.walk_packages(gs.__path__, "glshade."):  # glshade.glsl's modules too
        if info.name.rsplit(".", 1)[-1].startswith("_bench") or info.name.endswith("__main__"):
            continue
        module = importlib.import_module(info.name)
        result = doctest.testmod(module, optionflags=doctest.ELLIPSIS, verbose=False)
        assert result.failed == 0, info.name
        attempted += result.attempted
    assert attempted >= 30
