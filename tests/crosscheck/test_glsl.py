"""glshade.glsl: its compute shader run by Mesa's llvmpipe (moderngl) on programs that together
hold every distinction the generator and Scene.plan make over the core's feature subsets, against
gs.shade in float32; the specialisation read from the source; the values to bind; the helper's
errors.

The feature subsets are those of the core's specialisation tests (src/tests/specialisation.rs,
14 features: directional and positional lights, attenuation, spot, local viewer, shininess,
specular colour, two-sided lighting, separate specular, colour material, modelview, normalize,
Phong, light ambient), rebuilt here as reference scenes. Their 2^14 subsets make 206 distinct
`Scene.plan` lines and 7,724 distinct compute shader sources (the generator also specialises on
the colour material mode and face, the specular gate, two-sided lighting, ...). llvmpipe compiles
a program in 0.1 to 0.4 s, so all of them would take some 25 minutes; the test runs a greedy
cover instead: programs that between them hold every `Scene.plan` line, every distinct light
loop and every distinct function of the generated GLSL (light groups and counts aside), 509
programs, each on every subset that generates it (968 subsets), with every pair of features in
all four on/off combinations and every plan flag both ways among them (asserted).
"""

from __future__ import annotations

import functools
import heapq
import itertools
import re
from typing import Any

import numpy as np
import pytest
from conftest import require

import glshade as gs
from support import glpeers
from support.gl_reference import RefScene
from support.scenes import shade_kwargs, to_glshade

pytestmark = pytest.mark.gl

FEATURES = 14
VERTICES = 400
# The runs of the programs are split into this many tests, so a failure names a part.
PARTS = 16
# The bar: per vertex within 2e-6 of gs.shade in float32, where the sum of |terms| is
# at most 1 (scaled by that sum above), away from the discontinuities (n.VP = 0, a cone edge).
TOL = 2e-6
MARGIN = 2e-5
MODES = ["ambient_and_diffuse", "specular", "emission", "diffuse", "ambient"]
FACES = ["front_and_back", "front", "back"]
MODELVIEW = np.array(
    [[0.8, -0.1, 0.2, 0.1], [0.1, 1.3, -0.2, -0.3], [-0.2, 0.3, 0.7, -2.0], [0, 0, 0, 1]]
)
# A light loop of the generated source, and a function at the top level (after the loops are cut).
LOOP = re.compile(r"^    for \(int i = 0; i < \w+; \+\+i\) \{\n.*?\n    \}\n", re.S | re.M)
FUNCTION = re.compile(r"^\w[^\n]*\) \{\n.*?\n\}$", re.S | re.M)


def feature_scene(bits: int) -> RefScene:
    """The scene and options of feature subset `bits` (bit k on = feature k present), as the
    core's specialisation tests build it."""

    def on(k: int) -> bool:
        return bool(bits >> k & 1)

    ambient = (0.1, 0.05, 0.2, 1.0) if on(13) else (0.0, 0.0, 0.0, 1.0)
    lights: list[dict[str, Any]] = []
    if on(0):
        lights.append({"position": (0.3, 0.5, 1.0, 0.0), "ambient": ambient})
        lights.append(
            {
                "position": (-1.0, 0.2, 0.4, 0.0),
                "diffuse": (0.5, 0.3, 0.2, 1.0),
                "specular": (0.0, 0.0, 0.0, 1.0),
                "spot_cutoff": 80.0,
            }
        )
    if on(1):
        k = (0.5, 0.3, 0.2) if on(2) else (1.0, 0.0, 0.0)
        # The second light has a soft edge and a range where spot and attenuation are both on.
        edges = on(2) and on(3)
        for i, position in enumerate(((1.0, 2.0, 1.0, 1.0), (0.25, -0.5, 1.5, 0.5))):
            lights.append(
                {
                    "position": position,
                    "ambient": ambient,
                    "constant_attenuation": k[0],
                    "linear_attenuation": k[1],
                    "quadratic_attenuation": k[2],
                    "spot_cutoff": 60.0 if on(3) else 180.0,
                    "spot_direction": (-0.5, -1.0, -0.5),
                    "spot_exponent": 3.0,
                    "spot_inner_cutoff": 30.0 if edges and i == 1 else 180.0,
                    "range": 4.0 if edges and i == 1 else np.inf,
                }
            )
    material = {
        "ambient": (0.2, 0.2, 0.2, 1.0),
        "diffuse": (0.8, 0.8, 0.8, 1.0),
        "specular": (0.6, 0.5, 0.4, 1.0) if on(6) else (0.0, 0.0, 0.0, 1.0),
        "shininess": 20.0 if on(5) else 0.0,
        "emission": (0.05, 0.0, 0.1, 1.0),
    }
    ref = RefScene(
        lights=lights,
        material=material,
        back_material={**material, "diffuse": (0.2, 0.8, 0.3, 0.5)},
        viewer=(0.5, 0.0, 2.0, 1.0) if on(4) else (0.0, 0.0, 1.0, 0.0),
        two_side=on(7),
        separate_specular=on(8),
        specular="phong" if on(12) else "blinn",
        specular_gate=bin(bits).count("1") % 2 == 0,
        modelview=MODELVIEW if on(10) else None,
        normalize=on(11),
    )
    if on(9):
        ref.color_material = MODES[(bits // 7) % len(MODES)]
        ref.color_material_face = FACES[bits % 3]
    return ref


def options(ref: RefScene) -> dict[str, Any]:
    """The shader options of `ref` (colour material as if colours were bound)."""
    return {**shade_kwargs(ref), "color_material": ref.color_material,
            "color_material_face": ref.color_material_face}  # fmt: skip


def pieces(source: str) -> set[str]:
    """The light loops and functions of a generated source, with light group numbers and light
    counts made alike: what a program adds to the coverage."""
    alike = re.sub(r"i < \d+", "i < K", re.sub(r"gs_light\d+_", "gs_lightK_", source))
    loops = set(LOOP.findall(alike))
    return loops | set(FUNCTION.findall(LOOP.sub("    LOOP\n", alike)))


@functools.cache
def programs() -> list[tuple[int, ...]]:
    """The subsets of each program of the cover: greedily the program that adds the most pieces
    (a `Scene.plan` line counts as one) until every piece of the 2^14 subsets is held."""
    subsets: dict[str, list[int]] = {}
    lines: dict[str, str] = {}
    for bits in range(2**FEATURES):
        ref = feature_scene(bits)
        scene = to_glshade(ref)
        source = gs.glsl.compute_shader(scene, **options(ref)).compute
        assert source is not None
        if source not in subsets:
            lines[source] = scene.plan(**options(ref))
        subsets.setdefault(source, []).append(bits)
    held = {source: pieces(source) | {lines[source]} for source in subsets}
    # Lazy greedy: a program's gain only shrinks, so a popped gain that is still current wins.
    heap = [(-len(p), subsets[source][0], source) for source, p in held.items()]
    heapq.heapify(heap)
    covered: set[str] = set()
    chosen = []
    while heap:
        gain, first, source = heapq.heappop(heap)
        new = len(held[source] - covered)
        if new and new == -gain:
            chosen.append(tuple(subsets[source]))
            covered |= held[source]
        elif new:
            heapq.heappush(heap, (-new, first, source))
    # Then, for any pair of features not yet seen in all four combinations, a program that has it.
    by_bits = {bits: source for source, group in subsets.items() for bits in group}
    for j, k in itertools.combinations(range(FEATURES), 2):
        for want in itertools.product((0, 1), repeat=2):
            seen = {(b >> j & 1, b >> k & 1) for group in chosen for b in group}
            if want not in seen:
                bits = next(b for b in by_bits if (b >> j & 1, b >> k & 1) == want)
                chosen.append(tuple(subsets[by_bits[bits]]))
    return chosen


def vertices(seed: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    rng = np.random.default_rng(seed)
    p = rng.uniform(-2, 2, (VERTICES, 3))
    n = rng.normal(size=(VERTICES, 3))
    n /= np.linalg.norm(n, axis=1, keepdims=True)
    return p.astype(np.float32), n.astype(np.float32), rng.uniform(0, 1, (VERTICES, 4))


@pytest.fixture(scope="module", autouse=True)
def context() -> Any:
    return glpeers.moderngl_context()


@pytest.mark.slow
def test_the_programs_cover_every_pair_of_features_and_every_plan_flag() -> None:
    chosen = [bits for group in programs() for bits in group]
    for j, k in itertools.combinations(range(FEATURES), 2):
        seen = {(b >> j & 1, b >> k & 1) for b in chosen}
        assert len(seen) == 4, (j, k)
    tokens: dict[str, set[bool]] = {}
    for bits in chosen:
        ref = feature_scene(bits)
        line = to_glshade(ref).plan(**options(ref))
        for token in ("positions and normals", "n̂", "ln|n|", "VP_e per vertex", "ĥ constant",
                      "positional spot", "attenuation", "specular", "ambient",
                      "soft edge", "range"):  # fmt: skip
            tokens.setdefault(token, set()).add(token in line)
    assert all(both == {True, False} for both in tokens.values()), tokens


def test_pieces_are_the_loops_and_functions_of_the_source() -> None:
    """The cover is only as good as `pieces`: on the subset with every feature, each loop of the
    source and each function it defines is found whole."""
    ref = feature_scene(2**FEATURES - 1)
    source = gs.glsl.compute_shader(to_glshade(ref), **options(ref)).compute or ""
    loops = LOOP.findall(source)
    assert len(loops) == source.count("for (int i") > 0
    cut = LOOP.sub("", source)
    functions = FUNCTION.findall(cut)
    defined = re.findall(r"^\w+ (\w+)\(.*\) \{$", source, re.M)
    assert [re.match(r"\w+ (\w+)\(", f).group(1) for f in functions] == defined  # type: ignore[union-attr]
    assert "gs_cos_pow" in defined and "gs_lighting_back" in defined
    assert all(f.count("{") == f.count("}") for f in functions + loops)


@pytest.mark.parametrize("part", range(PARTS))
def test_compute_shader_agrees_with_shade_on_the_programs(part: int) -> None:
    """Every subset of the programs `part`, `part + PARTS`, ... of the cover: per vertex within
    2e-6 max(1, sum |terms|) of gs.shade plus the 4u s |specular term| its float32 fast mode
    allows its plain power (no allowance for a conditioning of the power: glshade.glsl forms
    it as the kernel's careful path does)."""
    for group in programs()[part::PARTS]:
        for bits in group:
            ref = feature_scene(bits)
            scene = to_glshade(ref)
            p, n, colors = vertices(bits)
            ref.colors = colors if ref.color_material else None
            kwargs = shade_kwargs(ref)
            got = gs.shade(p, n, scene, **kwargs)
            theirs = gs.glsl.shade(p, n, scene, **kwargs)
            assert theirs.shape == got.shape and theirs.dtype == np.float32
            tolerance = glpeers.float32_tolerance(ref, p, n, TOL, MARGIN, gl_pow=False)
            compared = glpeers.assert_agree(
                tolerance, got, theirs, tolerance.comparable, "GLSL", bits
            )
            assert compared >= 0.9 * VERTICES


def test_source_follows_the_plan() -> None:
    """Each light's terms in the source are the ones Scene.plan names for it, on the subsets of
    the cover."""
    for bits in (bits for group in programs() for bits in group):
        ref = feature_scene(bits)
        scene = to_glshade(ref)
        line = scene.plan(**options(ref))
        shaders = gs.glsl.compute_shader(scene, **options(ref))
        planned = dict(re.findall(r"light (\d+) [^:]*: ([a-z+ ]+)", line))
        described = {}
        for group in re.findall(
            r"// gs_light\d+: lights ([\d, ]+), \w+: ([a-z +]+)", shaders.compute or ""
        ):
            for i in group[0].split(", "):
                terms = set(group[1].replace("spot cone", "").split(" + ")) - {""}
                described[i] = terms
        for i, terms in planned.items():
            expected = set(terms.split("+")) - {"nothing"}
            assert described.get(i, set()) == expected, (bits, i, line)
        assert ("gs_positions" in (shaders.compute or "")) == ("positions and normals" in line)


def test_one_directional_light_holds_no_attenuation_or_spot_code() -> None:
    scene = gs.Scene(lights=[gs.Light(position=(1, 2, 3, 0))])
    shaders = [gs.glsl.compute_shader(scene)]
    shaders += [gs.glsl.raster_shaders(scene, s) for s in ("phong", "gouraud", "flat")]
    for s in shaders:
        for source in (s.library, *s.sources.values()):
            lowered = source.lower()
            for word in ("attenuation", "spot", "cutoff", "pow", "distance", "sqrt(dot(d"):
                assert word not in lowered, (word, source)
    # The same light made a spot, and a point light, bring their code.
    spot = gs.glsl.compute_shader(gs.Scene(lights=[gs.Light(position=(0, 0, 1, 1),
                                                            spot_cutoff=30)]))  # fmt: skip
    assert "spot_cos_cutoff" in spot.compute and "attenuation" not in spot.compute  # type: ignore[operator]
    point = gs.glsl.compute_shader(gs.Scene(lights=[gs.Light(position=(0, 0, 1, 1),
                                                             linear_attenuation=0.5)]))  # fmt: skip
    assert "attenuation" in point.compute and "spot" not in point.compute  # type: ignore[operator]


def test_uniforms_are_the_scene_values_in_float32() -> None:
    light = gs.Light(position=(0, 3, 4, 2), diffuse=(0.5, 0.25, 1), linear_attenuation=0.25,
                     spot_cutoff=90, spot_direction=(0, -2, 0), spot_exponent=4)  # fmt: skip
    sun = gs.Light(position=(0, 0, 2, 0), spot_cutoff=50, spot_direction=(0, -1, -1),
                   spot_exponent=2)  # fmt: skip
    scene = gs.Scene(lights=[light, sun], material=gs.Material(specular=(1, 1, 1), shininess=8))
    u = gs.glsl.compute_shader(scene, modelview=np.diag([2.0, 1, 1, 1])).uniforms
    assert all(v.dtype == np.float32 for v in u.values())
    positional = next(k for k in u if k.endswith("_point")).split("_point")[0]
    np.testing.assert_array_equal(u[f"{positional}_point"], [[0, 1.5, 2]])
    np.testing.assert_array_equal(u[f"{positional}_spot_direction"], [[0, -1, 0]])
    assert u[f"{positional}_spot_cos_cutoff"][0] == 0.0  # cos 90 is exactly 0
    directional = next(k for k in u if k.endswith("_vp")).split("_vp")[0]
    np.testing.assert_array_equal(u[f"{directional}_vp"], [[0, 0, 1]])
    # The spot factor of a directional light, a constant: (-VP . s_dl)^2 = cos(45 deg)^2.
    assert u[f"{directional}_spot"][0] == pytest.approx(0.5, abs=1e-7)
    # ĥ of a directional light with an infinite viewer, from float64.
    np.testing.assert_array_equal(u[f"{directional}_halfway"], [[0, 0, 1]])
    np.testing.assert_array_equal(u["gs_normal_matrix"], np.diag([0.5, 1, 1]).astype(np.float32))


def test_raster_shaders_render_like_render_on_a_coloured_mesh() -> None:
    """The helper's render (uint8 vertex colours, world lights) equals gs.render's image."""
    trimesh = require("trimesh")
    mesh = trimesh.creation.icosphere(subdivisions=3)
    rng = np.random.default_rng(2)
    mesh.visual.vertex_colors = rng.integers(0, 256, (len(mesh.vertices), 4), dtype=np.uint8)
    scene = gs.Scene(lights=[gs.Light(position=(2, 3, 4, 1))],
                     material=gs.Material(specular=(1, 1, 1), shininess=16))  # fmt: skip
    camera = gs.Camera.look_at((0.5, 1.0, 3.0))
    for shading in ("phong", "gouraud", "flat"):
        ours = gs.render(mesh, scene, camera, width=96, height=80, shading=shading,
                         lights_in="world")  # fmt: skip
        theirs = gs.glsl.render(mesh, scene, camera, width=96, height=80, shading=shading,
                                lights_in="world", context=glpeers.moderngl_context())  # fmt: skip
        result = gs.compare(ours, theirs)
        assert result.within_tolerance >= 0.995 and result.edge_only, (shading, str(result))


def test_helper_errors_name_the_argument() -> None:
    scene = gs.Scene(lights=[gs.Light()])
    with pytest.raises(TypeError, match=r"scene must be a glshade\.Scene"):
        gs.glsl.compute_shader("scene")  # type: ignore[arg-type]
    with pytest.raises(ValueError, match="shading must be 'phong', 'gouraud' or 'flat', got 'x'"):
        gs.glsl.raster_shaders(scene, "x")  # type: ignore[arg-type]
    with pytest.raises(ValueError, match="color_material must be one of"):
        gs.glsl.compute_shader(scene, color_material="shiny")
    with pytest.raises(ValueError, match="modelview must be affine"):
        gs.glsl.compute_shader(scene, modelview=np.ones((4, 4)))
    with pytest.raises(ValueError, match=r"positions must have shape \(\.\.\., 3\)"):
        gs.glsl.shade(np.zeros((3, 2)), np.zeros((3, 2)), scene)


def test_missing_moderngl_names_pip_install(monkeypatch: pytest.MonkeyPatch) -> None:
    import builtins

    real_import = builtins.__import__

    def no_moderngl(name: str, *args: Any, **kwargs: Any) -> Any:
        if name == "moderngl":
            raise ImportError("No module named 'moderngl'")
        return real_import(name, *args, **kwargs)

    monkeypatch.setattr(builtins, "__import__", no_moderngl)
    with pytest.raises(ImportError, match="pip install moderngl"):
        gs.glsl.context()
