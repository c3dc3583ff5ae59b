"""The corner cases of GL 2.1 section 2.14.1, each term of
the equation alone and combined, and glshade's conventions where GL says "undefined" (the
documentation's Conventions page, docs/pages/guide/conventions.md).

Expected values are worked out by hand from the equation; where a case is easier to state as
"equals the float64 transcription", the transcription in gl_reference.py is the oracle.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest

import glshade as gs
from support.gl_reference import RefScene, gl_lighting

DTYPES = [np.float64, np.float32]
ATOL = {np.float64: 1e-13, np.float32: 2e-6}
UP = (0.0, 0.0, 1.0)

pytestmark = pytest.mark.parametrize("dtype", DTYPES, ids=["f64", "f32"])

BLACK_MATERIAL = {
    "ambient": (0, 0, 0),
    "diffuse": (0, 0, 0),
    "specular": (0, 0, 0),
    "emission": (0, 0, 0),
}


def shade1(scene: gs.Scene, p: Any, n: Any, dtype: type, **kwargs: Any) -> np.ndarray:
    """The colours of one vertex: (4,) or (k, 4)."""
    out = gs.shade(np.array([p], dtype), np.array([n], dtype), scene, **kwargs)
    return out[0] if out.ndim == 2 else out[:, 0]


def close(got: np.ndarray, expected: Any, dtype: type) -> None:
    np.testing.assert_allclose(
        got, np.asarray(expected, dtype=np.float64), rtol=0, atol=ATOL[dtype]
    )


# --- each term alone --------------------------------------------------------------------------


def test_emission_alone(dtype: type) -> None:
    m = gs.Material(**{**BLACK_MATERIAL, "emission": (0.1, 0.2, 0.3)})
    close(shade1(gs.Scene(material=m), (0, 0, 0), UP, dtype), (0.1, 0.2, 0.3, 1), dtype)


def test_global_ambient_alone(dtype: type) -> None:
    m = gs.Material(**{**BLACK_MATERIAL, "ambient": (0.5, 1.0, 0.25), "diffuse": (0, 0, 0, 0.5)})
    scene = gs.Scene(material=m, global_ambient=(0.4, 0.2, 0.8))
    close(shade1(scene, (0, 0, 0), UP, dtype), (0.2, 0.2, 0.2, 0.5), dtype)


def test_light_ambient_alone_is_attenuated_and_spotted(dtype: type) -> None:
    m = gs.Material(**{**BLACK_MATERIAL, "ambient": (1, 0.5, 0.25)})
    light = gs.Light(
        position=(0, 0, 2, 1),
        ambient=(0.8, 0.8, 0.8),
        diffuse=(0, 0, 0),
        specular=(0, 0, 0),
        constant_attenuation=0.5,
        quadratic_attenuation=0.5,  # att = 1 / (0.5 + 0.5 * 4) = 0.4
        spot_cutoff=45,
        spot_exponent=2,
        spot_direction=(0, 0, -1),
    )
    scene = gs.Scene(lights=[light], material=m, global_ambient=(0, 0, 0))
    # On the spot axis: spot = 1^2 = 1; behind the normal (n = -z) the ambient stays.
    for n in (UP, (0, 0, -1)):
        close(shade1(scene, (0, 0, 0), n, dtype), (0.32, 0.16, 0.08, 1), dtype)
    # Off axis by 30 degrees: spot = cos(30)^2 = 0.75; outside the cone: 0.
    p = (2 * np.tan(np.radians(30)), 0, 0)
    d2 = 4 + p[0] ** 2
    att = 1 / (0.5 + 0.5 * d2)
    close(
        shade1(scene, p, UP, dtype),
        (0.8 * att * 0.75, 0.4 * att * 0.75, 0.2 * att * 0.75, 1),
        dtype,
    )
    close(shade1(scene, (3, 0, 0), UP, dtype), (0, 0, 0, 1), dtype)


def test_diffuse_alone_is_lambert(dtype: type) -> None:
    m = gs.Material(**{**BLACK_MATERIAL, "diffuse": (1, 0.5, 0.25, 0.75)})
    scene = gs.Scene(lights=[gs.Light(position=(0, 1, 1, 0))], material=m, global_ambient=(0, 0, 0))
    c = np.cos(np.radians(45))
    close(shade1(scene, (0, 0, 0), UP, dtype), (c, 0.5 * c, 0.25 * c, 0.75), dtype)


def test_specular_alone_is_blinn_with_the_halfway_vector(dtype: type) -> None:
    m = gs.Material(**{**BLACK_MATERIAL, "specular": (1, 1, 1), "shininess": 10})
    scene = gs.Scene(lights=[gs.Light(position=(0, 1, 1, 0))], material=m, global_ambient=(0, 0, 0))
    # h = normalize((0, 1, 1)/sqrt2 + (0, 0, 1)) makes 22.5 degrees with +z.
    s = np.cos(np.radians(22.5)) ** 10
    close(shade1(scene, (0, 0, 0), UP, dtype), (s, s, s, 1), dtype)


def test_specular_phong_uses_the_reflection_vector(dtype: type) -> None:
    m = gs.Material(**{**BLACK_MATERIAL, "specular": (1, 1, 1), "shininess": 10})
    light = gs.Light(position=(0, 1, 1, 0))
    scene = gs.Scene(lights=[light], material=m, global_ambient=(0, 0, 0), specular="phong")
    # R = reflect(-L, n) = (0, -1, 1)/sqrt2 makes 45 degrees with the viewer +z.
    s = np.cos(np.radians(45)) ** 10
    close(shade1(scene, (0, 0, 0), UP, dtype), (s, s, s, 1), dtype)


def test_all_terms_combined_is_their_sum(dtype: type) -> None:
    light = gs.Light(
        position=(1, 2, 3, 1),
        ambient=(0.1, 0.2, 0.1),
        diffuse=(0.7, 0.6, 0.5),
        linear_attenuation=0.2,
    )
    material = gs.Material(
        ambient=(0.3, 0.2, 0.1),
        diffuse=(0.5, 0.6, 0.7, 0.9),
        specular=(0.4, 0.4, 0.4),
        emission=(0.05, 0, 0),
        shininess=20,
    )
    total = shade1(
        gs.Scene(lights=[light], material=material), (0.1, 0.2, 0.0), (0.1, 0.2, 1.0), dtype
    )
    parts = []
    for keep in ("ambient", "diffuse", "specular", "emission"):
        m = gs.Material(**{**BLACK_MATERIAL, keep: getattr(material, keep), "shininess": 20})
        ga = (0.2, 0.2, 0.2) if keep == "ambient" else (0, 0, 0)
        parts.append(
            shade1(
                gs.Scene(lights=[light], material=m, global_ambient=ga),
                (0.1, 0.2, 0.0),
                (0.1, 0.2, 1.0),
                dtype,
            )
        )
    close(total[:3], sum(p[:3] for p in parts), dtype)
    assert total[3] == np.float64(0.9).astype(dtype)


# --- the corner cases of section 2.14.1 ----------------------------------------------------


def lit_scene(**material: Any) -> gs.Scene:
    m = {
        "ambient": (0.2, 0.2, 0.2),
        "diffuse": (0.5, 0.5, 0.5),
        "specular": (1, 1, 1),
        "shininess": 8.0,
        **material,
    }
    light = gs.Light(position=(0, 1, 1, 0), ambient=(0.5, 0.5, 0.5))
    return gs.Scene(lights=[light], material=gs.Material(**m), global_ambient=(0, 0, 0))


def test_1_back_lit_keeps_only_ambient(dtype: type) -> None:
    close(shade1(lit_scene(), (0, 0, 0), (0, -1, -1), dtype), (0.1, 0.1, 0.1, 1), dtype)


def test_2_grazing_light_has_no_specular_even_with_n_dot_h_positive(dtype: type) -> None:
    # n . VP = 0 exactly while n . h > 0: f = 0.
    light = gs.Light(position=(1, 0, 0, 0))
    m = gs.Material(**{**BLACK_MATERIAL, "specular": (1, 1, 1), "shininess": 0})
    scene = gs.Scene(lights=[light], material=m, global_ambient=(0, 0, 0))
    close(shade1(scene, (0, 0, 0), UP, dtype), (0, 0, 0, 1), dtype)


def test_3_shininess_zero_is_zero_to_the_zero(dtype: type) -> None:
    # n . h < 0 but n . VP > 0: (n (.) h)^0 = 0^0 = 1, so the specular is f s_cm s_cli.
    light = gs.Light(position=(0, 1, -0.2, 0))
    m = gs.Material(**{**BLACK_MATERIAL, "specular": (0.25, 0.5, 0.75)})
    scene = gs.Scene(lights=[light], material=m, global_ambient=(0, 0, 0), viewer=(0, -1, 0, 0))
    n = (0, 0.3, 1)
    assert np.dot(n, (0, 1, -0.2)) > 0
    close(shade1(scene, (0, 0, 0), n, dtype), (0.25, 0.5, 0.75, 1), dtype)


def test_4_n_dot_h_negative_with_positive_shininess_gives_no_specular(dtype: type) -> None:
    light = gs.Light(position=(0, 1, -0.2, 0))
    m = gs.Material(**{**BLACK_MATERIAL, "specular": (1, 1, 1), "shininess": 3})
    scene = gs.Scene(lights=[light], material=m, global_ambient=(0, 0, 0), viewer=(0, -1, 0, 0))
    close(shade1(scene, (0, 0, 0), (0, 0.3, 1), dtype), (0, 0, 0, 1), dtype)


def test_5_directional_light_ignores_attenuation_but_not_the_spot(dtype: type) -> None:
    m = gs.Material(**{**BLACK_MATERIAL, "diffuse": (1, 1, 1)})
    plain = gs.Light(position=(0, 0, 1, 0), constant_attenuation=4, linear_attenuation=3)
    close(
        shade1(
            gs.Scene(lights=[plain], material=m, global_ambient=(0, 0, 0)), (5, 5, 5), UP, dtype
        ),
        (1, 1, 1, 1),
        dtype,
    )
    # The light travels along -z; a cone around -z with exponent 2 at 60 degrees off axis.
    spot = gs.Light(
        position=(0, np.sin(np.radians(60)), np.cos(np.radians(60)), 0),
        spot_cutoff=70,
        spot_exponent=2,
        spot_direction=(0, 0, -1),
    )
    expected = np.cos(np.radians(60)) * np.cos(np.radians(60)) ** 2
    close(
        shade1(gs.Scene(lights=[spot], material=m, global_ambient=(0, 0, 0)), (0, 0, 0), UP, dtype)[
            :3
        ],
        [expected] * 3,
        dtype,
    )
    outside = gs.Light(position=(0, 1, 0.1, 0), spot_cutoff=70, spot_direction=(0, 0, -1))
    close(
        shade1(
            gs.Scene(lights=[outside], material=m, global_ambient=(0, 0, 0)), (0, 0, 0), UP, dtype
        )[:3],
        [0, 0, 0],
        dtype,
    )


def test_6_spot_edge_is_inside_and_cutoff_90_uses_cos_zero(dtype: type) -> None:
    m = gs.Material(**{**BLACK_MATERIAL, "ambient": (1, 1, 1)})
    # A point light at the origin aimed along +x with a 90 degree cone. Vertices on the cone's
    # edge (perpendicular to the axis) and behind it both have P_pli V (.) s = 0 >= cos 90 = 0:
    # they get 0^e, which is 1 for e = 0 and 0 for e > 0 (GL's letter, not Mesa's).
    for exponent, expected in ((0.0, 1.0), (3.0, 0.0)):
        light = gs.Light(
            position=(0, 0, 0, 1),
            ambient=(1, 1, 1),
            spot_cutoff=90,
            spot_exponent=exponent,
            spot_direction=(1, 0, 0),
        )
        scene = gs.Scene(lights=[light], material=m, global_ambient=(0, 0, 0))
        close(shade1(scene, (0, 2, 0), UP, dtype)[0], expected, dtype)
        close(shade1(scene, (-1, 2, 0), UP, dtype)[0], expected, dtype)  # behind
    # Equality is inside (eq. 2.5's >=, where Mesa's ffvertex uses >): a 0 degree cone, whose
    # cosine 1 is exact, lights exactly the vertices on its axis.
    light = gs.Light(
        position=(0, 0, 0, 1), ambient=(1, 1, 1), spot_cutoff=0, spot_direction=(2, 0, 0)
    )
    scene = gs.Scene(lights=[light], material=m, global_ambient=(0, 0, 0))
    close(shade1(scene, (3, 0, 0), UP, dtype)[0], 1.0, dtype)
    close(shade1(scene, (3, 1e-3, 0), UP, dtype)[0], 0.0, dtype)


def test_7_cutoff_180_is_exactly_no_spot(dtype: type) -> None:
    m = gs.Material(**{**BLACK_MATERIAL, "ambient": (1, 1, 1)})
    light = gs.Light(
        position=(0, 0, 0, 1), ambient=(0.5, 0.5, 0.5), spot_exponent=50, spot_direction=(1, 0, 0)
    )
    scene = gs.Scene(lights=[light], material=m, global_ambient=(0, 0, 0))
    assert shade1(scene, (-3, 1, 0), UP, dtype)[0] == 0.5


def test_8_unit_attenuation_is_exact_and_above_one_is_allowed(dtype: type) -> None:
    m = gs.Material(**{**BLACK_MATERIAL, "ambient": (1, 1, 1)})
    for k0, expected in ((1.0, 0.25), (0.5, 0.5)):
        light = gs.Light(position=(0, 0, 7, 1), ambient=(0.25, 0.25, 0.25), constant_attenuation=k0)
        scene = gs.Scene(lights=[light], material=m, global_ambient=(0, 0, 0))
        assert shade1(scene, (1, 2, 3), UP, dtype)[0] == expected


def test_9_non_unit_normals_scale_the_dots_unless_normalized(dtype: type) -> None:
    m = gs.Material(
        **{
            **BLACK_MATERIAL,
            "diffuse": (0.25, 0.25, 0.25),
            "specular": (0.01, 0.01, 0.01),
            "shininess": 4,
        }
    )
    scene = gs.Scene(lights=[gs.Light(position=(0, 0, 1, 0))], material=m, global_ambient=(0, 0, 0))
    # n = 2z: diffuse 2 * 0.25, specular (n . h)^4 = 16 * 0.01.
    close(shade1(scene, (0, 0, 0), (0, 0, 2), dtype)[:3], [0.66] * 3, dtype)
    close(shade1(scene, (0, 0, 0), (0, 0, 2), dtype, normalize=True)[:3], [0.26] * 3, dtype)


def test_10_two_sided_uses_the_back_material_and_minus_n(dtype: type) -> None:
    front = gs.Material(diffuse=(1, 0, 0), ambient=(0, 0, 0))
    back = gs.Material(diffuse=(0, 1, 0, 0.5), ambient=(0, 0, 0), specular=(0, 0, 1), shininess=2)
    scene = gs.Scene(
        lights=[gs.Light(position=(0, 0, 1, 0))],
        material=front,
        back_material=back,
        two_side=True,
        global_ambient=(0, 0, 0),
    )
    front_colour, back_colour = shade1(scene, (0, 0, 0), (0, 0, -1), dtype)
    close(front_colour, (0, 0, 0, 1), dtype)
    close(back_colour, (0, 1, 1, 0.5), dtype)  # -n faces the light and the viewer: spec = 1
    # Without two_side the back colour is not computed at all.
    assert shade1(gs.Scene(lights=scene.lights, material=front), (0, 0, 0), UP, dtype).shape == (4,)


def test_11_negative_colours_are_summed_then_clamped(dtype: type) -> None:
    m = gs.Material(ambient=(0, 0, 0), diffuse=(1, 1, 1), emission=(0.6, 0.6, 0.6))
    light = gs.Light(position=(0, 0, 1, 0), diffuse=(-0.5, -1, 0.2))
    scene = gs.Scene(lights=[light], material=m, global_ambient=(0, 0, 0))
    close(shade1(scene, (0, 0, 0), UP, dtype), (0.1, 0, 0.8, 1), dtype)


def test_12_alpha_is_diffuse_alpha_and_secondary_alpha_is_one(dtype: type) -> None:
    m = gs.Material(
        ambient=(0, 0, 0, 0.1),
        diffuse=(0, 0, 0, 0.3),
        specular=(1, 1, 1, 0.2),
        emission=(0, 0, 0, 0.9),
    )
    scene = gs.Scene(
        lights=[gs.Light()], material=m, separate_specular=True, global_ambient=(0, 0, 0)
    )
    primary, secondary = shade1(scene, (0, 0, 0), UP, dtype)
    close(primary, (0, 0, 0, 0.3), dtype)
    close(secondary, (1, 1, 1, 1), dtype)
    over = gs.Scene(material=gs.Material(diffuse=(0, 0, 0, 1.7)))
    assert shade1(over, (0, 0, 0), UP, dtype)[3] == 1.0


def test_13_local_viewer_moves_the_highlight(dtype: type) -> None:
    m = gs.Material(**{**BLACK_MATERIAL, "specular": (1, 1, 1), "shininess": 30})
    light = gs.Light(position=(0, 0, 1, 0))
    p = (3, 0, -3)
    infinite = shade1(gs.Scene(lights=[light], material=m, global_ambient=(0, 0, 0)), p, UP, dtype)
    local = shade1(
        gs.Scene(lights=[light], material=m, global_ambient=(0, 0, 0), viewer=(0, 0, 0, 1)),
        p,
        UP,
        dtype,
    )
    close(infinite[:3], [1, 1, 1], dtype)  # h = z exactly
    h = np.array([0, 0, 1.0]) + np.array([-1, 0, 1]) / np.sqrt(2)
    close(local[:3], [(h[2] / np.linalg.norm(h)) ** 30] * 3, dtype)


def test_15_specular_gate_off_lights_the_back_with_specular_only(dtype: type) -> None:
    # L = (0, 0.8, -0.6) behind n = +z: n.L = -0.6, so GL (f_i = 0) gives no specular and
    # no diffuse. Without the gate (learnopengl) the specular stays.
    m = gs.Material(**{**BLACK_MATERIAL, "diffuse": (1, 1, 1)})
    light = gs.Light(position=(0, 0.8, -0.6, 0))
    for spec, viewer, expected in (
        # Phong: R = 2(n.L)n - L = (0, -0.8, -0.6) points straight at this viewer: R.V = 1.
        ("phong", (0, -0.8, -0.6, 0), 1.0),
        # Blinn: h = normalize(L + (0, 0, 1)) = (0, 0.8, 0.4)/|.|, n.h = 0.4/sqrt(0.8).
        ("blinn", (0, 0, 1, 0), (0.4 / np.sqrt(0.8)) ** 5),
    ):
        for gate, factor in ((True, 0.0), (False, expected)):
            material = gs.Material(**{**BLACK_MATERIAL, "specular": (0.5, 0.25, 1), "shininess": 5})
            scene = gs.Scene(
                lights=[light],
                material=material,
                global_ambient=(0, 0, 0),
                viewer=viewer,
                specular=spec,
                specular_gate=gate,
            )
            got = shade1(scene, (0, 0, 0), UP, dtype)
            close(got, (0.5 * factor, 0.25 * factor, factor, 1), dtype)
    # The diffuse term keeps its max(n.L, 0) either way.
    for gate in (True, False):
        scene = gs.Scene(lights=[light], material=m, global_ambient=(0, 0, 0), specular_gate=gate)
        close(shade1(scene, (0, 0, 0), UP, dtype), (0, 0, 0, 1), dtype)


def test_15_specular_gate_off_keeps_the_undefined_cases_dark(dtype: type) -> None:
    # Shininess 0 makes any specular 0^0 = 1, so only the direction rules can keep it off.
    m = gs.Material(**{**BLACK_MATERIAL, "specular": (1, 1, 1), "shininess": 0})
    behind = gs.Scene(
        lights=[gs.Light(position=(0, 0.8, -0.6, 0))],
        material=m,
        global_ambient=(0, 0, 0),
        specular_gate=False,
    )
    close(shade1(behind, (0, 0, 0), UP, dtype), (1, 1, 1, 1), dtype)  # f_i = 1: 0^0 = 1
    close(shade1(behind, (0, 0, 0), (0, 0, 0), dtype), (0, 0, 0, 1), dtype)  # zero normal
    for spec in ("blinn", "phong"):
        at_vertex = gs.Scene(
            lights=[gs.Light(position=(1, 2, 3, 1))],
            material=m,
            global_ambient=(0, 0, 0),
            specular=spec,
            specular_gate=False,
        )
        close(shade1(at_vertex, (1, 2, 3), UP, dtype), (0, 0, 0, 1), dtype)  # VP = 0


# --- conventions where GL says "undefined" ----------------------------------------------------


def test_14a_zero_normal_gets_emission_and_ambient_only(dtype: type) -> None:
    scene = lit_scene(emission=(0.1, 0, 0))
    for normalize in (False, True):
        close(
            shade1(scene, (0, 0, 0), (0, 0, 0), dtype, normalize=normalize),
            (0.2, 0.1, 0.1, 1),
            dtype,
        )


def test_14b_light_at_the_vertex_gives_no_diffuse_and_finite_attenuation(dtype: type) -> None:
    m = gs.Material(ambient=(1, 1, 1), diffuse=(1, 1, 1), specular=(1, 1, 1))
    light = gs.Light(position=(1, 2, 3, 1), ambient=(0.1, 0, -0.1), constant_attenuation=0.5)
    scene = gs.Scene(lights=[light], material=m, global_ambient=(0, 0, 0))
    close(shade1(scene, (1, 2, 3), UP, dtype), (0.2, 0, 0, 1), dtype)
    singular = gs.Light(
        position=(1, 2, 3, 1),
        ambient=(0.1, 0, -0.1),
        constant_attenuation=0,
        quadratic_attenuation=1,
    )
    got = shade1(
        gs.Scene(lights=[singular], material=m, global_ambient=(0, 0, 0)), (1, 2, 3), UP, dtype
    )
    assert np.isfinite(got).all()
    close(got, (1, 0, 0, 1), dtype)


def test_14c_zero_halfway_vector_gives_no_specular(dtype: type) -> None:
    # Light along +z at the vertex's viewer-opposite side: VP + VPe = 0 for the local viewer.
    m = gs.Material(**{**BLACK_MATERIAL, "specular": (1, 1, 1), "shininess": 10})
    light = gs.Light(position=(0, 0, -5, 1))
    scene = gs.Scene(lights=[light], material=m, global_ambient=(0, 0, 0), viewer=(0, 0, 0, 1))
    close(shade1(scene, (0, 0, -1), (0, 0, -1), dtype), (0, 0, 0, 1), dtype)


def test_14c_with_shininess_zero_the_power_is_one_whatever_the_halfway_vector(
    dtype: type,
) -> None:
    # (n . h)^0 = 1 (section 2.1.1) needs no h: as Mesa's degenerate LIT, f_i alone decides.
    m = gs.Material(**{**BLACK_MATERIAL, "specular": (1, 1, 1), "shininess": 0})
    light = gs.Light(position=(0, 0, -5, 1))
    scene = gs.Scene(lights=[light], material=m, global_ambient=(0, 0, 0), viewer=(0, 0, 0, 1))
    close(shade1(scene, (0, 0, -1), (0, 0, -1), dtype), (1, 1, 1, 1), dtype)


def test_14d_viewer_at_the_vertex_gives_no_phong_specular(dtype: type) -> None:
    m = gs.Material(**{**BLACK_MATERIAL, "specular": (1, 1, 1), "shininess": 5})
    scene = gs.Scene(
        lights=[gs.Light()],
        material=m,
        global_ambient=(0, 0, 0),
        viewer=(1, 1, 1, 1),
        specular="phong",
    )
    close(shade1(scene, (1, 1, 1), UP, dtype), (0, 0, 0, 1), dtype)


def test_fractional_exponents_away_from_zero(dtype: type) -> None:
    # Exponents in (0, 1) are legal GL; cos^s has an unbounded slope only at cos = 0.
    for s in (0.1, 0.5, 0.9):
        m = gs.Material(**{**BLACK_MATERIAL, "specular": (1, 1, 1), "shininess": s})
        light = gs.Light(
            position=(0, np.sin(0.7), np.cos(0.7), 0),
            spot_cutoff=80,
            spot_exponent=s,
            spot_direction=(0, -np.sin(0.7), -np.cos(0.7)),
        )
        scene = gs.Scene(lights=[light], material=m, global_ambient=(0, 0, 0))
        p = np.zeros((1, 3))
        n = np.array([[0.3, -0.2, 1.0]])
        ref = gl_lighting(
            p,
            n,
            RefScene(
                lights=[
                    {
                        "position": (0, np.sin(0.7), np.cos(0.7), 0),
                        "spot_cutoff": 80,
                        "spot_exponent": s,
                        "spot_direction": (0, -np.sin(0.7), -np.cos(0.7)),
                    }
                ],
                material={
                    "ambient": (0, 0, 0),
                    "diffuse": (0, 0, 0),
                    "specular": (1, 1, 1),
                    "emission": (0, 0, 0),
                    "shininess": s,
                },
                global_ambient=(0, 0, 0),
            ),
        )
        close(shade1(scene, p[0], n[0], dtype), ref.outputs[0][0], dtype)


def test_nan_rows_stay_nan_and_alone(dtype: type) -> None:
    # The local viewer makes the scene read positions.
    scene = gs.Scene(lights=[gs.Light(position=(0, 1, 1, 0))], viewer=(0, 0, 0, 1))
    p = np.zeros((4, 3), dtype)
    n = np.tile(np.array(UP, dtype), (4, 1))
    p[1, 0] = np.nan
    n[2, 2] = np.inf
    out = gs.shade(p, n, scene)
    assert np.isnan(out[1:3]).all()
    clean = gs.shade(p[[0]], n[[0]], scene)
    assert np.array_equal(out[0], clean[0]) and np.array_equal(out[3], clean[0])
    # Directional lights under an infinite viewer never read positions: a NaN there is unseen.
    scene = lit_scene()
    out = gs.shade(p, n, scene)
    assert np.isfinite(out[[0, 1, 3]]).all() and np.isnan(out[2]).all()
    colors = np.ones((4, 3), dtype)
    colors[3, 1] = np.nan
    out = gs.shade(
        np.zeros((4, 3), dtype), np.tile(np.array(UP, dtype), (4, 1)), scene, colors=colors
    )
    assert np.isnan(out[3]).all() and np.isfinite(out[:3]).all()


def test_color_material_each_mode_and_face(dtype: type) -> None:
    base = {
        "ambient": (0.1, 0.2, 0.3),
        "diffuse": (0.4, 0.5, 0.6, 0.7),
        "specular": (0.2, 0.2, 0.2),
        "emission": (0.05, 0.0, 0.1),
        "shininess": 5.0,
    }
    back = {**base, "diffuse": (0.6, 0.1, 0.1, 0.4)}
    lights = [{"position": (0.3, 0.5, 1.0, 0.0), "ambient": (0.2, 0.2, 0.2)}]
    rng = np.random.default_rng(7)
    p = rng.uniform(-1, 1, (50, 3)).astype(dtype)
    n = rng.normal(size=(50, 3)).astype(dtype)
    colors = rng.uniform(0, 1, (50, 4)).astype(dtype)
    scene = gs.Scene(
        lights=[gs.Light(**lights[0])],
        material=gs.Material(**base),
        back_material=gs.Material(**back),
        two_side=True,
    )
    for mode in ("ambient", "diffuse", "specular", "emission", "ambient_and_diffuse"):
        for face in ("front", "back", "front_and_back"):
            got = gs.shade(
                p,
                n,
                scene,
                colors=colors,
                color_material=mode,
                color_material_face=face,
                normalize=True,
            )
            ref = RefScene(
                lights=lights,
                material=base,
                back_material=back,
                two_side=True,
                normalize=True,
                colors=colors,
                color_material=mode,
                color_material_face=face,
            )
            np.testing.assert_allclose(
                got,
                np.stack(gl_lighting(p, n, ref).outputs),
                atol=ATOL[dtype] * 10,
                err_msg=f"{mode}/{face}",
            )


def test_colors_default_to_ambient_and_diffuse(dtype: type) -> None:
    scene = gs.Scene(lights=[gs.Light()])
    c = np.array([[0.5, 0.25, 1.0]], dtype)
    got = gs.shade(np.zeros((1, 3), dtype), np.array([UP], dtype), scene, colors=c)
    close(got[0], (0.5 * 1.2, 0.25 * 1.2, 1.0, 1.0), dtype)
