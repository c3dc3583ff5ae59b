"""Names of options in any case: ``weighting="Area"``, ``alpha="PREMULTIPLIED"``,
``emission="Lambertian"``, ``attenuation="Inverse_Square"`` and the GLSL shading names give what
the lower-case names give, checked against the formulas they stand for; a name that is no option,
or no string, is refused naming the argument and its choices."""

from __future__ import annotations

import re
from collections.abc import Callable
from typing import Any

import numpy as np
import pytest

import glshade as gs
import glshade.presets as P


def _mesh(rng: np.random.Generator) -> tuple[np.ndarray, np.ndarray]:
    """A closed, irregular mesh: an icosphere with its vertices pushed in and out."""
    v, f = gs.meshes.icosphere(2)
    return v * rng.uniform(0.7, 1.3, (len(v), 1)), f


@pytest.mark.parametrize(
    ("given", "weights"),
    [("AREA", "area"), ("Angle", "angle"), ("uniform", "uniform"), ("UNIFORM", "uniform")],
)
def test_vertex_normals_take_the_weighting_in_any_case(
    rng: np.random.Generator, given: str, weights: str
) -> None:
    v, f = _mesh(rng)
    ours = gs.vertex_normals(v, f, weighting=given)  # type: ignore[arg-type]
    np.testing.assert_array_equal(ours, gs.vertex_normals(v, f, weighting=weights))  # type: ignore[arg-type]
    # The weighting's formula, summed here: area weights sum the raw cross products, uniform
    # weights the unit face normals, angle weights the unit normals times the corner angle.
    cross = np.cross(v[f[:, 1]] - v[f[:, 0]], v[f[:, 2]] - v[f[:, 1]])
    unit = cross / np.linalg.norm(cross, axis=1, keepdims=True)
    contributions = np.zeros((len(f), 3, 3))
    for corner in range(3):
        if weights == "area":
            contributions[:, corner] = cross
        elif weights == "uniform":
            contributions[:, corner] = unit
        else:
            a = v[f[:, (corner + 1) % 3]] - v[f[:, corner]]
            b = v[f[:, (corner + 2) % 3]] - v[f[:, corner]]
            cosine = (a * b).sum(1) / np.linalg.norm(a, axis=1) / np.linalg.norm(b, axis=1)
            contributions[:, corner] = unit * np.arccos(np.clip(cosine, -1, 1))[:, None]
    summed = np.zeros_like(v)
    np.add.at(summed, f.reshape(-1), contributions.reshape(-1, 3))
    expected = summed / np.linalg.norm(summed, axis=1, keepdims=True)
    np.testing.assert_allclose(ours, expected, atol=1e-12)


def test_compare_takes_the_alpha_names_in_any_case(rng: np.random.Generator) -> None:
    straight = rng.uniform(0, 1, (6, 7, 4))
    straight[..., 3] = rng.choice([0.25, 0.5, 1.0], (6, 7))
    premultiplied = straight.copy()
    premultiplied[..., :3] *= straight[..., 3:]
    upper = gs.compare(premultiplied, straight, alpha="PREMULTIPLIED", reference_alpha="Straight")  # type: ignore[arg-type]
    lower = gs.compare(premultiplied, straight, alpha="premultiplied", reference_alpha="straight")
    np.testing.assert_array_equal(upper.max_error, lower.max_error)
    # Divided by alpha, the premultiplied image is the straight one: no error but rounding.
    assert upper.max_error.max() < 1e-15 and upper.within_tolerance == 1.0
    # reference_alpha in upper case: the reference is the premultiplied one now.
    swapped = gs.compare(straight, premultiplied, reference_alpha="Premultiplied")  # type: ignore[arg-type]
    assert swapped.max_error.max() < 1e-15
    # Read as straight, the premultiplied colours differ by (1 - alpha) c, up to 3/4 of c.
    taken_straight = gs.compare(premultiplied, straight, alpha="Straight")  # type: ignore[arg-type]
    expected = np.abs(premultiplied - straight)[..., :3].max(axis=(0, 1))
    np.testing.assert_allclose(taken_straight.max_error[:3], expected, rtol=1e-12)


@pytest.mark.parametrize("make", [gs.rectangle_light, gs.disc_light])
def test_area_lights_take_the_emission_in_any_case(make: Callable[..., gs.Lights]) -> None:
    if make is gs.rectangle_light:
        args: tuple[Any, ...] = ((0, 0, 2), (1, 0, 0), (0, 1, 0), 5)
    else:
        args = ((0, 0, 2), (0, 0, -1), 0.5, 5)
    upper = make(*args, emission="LAMBERTIAN")
    assert upper == make(*args, emission="lambertian")
    assert make(*args, emission="Uniform") == make(*args, emission="uniform")
    # Lambertian is GL's spot factor with a 90 degree cutoff and exponent 1 about the panel's
    # normal: cross(u, v) for the rectangle, the given normal for the disc.
    normal = np.cross(args[1], args[2]) if make is gs.rectangle_light else np.array(args[1])
    np.testing.assert_array_equal(upper.spot_cutoff, np.full(5, 90.0))
    np.testing.assert_array_equal(upper.spot_exponent, np.ones(5))
    np.testing.assert_allclose(
        upper.spot_direction / np.linalg.norm(upper.spot_direction, axis=1, keepdims=True),
        np.tile(normal / np.linalg.norm(normal), (5, 1)),
    )


def test_the_lecture_attenuation_name_in_any_case() -> None:
    common: dict[str, Any] = {
        "k_a": 0.1,
        "k_d": 0.6,
        "k_s": 0.3,
        "n": 8.0,
        "I_a": 0.2,
        "I_l": 1.0,
        "viewer_position": (0.0, 0.0, 3.0),
        "light_position": (0.0, 2.0, 0.0),
    }
    upper = P.phong_illumination(**common, attenuation="Inverse_Square")
    assert upper == P.phong_illumination(**common, attenuation="inverse_square")
    # 1 / d^2: GL's (k0, k1, k2) = (0, 0, 1).
    lights = upper.scene.lights
    assert (
        float(lights.constant_attenuation[0]),
        float(lights.linear_attenuation[0]),
        float(lights.quadratic_attenuation[0]),
    ) == (0.0, 0.0, 1.0)
    # Lit from (0, 2, 0) at distance 2 along the normal: k_d I_l (N . L) / d^2 plus k_a I_a.
    colour = upper.shade(np.zeros((1, 3)), np.array([[0.0, 1.0, 0.0]]))
    direct = 0.6 * 1.0 * 1.0 / 4.0
    to_eye = np.array([0.0, 0.0, 3.0]) / 3.0
    highlight = 0.3 * max(float(np.dot([0.0, 1.0, 0.0], to_eye)), 0.0) ** 8 / 4.0
    np.testing.assert_allclose(colour[0, :3], 0.1 * 0.2 + direct + highlight, atol=1e-6)


def test_glsl_shaders_take_the_shading_name_in_any_case() -> None:
    scene = gs.Scene(lights=[gs.Light(position=(1, 1, 1, 0))])
    for name in ("phong", "gouraud", "flat"):
        upper = gs.glsl.raster_shaders(scene, name.upper())  # type: ignore[arg-type]
        lower = gs.glsl.raster_shaders(scene, name)
        assert upper.sources == lower.sources
    flat = gs.glsl.raster_shaders(scene, "Flat")  # type: ignore[arg-type]
    assert "flat out" in str(flat.vertex) and "flat in" in str(flat.fragment)


@pytest.mark.parametrize(
    ("call", "error", "words"),
    [
        (
            lambda: gs.vertex_normals(*gs.meshes.icosphere(1), weighting="cotangent"),  # type: ignore[arg-type]
            ValueError,
            "weighting must be 'angle', 'area' or 'uniform', got 'cotangent'",
        ),
        (
            lambda: gs.vertex_normals(*gs.meshes.icosphere(1), weighting=1),  # type: ignore[arg-type]
            TypeError,
            "weighting must be a string, got 1",
        ),
        (
            lambda: gs.compare(np.zeros((2, 2, 4)), np.zeros((2, 2, 4)), alpha="Linear"),  # type: ignore[arg-type]
            ValueError,
            "alpha must be 'straight' or 'premultiplied', got 'Linear'",
        ),
        (
            lambda: gs.compare(np.zeros((2, 2, 4)), np.zeros((2, 2, 4)), reference_alpha=True),  # type: ignore[arg-type]
            TypeError,
            "reference_alpha must be a string, got True",
        ),
        (
            lambda: gs.rectangle_light((0, 0, 0), (1, 0, 0), (0, 1, 0), 2, emission="Cosine"),  # type: ignore[arg-type]
            ValueError,
            "emission must be 'uniform' or 'lambertian', got 'Cosine'",
        ),
        (
            lambda: gs.disc_light((0, 0, 0), (0, 0, 1), 1, 2, emission=None),  # type: ignore[arg-type]
            TypeError,
            "emission must be a string, got None",
        ),
        (
            lambda: P.phong_illumination(
                k_a=0.1,
                k_d=0.5,
                k_s=0.5,
                n=8,
                I_a=0.2,
                I_l=1,
                viewer_position=(0, 0, 3),
                light_position=(0, 2, 0),
                attenuation="Inverse_Cube",
            ),
            ValueError,
            "attenuation must be None, 'inverse_square' or (a0, a1, a2), got 'Inverse_Cube'",
        ),
    ],
)
def test_a_name_that_is_no_option_is_refused_with_the_options(
    call: Callable[[], object], error: type[Exception], words: str
) -> None:
    with pytest.raises(error, match=re.escape(words)):
        call()
