"""The scenes the benchmarks time and the report measures: the benchmark's three typical scenes,
and one class per row of the table of stiff cases on the documentation's Accuracy page
(docs/pages/guide/accuracy.md; tests/core/accuracy/test_stiff.py),
each with the vertices that make it stiff."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

import glshade as gs

__all__ = [
    "SceneClass",
    "bench_scenes",
    "bench_vertices",
    "extra_bench_scenes",
    "report_classes",
    "scene_names",
    "shade_scenes",
    "world_scenes",
]

F64 = NDArray[np.float64]
F32 = NDArray[np.float32]
WorldScene = gs.gltf.Scene | gs.threejs.Scene
AnyScene = gs.Scene | WorldScene


def bench_scenes() -> dict[str, gs.Scene]:
    """The three scenes of the benchmark: one directional light (infinite viewer), one point
    light with a local viewer, and eight mixed lights (directional, attenuated point, spot),
    all with a Blinn-Phong specular term of shininess 32."""
    material = gs.Material(specular=(0.5, 0.5, 0.5, 1.0), shininess=32.0)
    grey = (0.3, 0.3, 0.3, 1.0)
    mixed = [
        gs.Light(position=(0.3, 0.5, 1.0, 0.0)),
        gs.Light(position=(-1.0, 0.5, 1.0, 0.0), diffuse=grey, specular=grey),
        gs.Light(position=(0.0, 3.0, 0.5, 0.0), diffuse=grey, specular=grey),
        gs.Light(position=(1.0, 2.0, 3.0, 1.0), linear_attenuation=0.1, diffuse=grey),
        gs.Light(position=(-2.0, 1.0, 3.0, 1.0), quadratic_attenuation=0.05, diffuse=grey),
        gs.Light(position=(2.0, -1.0, 3.0, 1.0), linear_attenuation=0.2, quadratic_attenuation=0.1),
        gs.Light(
            position=(0.0, 0.0, 4.0, 1.0),
            spot_direction=(0.0, 0.0, -1.0),
            spot_cutoff=30.0,
            spot_exponent=8.0,
        ),
        gs.Light(
            position=(1.0, 1.0, 4.0, 1.0),
            spot_direction=(-0.2, -0.2, -1.0),
            spot_cutoff=45.0,
            spot_exponent=2.0,
            linear_attenuation=0.1,
            ambient=(0.05, 0.05, 0.05, 1.0),
        ),
    ]
    return {
        "1 directional": gs.Scene([gs.Light(position=(0.3, 0.5, 1.0, 0.0))], material=material),
        "1 point, local viewer": gs.Scene(
            [gs.Light(position=(1.0, 2.0, 3.0, 1.0))], material=material, viewer=(0, 0, 0, 1)
        ),
        "8 mixed": gs.Scene(mixed, material=material, viewer=(0, 0, 0, 1)),
    }


def extra_bench_scenes() -> dict[str, gs.Scene]:
    """Four more scenes for ``bench shade``, beyond `bench_scenes`: 16 mixed lights (6
    directional, 6 attenuated point, 4 spots; local viewer), two directional lights (infinite
    viewer), a spot of non-integer exponent 2.5 beside a point light (local viewer) and 32
    attenuated point lights (local viewer); all with the specular term of shininess 32, and
    lights faint enough that most sums stay below GL's clamp.

    Returns
    -------
    dict of str to Scene
        ``"16 mixed"``, ``"2 directional"``, ``"spot 2.5"`` and ``"32 point"``, in that order.
    """
    material = gs.Material(specular=(0.5, 0.5, 0.5, 1.0), shininess=32.0)
    rng = np.random.default_rng(16)
    # Above the vertices (x, y in -3..3, z in -1..2; they lie at z -4..-2) or shining from there.
    above = rng.uniform((-3.0, -3.0, -1.0), (3.0, 3.0, 2.0), (32, 3))
    dim, faint = (0.1, 0.1, 0.1, 1.0), (0.06, 0.06, 0.06, 1.0)
    mixed = [
        *(
            gs.Light(position=(*map(float, xyz), 0.0), diffuse=dim, specular=dim)
            for xyz in above[:6] + np.array([0.0, 0.0, 3.0])
        ),
        *(
            gs.Light(
                position=(*map(float, xyz), 1.0),
                diffuse=dim,
                specular=dim,
                linear_attenuation=0.1 * (i % 3),
                quadratic_attenuation=0.05 * (i % 2 + 1),
            )
            for i, xyz in enumerate(above[6:12])
        ),
        *(
            gs.Light(
                position=(*map(float, xyz), 1.0),
                spot_direction=(-0.1 * xyz[0], -0.1 * xyz[1], -1.0),
                spot_cutoff=(30.0, 45.0, 60.0, 25.0)[i],
                spot_exponent=(8.0, 2.0, 1.0, 4.0)[i],
                linear_attenuation=0.1 * (i % 2),
                diffuse=dim,
                ambient=(0.03, 0.03, 0.03, 1.0),
            )
            for i, xyz in enumerate(above[12:16])
        ),
    ]
    points = [
        gs.Light(
            position=(*map(float, xyz), 1.0),
            diffuse=faint,
            specular=faint,
            linear_attenuation=0.1,
            quadratic_attenuation=0.05,
        )
        for xyz in above
    ]
    local = (0.0, 0.0, 0.0, 1.0)
    return {
        "16 mixed": gs.Scene(mixed, material=material, viewer=local),
        "2 directional": gs.Scene(
            [
                gs.Light(position=(0.3, 0.5, 1.0, 0.0), diffuse=(0.6, 0.6, 0.6, 1.0)),
                gs.Light(position=(-0.8, 0.2, 1.0, 0.0), diffuse=(0.3, 0.3, 0.4, 1.0)),
            ],
            material=material,
        ),
        "spot 2.5": gs.Scene(
            [
                gs.Light(
                    position=(0.5, 0.5, 1.0, 1.0),
                    spot_direction=(-0.1, -0.1, -1.0),
                    spot_cutoff=35.0,
                    spot_exponent=2.5,
                ),
                gs.Light(position=(-2.0, 1.0, 0.0, 1.0), diffuse=(0.3, 0.3, 0.3, 1.0)),
            ],
            material=material,
            viewer=local,
        ),
        "32 point": gs.Scene(points, material=material, viewer=local),
    }


def world_scenes() -> dict[str, WorldScene]:
    """Six scenes of the world models for ``bench shade``, three each of glTF's
    metallic-roughness and three.js' `MeshPhongMaterial`: one directional light; a point, a
    directional and a spot light; the three with an ambient light. The camera is at the
    origin, where `bench_vertices` face; the lights shine on them from above.

    Returns
    -------
    dict of str to glshade.gltf.Scene or glshade.threejs.Scene
        ``"gltf directional"``, ``"gltf 3 lights"``, ``"gltf 3 lights, ambient"`` and the same
        three names with ``threejs``, in that order.
    """
    g, t = gs.gltf, gs.threejs
    gltf_lights: list[g.DirectionalLight | g.PointLight | g.SpotLight] = [
        g.PointLight(color=(1.0, 0.9, 0.8), intensity=20.0, position=(1.0, 2.0, 1.0)),
        g.DirectionalLight(intensity=3.0, direction=(-0.3, -0.5, -1.0)),
        g.SpotLight(
            color=(0.8, 0.9, 1.0),
            intensity=30.0,
            position=(0.0, 0.0, 2.0),
            direction=(0.0, 0.0, -1.0),
            inner_cone_angle=0.3,
            outer_cone_angle=0.6,
        ),
    ]
    metal = g.Material(base_color=(0.8, 0.5, 0.3, 1.0), metallic=0.2, roughness=0.4)
    threejs_lights: list[t.Light] = [
        t.PointLight(color=(1.0, 0.9, 0.8), intensity=10.0, position=(1.0, 2.0, 1.0)),
        t.DirectionalLight(intensity=1.5, position=(0.3, 0.5, 1.0)),
        t.SpotLight(
            color=(0.8, 0.9, 1.0),
            intensity=15.0,
            angle=0.6,
            penumbra=0.5,
            position=(0.0, 0.0, 2.0),
            target=(0.0, 0.0, -3.0),
        ),
    ]
    phong = t.MeshPhongMaterial(color=(0.8, 0.5, 0.3), shininess=32.0)
    origin = (0.0, 0.0, 0.0)
    return {
        "gltf directional": g.Scene(gltf_lights[1:2], metal, camera_position=origin),
        "gltf 3 lights": g.Scene(gltf_lights, metal, camera_position=origin),
        "gltf 3 lights, ambient": g.Scene(
            gltf_lights, metal, ambient_light=(0.1, 0.1, 0.1), camera_position=origin
        ),
        "threejs directional": t.Scene(threejs_lights[1:2], phong, camera_position=origin),
        "threejs 3 lights": t.Scene(threejs_lights, phong, camera_position=origin),
        "threejs 3 lights, ambient": t.Scene(
            [*threejs_lights, t.AmbientLight(intensity=0.2)], phong, camera_position=origin
        ),
    }


def shade_scenes() -> dict[str, AnyScene]:
    """The scenes of ``bench shade`` by name: `bench_scenes`, `extra_bench_scenes`, then
    `world_scenes`."""
    return {**bench_scenes(), **extra_bench_scenes(), **world_scenes()}


def scene_names(text: str) -> list[str]:
    """The scenes a ``--scenes`` list names, each once, in the order given.

    Parameters
    ----------
    text : str
        Comma-separated names of `shade_scenes` (a name's own comma is kept: ``1 point, local
        viewer,8 mixed`` is two) or groups: ``bench`` (the three of `bench_scenes`), ``extra``
        (`extra_bench_scenes`), ``gl`` (the two), ``world`` (`world_scenes`) and ``all``.

    Returns
    -------
    list of str
        Keys of `shade_scenes`.

    Raises
    ------
    ValueError
        For a name that is neither a scene nor a group, or an empty list.
    """
    bench, extra, world = list(bench_scenes()), list(extra_bench_scenes()), list(world_scenes())
    groups = {
        "bench": bench, "extra": extra, "gl": bench + extra, "world": world,
        "all": bench + extra + world,
    }  # fmt: skip
    names: list[str] = []
    pending = ""
    for piece in text.split(","):
        # A piece that names nothing may be the first half of a name with a comma.
        pending = f"{pending},{piece}" if pending else piece
        name = pending.strip()
        if name in groups or name in bench + extra + world:
            names += [s for s in groups.get(name, [name]) if s not in names]
            pending = ""
    if pending.strip() or not names:
        known = ", ".join(f'"{name}"' for name in [*groups, *bench, *extra, *world])
        raise ValueError(f"no scene {pending.strip()!r}: the scenes are {known}")
    return names


def bench_vertices(n: int, seed: int = 0) -> tuple[F32, F32]:
    """`n` float32 positions in front of the eye and unit normals facing it, at random."""
    rng = np.random.default_rng(seed)
    positions = rng.uniform((-1.0, -1.0, -4.0), (1.0, 1.0, -2.0), (n, 3)).astype(np.float32)
    normals = rng.normal(size=(n, 3)) + np.array([0.0, 0.0, 1.5])
    normals /= np.linalg.norm(normals, axis=1, keepdims=True)
    return positions, normals.astype(np.float32)


@dataclass(frozen=True)
class SceneClass:
    """A scene and how to make `n` of its vertices (float64 eye-space positions and normals,
    as given to `gs.shade`); `share` scales the report's vertex count (a thousand lights
    shade a hundredth of the vertices in about the time of ten)."""

    name: str
    kind: str  # "typical" or "stiff"
    scene: gs.Scene
    vertices: Callable[[int, np.random.Generator], tuple[F64, F64]]
    share: float = 1.0


def _typical(n: int, rng: np.random.Generator) -> tuple[F64, F64]:
    p, normals = bench_vertices(n, int(rng.integers(1 << 30)))
    return p.astype(np.float64), normals.astype(np.float64)


def _directions(n: int, rng: np.random.Generator, axis: float = 1.5) -> F64:
    """Unit vectors spread around +z (a normal distribution shifted by `axis`)."""
    v = rng.normal(size=(n, 3)) + np.array([0.0, 0.0, axis])
    out: F64 = v / np.linalg.norm(v, axis=1, keepdims=True)
    return out


def _highlight(n: int, rng: np.random.Generator) -> tuple[F64, F64]:
    """Normals within 0.03 rad of +z, where cos^10^4 falls from 1 to 0.01."""
    tilt, turn = rng.uniform(0, 0.03, n), rng.uniform(0, 2 * np.pi, n)
    normals = np.c_[np.sin(tilt) * np.cos(turn), np.sin(tilt) * np.sin(turn), np.cos(tilt)]
    return _typical(n, rng)[0], normals


def _at_the_light(n: int, rng: np.random.Generator) -> tuple[F64, F64]:
    """Every tenth vertex exactly at the light (VP = 0), the others within 10^-3 .. 1 of it."""
    light = np.array([0.5, -0.25, -3.0])
    offset = _directions(n, rng, 0.0) * 10 ** rng.uniform(-3, 0, (n, 1))
    offset[::10] = 0
    return light + offset, _directions(n, rng)


def _normals_of_any_length(n: int, rng: np.random.Generator) -> tuple[F64, F64]:
    """Zero normals, normals of 3 float32 subnormal ulps, and lengths from 10^-3 to 10^3."""
    length = 10 ** rng.uniform(-3, 3, (n, 1))
    length[::10], length[1::10] = 0.0, 3 * 2.0**-149
    return _typical(n, rng)[0], _directions(n, rng) * length


def _scaled(scale: float) -> Callable[[int, np.random.Generator], tuple[F64, F64]]:
    def vertices(n: int, rng: np.random.Generator) -> tuple[F64, F64]:
        return rng.uniform(-1, 1, (n, 3)) * scale, _directions(n, rng, 2.0)

    return vertices


def _scaled_scene(scale: float) -> gs.Scene:
    """tests/core/accuracy/test_stiff.py's scene times `scale`, the linear attenuation over it:
    the exact colours do not change, but squared lengths overflow or underflow float32."""
    lights = [
        gs.Light(
            position=(1.0 * scale, 2.0 * scale, 3.0 * scale, 1.0),
            linear_attenuation=0.2 / scale,
            diffuse=(0.4,) * 3,
            specular=(0.3,) * 3,
        ),
        gs.Light(
            position=(0.0, 0.0, 4.0 * scale, 1.0),
            spot_direction=(0.0, 0.0, -1.0),
            spot_cutoff=60.0,
            spot_exponent=4.0,
            diffuse=(0.3,) * 3,
        ),
    ]
    material = gs.Material(specular=(0.5,) * 3, shininess=20.0)
    return gs.Scene(lights, material=material, viewer=(0.0, 0.0, 5.0 * scale, 1.0))


def _near_k0_zero_light(n: int, rng: np.random.Generator) -> tuple[F64, F64]:
    """Vertices 10^-30 .. 3 from a light at the origin with k0 = 0 (attenuation up to 10^60),
    every tenth at the light itself."""
    p = _directions(n, rng, 0.0) * 10 ** rng.uniform(-30, 0.5, (n, 1))
    p[::10] = 0
    return p, _directions(n, rng)


def _around_cones(n: int, rng: np.random.Generator) -> tuple[F64, F64]:
    """Directions from the lights at the origin over the whole sphere (in front of, on and
    behind the 90 deg cone's plane), a fifth within 10^-6 rad of the 30 deg cone's edge."""
    d = _directions(n, rng, 0.0)
    edge = np.radians(30.0) + rng.uniform(-1e-6, 1e-6, n // 5)
    turn = rng.uniform(0, 2 * np.pi, n // 5)
    d[: n // 5] = np.c_[np.sin(edge) * np.cos(turn), np.sin(edge) * np.sin(turn), -np.cos(edge)]
    return d * rng.uniform(0.5, 2.0, (n, 1)), _directions(n, rng)


def _grazing(n: int, rng: np.random.Generator) -> tuple[F64, F64]:
    """Normals (t, 0, 1) under a light along +x: n . VP = t exactly, |t| from 10^-30 to 0.1,
    either sign, a tenth 0."""
    t = rng.choice([-1.0, 1.0], n) * 10 ** rng.uniform(-30, -1, n)
    t[::10] = 0
    return _typical(n, rng)[0], np.c_[t, np.zeros(n), np.ones(n)]


def _thousand_lights() -> gs.Scene:
    """1,000 directional lights within 30 deg of +z whose diffuse colours alternate in sign,
    large against their sum: a running float32 sum loses the small ones (test_stiff's case)."""
    rng = np.random.default_rng(1)
    terms = np.sort(rng.uniform(0, 1.5e-4, 1000) * rng.choice([1, 1, 1, 20], 1000))
    terms = np.ravel(np.c_[terms[::2] * 50, -terms[::2] * 50 + terms[1::2]])
    tilt, turn = rng.uniform(0, np.radians(30), 1000), rng.uniform(0, 2 * np.pi, 1000)
    direction = np.c_[np.sin(tilt) * np.cos(turn), np.sin(tilt) * np.sin(turn), np.cos(tilt)]
    lights = gs.Lights(
        position=np.c_[direction, np.zeros(1000)],
        diffuse=np.c_[terms, terms, terms],
        specular=np.c_[terms, terms, terms] * 0.5,
    )
    material = gs.Material(diffuse=(1, 1, 1), specular=(1, 1, 1), shininess=8)
    return gs.Scene(lights, material=material, global_ambient=(0, 0, 0))


def _non_finite_rows(n: int, rng: np.random.Generator) -> tuple[F64, F64]:
    """The typical vertices with NaN, inf or -inf in one coordinate of 1% of the positions and
    1% of the normals."""
    p, normals = _typical(n, rng)
    for array in (p, normals):
        rows = rng.choice(n, max(1, n // 100), replace=False)
        array[rows, rng.integers(0, 3, len(rows))] = rng.choice(
            [np.nan, np.inf, -np.inf], len(rows)
        )
    return p, normals


def report_classes() -> list[SceneClass]:
    """The report's scene classes: the benchmark's three scenes, then every stiff case."""
    typical = [SceneClass(name, "typical", s, _typical) for name, s in bench_scenes().items()]
    glossy = gs.Material(diffuse=(0.5,) * 3, specular=(0.6, 0.5, 0.4), shininess=16)
    cones = [
        gs.Light(position=(0, 0, 0, 1), spot_direction=(0, 0, -1), spot_cutoff=90.0),
        gs.Light(
            position=(0, 0, 0, 1),
            spot_direction=(0, 0, -1),
            spot_cutoff=30.0,
            spot_exponent=3.0,
            diffuse=(0.4,) * 3,
        ),
    ]
    stiff = [
        SceneClass(
            "highlight, s = 10^4",
            "stiff",
            gs.Scene(
                [gs.Light(position=(0.0, 0.0, 1.0, 0.0))],
                material=gs.Material(diffuse=(0.3,) * 3, specular=(0.7,) * 3, shininess=1e4),
            ),
            _highlight,
        ),
        SceneClass(
            "light at the vertex",
            "stiff",
            gs.Scene(
                [
                    gs.Light(
                        position=(0.5, -0.25, -3.0, 1.0), linear_attenuation=0.5, ambient=(0.2,) * 3
                    )
                ],
                material=glossy,
                viewer=(0, 0, 0, 1),
            ),
            _at_the_light,
        ),
        SceneClass(
            "L + V = 0",
            "stiff",
            gs.Scene(
                [
                    gs.Light(position=(0.0, 0.0, -1.0, 0.0)),
                    gs.Light(position=(1e-3, 0.0, -1.0, 0.0), diffuse=(0.3,) * 3),
                    gs.Light(position=(0.0, 1e-6, -1.0, 0.0), diffuse=(0.3,) * 3),
                ],
                material=glossy,
            ),
            lambda n, rng: (_typical(n, rng)[0], -_directions(n, rng)),
        ),
        SceneClass(
            "zero, subnormal, non-unit normals",
            "stiff",
            gs.Scene(
                [gs.Light(position=(0.0, 0.5, 1.0, 0.0), diffuse=(0.3,) * 3, specular=(0.2,) * 3)],
                material=gs.Material(specular=(0.5,) * 3, shininess=8),
            ),
            _normals_of_any_length,
        ),
        SceneClass("scaled by 10^30", "stiff", _scaled_scene(1e30), _scaled(1e30)),
        SceneClass("scaled by 2^-100", "stiff", _scaled_scene(2.0**-100), _scaled(2.0**-100)),
        SceneClass(
            "k0 = 0, 10^-30 .. 3 from the light",
            "stiff",
            gs.Scene(
                [
                    gs.Light(
                        position=(0, 0, 0, 1),
                        constant_attenuation=0.0,
                        quadratic_attenuation=1.0,
                        ambient=(0.5,) * 3,
                        diffuse=(0.3,) * 3,
                    )
                ],
                material=gs.Material(ambient=(1, 1, 1), diffuse=(1, 1, 1)),
                global_ambient=(0, 0, 0),
            ),
            _near_k0_zero_light,
        ),
        SceneClass(
            "spot cutoff 90, cone edge",
            "stiff",
            gs.Scene(cones, material=gs.Material(diffuse=(0.5,) * 3), global_ambient=(0, 0, 0)),
            _around_cones,
        ),
        SceneClass(
            "grazing, n.VP to 10^-30",
            "stiff",
            gs.Scene(
                [gs.Light(position=(1.0, 0.0, 0.0, 0.0), diffuse=(0.5,) * 3)],
                material=gs.Material(specular=(0.5,) * 3, shininess=2.0),
            ),
            _grazing,
        ),
        SceneClass("1,000 lights, alternating", "stiff", _thousand_lights(), _typical, 0.01),
        SceneClass(
            "NaN and inf rows", "stiff", bench_scenes()["1 point, local viewer"], _non_finite_rows
        ),
    ]
    return typical + stiff
