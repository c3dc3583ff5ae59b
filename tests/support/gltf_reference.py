"""pyrender 0.1.45's ``shaders/mesh.frag`` for a metallic-roughness material without textures,
transcribed line by line into numpy in extended precision (``np.longdouble``, 64-bit mantissa
on x86-64): the oracle of glshade's metallic-roughness model.

Read from pyrender/shaders/mesh.frag (``compute_brdf``, ``specular_reflection``,
``geometric_occlusion``, ``microfacet_distribution`` and ``main``) and pyrender/renderer.py
(``_bind_lighting``: ``light_angle_scale``/``offset`` and ``direction = -pose[:3, 2]``). The one
change: ``emissive`` is added as given, where mesh.frag adds ``emissive_factor²``.
"""

from __future__ import annotations

from typing import Any

import numpy as np

import glshade as gs

L = np.longdouble
PI = L("3.14159265358979323846264338327950288")
MIN_ROUGHNESS = L("0.04")


def _normalize(v: Any) -> Any:
    return v / np.sqrt(np.sum(v * v, axis=-1, keepdims=True))


def _dot(a: Any, b: Any) -> Any:
    return np.sum(a * b, axis=-1)


def _brdf(
    n: Any, v: Any, to_light: Any, roughness: Any, f0: Any, c_diff: Any, radiance: Any
) -> Any:
    """``compute_brdf``: (k, 3) colours for unit n, v, to_light of k vertices."""
    h = _normalize(to_light + v)
    nl = np.clip(_dot(n, to_light), L("0.001"), L(1))
    nv = np.clip(np.abs(_dot(n, v)), L("0.001"), L(1))
    nh = np.clip(_dot(n, h), L(0), L(1))
    vh = np.clip(_dot(v, h), L(0), L(1))
    f = f0 + (1 - f0) * np.clip(1 - vh, L(0), L(1))[:, None] ** 5
    r = roughness + 1
    k = r * r / 8
    g = (nv / (nv * (1 - k) + k)) * (nl / (nl * (1 - k) + k))
    a = roughness * roughness
    a2 = a * a
    denom = nh * nh * (a2 - 1) + 1
    d = a2 / (PI * denom * denom)
    diffuse = (1 - f) * c_diff / PI
    spec = f * (g * d)[:, None] / (4 * nl * nv + L("0.001"))[:, None]
    return nl[:, None] * radiance * (diffuse + spec)


def mesh_frag(positions: Any, normals: Any, scene: gs.gltf.Scene, colors: Any = None) -> np.ndarray:
    """(k, 4) linear RGBA, unclamped, in longdouble: pyrender's colour before its gamma."""

    def given(x: Any) -> Any:
        return np.asarray(x, dtype=np.float64).astype(L)

    p = given(positions)
    n = _normalize(given(normals))
    m = scene.material
    roughness = np.clip(L(m.roughness), MIN_ROUGHNESS, L(1))
    metallic = np.clip(L(m.metallic), L(0), L(1))
    base = np.array(m.base_color, dtype=np.float64).astype(L)
    c_diff = base[:3] * (1 - MIN_ROUGHNESS) * (1 - metallic)
    f0 = MIN_ROUGHNESS * (1 - metallic) + base[:3] * metallic
    cam = given(scene.camera_position)
    v = _normalize(cam - p)
    color = np.zeros((len(p), 3), dtype=L)
    for light in scene.lights:
        light_color = np.array(light.color, dtype=np.float64).astype(L)
        if isinstance(light, gs.gltf.DirectionalLight):
            direction = _normalize(given(light.direction))
            to_light = np.broadcast_to(-direction, p.shape)
            attenuation = np.full(len(p), L(light.intensity))
        else:
            position = given(light.position)
            to_light = _normalize(position - p)
            dist = np.sqrt(_dot(position - p, position - p))
            if isinstance(light, gs.gltf.PointLight):
                attenuation = L(light.intensity) / (dist * dist)
            else:
                cos_inner = np.cos(L(light.inner_cone_angle))
                cos_outer = np.cos(L(light.outer_cone_angle))
                las = 1 / max(L("0.001"), cos_inner - cos_outer)
                lao = -cos_outer * las
                axis = _normalize(given(light.direction))
                cd = np.clip(_dot(np.broadcast_to(axis, p.shape), -to_light), L(0), L(1))
                s = np.clip(cd * las + lao, L(0), L(1))
                attenuation = s * s * L(light.intensity) / (dist * dist)
        radiance = attenuation[:, None] * light_color
        color += _brdf(n, v, to_light, roughness, f0, c_diff, radiance)
    color += base[:3] * np.array(scene.ambient_light, dtype=np.float64).astype(L)
    color += np.array(m.emissive, dtype=np.float64).astype(L)
    rgba = np.concatenate([color, np.ones((len(p), 1), dtype=L)], axis=1)
    if colors is not None:
        c = np.asarray(colors, dtype=np.float64).astype(L)
        if c.shape[1] == 3:
            c = np.concatenate([c, np.ones((len(c), 1), dtype=L)], axis=1)
        rgba = rgba * c
    rgba[:, 3] *= base[3]
    return rgba


def random_scene(rng: np.random.Generator, lights: int = 3) -> gs.gltf.Scene:
    """A scene of `lights` lights of random kinds, colours, intensities and places, with a
    material whose metallic and roughness are 0, 1 or between, in equal shares."""

    def factor() -> float:
        return float(rng.choice([0.0, 1.0, rng.uniform(0, 1)]))

    def direction() -> np.ndarray:
        return rng.normal(size=3)

    made: list[Any] = []
    for _ in range(lights):
        kind = rng.integers(3)
        color = tuple(rng.uniform(0, 1, 3))
        intensity = float(rng.choice([rng.uniform(0, 5), rng.uniform(0, 500)]))
        position = tuple(rng.uniform(-4, 4, 3))
        if kind == 0:
            made.append(gs.gltf.DirectionalLight(color, intensity, tuple(direction())))
        elif kind == 1:
            made.append(gs.gltf.PointLight(color, intensity, position))
        else:
            outer = float(rng.uniform(0.05, np.pi / 2))
            inner = float(rng.choice([0.0, outer, rng.uniform(0, outer)]))
            made.append(
                gs.gltf.SpotLight(color, intensity, position, tuple(direction()), inner, outer)
            )
    material = gs.gltf.Material(
        base_color=tuple(rng.uniform(0, 1, 4)),
        metallic=factor(),
        roughness=factor(),
        emissive=tuple(rng.choice([0.0, 1.0]) * rng.uniform(0, 1, 3)),
    )
    return gs.gltf.Scene(
        made,
        material,
        ambient_light=tuple(rng.choice([0.0, 1.0]) * rng.uniform(0, 0.5, 3)),
        camera_position=tuple(rng.uniform(-6, 6, 3)),
    )


U32 = 2.0**-24


def fast_bound(
    positions: Any, normals: Any, scene: gs.gltf.Scene, colors: Any = None
) -> np.ndarray:
    """(k, 3) The bound of float32 fast mode against the exact value, per vertex and channel
    (the Accuracy page's, in float64, without a model matrix):

        2e-6 · max(1, Σ|terms|) + 8u · Σ_i κ_i · t_i

    t_i is light i's term with its Fresnel factor and 1 - F taken as 1 (an upper bound of its
    term), and κ_i the sum of the term's sensitivities to the cosines float32 forms, each
    known to a few u: 1/nl, 1/nv, the spot cone's 2·scale/s, 3 for the distance and the
    normalisations, and, over min(1, |l + v|) (the halfway vector's direction is as uncertain
    as u/|l + v| where the light faces the viewer), GGX's
    4·sin θ_h·(1 - alpha²)/(alpha² + (1 - alpha²)·sin² θ_h) (2/alpha at sin θ_h = alpha: 1250
    at roughness 0.04) and 5 for Fresnel's (1 - v·h)^5.
    """
    p = np.asarray(positions, np.float64)
    n = _normalize(np.asarray(normals, np.float64))
    m = scene.material
    r = min(max(m.roughness, 0.04), 1.0)
    metallic = min(max(m.metallic, 0.0), 1.0)
    base = np.array(m.base_color, np.float64)
    c_diff = base[:3] * 0.96 * (1 - metallic)
    f0 = 0.04 * (1 - metallic) + base[:3] * metallic
    diffuse = (1 - f0) * c_diff / np.pi
    k, a2 = (r + 1) ** 2 / 8, r**4
    v = _normalize(np.asarray(scene.camera_position, np.float64) - p)
    nv = np.clip(np.abs(_dot(n, v)), 0.001, 1)
    terms = np.zeros((len(p), 3))
    weighted = np.zeros((len(p), 3))
    for light in scene.lights:
        color = np.array(light.color, np.float64) * light.intensity
        cone = np.zeros(len(p))
        if isinstance(light, gs.gltf.DirectionalLight):
            to_light = np.broadcast_to(-_normalize(np.array(light.direction, np.float64)), p.shape)
            attenuation = np.ones(len(p))
        else:
            offset = np.array(light.position, np.float64) - p
            to_light = _normalize(offset)
            attenuation = 1 / np.maximum(_dot(offset, offset), np.finfo(np.float32).tiny)
            if isinstance(light, gs.gltf.SpotLight):
                cos_inner, cos_outer = (
                    np.cos(light.inner_cone_angle),
                    np.cos(light.outer_cone_angle),
                )
                scale = 1 / max(0.001, cos_inner - cos_outer)
                axis = _normalize(np.array(light.direction, np.float64))
                cd = np.clip(-_dot(np.broadcast_to(axis, p.shape), to_light), 0, 1)
                s = np.clip(cd * scale - cos_outer * scale, 0, 1)
                attenuation = attenuation * s * s
                # 2·scale/s times the term, which holds s²: 2·scale·s times the rest.
                cone = np.where((s > 0) & (s < 1), 2 * scale / np.where(s > 0, s, 1), 0)
        halfway = to_light + v
        h = _normalize(halfway)
        nl = np.clip(_dot(n, to_light), 0.001, 1)
        sin2 = np.minimum(np.sum(np.cross(n, h) ** 2, axis=-1), 1)
        den = np.where(_dot(n, h) > 0, a2 + (1 - a2) * sin2, 1)
        g = nv / (nv * (1 - k) + k) * nl / (nl * (1 - k) + k)
        specular = g * a2 / (np.pi * den * den) / (4 * nl * nv + 0.001)
        ggx = np.where(_dot(n, h) > 0, 4 * np.sqrt(sin2) * (1 - a2) / den, 0)
        spread = np.minimum(1, np.sqrt(_dot(halfway, halfway)))
        kappa = 1 / nl + 1 / nv + cone + 3 + (ggx + 5) / spread
        t = (nl * attenuation)[:, None] * color * (diffuse + specular[:, None])
        terms += t
        weighted += kappa[:, None] * t
    constant = base[:3] * np.array(scene.ambient_light) + np.array(m.emissive)
    if colors is not None:
        c = np.abs(np.asarray(colors, np.float64)[:, :3])
        terms, weighted = terms * c, weighted * c
    total = terms + np.abs(constant)
    return 2e-6 * np.maximum(1, total) + 8 * U32 * weighted
