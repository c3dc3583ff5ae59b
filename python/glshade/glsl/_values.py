"""The uniform values of a plan's GLSL: per-light constants computed in float64 and rounded once
to float32, as the CPU kernel's `prepare` does (``src/lighting/fixed_function/prepare.rs``)."""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from .._scene import Scene
from ._plan import LightGroup, Plan

SIDE_NAMES = ("front", "back")


def _unit(v: NDArray[np.float64]) -> NDArray[np.float64]:
    """Rows of `v` scaled to unit length, 0 for a zero row (glshade's convention)."""
    length = np.linalg.norm(v, axis=-1, keepdims=True)
    unit: NDArray[np.float64] = np.divide(v, length, out=np.zeros_like(v), where=length > 0)
    return unit


def _pow(x: NDArray[np.float64], e: NDArray[np.float64]) -> NDArray[np.float64]:
    """x^e for x >= 0 with 0^0 = 1."""
    with np.errstate(divide="ignore", over="ignore", invalid="ignore"):
        power = np.where(x > 0, np.power(np.maximum(x, 0.0), e), 0.0)
    result: NDArray[np.float64] = np.where(e == 0, 1.0, power)
    return result


def _cos_degrees(degrees: NDArray[np.float64]) -> NDArray[np.float64]:
    """cos of angles in degrees, exactly 0 at 90."""
    cosine: NDArray[np.float64] = np.where(degrees == 90.0, 0.0, np.cos(np.radians(degrees)))
    return cosine


def _spot_constants(
    scene: Scene, ix: list[int]
) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]:
    """Unit spot directions, cos(cutoff) (exactly 0 at 90 degrees), exponents and soft-edge
    widths cos(inner) - cos(cutoff) (inf for a hard edge, whose ramp is then 1) of lights `ix`."""
    lights = scene.lights
    direction = _unit(lights._column("spot_direction").reshape(-1, 3)[ix])
    cutoff = lights._column("spot_cutoff").reshape(-1)[ix]
    inner = lights._column("spot_inner_cutoff").reshape(-1)[ix]
    cos_cutoff = _cos_degrees(cutoff)
    width = np.where(
        inner < cutoff,
        np.maximum(_cos_degrees(inner) - cos_cutoff, np.finfo(np.float32).tiny),
        np.inf,
    )
    return direction, cos_cutoff, lights._column("spot_exponent").reshape(-1)[ix], width


def _group_values(
    scene: Scene, group: LightGroup, prefix: str, viewer_direction: NDArray[np.float64]
) -> dict[str, NDArray[np.float64]]:
    lights = scene.lights
    ix = list(group.indices)
    position = lights._column("position").reshape(-1, 4)[ix]
    values: dict[str, NDArray[np.float64]] = {}
    if group.directional:
        vp = _unit(position[:, :3])
        values["vp"] = vp
        if group.halfway:
            values["halfway"] = _unit(vp + viewer_direction)
        if group.spot:
            # eq. 2.5 with P_pli->V = -VP: a per-light constant.
            direction, cos_cutoff, exponent, width = _spot_constants(scene, ix)
            c = np.maximum(np.sum(-vp * direction, axis=1), 0.0)
            ramp = np.clip((c - cos_cutoff) / width, 0.0, 1.0)
            ramp = np.where(np.isinf(width), 1.0, ramp)
            values["spot"] = np.where(c >= cos_cutoff, _pow(c, exponent), 0.0) * ramp
    else:
        values["point"] = position[:, :3] / position[:, 3:]
        if group.attenuated:
            values["attenuation"] = np.stack(
                [lights._column(k).reshape(-1)[ix] for k in ("constant_attenuation",
                 "linear_attenuation", "quadratic_attenuation")], axis=1)  # fmt: skip
        if group.spot:
            direction, cos_cutoff, exponent, width = _spot_constants(scene, ix)
            values["spot_direction"] = direction
            values["spot_cos_cutoff"] = cos_cutoff
            values["spot_exponent"] = exponent
            if group.soft:
                values["spot_edge_width"] = width
        if group.ranged:
            values["range"] = lights._column("range").reshape(-1)[ix]
    for term in ("ambient", "diffuse", "specular"):
        if getattr(group, term):
            values[term] = lights._column(term).reshape(-1, 4)[ix, :3]
    return {f"{prefix}_{name}": value for name, value in values.items()}


def values(scene: Scene, plan: Plan) -> dict[str, NDArray[np.float64]]:
    """Every uniform the plan's source declares, in float64 (rounded by the caller)."""
    out: dict[str, NDArray[np.float64]] = {
        "gs_global_ambient": np.asarray(scene.global_ambient, np.float64)[:3]
    }
    for index, side in enumerate(plan.sides):
        material = (scene.material, scene.back_material)[index]
        name = SIDE_NAMES[index]
        for parameter in ("ambient", "diffuse", "emission") + (("specular",) * side.specular):
            if parameter not in side.tracked:
                out[f"gs_{name}_{parameter}"] = np.asarray(getattr(material, parameter))
        if side.power:
            out[f"gs_{name}_shininess"] = np.asarray(material.shininess, np.float64)
    viewer = np.asarray(scene.viewer, np.float64)
    direction = _unit(viewer[:3]) if viewer[3] == 0 else np.zeros(3)
    if plan.viewer_direction:
        out["gs_viewer_direction"] = direction
    if plan.view:
        out["gs_viewer_point"] = viewer[:3] / viewer[3]
    for g, group in enumerate(plan.groups):
        out.update(_group_values(scene, group, f"gs_light{g}", direction))
    if plan.modelview is not None:
        m = plan.modelview
        inverse = np.asarray(np.linalg.inv(m[:3, :3]), np.float64)
        # GL's GL_RESCALE_NORMAL factor 1/|row 2 of M^-1| (section 2.11.3), else 1.
        scale = 1.0 / float(np.linalg.norm(inverse[2])) if plan.rescale_normal else 1.0
        normal_matrix = inverse.T * scale
        out["gs_modelview"] = m
        out["gs_normal_matrix"] = normal_matrix
    return out
