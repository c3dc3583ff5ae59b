"""Each lighting model of the source documents, transcribed here in numpy as the document writes it
(its own names, its own structure; nothing imported from glshade), against `gs.presets` on
random inputs, in float64, within 1e-12.

Documents (../shared/seeds/): 000 the OpenGL lighting equation, 001 a DirectX 11 lighting
tutorial, 002 learnopengl's Basic Lighting, 004 lecture notes on the Phong illumination model.
Where a document leaves something out, the transcription says what it assumes:

- 000 uses the spec's ⊙ without defining it; it is GL 2.1's ``max(a . b, 0)``. Its f reads
  ``n ⊙ VP >= 0`` (with ⊙ clamped that is always true); its text ("the angle is over 90
  degrees") means the plain dot product, so f = 1 where ``n . VP >= 0``. GL's f_i is 0 at
  ``n . VP = 0`` exactly, which random inputs never hit.
- 001 names r "the reflection vector" without a formula: r = reflect(-L, n) = 2 (L . n) n - L.
  It says L and n are unit vectors, so the transcription normalises n.
- 002 is the shader as written; GLSL's ``reflect(I, N) = I - 2 dot(N, I) N``.
- 004 shows the attenuation functions and the ambient + diffuse "conditional formula" only as
  images. Assumed, from the text around them and Hearn & Baker's book the lecture follows:
  radial ``1 / d^2`` or ``1 / (a0 + a1 d + a2 d^2)``, none for infinitely distant lights; angular
  ``(V_obj . V_light)^a_l`` inside the cone of half-angle θ_l, 0 outside; diffuse and specular
  only where ``N . L > 0``; ``(R . V)`` limited to angles in [0, 90] degrees, i.e. max(R . V, 0).
- No document clamps (GL and the framebuffers do): the transcriptions are clamped to [0, 1],
  and each test checks that most channels are inside (0, 1), so the comparison is not vacuous.
"""

from __future__ import annotations

import itertools
import re
from collections.abc import Callable
from typing import Any

import numpy as np
import pytest
from conftest import require

import glshade as gs
from support.gl_reference import RefScene, gl_lighting

TOL = 1e-12
TRIALS = 40
VERTICES = 500


def unit(v: np.ndarray) -> np.ndarray:
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def dot(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    return np.sum(a * b, axis=-1)


def agree(got: np.ndarray, expected: np.ndarray) -> None:
    """Within TOL, and mostly unclamped so that the numbers were really compared."""
    assert got.dtype == np.float64
    np.testing.assert_allclose(got, expected, rtol=0, atol=TOL)
    rgb = expected[..., :3]
    inside = np.mean((rgb > 1e-6) & (rgb < 1 - 1e-6))
    assert inside > 0.5, f"only {inside:.0%} of the channels are inside (0, 1)"


def random_unit_normals(rng: np.random.Generator, n: int) -> np.ndarray:
    return unit(rng.normal(size=(n, 3)))


# --- 000: the OpenGL lighting equation -------------------------------------------------------


def document_000(
    V: np.ndarray,
    n: np.ndarray,
    lights: list[dict[str, Any]],
    material: dict[str, Any],
    a_cs: np.ndarray,
    v_bs: bool,
) -> np.ndarray:
    """c_pri = e_cm + a_cm*a_cs + sum_i (att_i)(spot_i)[a_cm*a_cli + (n ⊙ VP_pli) d_cm*d_cli
    + (f_i)(n ⊙ h_i)^s_rm s_cm*s_cli], term by term as document 000 writes it."""
    e_cm, a_cm, d_cm, s_cm, s_rm = (material[k] for k in ("e_cm", "a_cm", "d_cm", "s_cm", "s_rm"))
    c_pri = e_cm + (a_cm * a_cs)
    for light in lights:
        P_pl = light["P_pl"]
        if P_pl[3] != 0:  # both w != 0: the unit vector from V to P_pl
            VP_pl_vector = P_pl[:3] / P_pl[3] - V
            VP_pl = unit(VP_pl_vector)
            distance = np.linalg.norm(VP_pl_vector, axis=-1)
            k0, k1, k2 = light["k0"], light["k1"], light["k2"]
            att = 1.0 / (k0 + k1 * distance + k2 * distance**2)
        else:  # P_pl's w = 0: the unit vector of P_pl
            VP_pl = np.broadcast_to(unit(P_pl[:3]), V.shape)
            att = np.ones(len(V))
        n_odot_VP = np.maximum(dot(n, VP_pl), 0.0)
        if v_bs:
            VP_e = unit(np.array([0.0, 0.0, 0.0]) - V)  # P_e = (0 0 0 1)
            h = VP_pl + VP_e
        else:
            h = VP_pl + np.array([0.0, 0.0, 1.0])
        h_hat = unit(h)
        f = np.where(dot(n, VP_pl) >= 0, 1.0, 0.0)
        c_rl = light["c_rl"]
        if c_rl == 180.0:
            spot = np.ones(len(V))
        else:
            P_plV = -VP_pl  # from the light to the vertex
            S_dl_hat = unit(light["s_dl"])
            P_plV_odot_S_dl = np.maximum(dot(P_plV, S_dl_hat), 0.0)
            spot = np.where(
                P_plV_odot_S_dl >= np.cos(np.radians(c_rl)), P_plV_odot_S_dl ** light["s_rl"], 0.0
            )
        n_odot_h = np.maximum(dot(n, h_hat), 0.0)
        F = (
            a_cm * light["a_cl"]
            + n_odot_VP[:, None] * d_cm * light["d_cl"]
            + (f * n_odot_h**s_rm)[:, None] * s_cm * light["s_cl"]
        )
        c_pri = c_pri + (att * spot)[:, None] * F
    return np.clip(c_pri, 0.0, 1.0)


def test_opengl_preset_is_the_default_scene() -> None:
    assert gs.presets.opengl().scene == gs.Scene()
    assert gs.presets.opengl(local_viewer=True).scene == gs.Scene(viewer=(0, 0, 0, 1))
    assert dict(gs.presets.opengl().shade_kwargs) == {}


@pytest.mark.parametrize("trial", range(TRIALS))
def test_opengl_matches_document_000(trial: int) -> None:
    rng = np.random.default_rng(1000 + trial)
    lights = []
    for _ in range(int(rng.integers(1, 4))):
        directional = rng.random() < 0.4
        spot = rng.random() < 0.5
        lights.append(
            {
                "P_pl": np.r_[rng.uniform(-3, 3, 3), 0.0 if directional else 1.0],
                "a_cl": rng.uniform(0, 0.2, 3),
                "d_cl": rng.uniform(0, 0.5, 3),
                "s_cl": rng.uniform(0, 0.5, 3),
                "k0": rng.uniform(0.5, 1.5),
                "k1": rng.uniform(0, 0.3),
                "k2": rng.uniform(0, 0.2),
                "s_dl": rng.normal(size=3),
                "s_rl": rng.uniform(0, 20),
                "c_rl": rng.uniform(20, 89) if spot else 180.0,
            }
        )
    material = {
        "e_cm": rng.uniform(0, 0.1, 3),
        "a_cm": rng.uniform(0, 0.5, 3),
        "d_cm": rng.uniform(0.2, 1, 3),
        "s_cm": rng.uniform(0, 1, 3),
        "s_rm": rng.uniform(1, 64),
    }
    a_cs = rng.uniform(0, 0.3, 3)
    v_bs = bool(trial % 2)
    V = rng.uniform(-1, 1, (VERTICES, 3)) - (0, 0, 2)
    n = random_unit_normals(rng, VERTICES)

    preset = gs.presets.opengl(
        lights=[
            gs.Light(
                position=L["P_pl"],
                ambient=L["a_cl"],
                diffuse=L["d_cl"],
                specular=L["s_cl"],
                constant_attenuation=L["k0"],
                linear_attenuation=L["k1"],
                quadratic_attenuation=L["k2"],
                spot_direction=L["s_dl"],
                spot_exponent=L["s_rl"],
                spot_cutoff=L["c_rl"],
            )
            for L in lights
        ],
        material=gs.Material(
            emission=material["e_cm"],
            ambient=material["a_cm"],
            diffuse=material["d_cm"],
            specular=material["s_cm"],
            shininess=material["s_rm"],
        ),
        global_ambient=a_cs,
        local_viewer=v_bs,
    )
    got = preset.shade(V, n)
    expected = document_000(V, n, lights, material, a_cs, v_bs)
    agree(got[:, :3], expected)
    assert (got[:, 3] == 1).all()


# --- 001: DirectX 11 --------------------------------------------------------------------------


def document_001(
    pos: np.ndarray,
    n: np.ndarray,
    L: np.ndarray,
    eye: np.ndarray,
    c: dict[str, np.ndarray],
    p: float,
) -> np.ndarray:
    """LitColor = l_a ⊗ m_a + k_d l_d ⊗ m_d + k_s l_s ⊗ m_s = A + k_d D + k_s S."""
    n = unit(n)  # "L and n are unit vectors"
    v = unit(eye - pos)
    r = 2 * dot(L, n)[:, None] * n - L  # the reflection of the incident light -L about n
    A = c["l_a"] * c["m_a"]
    D = c["l_d"] * c["m_d"]
    S = c["l_s"] * c["m_s"]
    k_d = np.maximum(dot(L, n), 0.0)
    k_s = np.where(dot(L, n) > 0, np.maximum(dot(v, r), 0.0) ** p, 0.0)
    LitColor = A + k_d[:, None] * D + k_s[:, None] * S
    return np.clip(LitColor, 0.0, 1.0)


@pytest.mark.parametrize("trial", range(TRIALS))
def test_directx11_matches_document_001(trial: int) -> None:
    rng = np.random.default_rng(2000 + trial)
    colors = {
        "l_a": rng.uniform(0, 0.4, 3),
        "l_d": rng.uniform(0.2, 0.8, 3),
        "l_s": rng.uniform(0, 0.6, 3),
        "m_a": rng.uniform(0, 0.5, 3),
        "m_d": rng.uniform(0.2, 0.8, 3),
        "m_s": rng.uniform(0, 0.6, 3),
    }
    p = float(rng.uniform(1, 64))
    eye = rng.uniform(-4, 4, 3)
    pos = rng.uniform(-1, 1, (VERTICES, 3))
    n = rng.normal(size=(VERTICES, 3)) * rng.uniform(0.2, 3, (VERTICES, 1))
    if trial % 2:  # a directional light: L is the light vector itself
        light = {"light_vector": rng.normal(size=3)}
        L = np.broadcast_to(unit(light["light_vector"]), pos.shape)
    else:  # a point light
        light = {"light_position": rng.uniform(-4, 4, 3)}
        L = unit(light["light_position"] - pos)
    preset = gs.presets.directx11(**colors, p=p, eye_position=eye, **light)
    got = preset.shade(pos, n)
    agree(got[:, :3], document_001(pos, n, L, eye, colors, p))
    assert (got[:, 3] == 1).all()


def test_directx11_alpha_is_the_diffuse_materials() -> None:
    colors = dict.fromkeys(("l_a", "l_d", "l_s", "m_a", "m_s"), (0.5, 0.5, 0.5))
    preset = gs.presets.directx11(
        **colors, m_d=(0.5, 0.5, 0.5, 0.25), p=8, eye_position=(0, 0, 5), light_vector=(0, 0, 1)
    )
    assert preset.shade([[0.0, 0.0, 0.0]], [[0.0, 0.0, 1.0]])[0, 3] == 0.25


# --- 002: learnopengl Basic Lighting -----------------------------------------------------------


def document_002(
    aPos: np.ndarray, aNormal: np.ndarray, model: np.ndarray, u: dict[str, Any]
) -> np.ndarray:
    """2.2.basic_lighting.vs and .fs, line by line."""
    # vertex shader
    FragPos = (model @ np.c_[aPos, np.ones(len(aPos))].T).T[:, :3]
    Normal = (np.linalg.inv(model[:3, :3]).T @ aNormal.T).T  # mat3(transpose(inverse(model)))
    # fragment shader
    lightColor, objectColor = u["lightColor"], u["objectColor"]
    ambientStrength = u["ambientStrength"]
    ambient = ambientStrength * lightColor
    norm = unit(Normal)
    lightDir = unit(u["lightPos"] - FragPos)
    diff = np.maximum(dot(norm, lightDir), 0.0)
    diffuse = diff[:, None] * lightColor
    specularStrength = u["specularStrength"]
    viewDir = unit(u["viewPos"] - FragPos)
    I = -lightDir  # noqa: E741 (GLSL's name)
    reflectDir = I - 2.0 * dot(norm, I)[:, None] * norm  # reflect(-lightDir, norm)
    spec = np.maximum(dot(viewDir, reflectDir), 0.0) ** u["shininess"]
    specular = specularStrength * spec[:, None] * lightColor
    result = (ambient + diffuse + specular) * objectColor
    FragColor = np.c_[result, np.ones(len(result))]
    return np.clip(FragColor, 0.0, 1.0)


def random_model_matrix(rng: np.random.Generator) -> np.ndarray:
    q, _ = np.linalg.qr(rng.normal(size=(3, 3)))
    m = np.eye(4)
    m[:3, :3] = q @ np.diag(rng.uniform(0.4, 2.5, 3))  # non-uniform scale: needs the normal matrix
    m[:3, 3] = rng.uniform(-1, 1, 3)
    return m


@pytest.mark.parametrize("trial", range(TRIALS))
def test_learnopengl_matches_document_002(trial: int) -> None:
    rng = np.random.default_rng(3000 + trial)
    uniforms = {
        "lightPos": rng.uniform(-3, 3, 3),
        "viewPos": rng.uniform(-4, 4, 3),
        "lightColor": rng.uniform(0.3, 1.0, 3),
        "objectColor": rng.uniform(0.2, 0.9, 3),
        "ambientStrength": float(rng.uniform(0, 0.3)),
        "specularStrength": float(rng.uniform(0, 1)),
        "shininess": 32.0 if trial % 2 else float(rng.uniform(1, 128)),
    }
    model = random_model_matrix(rng) if trial % 3 else np.eye(4)
    aPos = rng.uniform(-1, 1, (VERTICES, 3))
    aNormal = rng.normal(size=(VERTICES, 3))
    preset = gs.presets.learnopengl(
        light_pos=uniforms["lightPos"],
        view_pos=uniforms["viewPos"],
        light_color=uniforms["lightColor"],
        object_color=uniforms["objectColor"],
        ambient_strength=uniforms["ambientStrength"],
        specular_strength=uniforms["specularStrength"],
        shininess=uniforms["shininess"],
        model=None if trial % 3 == 0 else model,
    )
    got = preset.shade(aPos, aNormal)
    expected = document_002(aPos, aNormal, model, uniforms)
    agree(got, expected)


def test_learnopengl_highlights_where_the_light_is_behind() -> None:
    # The shader has no gate: with the light behind the surface (n . L < 0) the reflection can
    # still point at the viewer. GL's f_i would leave such a vertex at the ambient term.
    preset = gs.presets.learnopengl(light_pos=(0, 1, -0.2), view_pos=(0, -1, -0.2))
    got = preset.shade([[0.0, 0.0, 0.0]], [[0.0, 0.0, 1.0]])[0]
    # ambient 0.1 + spec 0.5 * 1^32 (R = reflect(-L, n) = (0, -1, -0.2)/|.| = viewDir), times
    # objectColor (1, 0.5, 0.31).
    np.testing.assert_allclose(got, [0.6, 0.3, 0.186, 1.0], rtol=0, atol=TOL)


def test_learnopengl_defaults_are_the_tutorials() -> None:
    expected = document_002(
        np.zeros((1, 3)),
        np.array([[0.0, 0.0, 1.0]]),
        np.eye(4),
        {
            "lightPos": np.array([1.2, 1.0, 2.0]),
            "viewPos": np.array([0.0, 0.0, 3.0]),
            "lightColor": np.ones(3),
            "objectColor": np.array([1.0, 0.5, 0.31]),
            "ambientStrength": 0.1,
            "specularStrength": 0.5,
            "shininess": 32.0,
        },
    )
    got = gs.presets.learnopengl().shade(np.zeros((1, 3)), [[0.0, 0.0, 1.0]])
    np.testing.assert_allclose(got, expected, rtol=0, atol=TOL)


# --- 004: the lecture's Phong illumination model -----------------------------------------------


def document_004(p: np.ndarray, normal: np.ndarray, m: dict[str, Any]) -> np.ndarray:
    """I = k_a I_a + sum_l f_radatten f_angatten [k_d I_l (N . L) + k_s I_l (R . V)^n]."""
    N = unit(normal)  # "N: the unit surface normal"
    V = unit(m["viewer"] - p)
    I = m["k_a"] * m["I_a"]  # noqa: E741 (the lecture's name)
    for l_index in range(len(m["lights"])):
        light = m["lights"][l_index]
        I_l = m["I_l"][l_index]
        if "position" in light:
            to_light = light["position"] - p
            d = np.linalg.norm(to_light, axis=-1)
            L = unit(to_light)
            if m["attenuation"] is None:
                f_radatten = np.ones(len(p))
            elif m["attenuation"] == "inverse_square":
                f_radatten = 1.0 / d**2
            else:
                a0, a1, a2 = m["attenuation"]
                f_radatten = 1.0 / (a0 + a1 * d + a2 * d**2)
        else:  # infinitely distant: no attenuation
            L = np.broadcast_to(unit(light["direction"]), p.shape)
            f_radatten = np.ones(len(p))
        if m["spot"] is None:
            f_angatten = np.ones(len(p))
        else:
            V_obj = -L  # from the light to the object
            V_light = unit(m["spot"]["direction"])
            cos_alpha = dot(V_obj, V_light)
            theta_l, a_l = m["spot"]["theta_l"], m["spot"]["a_l"]
            with np.errstate(invalid="ignore"):  # cos_alpha < 0 ** a_l in the branch not taken
                f_angatten = np.where(cos_alpha >= np.cos(np.radians(theta_l)), cos_alpha**a_l, 0.0)
        NL = dot(N, L)
        R = dot(2 * L, N)[:, None] * N - L  # "R = dot(2L, N)*N - L"
        RV = np.maximum(dot(R, V), 0.0)
        lit = np.where(
            (NL > 0)[:, None],
            m["k_d"] * I_l * NL[:, None] + m["k_s"] * I_l * (RV ** m["n"])[:, None],
            0.0,
        )
        I = I + (f_radatten * f_angatten)[:, None] * lit  # noqa: E741
    return np.clip(I, 0.0, 1.0)


@pytest.mark.parametrize("trial", range(TRIALS))
def test_phong_illumination_matches_document_004(trial: int) -> None:
    rng = np.random.default_rng(4000 + trial)
    count = int(rng.integers(1, 4))
    directional = trial % 4 == 3
    lights = [
        {"direction": rng.normal(size=3)} if directional else {"position": rng.uniform(-3, 3, 3)}
        for _ in range(count)
    ]
    attenuation: Any = [None, "inverse_square", tuple(rng.uniform(0.1, 1.0, 3))][trial % 3]
    spot = None
    if trial % 2:
        spot = {
            "direction": rng.normal(size=3),
            "theta_l": float(rng.uniform(30, 89)),
            "a_l": float(rng.uniform(0, 8)),
        }
    I_l = rng.uniform(0.2, 1.0, (count, 3)) * (1.0 if attenuation != "inverse_square" else 2.0)
    m = {
        "k_a": float(rng.uniform(0, 0.5)),
        "k_d": float(rng.uniform(0.2, 0.8)),
        "k_s": float(rng.uniform(0, 0.6)),
        "n": float(rng.uniform(1, 64)),
        "I_a": rng.uniform(0, 0.5, 3),
        "I_l": I_l,
        "viewer": rng.uniform(-4, 4, 3),
        "lights": lights,
        "attenuation": attenuation,
        "spot": spot,
    }
    p = rng.uniform(-1, 1, (VERTICES, 3))
    normal = rng.normal(size=(VERTICES, 3))
    where = np.array([light.get("position", light.get("direction")) for light in lights])
    kwargs: dict[str, Any] = {"light_direction" if directional else "light_position": where}
    if spot is not None:
        kwargs.update(
            spot_direction=spot["direction"],
            spot_cutoff=spot["theta_l"],
            spot_exponent=spot["a_l"],
        )
    preset = gs.presets.phong_illumination(
        k_a=m["k_a"],
        k_d=m["k_d"],
        k_s=m["k_s"],
        n=m["n"],
        I_a=m["I_a"],
        I_l=I_l,
        viewer_position=m["viewer"],
        attenuation=attenuation,
        **kwargs,
    )
    got = preset.shade(p, normal)
    agree(got[:, :3], document_004(p, normal, m))
    assert (got[:, 3] == 1).all()


def test_phong_illumination_takes_one_light_and_scalar_intensities() -> None:
    preset = gs.presets.phong_illumination(
        k_a=0.2,
        k_d=0.5,
        k_s=0.25,
        n=4,
        I_a=0.5,
        I_l=0.8,
        viewer_position=(0, 0, 5),
        light_position=(0, 0, 2),
        attenuation="inverse_square",
    )
    # On the axis: N.L = 1, R = V: I = 0.2*0.5 + (0.5*0.8 + 0.25*0.8) / 2^2.
    got = preset.shade([[0.0, 0.0, 0.0]], [[0.0, 0.0, 1.0]])
    np.testing.assert_allclose(got, [[0.25, 0.25, 0.25, 1.0]], rtol=0, atol=TOL)


# --- flat and smooth shading (004) ------------------------------------------------------------


def jittered_sphere(rng: np.random.Generator) -> tuple[np.ndarray, np.ndarray]:
    trimesh = require("trimesh")
    mesh = trimesh.creation.icosphere(subdivisions=2)
    vertices = mesh.vertices * rng.uniform(0.8, 1.2, (len(mesh.vertices), 1)) - (0, 0, 3)
    return np.asarray(vertices, dtype=np.float64), np.asarray(mesh.faces)


def lecture_face_normals(v: np.ndarray, f: np.ndarray) -> np.ndarray:
    """ "(p1 - p0) x (p2 - p0)", normalised: one N per triangle."""
    p0, p1, p2 = v[f[:, 0]], v[f[:, 1]], v[f[:, 2]]
    return unit(np.cross(p1 - p0, p2 - p0))


def lecture_vertex_normals(v: np.ndarray, f: np.ndarray) -> np.ndarray:
    """ "The N of a vertex is the average of the N of the triangles that contain it (add them
    all, then make the length 1)"."""
    total = np.zeros_like(v)
    for corner in range(3):
        np.add.at(total, f[:, corner], lecture_face_normals(v, f))
    return unit(total)


def sphere_scene() -> tuple[gs.Scene, RefScene]:
    light = {
        "position": (2.0, 1.0, 1.0, 1.0),
        "diffuse": (0.7, 0.6, 0.5),
        "linear_attenuation": 0.2,
    }
    material = {
        "ambient": (0.2, 0.2, 0.2),
        "diffuse": (0.6, 0.7, 0.8),
        "specular": (0.4, 0.4, 0.4),
        "emission": (0.0, 0.0, 0.0),
        "shininess": 12.0,
    }
    scene = gs.Scene(
        lights=[gs.Light(**light)], material=gs.Material(**material), viewer=(0, 0, 0, 1)
    )
    return scene, RefScene(lights=[light], material=material, viewer=(0.0, 0.0, 0.0, 1.0))


def test_flat_shading_is_one_colour_per_face_from_its_normal_at_its_centroid() -> None:
    rng = np.random.default_rng(7)
    v, f = jittered_sphere(rng)
    scene, ref = sphere_scene()
    got = gs.shade_mesh(v, f, scene=scene, per="face")
    centroids = (v[f[:, 0]] + v[f[:, 1]] + v[f[:, 2]]) / 3
    expected = gl_lighting(centroids, lecture_face_normals(v, f), ref).outputs[0]
    assert got.shape == (len(f), 4)
    agree(got, expected)


def test_smooth_shading_is_one_colour_per_vertex_from_averaged_normals() -> None:
    rng = np.random.default_rng(8)
    v, f = jittered_sphere(rng)
    scene, ref = sphere_scene()
    got = gs.shade_mesh(v, f, scene=scene, per="vertex", weighting="uniform")
    expected = gl_lighting(v, lecture_vertex_normals(v, f), ref).outputs[0]
    assert got.shape == (len(v), 4)
    agree(got, expected)


def test_shade_mesh_takes_a_trimesh_and_every_shade_keyword() -> None:
    trimesh = require("trimesh")
    mesh = trimesh.creation.box()
    scene = gs.Scene(lights=[gs.Light(position=(1, 2, 3, 1))], two_side=True)
    m = np.eye(4)
    m[:3, 3] = (0, 0, -4)
    flat = gs.shade_mesh(mesh, scene=scene, per="face", modelview=m)
    assert flat.shape == (2, len(mesh.faces), 4)
    centroids = mesh.triangles_center
    expected = gs.shade(centroids, mesh.face_normals, scene, modelview=m)
    np.testing.assert_allclose(flat, expected, rtol=0, atol=TOL)
    smooth = gs.presets.Preset(scene, {"modelview": m}).shade_mesh(mesh)
    assert smooth.shape == (2, len(mesh.vertices), 4)
    f32 = gs.shade_mesh(mesh.vertices.astype(np.float32), mesh.faces, scene=scene, per="face")
    assert f32.dtype == np.float32


def test_flat_shading_of_a_degenerate_face_is_emission_and_ambient() -> None:
    v = np.array([[0, 0, -1], [1, 0, -1], [2, 0, -1], [0, 1, -1]], np.float64)
    f = np.array([[0, 1, 2], [0, 1, 3]])  # the first face is a line
    scene = gs.Scene(lights=[gs.Light()], material=gs.Material(emission=(0.1, 0, 0)))
    got = gs.shade_mesh(v, f, scene=scene, per="face")
    np.testing.assert_allclose(got, [[0.14, 0.04, 0.04, 1], [0.94, 0.84, 0.84, 1]], atol=TOL)


# --- area lights (004: "an area light is the sum of many point lights") -----------------------


def test_one_sample_is_the_centre_point_light() -> None:
    colours = {"diffuse": (0.3, 0.2, 0.1), "specular": (0.5, 0.5, 0.5), "ambient": (0.1, 0, 0)}
    attenuation = {"constant_attenuation": 0.5, "quadratic_attenuation": 0.25}
    centre = gs.Light(position=(1, 2, 3, 1), **colours, **attenuation)
    assert (
        gs.rectangle_light((1, 2, 3), (1, 0, 0), (0, 2, 1), 1, **colours, **attenuation) == centre
    )
    assert gs.disc_light((1, 2, 3), (0, 1, 1), 0.5, 1, **colours, **attenuation) == centre


@pytest.mark.parametrize("k", [2, 7, 64, 1000])
def test_rectangle_samples_lie_on_the_rectangle_and_share_the_power(k: int) -> None:
    c, u, v = np.array([1.0, -2, 0.5]), np.array([2.0, 0, 1]), np.array([0.5, 1, 0])
    lights = gs.rectangle_light(c, u, v, k, diffuse=(0.6, 0.3, 0.9), specular=(1, 1, 1))
    assert len(lights) == k
    assert (lights.position[:, 3] == 1).all()
    st = np.linalg.lstsq(np.c_[u, v], (lights.position[:, :3] - c).T, rcond=None)[0].T
    np.testing.assert_allclose(c + st @ np.stack([u, v]), lights.position[:, :3], atol=1e-14)
    assert (np.abs(st) < 0.5).all()
    # Stratified along u: one sample per strip of width 1/k.
    assert sorted(np.floor((st[:, 0] + 0.5) * k).astype(int)) == list(range(k))
    np.testing.assert_allclose(lights.diffuse[:, :3].sum(axis=0), (0.6, 0.3, 0.9), rtol=1e-12)
    np.testing.assert_allclose(lights.specular[:, :3].sum(axis=0), (1, 1, 1), rtol=1e-12)
    assert (lights.spot_cutoff == 180).all()


@pytest.mark.parametrize("k", [2, 7, 64, 1000])
def test_disc_samples_lie_on_the_disc_and_share_the_power(k: int) -> None:
    c, normal, radius = np.array([0.0, 3, -1]), np.array([1.0, 1, 0]), 0.75
    lights = gs.disc_light(c, normal, radius, k, diffuse=(0.2, 0.4, 0.8), emission="lambertian")
    offsets = lights.position[:, :3] - c
    np.testing.assert_allclose(offsets @ unit(normal), 0, atol=1e-15)
    assert (np.linalg.norm(offsets, axis=1) <= radius * (1 + 1e-15)).all()
    # Equal areas: about a quarter of the samples fall inside half the radius.
    inner = np.mean(np.linalg.norm(offsets, axis=1) < radius / 2)
    assert abs(inner - 0.25) <= 2 / k + 0.01
    np.testing.assert_allclose(lights.diffuse[:, :3].sum(axis=0), (0.2, 0.4, 0.8), rtol=1e-12)
    np.testing.assert_allclose(lights.spot_direction, np.tile(normal, (k, 1)))
    assert (lights.spot_cutoff == 90).all() and (lights.spot_exponent == 1).all()


def irradiance_on_axis(lights: gs.Lights, h: float) -> float:
    """The diffuse of a white material h below `lights` (at y = 0), facing them."""
    m = gs.Material(ambient=(0, 0, 0), diffuse=(1, 1, 1), specular=(0, 0, 0))
    scene = gs.Scene(lights=lights, material=m, global_ambient=(0, 0, 0))
    return float(gs.shade([[0.0, -h, 0.0]], [[0.0, 1.0, 0.0]], scene)[0, 0])


@pytest.mark.parametrize(("k", "rel"), [(4096, 2e-5), (4181, 1e-8)])
def test_area_lights_converge_to_the_analytic_irradiance(k: int, rel: float) -> None:
    # Isotropic points of total colour c with 1/d^2 attenuation, on the axis h below:
    # (c / area) * integral of cos / d^2 dA = c * (solid angle of the light) / area.
    # k = 4181 is a Fibonacci number, where the lattice is a true Fibonacci lattice.
    from glshade.lab.studies import area_light_closed_form

    h, a, b, radius, c = 0.7, 0.5, 0.25, 0.6, 0.25
    light = {"diffuse": (c, c, c), "constant_attenuation": 0.0, "quadratic_attenuation": 1.0}
    rect = gs.rectangle_light((0, 0, 0), (2 * a, 0, 0), (0, 0, 2 * b), k, **light)
    solid_angle = 4 * np.arctan(a * b / (h * np.sqrt(a**2 + b**2 + h**2)))
    rect_error = irradiance_on_axis(rect, h) / (c * solid_angle / (4 * a * b)) - 1
    disc = gs.disc_light((0, 0, 0), (0, -1, 0), radius, k, **light)
    solid_angle = 2 * np.pi * (1 - h / np.hypot(radius, h))
    disc_error = irradiance_on_axis(disc, h) / (c * solid_angle / (np.pi * radius**2)) - 1
    assert abs(rect_error) < rel
    assert abs(disc_error) < max(rel, 1e-7)
    # The documentation's Area lights page (docs/pages/guide/area-lights.md) quotes these
    # errors from the study; it computes the same numbers.
    [row] = area_light_closed_form([k])
    assert row["k"] == k
    assert row["rectangle"] == pytest.approx(rect_error, abs=1e-12)
    assert row["disc"] == pytest.approx(disc_error, abs=1e-12)


def test_area_light_error_falls_with_k() -> None:
    from glshade.lab.studies import area_light_convergence

    rows = area_light_convergence(ks=(1, 4, 16, 64, 256), reference_k=4096, grid=24, repeat=1)
    assert [row["k"] for row in rows] == [1, 4, 16, 64, 256]
    for key in ("max_error", "mean_error"):
        errors = [row[key] for row in rows]
        assert all(b < a for a, b in itertools.pairwise(errors)), (key, errors)
    assert rows[0]["max_error"] > 1e-2 > rows[-1]["max_error"]
    assert all(row["ms"] > 0 for row in rows)


# --- errors name the argument -----------------------------------------------------------------

DX = dict.fromkeys(("l_a", "l_d", "l_s", "m_a", "m_d", "m_s"), (0.5, 0.5, 0.5))
LECTURE = {
    "k_a": 0.1,
    "k_d": 0.5,
    "k_s": 0.2,
    "n": 8,
    "I_a": 1,
    "I_l": 1,
    "viewer_position": (0, 0, 5),
}
P = gs.presets

BAD: list[tuple[Callable[[], object], type[Exception], str]] = [
    (
        lambda: P.directx11(
            **{**DX, "l_d": (1, 1)}, p=8, eye_position=(0, 0, 1), light_vector=(0, 0, 1)
        ),
        ValueError,
        "l_d must have shape (3,) or (4,), got (2,)",
    ),
    (
        lambda: P.directx11(**DX, p=-1, eye_position=(0, 0, 1), light_vector=(0, 0, 1)),
        ValueError,
        "p must be >= 0, got -1",
    ),
    (
        lambda: P.directx11(**DX, p=8, eye_position=(0, 0, 1)),
        TypeError,
        "exactly one of light_vector",
    ),
    (
        lambda: P.directx11(
            **DX, p=8, eye_position=(0, 0, 1), light_vector=(0, 0, 1), light_position=(0, 0, 1)
        ),
        TypeError,
        "got both",
    ),
    (
        lambda: P.directx11(**DX, p=8, eye_position=(0, 0, 1), light_vector=(0, 0, 0)),
        ValueError,
        "light_vector must be a nonzero vector",
    ),
    (
        lambda: P.directx11(
            **{**DX, "m_s": "red"}, p=8, eye_position=(0, 0, 1), light_vector=(0, 0, 1)
        ),
        TypeError,
        "m_s takes numbers, not a colour name: got 'red'",
    ),
    (lambda: P.learnopengl(view_pos=(0, 0)), ValueError, "view_pos must have shape (3,), got (2,)"),
    (
        lambda: P.learnopengl(light_color=(1, 1, 1, 1)),
        ValueError,
        "light_color must have shape (3,)",
    ),
    (lambda: P.learnopengl(ambient_strength=np.nan), ValueError, "ambient_strength must be finite"),
    (lambda: P.learnopengl(shininess=-2), ValueError, "shininess must be >= 0"),
    (
        lambda: P.learnopengl(model=np.eye(3)),
        ValueError,
        "model must have shape (4, 4), got (3, 3)",
    ),
    (lambda: P.learnopengl(model=np.diag([1, 1, 0, 1])), ValueError, "model must be invertible"),
    (lambda: P.learnopengl(model=np.ones((4, 4))), ValueError, "model must be affine"),
    (lambda: P.opengl(local_viewer="yes"), TypeError, "local_viewer must be True or False"),
    (
        lambda: P.phong_illumination(**{**LECTURE, "k_d": -0.1}, light_position=(0, 1, 0)),
        ValueError,
        "k_d must be >= 0, got -0.1",
    ),
    (
        lambda: P.phong_illumination(**{**LECTURE, "n": [1, 2]}, light_position=(0, 1, 0)),
        ValueError,
        "n must be a number",
    ),
    (
        lambda: P.phong_illumination(**{**LECTURE, "I_a": (1, 1)}, light_position=(0, 1, 0)),
        ValueError,
        "I_a must have shape a number or (3,)",
    ),
    (
        lambda: P.phong_illumination(**{**LECTURE, "I_l": (1, 1)}, light_position=(0, 1, 0)),
        ValueError,
        "I_l must be a number or have shape (3,) or (L, 3), got (2,)",
    ),
    (
        lambda: P.phong_illumination(
            **{**LECTURE, "I_l": np.ones((2, 3))}, light_position=(0, 1, 0)
        ),
        ValueError,
        "I_l has 2 rows, so light_position must have shape (2, 3)",
    ),
    (lambda: P.phong_illumination(**LECTURE), TypeError, "exactly one of light_direction"),
    (
        lambda: P.phong_illumination(**LECTURE, light_position=(0, 1, 0), attenuation="cubic"),
        ValueError,
        "attenuation must be None, 'inverse_square' or (a0, a1, a2)",
    ),
    (
        lambda: P.phong_illumination(**LECTURE, light_position=(0, 1, 0), attenuation=(0, 0, 0)),
        ValueError,
        "not all 0",
    ),
    (
        lambda: P.phong_illumination(**LECTURE, light_position=(0, 1, 0), spot_cutoff=30),
        TypeError,
        "need a spot_direction",
    ),
    (
        lambda: P.phong_illumination(
            **LECTURE, light_position=(0, 1, 0), spot_direction=(0, -1, 0), spot_cutoff=120
        ),
        ValueError,
        "spot_cutoff must be in [0, 90]",
    ),
    (
        lambda: P.phong_illumination(
            **LECTURE, light_position=(0, 1, 0), spot_direction=(0, -1, 0), spot_exponent=-1
        ),
        ValueError,
        "spot_exponent must be >= 0",
    ),
    (
        lambda: gs.rectangle_light((0, 0, 0), (1, 0, 0), (2, 0, 0), 4),
        ValueError,
        "u and v must not be parallel",
    ),
    (
        lambda: gs.rectangle_light((0, 0, 0), (1, 0, 0), (0, 1, 0), 0),
        ValueError,
        "k must be an integer >= 1, got 0",
    ),
    (
        lambda: gs.rectangle_light((0, 0, 0), (1, 0, 0), (0, 1, 0), 2.5),
        TypeError,
        "k must be an integer >= 1, got 2.5",
    ),
    (
        lambda: gs.rectangle_light((0, 0), (1, 0, 0), (0, 1, 0), 4),
        ValueError,
        "center must have shape (3,)",
    ),
    (
        lambda: gs.rectangle_light((0, 0, 0), (1, 0, 0), (0, 1, 0), 4, emission="cosine"),
        ValueError,
        "emission must be 'uniform' or 'lambertian'",
    ),
    (
        lambda: gs.rectangle_light((0, 0, 0), (1, 0, 0), (0, 1, 0), 4, quadratic_attenuation=-1),
        ValueError,
        "quadratic_attenuation must be >= 0",
    ),
    (
        lambda: gs.disc_light((0, 0, 0), (0, 0, 0), 1, 4),
        ValueError,
        "normal must be a nonzero vector",
    ),
    (lambda: gs.disc_light((0, 0, 0), (0, 0, 1), 0, 4), ValueError, "radius must be > 0, got 0"),
    (
        lambda: gs.disc_light((0, 0, 0), (0, 0, 1), 1, 4, diffuse=(1,)),
        ValueError,
        "diffuse must have shape (3,) or (4,)",
    ),
    (
        lambda: gs.shade_mesh(np.zeros((3, 3)), [[0, 1, 2]], scene=gs.Scene(), per="edge"),
        ValueError,
        "per must be 'vertex' or 'face', got 'edge'",
    ),
    (
        lambda: gs.shade_mesh(np.zeros((3, 3)), [[0, 1, 2]], scene=gs.Scene(), weighting="cot"),
        ValueError,
        "weighting must be 'angle', 'area' or 'uniform'",
    ),
    (
        lambda: gs.shade_mesh(np.zeros((3, 3)), [[0, 1, 5]], scene=gs.Scene(), per="face"),
        IndexError,
        "face 0 refers to vertex 5",
    ),
    (
        lambda: gs.shade_mesh(np.zeros((3, 3)), [[0, 1, 2]], scene="sun"),  # type: ignore[arg-type]
        TypeError,
        "scene must be a glshade.Scene",
    ),
    (lambda: gs.shade_mesh(np.zeros((3, 3)), scene=gs.Scene()), TypeError, "faces is required"),
]


@pytest.mark.parametrize("call, exception, words", BAD, ids=range(len(BAD)))
def test_bad_parameters_raise_naming_the_argument(
    call: Callable[[], object], exception: type[Exception], words: str
) -> None:
    with pytest.raises(exception, match=re.escape(words)):
        call()


def test_a_preset_is_frozen() -> None:
    preset = gs.presets.directx11(**DX, p=8, eye_position=(0, 0, 1), light_vector=(0, 0, 1))
    with pytest.raises(AttributeError):
        preset.scene = gs.Scene()
    with pytest.raises(TypeError):
        preset.shade_kwargs["normalize"] = False
    # Extra keywords override the preset's for one call.
    off = preset.shade([[0.0, 0, 0]], [[0.0, 0, 2]], normalize=False)
    on = preset.shade([[0.0, 0, 0]], [[0.0, 0, 2]])
    assert not np.array_equal(off, on)
