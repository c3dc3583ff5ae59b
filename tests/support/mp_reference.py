"""The GL 2.1 lighting equation (eqs. 2.2-2.5) for one vertex in mpmath at 50 digits: the
high-precision oracle of the stiff cases, where a float64 transcription is not accurate enough
(float64 inputs with shininess 10^6 lose six digits in a naive pow).

Inputs are taken exactly as given (a float32 or float64 value widens exactly to mpf). Covers
what the stiff cases use: directional and positional lights, attenuation, spots, infinite and
local viewers, Blinn's halfway vector, GL's specular gate, `normalize`; glshade's conventions
where GL says "undefined", as the documentation's Conventions page
(docs/pages/guide/conventions.md) states them (0^0 = 1; no specular from a zero halfway vector;
VP = 0 for a light at the vertex; cos 90 deg = 0).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import mpmath as mp

from support.gl_reference import GL_LIGHT0, GL_MATERIAL

mp.mp.dps = 50
Vec = list[Any]


def _v(x: Any) -> Vec:
    return [mp.mpf(float(c)) for c in x]


def _dot(a: Vec, b: Vec) -> Any:
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def _unit(a: Vec) -> tuple[Vec, Any]:
    length = mp.sqrt(_dot(a, a))
    return ([c / length for c in a] if length > 0 else [mp.mpf(0)] * 3), length


def _rgb(c: Any) -> Vec:
    return _v(list(c)[:3])


@dataclass
class MpVertex:
    """The unclamped RGB of one vertex and the scales its rounding error is relative to:
    `magnitude`, the largest sum of |terms| over the channels; `sensitivity`, the largest sum
    over the channels of (s tan(theta) + e tan(phi)) |term| (the condition numbers of the
    specular power cos^s and the spot power cos^e); `powered`, the largest sum over the channels
    of s |specular term|, the scale of a plain float32 power's error (s times the rounding of
    its base), which the fast float32 mode's bound allows."""

    rgb: list[float]
    magnitude: float
    sensitivity: float
    powered: float = 0.0


def mp_vertex(
    p: Any,
    n: Any,
    lights: list[dict[str, Any]],
    material: dict[str, Any] | None = None,
    global_ambient: Any = (0.2, 0.2, 0.2),
    viewer: Any = (0.0, 0.0, 1.0, 0.0),
    normalize: bool = False,
) -> MpVertex:
    m = {**GL_MATERIAL, **(material or {})}
    V, normal = _v(p), _v(n)
    if normalize:
        normal, _ = _unit(normal)
    n_hat, _ = _unit(normal)
    a_cm, d_cm, s_cm, e_cm = (_rgb(m[k]) for k in ("ambient", "diffuse", "specular", "emission"))
    srm = mp.mpf(float(m["shininess"]))
    acs = _rgb(global_ambient)
    eye = _v(viewer)
    if eye[3] == 0:
        VPe, _ = _unit(eye[:3])
    else:
        VPe, _ = _unit([e / eye[3] - v for e, v in zip(eye[:3], V, strict=True)])
    total = [e + a * g for e, a, g in zip(e_cm, a_cm, acs, strict=True)]
    magnitude = [abs(t) for t in total]
    sensitivity = [mp.mpf(0)] * 3
    powered = [mp.mpf(0)] * 3
    for given in lights:
        light = {**GL_LIGHT0, **given}
        P = _v(light["position"])
        if P[3] == 0:
            VP, _ = _unit(P[:3])
            att = mp.mpf(1)
        else:
            VP, d = _unit([c / P[3] - v for c, v in zip(P[:3], V, strict=True)])
            k0, k1, k2 = (
                mp.mpf(float(light[k]))
                for k in ("constant_attenuation", "linear_attenuation", "quadratic_attenuation")
            )
            den = k0 + k1 * d + k2 * d * d
            att = 1 / den if den > 0 else mp.inf
        spot, spot_cond = mp.mpf(1), mp.mpf(0)
        if float(light["spot_cutoff"]) != 180:
            axis, _ = _unit(_v(light["spot_direction"]))
            c = max(-_dot(VP, axis), mp.mpf(0))
            cutoff = float(light["spot_cutoff"])
            cos_c = mp.mpf(0) if cutoff == 90 else mp.cos(mp.radians(cutoff))
            e = mp.mpf(float(light["spot_exponent"]))
            spot = (c**e if c > 0 or e > 0 else mp.mpf(1)) if c >= cos_c else mp.mpf(0)
            if 0 < c < 1:
                spot_cond = e * mp.sqrt(1 - c * c) / c
        n_dot_vp = _dot(normal, VP)
        lit = n_dot_vp > 0
        h = [a + b for a, b in zip(VP, VPe, strict=True)]
        h_hat, h_len = _unit(h)
        base = max(_dot(normal, h_hat), mp.mpf(0))
        if srm == 0:
            power = mp.mpf(1)
        elif h_len == 0 or base == 0:
            power = mp.mpf(0)
        else:
            power = base**srm
        cos_theta = min(max(_dot(n_hat, h_hat), mp.mpf("1e-300")), mp.mpf(1))
        tan_theta = mp.sqrt(1 - cos_theta**2) / cos_theta
        w = att * spot
        for k in range(3):
            a_cl, d_cl, s_cl = (_rgb(light[key])[k] for key in ("ambient", "diffuse", "specular"))
            terms = [w * a_cm[k] * a_cl if a_cm[k] * a_cl != 0 else mp.mpf(0)]
            terms.append(w * n_dot_vp * d_cm[k] * d_cl if lit and d_cm[k] * d_cl != 0 else 0)
            spec = w * power * s_cm[k] * s_cl if lit and s_cm[k] * s_cl != 0 else mp.mpf(0)
            total[k] += sum(terms) + spec
            magnitude[k] += sum(abs(t) for t in terms) + abs(spec)
            sensitivity[k] += srm * tan_theta * abs(spec) + spot_cond * (
                sum(abs(t) for t in terms) + abs(spec)
            )
            powered[k] += srm * abs(spec)
    return MpVertex(
        [float(t) for t in total],
        float(max(magnitude)),
        float(max(sensitivity)),
        float(max(powered)),
    )
