"""Random lit scenes covering every feature, built twice from the same draws: as the oracle's
`RefScene` and as glshade's `Scene` plus `shade` keywords."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

import glshade as gs
from support.gl_reference import RefScene

COLOR_MATERIAL_MODES = ("ambient", "diffuse", "specular", "emission", "ambient_and_diffuse")
FACES = ("front", "back", "front_and_back")


@dataclass
class Case:
    ref: RefScene
    scene: gs.Scene
    kwargs: dict[str, Any]
    positions: np.ndarray
    normals: np.ndarray
    description: str


def _colour(rng: np.random.Generator, low: float = -0.2, high: float = 1.0) -> tuple[float, ...]:
    c = rng.uniform(low, high, 4)
    c[3] = rng.uniform(0.0, 1.0)
    return tuple(c[: 3 if rng.random() < 0.3 else 4])


def random_light(rng: np.random.Generator) -> dict[str, Any]:
    light: dict[str, Any] = {
        "ambient": _colour(rng, -0.1, 0.3),
        "diffuse": _colour(rng, -0.1, 1.0),
        "specular": _colour(rng, -0.1, 1.0),
    }
    if rng.random() < 0.4:
        light["position"] = (*rng.normal(size=3), 0.0)  # directional
    else:
        w = rng.choice([1.0, 1.0, 2.0, -0.5])
        light["position"] = (*(rng.uniform(-4, 4, 3) * w), w)
    if rng.random() < 0.6:
        k = rng.uniform(0, 1, 3) * (rng.random(3) < 0.6)
        k[0] = (
            rng.choice([0.0, rng.uniform(0.2, 2.0)]) if k[1] + k[2] > 0 else rng.uniform(0.2, 2.0)
        )
        (
            light["constant_attenuation"],
            light["linear_attenuation"],
            light["quadratic_attenuation"],
        ) = k
    if rng.random() < 0.5:
        light["spot_cutoff"] = float(rng.choice([rng.uniform(0, 90), 90.0, 45.0, 0.0]))
        light["spot_direction"] = tuple(rng.normal(size=3) * rng.uniform(0.1, 3))
        light["spot_exponent"] = float(rng.choice([0.0, rng.uniform(1, 128), 1.0]))
    return light


def random_material(rng: np.random.Generator) -> dict[str, Any]:
    return {
        "ambient": _colour(rng),
        "diffuse": _colour(rng),
        "specular": _colour(rng),
        "emission": _colour(rng, -0.1, 0.4),
        # Exponents in (0, 1) have an unbounded slope at 0: test_corner_cases covers them.
        "shininess": float(rng.choice([0.0, 1.0, rng.uniform(1, 128), rng.uniform(1, 5), 128.0])),
    }


def random_modelview(rng: np.random.Generator) -> np.ndarray:
    q, _ = np.linalg.qr(rng.normal(size=(3, 3)))
    m = np.eye(4)
    m[:3, :3] = q @ np.diag(rng.uniform(0.3, 3.0, 3))  # rotation with non-uniform scale
    m[:3, 3] = rng.uniform(-2, 2, 3)
    return m


def add_edges(lights: list[dict[str, Any]], seed: int) -> None:
    """Gives the lights, in place, learnopengl's soft spot edges and (positional ones) Luna's
    ranges (not GL: Mesa has neither), drawn from their own generator so `seed`'s other draws
    keep their values."""
    rng = np.random.default_rng(10**6 + seed)
    for light in lights:
        if light["position"][3] != 0 and rng.random() < 0.6:
            light["range"] = float(rng.uniform(0.5, 6.0))
        if rng.random() < 0.7:
            outer = float(rng.uniform(5, 90))
            light["spot_cutoff"] = outer
            light.setdefault("spot_direction", tuple(rng.normal(size=3)))
            light["spot_inner_cutoff"] = float(rng.choice([0.0, rng.uniform(0, outer)]))


def random_case(seed: int, n: int, dtype: Any, edges: bool = False) -> Case:
    """A scene drawn from `seed` with `n` vertices of `dtype`; each feature is on in some seeds.
    With `edges`, positional lights get soft spot edges and ranges too (`add_edges`)."""
    rng = np.random.default_rng(seed)
    lights = [random_light(rng) for _ in range(int(rng.integers(1, 9)))]
    material = random_material(rng)
    back = random_material(rng) if rng.random() < 0.5 else None
    viewer = [
        (0.0, 0.0, 1.0, 0.0),
        (0.0, 0.0, 0.0, 1.0),
        (*rng.uniform(-3, 3, 3), 1.0),
        (*rng.normal(size=3), 0.0),
    ][seed % 4]
    ref = RefScene(
        lights=lights,
        material=material,
        back_material=back,
        global_ambient=_colour(rng, 0.0, 0.4),
        viewer=viewer,
        two_side=bool(rng.random() < 0.5),
        separate_specular=bool(rng.random() < 0.5),
        specular=str(rng.choice(["blinn", "phong"])),
        modelview=random_modelview(rng) if rng.random() < 0.5 else None,
        normalize=bool(rng.random() < 0.5),
        rescale_normal=bool(rng.random() < 0.3),
    )
    positions = rng.uniform(-1.5, 1.5, (n, 3))
    normals = rng.normal(size=(n, 3))
    if ref.normalize:
        normals *= rng.uniform(0.01, 10.0, (n, 1))
    else:
        normals /= np.linalg.norm(normals, axis=1, keepdims=True)
        normals *= rng.choice([1.0, 1.0, 0.5, 1.3], (n, 1))
    if rng.random() < 0.4:
        ref.color_material = str(rng.choice(COLOR_MATERIAL_MODES))
        ref.color_material_face = str(rng.choice(FACES))
        ref.colors = rng.uniform(-0.1, 1.0, (n, int(rng.choice([3, 4]))))
    ref.specular_gate = bool(rng.random() < 0.7)  # drawn last: earlier draws keep their values
    if edges:
        add_edges(ref.lights, seed)
    positions = positions.astype(dtype)
    normals = normals.astype(dtype)
    if ref.colors is not None:
        ref.colors = ref.colors.astype(dtype)
    # The oracle sees exactly the inputs glshade sees.
    return Case(ref, to_glshade(ref), shade_kwargs(ref), positions, normals, describe(ref))


def to_glshade(ref: RefScene) -> gs.Scene:
    lights = [gs.Light(**light) for light in ref.lights]
    material = gs.Material(**ref.material)
    back = gs.Material(**ref.back_material) if ref.back_material else None
    return gs.Scene(
        lights=lights,
        material=material,
        back_material=back,
        global_ambient=ref.global_ambient,
        viewer=ref.viewer,
        two_side=ref.two_side,
        separate_specular=ref.separate_specular,
        specular=ref.specular,
        specular_gate=ref.specular_gate,
    )


def shade_kwargs(ref: RefScene) -> dict[str, Any]:
    kwargs: dict[str, Any] = {
        "modelview": ref.modelview,
        "normalize": ref.normalize,
        "rescale_normal": ref.rescale_normal,
    }
    if ref.colors is not None:
        kwargs.update(
            colors=ref.colors,
            color_material=ref.color_material,
            color_material_face=ref.color_material_face,
        )
    return kwargs


def describe(ref: RefScene) -> str:
    kinds = [
        "dir" if light.get("position", (0, 0, 1, 0))[3] == 0 else "pos" for light in ref.lights
    ]
    spots = sum(light.get("spot_cutoff", 180) != 180 for light in ref.lights)
    return (
        f"{len(ref.lights)} lights {kinds} ({spots} spot), viewer={ref.viewer}, "
        f"two_side={ref.two_side}, separate={ref.separate_specular}, {ref.specular}, "
        f"specular_gate={ref.specular_gate}, "
        f"modelview={ref.modelview is not None}, normalize={ref.normalize}, "
        f"rescale={ref.rescale_normal}, color_material={ref.color_material}"
        f"/{ref.color_material_face}, shininess={ref.material['shininess']:.3g}"
    )


def stacked(outputs: list[np.ndarray]) -> np.ndarray:
    """The oracle's outputs in glshade's layout: (n, 4) for one colour, else (k, n, 4)."""
    return outputs[0] if len(outputs) == 1 else np.stack(outputs)
