"""The range: finite input gives finite output in [0, 1] (extreme parameters, modelviews scaled
far from one, float32 beyond its range), and images of huge triangles are those of small ones."""

from __future__ import annotations

import inspect
from typing import Any

import numpy as np
import pytest

import glshade as gs
from support.boundary import LIT, MIXED, SUN, rows


def finite_in_unit(a: np.ndarray) -> bool:
    return bool(np.isfinite(a).all() and (a >= 0).all() and (a <= 1).all())


@pytest.mark.parametrize("dtype", [np.float32, np.float64])
@pytest.mark.parametrize(
    "parameters",
    [
        {"light": {"linear_attenuation": 1e39, "position": (1, 2, 3, 1)}},
        {"light": {"quadratic_attenuation": 1e300, "position": (1, 2, 3, 1)}},
        {"light": {"constant_attenuation": 1e39, "position": (1, 2, 3, 1)}},
        {"light": {"spot_exponent": 1e39, "spot_cutoff": 60, "spot_direction": (0, 0, -1)}},
        {"light": {"position": (1e39, 2e39, 3e39, 1)}},
        {"light": {"position": (1e300, 0, 1e300, 1)}},
        {"light": {"position": (1e-39, 0, 1e-39, 1)}},
        {"light": {"diffuse": (1e39, 1e39, 1e39), "specular": (1e300, 0, 0)}},
        {"material": {"shininess": 1e39, "specular": (1, 1, 1)}},
        {"material": {"shininess": 1e300, "specular": (1, 1, 1)}},
        {"material": {"emission": (1e39, -1e39, 1e300)}},
        {"scene": {"viewer": (1e39, 1e39, 1e39, 1)}},
        {"scene": {"viewer": (1e-300, 0, 1e-300, 0)}},
        {"scene": {"global_ambient": (1e300, 1e39, -1e300)}},
    ],
)
def test_extreme_parameters_give_finite_results_in_the_unit_range(
    dtype: Any, parameters: dict[str, dict[str, Any]], rng: np.random.Generator
) -> None:
    light = gs.Light(**parameters.get("light", {}))
    material = gs.Material(
        **{"specular": (1, 1, 1), "shininess": 8, **parameters.get("material", {})}
    )
    scene = gs.Scene(
        lights=[light, gs.Light(position=(0, 1, 1, 1))],
        material=material,
        **parameters.get("scene", {}),
    )
    p, n = rows(rng, 200, dtype)
    for accuracy in ("fast", "exact"):
        try:
            result = gs.shade(p, n, scene, accuracy=accuracy)
        except ValueError as e:
            # Rejected is allowed only with a message that names a parameter of the scene.
            assert any(name in str(e) for name in PARAMETER_NAMES), e
            continue
        assert finite_in_unit(result), (accuracy, result[~np.isfinite(result)][:4])


PARAMETER_NAMES = (
    *inspect.signature(gs.Light).parameters,
    "shininess",
    "emission",
    "viewer",
    "global_ambient",
)


def reference_scene() -> gs.Scene:
    return gs.Scene(lights=[gs.Light(position=(0, 0, 1, 0))])


@pytest.mark.parametrize("dtype", [np.float32, np.float64])
@pytest.mark.parametrize("flags", [{"normalize": True}, {"rescale_normal": True}])
def test_scaling_the_modelview_by_powers_of_ten_changes_nothing(
    dtype: Any, flags: dict[str, bool]
) -> None:
    p = np.zeros((1, 3), dtype)
    n = np.array([[0, 0, 1]], dtype)
    top = 300 if dtype == np.float64 else 30
    rotation = np.eye(4)
    c, s = np.cos(0.3), np.sin(0.3)
    rotation[:2, :2] = [[c, -s], [s, c]]
    expected = gs.shade(p, n, reference_scene(), modelview=rotation, **flags)
    np.testing.assert_allclose(expected[:, :3], LIT, rtol=1e-6)
    for k in range(-top, top + 1, 10):
        m = rotation.copy()
        m[:3, :3] *= 10.0**k
        result = gs.shade(p, n, reference_scene(), modelview=m, **flags)
        np.testing.assert_allclose(result, expected, rtol=2e-6, err_msg=f"10^{k}")


@pytest.mark.parametrize(
    "modelview",
    [np.diag([1e50, 1e50, 1e50, 1]), np.diag([1e-50, 1e-50, 1e-50, 1]), np.diag([1e39, 1, 1, 1])],
)
def test_float32_modelviews_beyond_its_range_give_finite_results_or_a_clear_error(
    modelview: np.ndarray,
    rng: np.random.Generator,
) -> None:
    p, n = rows(rng, 50, np.float32)
    for scene in (SUN, MIXED):
        for normalize in (False, True):
            try:
                result = gs.shade(p, n, scene, modelview=modelview, normalize=normalize)
            except ValueError as e:
                assert "modelview" in str(e)
                continue
            assert finite_in_unit(result)


def test_float32_translation_beyond_its_range_is_finite_or_named(rng: np.random.Generator) -> None:
    m = np.eye(4)
    m[:3, 3] = 1e39
    p, n = rows(rng, 50, np.float32)
    try:
        result = gs.shade(p, n, MIXED, modelview=m)
    except ValueError as e:
        assert "modelview" in str(e)
    else:
        assert finite_in_unit(result)


def test_gouraud_float64_images_never_exceed_one() -> None:
    mesh_v = np.array([[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]], np.float64) * 0.9
    faces = [[0, 1, 2], [0, 2, 3]]
    bright = gs.Scene(lights=[gs.Light(position=(0, 0, 1, 0), diffuse=(5, 5, 5))])
    for shading in ("gouraud", "phong", "flat"):
        image = gs.render(mesh_v, faces, bright, gs.Camera(), width=64, height=64, shading=shading)
        assert image.max() <= 1.0 and image.min() >= 0.0, shading


@pytest.mark.parametrize(
    ("dtype", "exponent"),
    [(np.float64, k) for k in (0, 18, 50, 200, 300)] + [(np.float32, k) for k in (0, 10, 20, 30)],
)
def test_a_huge_triangle_covering_the_view_rasterises_as_a_small_one(
    dtype: Any, exponent: int
) -> None:
    corners = np.array([[-3, -3, 0], [3, -3, 0], [0, 3, 0]], np.float64) * 10.0**exponent
    image = gs.render(corners.astype(dtype), [[0, 1, 2]], SUN, gs.Camera(), width=16, height=16)
    small = gs.render(
        corners.astype(dtype) / 10.0**exponent, [[0, 1, 2]], SUN, gs.Camera(), width=16, height=16
    )
    assert np.isfinite(image).all()
    np.testing.assert_array_equal(image[..., 3] > 0, small[..., 3] > 0)
    np.testing.assert_allclose(image, small, atol=1e-6)
