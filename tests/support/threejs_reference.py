"""three.js' ``MeshPhongMaterial`` transcribed from release 111 in float64, chunk by chunk,
independently of glshade's kernel: the reference of `tests/core/shading/test_threejs.py`.

Source: Debian's ``libjs-three`` 111+dfsg1-3, ``/usr/share/javascript/three/three.js``, the
shader chunks ``bsdfs`` (l. 14095: ``punctualLightIntensityToIrradianceFactor``,
``BRDF_Diffuse_Lambert``, ``F_Schlick``, ``D_BlinnPhong``, ``BRDF_Specular_BlinnPhong``),
``lights_pars_begin`` (l. 14159: ``getAmbientLightIrradiance``, the directional, point, spot and
hemisphere lights), ``lights_phong_pars_fragment`` (l. 14165: ``RE_Direct_BlinnPhong``,
``RE_IndirectDiffuse_BlinnPhong``), ``lights_fragment_begin`` (l. 14171: the light loops, point
then spot then directional), ``normal_fragment_begin`` (l. 14203: ``DOUBLE_SIDED``),
``meshphong_frag`` (l. 14303: ``outgoingLight``) and ``WebGLLights`` (l. 18952: colour times
intensity, ``coneCos``, ``penumbraCos``, directions from position - target). The shader's
``smoothstep`` with equal edges (penumbra 0) is taken as the step its preceding
``angleCos > coneCos`` test makes it on GPUs. The shininess is at least 1e-4, as
``refreshUniformsPhong`` (l. 25816) passes it; ``pow(x, 0)`` (a decay of 0) is 1.
"""

from __future__ import annotations

import math

import numpy as np

import glshade as gs

PI = math.pi
RECIPROCAL_PI = 1 / math.pi


def saturate(x: np.ndarray) -> np.ndarray:
    return np.clip(x, 0.0, 1.0)


def normalize(v: np.ndarray) -> np.ndarray:
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def dot(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    return np.sum(a * b, axis=-1)


def glsl_pow(x: np.ndarray, y: float) -> np.ndarray:
    """GLSL's pow for x >= 0, with pow(0, 0) = 1."""
    return np.ones_like(x) if y == 0 else np.power(x, y)


def smoothstep(edge0: float, edge1: float, x: np.ndarray) -> np.ndarray:
    if edge1 == edge0:
        return (x > edge0).astype(np.float64)
    t = np.clip((x - edge0) / (edge1 - edge0), 0.0, 1.0)
    return t * t * (3.0 - 2.0 * t)


def irradiance_factor(d: np.ndarray, cutoff: float, decay: float, physical: bool) -> np.ndarray:
    """``punctualLightIntensityToIrradianceFactor``."""
    if physical:
        falloff = 1.0 / np.maximum(glsl_pow(d, decay), 0.01)
        if cutoff > 0.0:
            falloff = falloff * saturate(1.0 - (d / cutoff) ** 4) ** 2
        return falloff
    if cutoff > 0.0 and decay > 0.0:
        return glsl_pow(saturate(-d / cutoff + 1.0), decay)
    return np.ones_like(d)


def blinn_phong(
    direction: np.ndarray, n: np.ndarray, view: np.ndarray, specular: np.ndarray, s: float
) -> np.ndarray:
    """``BRDF_Specular_BlinnPhong``: F · G · D, RGB."""
    half = normalize(direction + view)
    dot_nh = saturate(dot(n, half))
    dot_lh = saturate(dot(direction, half))
    fresnel = np.exp2((-5.55473 * dot_lh - 6.98316) * dot_lh)
    f = (1.0 - specular) * fresnel[:, None] + specular
    d = RECIPROCAL_PI * (s * 0.5 + 1.0) * glsl_pow(dot_nh, s)
    return f * (0.25 * d)[:, None]


def incident(light: object, p: np.ndarray, physical: bool) -> tuple[np.ndarray, np.ndarray]:
    """(directLight.direction, directLight.color) of a direct light at points `p`."""
    color = np.array(light.color) * light.intensity  # type: ignore[attr-defined]
    if isinstance(light, gs.threejs.DirectionalLight):
        direction = normalize(np.array(light.position) - np.array(light.target))
        return np.broadcast_to(direction, p.shape), np.broadcast_to(color, p.shape)
    l_vector = np.array(light.position) - p  # type: ignore[attr-defined]
    direction = normalize(l_vector)
    distance = np.linalg.norm(l_vector, axis=-1)
    factor = irradiance_factor(distance, light.distance, light.decay, physical)  # type: ignore[attr-defined]
    if isinstance(light, gs.threejs.SpotLight):
        axis = normalize(np.array(light.position) - np.array(light.target))
        cone_cos = math.cos(light.angle)
        penumbra_cos = math.cos(light.angle * (1 - light.penumbra))
        angle_cos = dot(direction, axis)
        spot = np.where(angle_cos > cone_cos, smoothstep(cone_cos, penumbra_cos, angle_cos), 0.0)
        factor = factor * spot
    return direction, color * factor[:, None]


def normal_and_view(
    p: np.ndarray, n: np.ndarray, scene: gs.threejs.Scene, back: bool
) -> tuple[np.ndarray, np.ndarray]:
    """The unit normal as the side lit sees it (``normal_fragment_begin``: negated for a
    back-sided material or the back of a double-sided one) and the unit view vector."""
    normal = normalize(n)
    if scene.material.side == "back" or back:
        normal = -normal
    if scene.view_direction is None:
        return normal, normalize(scene.camera_position - p)
    return normal, np.broadcast_to(normalize(scene.view_direction), p.shape)


def meshphong_frag(
    p: np.ndarray,
    n: np.ndarray,
    scene: gs.threejs.Scene,
    colors: np.ndarray | None = None,
    back: bool = False,
) -> np.ndarray:
    """The unclamped RGBA of ``meshphong_frag`` at world positions `p` and normals `n` (float64),
    for the front, or the back of a double-sided material (`back`)."""
    p, n = np.asarray(p, np.float64), np.asarray(n, np.float64)
    m = scene.material
    physical = scene.physically_correct_lights
    diffuse_color = np.broadcast_to(np.array(m.color), p.shape).copy()
    opacity = np.full(len(p), m.opacity)
    if colors is not None:
        c = np.asarray(colors, np.float64)
        diffuse_color *= c[:, :3]
        if c.shape[1] == 4:
            opacity = opacity * c[:, 3]
    normal, view = normal_and_view(p, n, scene, back)
    specular = np.array(m.specular)
    shininess = max(m.shininess, 1e-4)  # refreshUniformsPhong: "to prevent pow( 0.0, 0.0 )"
    direct_diffuse = np.zeros_like(p)
    direct_specular = np.zeros_like(p)
    kinds = (gs.threejs.PointLight, gs.threejs.SpotLight, gs.threejs.DirectionalLight)
    for kind in kinds:
        for light in (x for x in scene.lights if isinstance(x, kind)):
            direction, color = incident(light, p, physical)
            irradiance = saturate(dot(normal, direction))[:, None] * color
            if not physical:
                irradiance = irradiance * PI
            direct_diffuse += irradiance * RECIPROCAL_PI * diffuse_color
            direct_specular += irradiance * blinn_phong(
                direction, normal, view, specular, shininess
            )
    ambient = np.zeros(3)
    for light in (x for x in scene.lights if isinstance(x, gs.threejs.AmbientLight)):
        ambient = ambient + np.array(light.color) * light.intensity
    irradiance = np.broadcast_to(ambient * (1.0 if physical else PI), p.shape).copy()
    for light in (x for x in scene.lights if isinstance(x, gs.threejs.HemisphereLight)):
        d = normalize(np.array(light.position))
        weight = (0.5 * dot(normal, d) + 0.5)[:, None]
        sky = np.array(light.sky_color) * light.intensity
        ground = np.array(light.ground_color) * light.intensity
        hemi = ground * (1 - weight) + sky * weight
        irradiance += hemi if physical else hemi * PI
    indirect_diffuse = irradiance * RECIPROCAL_PI * diffuse_color
    emissive = np.array(m.emissive) * m.emissive_intensity
    outgoing = direct_diffuse + indirect_diffuse + direct_specular + emissive
    return np.concatenate([outgoing, opacity[:, None]], axis=1)


def random_scene(rng: np.random.Generator, lights: int) -> gs.threejs.Scene:
    """A scene of `lights` random lights of every kind (distances 0 or finite, decays 0, 1, 2 or
    fractional, penumbras 0 to 1), a random material (shininess 0, 1, 30 or large, any side)
    and either a perspective or an orthographic camera, with either light convention."""
    t = gs.threejs

    def color() -> np.ndarray:
        return rng.uniform(0, 1, 3)

    def where() -> np.ndarray:
        return rng.uniform(-4, 4, 3)

    def reach() -> float:
        return float(rng.choice([0.0, rng.uniform(2, 8)]))

    def decay() -> float:
        return float(rng.choice([0.0, 1.0, 2.0, rng.uniform(0.2, 3)]))

    made: list[t.Light] = []
    for _ in range(lights):
        kind = int(rng.integers(0, 5))
        intensity = float(rng.uniform(0.2, 2))
        if kind == 0:
            made.append(t.AmbientLight(color(), 0.3 * intensity))
        elif kind == 1:
            made.append(t.HemisphereLight(color(), color(), 0.5 * intensity, where()))
        elif kind == 2:
            made.append(t.DirectionalLight(color(), intensity, where(), where()))
        elif kind == 3:
            made.append(t.PointLight(color(), 4 * intensity, reach(), decay(), where()))
        else:
            angle = float(rng.uniform(0.2, math.pi / 2))
            penumbra = float(rng.choice([0.0, 1.0, rng.uniform(0, 1)]))
            made.append(
                t.SpotLight(
                    color(), 4 * intensity, reach(), angle, penumbra, decay(), where(), where()
                )
            )
    material = t.MeshPhongMaterial(
        color=color(),
        specular=color() * rng.choice([0.1, 1.0]),
        shininess=float(rng.choice([0.0, 1.0, 30.0, rng.uniform(1, 300)])),
        emissive=color() * rng.choice([0.0, 0.3]),
        emissive_intensity=float(rng.uniform(0, 2)),
        opacity=float(rng.uniform(0, 1)),
        side=str(rng.choice(["front", "back", "double"])),  # type: ignore[arg-type]
    )
    orthographic = rng.uniform() < 0.25
    return t.Scene(
        made,
        material,
        camera_position=rng.uniform(-6, 6, 3),
        view_direction=rng.normal(size=3) if orthographic else None,
        physically_correct_lights=bool(rng.uniform() < 0.5),
    )


U32 = 2.0**-24


def _falloff_condition(d: np.ndarray, cutoff: float, decay: float, physical: bool) -> np.ndarray:
    """The sensitivity of `irradiance_factor` to d and to its power's rounding: decay·(1 + |ln d|)
    for d^decay, and the distance cutoff's 8r⁴/(1 - r⁴) (physical) or decay·r/(1 - r) (legacy)."""
    with np.errstate(divide="ignore", invalid="ignore"):
        r = d / cutoff if cutoff > 0 else np.zeros_like(d)
        if physical:
            kappa = decay * (1 + np.abs(np.log(np.maximum(d, 1e-30))))
            if cutoff > 0:
                kappa = kappa + np.where(r < 1, 8 * r**4 / (1 - r**4), 0)
        elif cutoff > 0 and decay > 0:
            kappa = np.where(r < 1, decay * (1 + r / (1 - r) + np.abs(np.log1p(-r))), 0)
        else:
            kappa = np.zeros_like(d)
    return np.nan_to_num(kappa, posinf=0.0)


def fast_bound(
    p: np.ndarray,
    n: np.ndarray,
    scene: gs.threejs.Scene,
    colors: np.ndarray | None = None,
    back: bool = False,
) -> np.ndarray:
    """(k, 3) The bound of float32 fast mode against the exact value, per vertex and channel,
    off the kinks `kinks` names (the Accuracy page's, in float64, without a model matrix):

        2e-6 · max(1, Σ|terms|) + 8u · Σ_i κ_i · t_i

    t_i is light i's term (diffuse and specular), κ_i the sum of its sensitivities to what
    float32 forms: 1/nl, the spot's smoothstep slope over its value, the falloff's
    (`_falloff_condition`), 6 for the normalisations and the sums, and on the specular part,
    over min(1, |l + v|) (the halfway vector's direction is as uncertain as u/|l + v| where
    the light faces the viewer), the power's s·(1/nh + |ln nh|) and 6 for Fresnel's power.
    """
    p, n = np.asarray(p, np.float64), np.asarray(n, np.float64)
    m = scene.material
    physical = scene.physically_correct_lights
    diffuse_color = np.broadcast_to(np.abs(np.array(m.color)), p.shape).copy()
    if colors is not None:
        diffuse_color *= np.abs(np.asarray(colors, np.float64)[:, :3])
    normal, view = normal_and_view(p, n, scene, back)
    specular = np.array(m.specular)
    s = max(m.shininess, 1e-4)
    terms = np.zeros_like(p)
    weighted = np.zeros_like(p)
    pi = 1.0 if physical else PI
    for light in scene.lights:
        if isinstance(light, (gs.threejs.AmbientLight, gs.threejs.HemisphereLight)):
            continue
        direction, color = incident(light, p, physical)
        kappa = np.full(len(p), 6.0)
        if not isinstance(light, gs.threejs.DirectionalLight):
            distance = np.linalg.norm(np.array(light.position) - p, axis=-1)
            kappa += _falloff_condition(distance, light.distance, light.decay, physical)
        if isinstance(light, gs.threejs.SpotLight) and light.penumbra > 0:
            axis = normalize(np.array(light.position) - np.array(light.target))
            cone_cos = math.cos(light.angle)
            width = math.cos(light.angle * (1 - light.penumbra)) - cone_cos
            t = np.clip((dot(direction, axis) - cone_cos) / width, 0, 1)
            smooth = t * t * (3 - 2 * t)
            with np.errstate(divide="ignore", invalid="ignore"):
                kappa += np.where(smooth > 0, 6 * t * (1 - t) / width / smooth, 0)
        nl = saturate(dot(normal, direction))
        irradiance = nl[:, None] * color * pi
        halfway = direction + view
        spread = np.minimum(1, np.linalg.norm(halfway, axis=-1))
        nh = saturate(dot(normal, normalize(halfway)))
        with np.errstate(divide="ignore"):
            power = (s * (1 / nh + np.abs(np.log(nh))) + 6) / spread
        spec = irradiance * blinn_phong(direction, normal, view, specular, s)
        diff = irradiance * RECIPROCAL_PI * diffuse_color
        # 1/nl times the term: the term without its nl (finite where nl = 0).
        unlit = (
            color
            * pi
            * (RECIPROCAL_PI * diffuse_color + blinn_phong(direction, normal, view, specular, s))
        )
        terms += diff + spec
        weighted += kappa[:, None] * (diff + spec) + unlit
        weighted += np.where(spec > 0, np.nan_to_num(power)[:, None] * spec, 0)
    rest = meshphong_frag(p, n, scene, colors, back)[:, :3] - terms  # indirect and emitted
    return 2e-6 * np.maximum(1, terms + np.abs(rest)) + 8 * U32 * weighted


def kinks(
    p: np.ndarray, n: np.ndarray, scene: gs.threejs.Scene, margin: float = 1e-4, back: bool = False
) -> np.ndarray:
    """(k,) True where a vertex is within `margin` of a jump of the model, where the inputs' own
    rounding picks the side: the edge of a spot without penumbra (its step), and n·h = 0 for a
    shininess below 1 (where (n·h)^s leaps from 0 to nearly 1)."""
    p, n = np.asarray(p, np.float64), np.asarray(n, np.float64)
    normal, view = normal_and_view(p, n, scene, back)
    near = np.zeros(len(p), bool)
    for light in scene.lights:
        if isinstance(light, (gs.threejs.AmbientLight, gs.threejs.HemisphereLight)):
            continue
        direction, _ = incident(light, p, scene.physically_correct_lights)
        if isinstance(light, gs.threejs.SpotLight) and light.penumbra == 0:
            axis = normalize(np.array(light.position) - np.array(light.target))
            near |= np.abs(dot(direction, axis) - math.cos(light.angle)) < margin
        if scene.material.shininess < 1:
            near |= np.abs(dot(normal, normalize(direction + view))) < margin
    return near
