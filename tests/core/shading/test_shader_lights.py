"""learnopengl's Light casters (5.4) and Multiple lights (6) shaders and Luna's LightHelper.fx,
transcribed here in numpy as the shaders are written (their names, their structure, nothing
from glshade), against `gs.presets.learnopengl_lights` and `gs.presets.directx11_lights` on
random scenes: within 1e-12 in float64 and 1e-5 in float32.

Sources:
- JoeyDeVries/LearnOpenGL at commit d99731d752c04aced62f8d26bc2dfce4f63c8847:
  ``src/2.lighting/6.multiple_lights/6.multiple_lights.fs`` and
  ``src/2.lighting/5.4.light_casters_spot_soft/5.4.light_casters.fs``; the material's
  samplers are replaced by per-vertex texels (the diffuse map) and a constant specular texel.
- Frank Luna, Introduction to 3D Game Programming with DirectX 11 (2012), chapter 7,
  ``LightHelper.fx`` (``ComputeDirectionalLight``, ``ComputePointLight``,
  ``ComputeSpotLight``) and ``Basic.fx`` (the sum, ``litColor.a = gMaterial.Diffuse.a``).

The shaders do not clamp; the framebuffer (and glshade) does, so the transcriptions are clamped.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import pytest

import glshade as gs
from support.shader_math import clamp, dot, normalize, reflect

TOL = {np.float64: 1e-12, np.float32: 1e-5}
VERTICES = 600


# --- learnopengl ------------------------------------------------------------------------------


def calc_dir_light(light: dict, normal, viewDir, diffuseTex, specularTex, shininess):
    lightDir = normalize(-light["direction"])
    diff = np.maximum(dot(normal, lightDir), 0.0)
    reflectDir = reflect(-lightDir, normal)
    spec = np.maximum(dot(viewDir, reflectDir), 0.0) ** shininess
    ambient = light["ambient"] * diffuseTex
    diffuse = light["diffuse"] * diff * diffuseTex
    specular = light["specular"] * spec * specularTex
    return ambient + diffuse + specular


def calc_point_light(light: dict, normal, fragPos, viewDir, diffuseTex, specularTex, shininess):
    lightDir = normalize(light["position"] - fragPos)
    diff = np.maximum(dot(normal, lightDir), 0.0)
    reflectDir = reflect(-lightDir, normal)
    spec = np.maximum(dot(viewDir, reflectDir), 0.0) ** shininess
    distance = np.linalg.norm(light["position"] - fragPos, axis=-1, keepdims=True)
    attenuation = 1.0 / (
        light["constant"] + light["linear"] * distance + light["quadratic"] * (distance * distance)
    )
    ambient = light["ambient"] * diffuseTex
    diffuse = light["diffuse"] * diff * diffuseTex
    specular = light["specular"] * spec * specularTex
    return (ambient + diffuse + specular) * attenuation


def calc_spot_light(  # 6.multiple_lights.fs, or 5.4.light_casters.fs's main() with chapter "5.4"
    light: dict, normal, fragPos, viewDir, diffuseTex, specularTex, shininess, chapter: str
):
    lightDir = normalize(light["position"] - fragPos)
    diff = np.maximum(dot(normal, lightDir), 0.0)
    reflectDir = reflect(-lightDir, normal)
    spec = np.maximum(dot(viewDir, reflectDir), 0.0) ** shininess
    distance = np.linalg.norm(light["position"] - fragPos, axis=-1, keepdims=True)
    attenuation = 1.0 / (
        light["constant"] + light["linear"] * distance + light["quadratic"] * (distance * distance)
    )
    theta = dot(lightDir, normalize(-light["direction"]))
    epsilon = light["cutOff"] - light["outerCutOff"]
    if epsilon > 0:
        intensity = clamp((theta - light["outerCutOff"]) / epsilon, 0.0, 1.0)
    else:  # the shader's x / 0: +inf (1) inside, -inf (0) outside; GL's hard edge at equality
        intensity = (theta >= light["outerCutOff"]).astype(float)
    ambient = light["ambient"] * diffuseTex
    diffuse = light["diffuse"] * diff * diffuseTex
    specular = light["specular"] * spec * specularTex
    if chapter == "6":
        ambient = ambient * attenuation * intensity
    else:
        ambient = ambient * attenuation
    diffuse = diffuse * attenuation * intensity
    specular = specular * attenuation * intensity
    return ambient + diffuse + specular


def learnopengl_shader(aPos, aNormal, model, diffuseTex, u: dict, chapter: str) -> np.ndarray:
    FragPos = (model @ np.c_[aPos, np.ones(len(aPos))].T).T[:, :3]
    Normal = (np.linalg.inv(model[:3, :3]).T @ aNormal.T).T  # mat3(transpose(inverse(model)))
    norm = normalize(Normal)
    viewDir = normalize(u["viewPos"] - FragPos)
    m = u["material"]
    args = (diffuseTex, m["specular"], m["shininess"])
    result = np.zeros_like(FragPos)
    if u["dirLight"] is not None:
        result = result + calc_dir_light(u["dirLight"], norm, viewDir, *args)
    for light in u["pointLights"]:
        result = result + calc_point_light(light, norm, FragPos, viewDir, *args)
    if u["spotLight"] is not None:
        result = result + calc_spot_light(u["spotLight"], norm, FragPos, viewDir, *args, chapter)
    return clamp(np.c_[result, np.ones(len(result))], 0.0, 1.0)


def random_model(rng: np.random.Generator) -> np.ndarray:
    q, _ = np.linalg.qr(rng.normal(size=(3, 3)))
    m = np.eye(4)
    m[:3, :3] = q @ np.diag(rng.uniform(0.5, 2.0, 3))
    m[:3, 3] = rng.uniform(-0.5, 0.5, 3)
    return m


def spot_towards(rng: np.random.Generator) -> tuple[np.ndarray, np.ndarray]:
    """A spot 3 away from the origin, aimed near it, so that a cone of 8 to 18 degrees cuts
    through the vertices in [-1, 1]^3."""
    position = 3.0 * normalize(rng.normal(size=3))
    return position, normalize(rng.uniform(-0.6, 0.6, 3) - position)


def learnopengl_case(seed: int, chapter: str) -> dict:
    rng = np.random.default_rng(seed)
    colour = lambda lo, hi: rng.uniform(lo, hi, 3)  # noqa: E731
    position, direction = spot_towards(rng)
    outer = rng.uniform(8, 18)
    inner = outer - rng.uniform(1, 6) if seed % 4 else outer  # equal: GL's hard edge
    spot = {
        "position": position,
        "direction": direction,
        "cutOff": math.cos(math.radians(inner)),
        "outerCutOff": math.cos(math.radians(outer)),
        "constant": 1.0,
        "linear": rng.uniform(0, 0.3),
        "quadratic": rng.uniform(0, 0.1),
        "ambient": colour(0, 0.2),
        "diffuse": colour(0.3, 1),
        "specular": colour(0, 1),
    }
    u: dict[str, Any] = {
        "viewPos": rng.uniform(-4, 4, 3),
        "material": {
            "diffuse": colour(0.2, 0.9),
            "specular": colour(0.2, 0.9),
            "shininess": 32.0 if seed % 2 else rng.uniform(1, 128),
        },
        "spotLight": spot,
        "dirLight": None,
        "pointLights": [],
    }
    if chapter == "6":
        u["dirLight"] = {
            "direction": rng.normal(size=3),
            "ambient": colour(0, 0.1),
            "diffuse": colour(0, 0.4),
            "specular": colour(0, 0.5),
        }
        u["pointLights"] = [
            {
                "position": rng.uniform(-3, 3, 3),
                "constant": 1.0,
                "linear": rng.uniform(0, 0.2),
                "quadratic": rng.uniform(0, 0.1),
                "ambient": colour(0, 0.1),
                "diffuse": colour(0, 0.5),
                "specular": colour(0, 0.5),
            }
            for _ in range(int(rng.integers(0, 5)))
        ]
    return u


def learnopengl_preset(u: dict, chapter: str, model: np.ndarray | None) -> gs.presets.Preset:
    return gs.presets.learnopengl_lights(
        view_pos=u["viewPos"],
        material=u["material"],
        dir_light=u["dirLight"],
        point_lights=u["pointLights"],
        spot_light=u["spotLight"],
        chapter=chapter,
        model=model,
    )


@pytest.mark.parametrize("dtype", [np.float64, np.float32])
@pytest.mark.parametrize("chapter", ["6", "5.4"])
@pytest.mark.parametrize("seed", range(16))
def test_learnopengl_lights_match_the_shaders(seed: int, chapter: str, dtype: type) -> None:
    u = learnopengl_case(seed, chapter)
    rng = np.random.default_rng(500 + seed)
    model = random_model(rng) if seed % 3 else np.eye(4)
    aPos = rng.uniform(-1, 1, (VERTICES, 3)).astype(dtype)
    aNormal = rng.normal(size=(VERTICES, 3)).astype(dtype)
    texels = rng.uniform(0.1, 1, (VERTICES, 3)).astype(dtype)
    preset = learnopengl_preset(u, chapter, None if seed % 3 == 0 else model)
    got = preset.shade(aPos, aNormal, colors=texels)
    assert got.dtype == dtype
    want = learnopengl_shader(
        aPos.astype(float), aNormal.astype(float), model, texels.astype(float), u, chapter
    )
    # Not vacuous: the spot's edge crosses the vertices, and most colours are unclamped.
    spot = u["spotLight"]
    world = (model @ np.c_[aPos.astype(float), np.ones(VERTICES)].T).T[:, :3]
    theta = dot(normalize(spot["position"] - world), normalize(-spot["direction"]))[:, 0]
    assert 0 < (theta > spot["outerCutOff"]).sum() < VERTICES
    epsilon = spot["cutOff"] - spot["outerCutOff"]
    ramp = (theta > spot["outerCutOff"]) & (theta < spot["cutOff"])
    assert epsilon == 0 or ramp.any()
    tol = np.full(VERTICES, TOL[dtype])
    if dtype == np.float32 and epsilon > 0:
        # The ramp's slope 1 / epsilon multiplies theta's float32 rounding (a few 2^-24).
        tol[ramp] += 8 * 2.0**-24 / epsilon
    error = np.abs(got - want).max(axis=1)
    assert (error <= tol).all(), (
        f"{error.max():.3g} at {error.argmax()}, in the ramp: {ramp[error.argmax()]}"
    )
    assert np.mean((want[:, :3] > 1e-6) & (want[:, :3] < 1 - 1e-6)) > 0.5
    # Without texels the diffuse map is material["diffuse"] everywhere.
    constant = np.broadcast_to(u["material"]["diffuse"], (VERTICES, 3))
    want = learnopengl_shader(
        aPos.astype(float), aNormal.astype(float), model, constant, u, chapter
    )
    assert (np.abs(preset.shade(aPos, aNormal) - want).max(axis=1) <= tol).all()


def test_learnopengl_lights_chapter_54_keeps_the_ambient_outside_the_cone() -> None:
    # Chapter 5.4 attenuates its ambient term but does not scale it by the spot intensity:
    # behind the cone the vertex keeps ambient * attenuation; chapter 6 makes it black.
    u = learnopengl_case(1, "5.4")
    spot = u["spotLight"]
    p = spot["position"] - 2.0 * spot["direction"]  # behind the light
    n = normalize(spot["position"] - p)
    got = {c: learnopengl_preset(u, c, None).shade(p[None], n[None])[0, :3] for c in ("5.4", "6")}
    attenuation = 1 / (spot["constant"] + 2 * spot["linear"] + 4 * spot["quadratic"])
    want = spot["ambient"] * u["material"]["diffuse"] * attenuation
    np.testing.assert_allclose(got["5.4"], want, rtol=0, atol=1e-12)
    np.testing.assert_allclose(got["6"], 0.0, rtol=0, atol=1e-12)


def test_learnopengl_lights_describe_the_soft_edge() -> None:
    u = learnopengl_case(1, "6")
    plan = learnopengl_preset(u, "6", None).scene.plan(normalize=True)
    assert "soft edge" in plan


# --- Luna's LightHelper.fx --------------------------------------------------------------------


def compute_directional_light(mat: dict, L: dict, normal, toEye):
    lightVec = -L["Direction"]
    ambient = mat["Ambient"] * L["Ambient"]
    diffuseFactor = dot(lightVec, normal)
    v = reflect(-lightVec, normal)
    specFactor = np.maximum(dot(v, toEye), 0.0) ** mat["Specular"][3]
    lit = diffuseFactor > 0.0  # [flatten] if (diffuseFactor > 0.0f)
    diffuse = np.where(lit, diffuseFactor * mat["Diffuse"] * L["Diffuse"], 0.0)
    spec = np.where(lit, specFactor * mat["Specular"] * L["Specular"], 0.0)
    return ambient + 0 * normal[:, :1], diffuse, spec


def compute_point_light(mat: dict, L: dict, pos, normal, toEye, spot_light: bool = False):
    lightVec = L["Position"] - pos
    d = np.linalg.norm(lightVec, axis=-1, keepdims=True)
    in_range = d <= L["Range"]  # if (d > L.Range) return;
    lightVec = lightVec / d
    ambient = mat["Ambient"] * L["Ambient"] + 0 * d
    diffuseFactor = dot(lightVec, normal)
    v = reflect(-lightVec, normal)
    specFactor = np.maximum(dot(v, toEye), 0.0) ** mat["Specular"][3]
    lit = diffuseFactor > 0.0
    diffuse = np.where(lit, diffuseFactor * mat["Diffuse"] * L["Diffuse"], 0.0)
    spec = np.where(lit, specFactor * mat["Specular"] * L["Specular"], 0.0)
    att = 1.0 / dot(L["Att"], np.c_[np.ones_like(d), d, d * d])
    if spot_light:
        spot = np.maximum(dot(-lightVec, L["Direction"]), 0.0) ** L["Spot"]
        att = spot * att
        ambient = ambient * spot
    diffuse, spec = diffuse * att, spec * att
    return (np.where(in_range, x, 0.0) for x in (ambient, diffuse, spec))


def luna_shader(pos, normal, world, u: dict) -> np.ndarray:
    posW = (world @ np.c_[pos, np.ones(len(pos))].T).T[:, :3]
    normalW = (np.linalg.inv(world[:3, :3]).T @ normal.T).T  # gWorldInvTranspose
    normalW = normalize(normalW)
    toEye = normalize(u["gEyePosW"] - posW)
    mat = u["gMaterial"]
    total = np.zeros((len(pos), 4))
    for L in u["gDirLights"]:
        total += sum(compute_directional_light(mat, L, normalW, toEye))
    for L in u["gPointLights"]:
        total += sum(compute_point_light(mat, L, posW, normalW, toEye))
    for L in u["gSpotLights"]:
        total += sum(compute_point_light(mat, L, posW, normalW, toEye, spot_light=True))
    litColor = total
    litColor[:, 3] = mat["Diffuse"][3]
    return clamp(litColor, 0.0, 1.0)


def luna_case(seed: int) -> dict:
    rng = np.random.default_rng(7000 + seed)
    rgba = lambda lo, hi: np.r_[rng.uniform(lo, hi, 3), rng.uniform(0, 1)]  # noqa: E731

    def positional() -> dict:
        position = rng.uniform(-3, 3, 3)
        att = (1.0, 0.0, 0.0) if seed % 4 == 0 else (1.0, rng.uniform(0, 0.3), rng.uniform(0, 0.1))
        return {
            "Ambient": rgba(0, 0.15),
            "Diffuse": rgba(0.2, 0.7),
            "Specular": rgba(0, 0.6),
            "Position": position,
            # Some vertices beyond the range, some inside.
            "Range": float(np.linalg.norm(position)) + rng.uniform(-0.5, 0.5),
            "Att": np.array(att),
        }

    spots = []
    for _ in range(int(rng.integers(1, 3))):
        s = positional()
        s["Direction"] = normalize(-s["Position"] + rng.normal(scale=0.3, size=3))
        # Spot 0: HLSL's pow(0, 0) behind the light is undefined; numpy's 0.0 ** 0 is GL's 1.
        s["Spot"] = float(rng.choice([0.0, 1.0, 8.0, rng.uniform(0.5, 64)]))
        spots.append(s)
    return {
        "gEyePosW": rng.uniform(-4, 4, 3),
        "gMaterial": {
            "Ambient": rgba(0.3, 1),
            "Diffuse": rgba(0.3, 1),
            "Specular": np.r_[rng.uniform(0.2, 1, 3), 16.0 if seed % 2 else rng.uniform(1, 100)],
        },
        "gDirLights": [
            {
                "Ambient": rgba(0, 0.1),
                "Diffuse": rgba(0, 0.3),
                "Specular": rgba(0, 0.3),
                "Direction": normalize(rng.normal(size=3)),
            }
            for _ in range(int(rng.integers(1, 3)))
        ],
        "gPointLights": [positional() for _ in range(int(rng.integers(1, 3)))],
        "gSpotLights": spots,
    }


def luna_preset(u: dict, world: np.ndarray | None) -> gs.presets.Preset:
    return gs.presets.directx11_lights(
        material=u["gMaterial"],
        eye_position=u["gEyePosW"],
        dir_lights=u["gDirLights"],
        point_lights=u["gPointLights"],
        spot_lights=u["gSpotLights"],
        world=world,
    )


@pytest.mark.parametrize("dtype", [np.float64, np.float32])
@pytest.mark.parametrize("seed", range(20))
def test_directx11_lights_match_light_helper(seed: int, dtype: type) -> None:
    u = luna_case(seed)
    rng = np.random.default_rng(900 + seed)
    world = random_model(rng) if seed % 3 else np.eye(4)
    pos = rng.uniform(-1, 1, (VERTICES, 3)).astype(dtype)
    normal = rng.normal(size=(VERTICES, 3)).astype(dtype)
    got = luna_preset(u, None if seed % 3 == 0 else world).shade(pos, normal)
    assert got.dtype == dtype
    want = luna_shader(pos.astype(float), normal.astype(float), world, u)
    np.testing.assert_allclose(got, want, rtol=0, atol=TOL[dtype])
    # Not vacuous: every positional light's range cuts the vertices.
    posW = (world @ np.c_[pos.astype(float), np.ones(VERTICES)].T).T[:, :3]
    for L in u["gPointLights"] + u["gSpotLights"]:
        reached = np.linalg.norm(L["Position"] - posW, axis=-1) <= L["Range"]
        assert 0 < reached.sum() < VERTICES
    assert np.mean((want[:, :3] > 1e-6) & (want[:, :3] < 1 - 1e-6)) > 0.5


def test_directx11_lights_split_only_where_the_ambient_is_attenuated_differently() -> None:
    u = luna_case(1)
    point = {**u["gPointLights"][0], "Att": (1.0, 0.0, 0.0)}
    one = gs.presets.directx11_lights(
        material=u["gMaterial"], eye_position=(0, 0, 3), point_lights=[point]
    )
    assert len(one.scene.lights) == 1
    two = gs.presets.directx11_lights(
        material=u["gMaterial"], eye_position=(0, 0, 3), point_lights=[{**point, "Att": (0, 1, 0)}]
    )
    assert len(two.scene.lights) == 2
    dark = {**point, "Att": (0, 1, 0), "Ambient": (0, 0, 0, 1)}
    dark_preset = gs.presets.directx11_lights(
        material=u["gMaterial"], eye_position=(0, 0, 3), point_lights=[dark]
    )
    assert len(dark_preset.scene.lights) == 1


def test_directx11_lights_with_one_directional_light_is_directx11() -> None:
    u = luna_case(2)
    L = {
        "Ambient": (0.2, 0.2, 0.2, 1),
        "Diffuse": (0.5, 0.4, 0.3, 1),
        "Specular": (0.5, 0.5, 0.5, 1),
        "Direction": (0.57735, -0.57735, 0.57735),
    }
    mat = u["gMaterial"]
    many = gs.presets.directx11_lights(material=mat, eye_position=(1, 2, 3), dir_lights=[L])
    one = gs.presets.directx11(
        l_a=L["Ambient"], l_d=L["Diffuse"], l_s=L["Specular"], m_a=mat["Ambient"],
        m_d=mat["Diffuse"], m_s=mat["Specular"][:3], p=mat["Specular"][3],
        eye_position=(1, 2, 3), light_vector=-np.asarray(L["Direction"]),
    )  # fmt: skip
    rng = np.random.default_rng(4)
    p, n = rng.uniform(-1, 1, (200, 3)), rng.normal(size=(200, 3))
    np.testing.assert_allclose(many.shade(p, n), one.shade(p, n), rtol=0, atol=1e-15)


# --- errors -----------------------------------------------------------------------------------

P = gs.presets
GLSL_MATERIAL = {"diffuse": (1, 0.5, 0.3), "specular": (0.5, 0.5, 0.5), "shininess": 32.0}
GLSL_SPOT = {
    "position": (0, 0, 3), "direction": (0, 0, -1), "cutOff": 0.976, "outerCutOff": 0.966,
    "constant": 1.0, "linear": 0.09, "quadratic": 0.032,
    "ambient": (0, 0, 0), "diffuse": (1, 1, 1), "specular": (1, 1, 1),
}  # fmt: skip
HLSL_MATERIAL = {"Ambient": (0.5, 0.5, 0.5, 1), "Diffuse": (1, 0.5, 0.3, 1),
                 "Specular": (0.5, 0.5, 0.5, 16)}  # fmt: skip
HLSL_POINT = {"Ambient": (0.1, 0.1, 0.1, 1), "Diffuse": (1, 1, 1, 1), "Specular": (1, 1, 1, 1),
              "Position": (0, 2, 0), "Range": 25.0, "Att": (0, 0.1, 0)}  # fmt: skip


RENAMED = {k: v for k, v in GLSL_SPOT.items() if k != "cutOff"}


def glsl(**kw: Any) -> Any:
    return P.learnopengl_lights(view_pos=(0, 0, 3), material=GLSL_MATERIAL, **kw)


def hlsl(**kw: Any) -> Any:
    return P.directx11_lights(
        material=kw.pop("material", HLSL_MATERIAL), eye_position=(0, 0, 3), **kw
    )


ERRORS = [
    (lambda: glsl(spot_light={**RENAMED, "cutoff": 1}), TypeError,
     r"spot_light must have exactly the members .*missing \['cutOff'\]; unknown \['cutoff'\]"),
    (lambda: glsl(spot_light=[GLSL_SPOT]), TypeError, "spot_light must be a mapping"),
    (lambda: glsl(point_lights=GLSL_SPOT), TypeError, "point_lights must be a sequence"),
    (lambda: glsl(spot_light={**GLSL_SPOT, "cutOff": 0.9}), ValueError,
     r'"outerCutOff" <= "cutOff".*outerCutOff=0.966, cutOff=0.9'),
    (lambda: glsl(spot_light={**GLSL_SPOT, "outerCutOff": -0.1}), ValueError, "at most 90"),
    (lambda: glsl(spot_light={**GLSL_SPOT, "linear": -1}), ValueError,
     "spot_light's constant, linear, quadratic must be >= 0"),
    (lambda: glsl(spot_light={**GLSL_SPOT, "direction": (0, 0, 0)}), ValueError,
     r'spot_light\["direction"\] must be a nonzero vector'),
    (lambda: glsl(spot_light={**GLSL_SPOT, "diffuse": "white"}), TypeError,
     r'spot_light\["diffuse"\]'),
    (lambda: glsl(spot_light=GLSL_SPOT, chapter="5"), ValueError, 'chapter must be "6" or "5.4"'),
    (lambda: glsl(dir_light={"direction": (0, -1, 0), "ambient": (0, 0, 0), "diffuse": (1, 1, 1),
                             "specular": (1, 1, 1)}, chapter="5.4"), ValueError,
     "chapter 5.4's shader has one light"),
    (lambda: P.learnopengl_lights(view_pos=(0, 0, 3), material={**GLSL_MATERIAL, "shininess": -1}),
     ValueError, r'material\["shininess"\] must be >= 0'),
    (lambda: hlsl(point_lights=[{**HLSL_POINT, "Range": 0}]), ValueError,
     r'point_lights\[0\]\["Range"\] must be > 0, got 0'),
    (lambda: hlsl(point_lights=[{**HLSL_POINT, "Att": (0, 0, 0)}]), ValueError,
     r'point_lights\[0\]\["Att"\]\'s a0, a1, a2 must be >= 0, not all 0'),
    (lambda: hlsl(spot_lights=[{**HLSL_POINT, "Direction": (0, -1, 0), "Spot": -2}]), ValueError,
     r'spot_lights\[0\]\["Spot"\] must be >= 0'),
    (lambda: hlsl(spot_lights=[HLSL_POINT]), TypeError, r"missing \['Direction', 'Spot'\]"),
    (lambda: hlsl(material={**HLSL_MATERIAL, "Specular": (1, 1, 1)}), ValueError,
     r'material\["Specular"\] must have shape \(4,\)'),
    (lambda: hlsl(material={**HLSL_MATERIAL, "Specular": (1, 1, 1, -1)}), ValueError,
     "the specular power, must be >= 0"),
    (lambda: hlsl(world=np.eye(3)), ValueError, r"world must have shape \(4, 4\)"),
]  # fmt: skip


@pytest.mark.parametrize(("call", "error", "message"), ERRORS)
def test_shader_light_presets_name_the_bad_member(call: Any, error: type, message: str) -> None:
    with pytest.raises(error, match=message):
        call()
