"""A float64 transcription of the OpenGL 2.1 lighting equation (section 2.14.1, eqs. 2.2-2.5).

Written from the specification, term by term, as the test oracle: it shares no code with
glshade. Where the spec says "undefined", it follows glshade's conventions, as the
documentation's Conventions page (docs/pages/guide/conventions.md) states them (for a shininess
above 0, a zero halfway or reflection vector or a viewer at the vertex gives no specular, while
a shininess of 0 gives 0^0 = 1 whatever they are; VP = 0 for a light at the vertex; cos(90 deg)
is exactly 0). `specular_gate=False` replaces f_i by 1 (learnopengl's shaders). Lights and
materials are plain dicts with GL's names.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

GL_LIGHT0 = {
    "position": (0.0, 0.0, 1.0, 0.0),
    "ambient": (0.0, 0.0, 0.0, 1.0),
    "diffuse": (1.0, 1.0, 1.0, 1.0),
    "specular": (1.0, 1.0, 1.0, 1.0),
    "spot_direction": (0.0, 0.0, -1.0),
    "spot_exponent": 0.0,
    "spot_cutoff": 180.0,
    "constant_attenuation": 1.0,
    "linear_attenuation": 0.0,
    "quadratic_attenuation": 0.0,
}
GL_MATERIAL = {
    "ambient": (0.2, 0.2, 0.2, 1.0),
    "diffuse": (0.8, 0.8, 0.8, 1.0),
    "specular": (0.0, 0.0, 0.0, 1.0),
    "emission": (0.0, 0.0, 0.0, 1.0),
    "shininess": 0.0,
}


@dataclass
class RefScene:
    """Everything eqs. 2.2-2.5 read, plus the per-vertex state of the call."""

    lights: list[dict[str, Any]] = field(default_factory=list)
    material: dict[str, Any] = field(default_factory=lambda: dict(GL_MATERIAL))
    back_material: dict[str, Any] | None = None
    global_ambient: tuple[float, ...] = (0.2, 0.2, 0.2, 1.0)
    viewer: tuple[float, ...] = (0.0, 0.0, 1.0, 0.0)
    two_side: bool = False
    separate_specular: bool = False
    specular: str = "blinn"
    specular_gate: bool = True  # False: learnopengl's shaders, no f_i on the specular term
    modelview: np.ndarray | None = None
    normalize: bool = False
    rescale_normal: bool = False
    colors: np.ndarray | None = None
    color_material: str | None = None
    color_material_face: str = "front_and_back"


def rgba(c: Any) -> np.ndarray:
    c = np.asarray(c, dtype=np.float64)
    return np.append(c, 1.0) if c.shape[-1] == 3 else c


def unit(v: np.ndarray) -> np.ndarray:
    """v / |v| row by row, 0 where |v| = 0."""
    length = np.linalg.norm(v, axis=-1, keepdims=True)
    return np.divide(v, length, out=np.zeros_like(v), where=length > 0)


def dot(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    return np.sum(a * b, axis=-1)


@dataclass
class Reference:
    """The colours of each output (already clamped) and their pre-clamp values; per vertex, the
    distance to the nearest discontinuity of the equation (for excluding ill-posed vertices), the
    largest sum of |terms| over the channels (the scale any rounding error is relative to), and
    the sensitivity of the specular terms to a relative direction error, sum of s tan(theta)
    |term| (the condition number of cos^s is s tan(theta))."""

    outputs: list[np.ndarray]
    unclamped: list[np.ndarray]
    margin: np.ndarray
    magnitude: np.ndarray
    sensitivity: np.ndarray


def eye_space(P: np.ndarray, N: np.ndarray, s: RefScene) -> tuple[np.ndarray, np.ndarray]:
    """Section 2.11.3: V = M (p, 1); n' = n M^-1 (row vector), then rescale and normalize."""
    V = P.astype(np.float64)
    n = N.astype(np.float64)
    M = np.eye(4) if s.modelview is None else np.asarray(s.modelview, dtype=np.float64)
    Minv = np.linalg.inv(M)
    Vh = np.c_[V, np.ones(len(V))] @ M.T
    V = Vh[:, :3] / Vh[:, 3:]
    n = n @ Minv[:3, :3]
    if s.rescale_normal:
        n = n / np.sqrt(Minv[2, 0] ** 2 + Minv[2, 1] ** 2 + Minv[2, 2] ** 2)
    if s.normalize:
        n = unit(n)
    return V, n


def material_at(m: dict[str, Any], s: RefScene, back: bool, n_vertices: int) -> dict[str, Any]:
    """Section 2.14.3: with COLOR_MATERIAL the vertex colour replaces the tracked parameters."""
    out = {
        k: np.broadcast_to(rgba(m[k]), (n_vertices, 4))
        for k in ("ambient", "diffuse", "specular", "emission")
    }
    out["shininess"] = float(m["shininess"])
    face_tracks = {"front_and_back": True, "front": not back, "back": back}[s.color_material_face]
    if s.colors is not None and face_tracks:
        c = np.asarray(s.colors, dtype=np.float64)
        c = np.c_[c, np.ones(len(c))] if c.shape[1] == 3 else c
        tracked = {"ambient_and_diffuse": ("ambient", "diffuse")}.get(
            s.color_material, (s.color_material,)
        )
        for k in tracked:
            out[k] = c
    return out


def gl_lighting(P: np.ndarray, N: np.ndarray, s: RefScene) -> Reference:
    V, n_front = eye_space(P, N, s)
    n_vertices = len(V)
    acs = rgba(s.global_ambient)[:3]
    viewer = np.asarray(s.viewer, dtype=np.float64)
    if viewer[3] == 0:
        VPe = np.broadcast_to(unit(viewer[:3]), V.shape)  # (0, 0, 1) for GL's infinite viewer
    else:
        VPe = unit(viewer[:3] / viewer[3] - V)
    margin = np.full(n_vertices, np.inf)

    sides = [(n_front, s.material, False)]
    if s.two_side:
        sides.append((-n_front, s.back_material or s.material, True))
    outputs, unclamped = [], []
    magnitudes, sensitivities = [], []
    for n, mat, back in sides:
        m = material_at(mat, s, back, n_vertices)
        a_cm, d_cm, s_cm, e_cm = (
            m[k][:, :3] for k in ("ambient", "diffuse", "specular", "emission")
        )
        srm = m["shininess"]
        c_pri = e_cm + a_cm * acs
        c_sec = np.zeros((n_vertices, 3))
        magnitude = np.abs(e_cm) + np.abs(a_cm * acs)
        sensitivity = np.zeros((n_vertices, 3))
        for light in s.lights:
            L = {**GL_LIGHT0, **light}
            Ppl = np.asarray(L["position"], dtype=np.float64)
            if Ppl[3] == 0:
                VP = np.broadcast_to(unit(Ppl[:3]), V.shape)
                att = np.ones(n_vertices)  # eq. 2.4: 1 for directional lights
            else:
                D = Ppl[:3] / Ppl[3] - V
                d = np.linalg.norm(D, axis=1)
                VP = unit(D)
                k0, k1, k2 = (
                    L["constant_attenuation"],
                    L["linear_attenuation"],
                    L["quadratic_attenuation"],
                )
                att = 1.0 / (k0 + k1 * d + k2 * d**2)
                margin = np.minimum(margin, d)
            if L["spot_cutoff"] == 180:
                spot = np.ones(n_vertices)  # eq. 2.5, third case
            else:
                sdl = unit(np.asarray(L["spot_direction"], dtype=np.float64))
                cos_c = 0.0 if L["spot_cutoff"] == 90 else np.cos(np.radians(L["spot_cutoff"]))
                c = np.maximum(dot(-VP, sdl), 0.0)  # P_pli V (.) s_dli
                spot = np.where(c >= cos_c, c ** L["spot_exponent"], 0.0)
                margin = np.minimum(margin, np.abs(dot(-VP, sdl) - cos_c))
                inner = L.get("spot_inner_cutoff", 180.0)
                if inner < L["spot_cutoff"]:
                    # Not GL: learnopengl's clamp((theta - outerCutOff) / epsilon, 0.0, 1.0).
                    epsilon = np.cos(np.radians(inner)) - cos_c
                    spot = spot * np.clip((c - cos_c) / epsilon, 0.0, 1.0)
                    margin = np.minimum(margin, np.abs(c - np.cos(np.radians(inner))))
            if Ppl[3] != 0 and L.get("range", np.inf) != np.inf:
                # Not GL: Luna's `if (d > L.Range) return;`, the ambient term included.
                att = np.where(d <= L["range"], att, 0.0)
                margin = np.minimum(margin, np.abs(d - L["range"]))
            n_dot_vp = dot(n, VP)
            if s.specular_gate:
                f = (np.maximum(n_dot_vp, 0.0) != 0).astype(np.float64)  # eq. 2.2
            else:
                # No f_i; the pinned conventions still give no specular without a direction
                # (a zero normal, or VP = 0 for a light at the vertex).
                f = ((dot(n, n) > 0) & (dot(VP, VP) > 0)).astype(np.float64)
            n_hat = unit(n)
            margin = np.minimum(margin, np.abs(dot(n_hat, VP)))
            if s.specular == "blinn":
                h = VP + VPe  # eq. 2.3
                h_hat = unit(h)
                base = np.maximum(dot(n, h_hat), 0.0)
                # 0^0 = 1 whatever h; for s > 0 a zero h gives no specular.
                power = np.where((np.linalg.norm(h, axis=1) > 0) | (srm == 0), base**srm, 0.0)
                cos_theta = dot(n_hat, h_hat)
            else:
                R = 2 * n_dot_vp[:, None] * n - VP
                base = np.maximum(dot(R, VPe), 0.0)
                has_r = np.linalg.norm(R, axis=1) > 0
                power = np.where(
                    (np.linalg.norm(VPe, axis=1) > 0) & has_r | (srm == 0), base**srm, 0.0
                )
                cos_theta = dot(unit(R), VPe)
            w = (att * spot)[:, None]
            a_cli, d_cli, s_cli = (rgba(L[k])[:3] for k in ("ambient", "diffuse", "specular"))
            ambient = w * a_cm * a_cli
            diffuse = w * np.maximum(n_dot_vp, 0.0)[:, None] * d_cm * d_cli
            spec = w * (f * power)[:, None] * s_cm * s_cli
            c_pri += ambient + diffuse
            magnitude += np.abs(ambient) + np.abs(diffuse) + np.abs(spec)
            c = np.clip(cos_theta, 1e-300, 1.0)
            tan_theta = np.sqrt(1.0 - c**2) / c
            sensitivity += (srm * tan_theta)[:, None] * np.abs(spec)
            if s.separate_specular:
                c_sec += spec
            else:
                c_pri += spec
        magnitudes.append(magnitude.max(axis=1))
        sensitivities.append(sensitivity.max(axis=1))
        alpha = m["diffuse"][:, 3:]
        pri = np.c_[c_pri, alpha]
        unclamped.append(pri)
        outputs.append(np.clip(pri, 0.0, 1.0))
        if s.separate_specular:
            sec = np.c_[c_sec, np.ones(n_vertices)]
            unclamped.append(sec)
            outputs.append(np.clip(sec, 0.0, 1.0))
    return Reference(
        outputs, unclamped, margin, np.max(magnitudes, axis=0), np.max(sensitivities, axis=0)
    )
