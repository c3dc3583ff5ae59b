"""Panda3D's shader generator, transcribed here in numpy as the Cg it writes (its names, its
structure, nothing from glshade), against `gs.presets.panda3d` on random scenes: within 1e-12
in float64 and 1e-5 in float32.

Sources, panda3d/panda3d:
- ``panda/src/pgraphnodes/shaderGenerator.cxx`` (commit 0224c1441bc00cd8871bac5ff91cecf95049d7b8):
  the per-light code, the summation, ``saturate``, the specular added after it,
  ``o_color = result * 1.000001``;
- ``panda/src/display/graphicsStateGuardian.cxx``, ``fetch_specified_part``: the light inputs
  (``dlight``: colour, specular, ``d = normalize(-direction)``, ``h = normalize(d + (0, -1, 0))``;
  ``slight``: ``-view_vector`` and ``cos(hfov / 2)``; ``satten``: attenuation and exponent).

The framebuffer clamps what the shader writes: the transcription is clamped, and compared with
the preset after dividing out the shader's ``* 1.000001`` (a driver workaround the preset leaves
out; the test checks that it changes nothing by more than 1e-6). The shader adds the specular
term after its clamp; the framebuffer's clamp of the sum makes that GL's single clamped sum
(every term is at least 0).
"""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest

import glshade as gs
from support.shader_math import dot, normalize, saturate

TOL = {np.float64: 1e-12, np.float32: 1e-5}
VERTICES = 600


def rgba(c: Any) -> np.ndarray:
    c = np.asarray(c, dtype=float)
    return np.r_[c, 1.0] if c.shape == (3,) else c


def generated_shader(l_eye_position, l_eye_normal, u: dict, l_color=None) -> np.ndarray:
    """The fragment program for these lights, as ShaderGenerator writes it, per vertex."""
    n = len(l_eye_position)
    material = u["material"]
    local = u["local"]
    l_eye_normal = normalize(l_eye_normal)
    tot_ambient = np.zeros((n, 4))
    tot_diffuse = np.zeros((n, 4))
    tot_specular = np.zeros((n, 4))
    shininess = material["shininess"] if material is not None else 50.0
    tot_ambient += sum((rgba(c) for c in u["ambient_lights"]), np.zeros(4))  # attr_ambient

    for light in u["directional_lights"]:
        lcolor = rgba(light["color"])
        lspec = rgba(light["specular_color"])
        lvec = normalize(-np.asarray(light["direction"], dtype=float))  # dlight_rel_view[2]
        lcolor = lcolor * saturate(dot(l_eye_normal, lvec))
        tot_diffuse += lcolor
        if local:
            lhalf = normalize(lvec - normalize(l_eye_position))
        else:
            lhalf = normalize(lvec + np.array([0.0, -1.0, 0.0]))  # dlight_rel_view[3]
        lspec = lspec * saturate(dot(l_eye_normal, lhalf)) ** shininess
        tot_specular += lspec
    for light in u["point_lights"] + u["spotlights"]:
        spot = "fov" in light
        lcolor = rgba(light["color"])
        lspec = rgba(light["specular_color"])
        lpoint = np.asarray(light["point"], dtype=float)
        latten = np.asarray(light["attenuation"], dtype=float)
        lvec = lpoint - l_eye_position
        ldist = np.linalg.norm(lvec, axis=-1, keepdims=True)
        lvec = lvec / ldist
        lattenv = 1 / (latten[0] + latten[1] * ldist + latten[2] * ldist * ldist)
        if spot:
            ldir = -np.asarray(light["direction"], dtype=float)  # -lens view vector
            cutoff = np.cos(np.radians(light["fov"] * 0.5))
            langle = saturate(dot(ldir, lvec))
            lattenv = lattenv * langle ** light["exponent"]
            lattenv = np.where(langle < cutoff, 0.0, lattenv)
        lcolor = lcolor * lattenv * saturate(dot(l_eye_normal, lvec))
        tot_diffuse += lcolor
        if local:
            lhalf = normalize(lvec - normalize(l_eye_position))
        else:
            lhalf = normalize(lvec - np.array([0.0, 1.0, 0.0]))
        lspec = lspec * lattenv
        lspec = lspec * saturate(dot(l_eye_normal, lhalf)) ** shininess
        tot_specular += lspec
    # Begin view-space light summation
    if material is not None:
        result = np.broadcast_to(rgba(material["emission"]), (n, 4)).copy()
        result += tot_ambient * rgba(material["ambient"])
        result += tot_diffuse * rgba(material["diffuse"])
    else:
        color = np.ones((n, 4)) if l_color is None else l_color
        result = tot_ambient * color + tot_diffuse * color
    result = saturate(result)
    result[:, 3] = 1.0 if l_color is None else l_color[:, 3]
    if material is not None:  # _have_specular: the material has a specular colour
        tot_specular = tot_specular * rgba(material["specular"])
        result[:, :3] = result[:, :3] + tot_specular[:, :3]
    o_color = result * 1.000001
    return o_color


def framebuffer(o_color: np.ndarray, workaround: bool = False) -> np.ndarray:
    """What a [0, 1] framebuffer holds, with the shader's * 1.000001 or without it."""
    return saturate(o_color if workaround else o_color / 1.000001)


def case(seed: int, with_material: bool = True) -> dict:
    rng = np.random.default_rng(4400 + seed)
    colour = lambda lo, hi: rng.uniform(lo, hi, 3)  # noqa: E731

    def positional() -> dict:
        return {
            "color": colour(0.2, 0.9),
            "specular_color": colour(0, 1),
            "point": rng.uniform(-3, 3, 3),
            "attenuation": (1.0, rng.uniform(0, 0.3), rng.uniform(0, 0.1)),
        }

    spots = []
    for _ in range(int(rng.integers(0, 3))):
        s = positional()
        s["direction"] = normalize(rng.uniform(-0.5, 0.5, 3) - s["point"])
        s["exponent"] = float(rng.choice([0.0, 2.0, rng.uniform(0, 40)]))
        s["fov"] = rng.uniform(40, 150)
        spots.append(s)
    material = {
        "ambient": colour(0.2, 1),
        "diffuse": np.r_[colour(0.2, 0.9), rng.uniform(0.2, 1)],  # the shader writes alpha 1
        "emission": colour(0, 0.1),
        "specular": colour(0.2, 1),
        "shininess": 32.0 if seed % 2 else rng.uniform(1, 100),
    }
    return {
        "material": material if with_material else None,
        "local": bool(seed % 3 == 0),
        "ambient_lights": [colour(0, 0.15) for _ in range(int(rng.integers(0, 3)))],
        "directional_lights": [
            {
                "color": colour(0, 0.5),
                "specular_color": colour(0, 0.5),
                "direction": rng.normal(size=3),
            }
            for _ in range(int(rng.integers(1, 3)))
        ],
        "point_lights": [positional() for _ in range(int(rng.integers(0, 3)))],
        "spotlights": spots,
    }


def preset(u: dict) -> gs.presets.Preset:
    return gs.presets.panda3d(
        material=u["material"],
        local=u["local"],
        ambient_lights=u["ambient_lights"],
        directional_lights=u["directional_lights"],
        point_lights=u["point_lights"],
        spotlights=u["spotlights"],
    )


@pytest.mark.parametrize("dtype", [np.float64, np.float32])
@pytest.mark.parametrize("seed", range(24))
def test_panda3d_matches_the_generated_shader(seed: int, dtype: type) -> None:
    u = case(seed)
    rng = np.random.default_rng(seed)
    p = rng.uniform(-1, 1, (VERTICES, 3)).astype(dtype)
    n = rng.normal(size=(VERTICES, 3)).astype(dtype)
    got = preset(u).shade(p, n)
    assert got.dtype == dtype and got.shape == (VERTICES, 4)
    o_color = generated_shader(p.astype(float), n.astype(float), u)
    want = framebuffer(o_color)
    # The shader's * 1.000001 moves a value by at most 1e-6; the preset leaves it out.
    np.testing.assert_allclose(framebuffer(o_color, workaround=True), want, rtol=0, atol=1e-6)
    np.testing.assert_allclose(got, want, rtol=0, atol=TOL[dtype])
    assert np.mean((want[:, :3] > 1e-6) & (want[:, :3] < 1 - 1e-6)) > 0.5


def test_panda3d_without_a_material_lights_the_vertex_colours() -> None:
    u = case(5, with_material=False)
    rng = np.random.default_rng(5)
    p, n = rng.uniform(-1, 1, (VERTICES, 3)), rng.normal(size=(VERTICES, 3))
    l_color = rng.uniform(0.2, 1, (VERTICES, 4))
    got = preset(u).shade(p, n, colors=l_color)
    want = framebuffer(generated_shader(p, n, u, l_color=l_color))
    np.testing.assert_allclose(got, want, rtol=0, atol=1e-12)
    white = preset(u).shade(p, n)
    want = framebuffer(generated_shader(p, n, u))
    np.testing.assert_allclose(white, want, rtol=0, atol=1e-12)


def test_panda3d_highlights_where_the_light_is_behind() -> None:
    # No gate: the light at 100 degrees from the normal (n . L < 0) still gives the half vector
    # a positive n . h, so a highlight.
    light = {"color": (1, 1, 1), "specular_color": (1, 1, 1)}
    # The normal faces the viewer (-y); the light is 100 degrees from it, towards +z.
    angle = np.radians(100)
    normal = np.array([0.0, -1.0, 0.0])
    towards = np.array([0.0, -np.cos(angle), np.sin(angle)])
    model = gs.presets.panda3d(
        material={"ambient": (1, 1, 1), "diffuse": (1, 1, 1), "emission": (0, 0, 0),
                  "specular": (0.5, 0.5, 0.5), "shininess": 1.0},
        ambient_lights=[(0.2, 0.2, 0.2)],
        directional_lights=[{**light, "direction": -towards}],
    )  # fmt: skip
    got = model.shade([[0.0, 0.0, 0.0]], [normal])[0]
    h = normalize(towards + np.array([0.0, -1.0, 0.0]))
    assert towards @ normal < 0 and h @ normal > 0
    expected = 0.2 + 0.5 * (h @ normal)  # ambient (no diffuse: n . L < 0) plus the ungated specular
    np.testing.assert_allclose(got, [expected, expected, expected, 1.0], rtol=0, atol=1e-12)


ERRORS = [
    (lambda: gs.presets.panda3d(), ValueError, "needs a light"),
    (lambda: gs.presets.panda3d(point_lights=[{"color": (1, 1, 1), "point": (0, 0, 0)}]),
     TypeError, r"point_lights\[0\] must have exactly the members .*missing"),
    (lambda: gs.presets.panda3d(spotlights=[{
        "color": (1, 1, 1), "specular_color": (1, 1, 1), "point": (0, 0, 0),
        "attenuation": (1, 0, 0), "direction": (0, 1, 0), "exponent": 1.0, "fov": 200}]),
     ValueError, r'spotlights\[0\]\["fov"\] must be in \[0, 180\]'),
    (lambda: gs.presets.panda3d(ambient_lights=[(1, 1)]), ValueError, r"ambient_lights\[0\]"),
    (lambda: gs.presets.panda3d(ambient_lights=[(0.1, 0.1, 0.1)], local=1), TypeError,
     "local must be True or False"),
    (lambda: gs.presets.panda3d(ambient_lights=[(0.1, 0.1, 0.1)], material={
        "ambient": (1, 1, 1), "diffuse": (1, 1, 1), "emission": (0, 0, 0),
        "specular": (1, 1, 1), "shininess": -1}), ValueError, "shininess"),
]  # fmt: skip


@pytest.mark.parametrize(("call", "error", "message"), ERRORS)
def test_panda3d_names_the_bad_argument(call: Any, error: type, message: str) -> None:
    with pytest.raises(error, match=message):
        call()
