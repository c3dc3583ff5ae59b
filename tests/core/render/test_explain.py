"""`gs.explain` on renders with one or two convention switches planted (35 cases across every
switch, 256 x 256): it must name exactly the planted switches (the scales within 1%) in at
least 90% of the cases and bring the residual within 1e-5 of the truth's (0); on images no
convention explains (noise, another mesh, a tinted render) it must say so and name nothing.
The planted pictures are made here, by hand, without the search's code; the light and ambient
scales are off any grid (the shininess scales are the conventions the search names)."""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import pytest

import glshade as gs
from glshade._explain_search import SWITCHES

pytestmark = pytest.mark.slow

SIZE = 256
RNG = np.random.default_rng(1)
# A coarse torus with its vertices jittered (so the weightings differ) and 40 faces cut away
# (so back faces show): every switch changes this picture.
V, F = gs.meshes.torus(16, 10, 1.0, 0.45)
V = V + RNG.normal(0, 0.03, V.shape)
F = F[40:]
SCENE = gs.Scene(
    lights=gs.Lights(
        position=[(1, 1, 2, 0), (-2, 1, 1, 1), (-2.5, -2.0, -3.0, 0)],  # key, fill, back
        diffuse=[(0.9, 0.9, 0.9), (0.6, 0.5, 0.4), (0.3, 0.3, 0.3)],
        specular=[(0.7, 0.7, 0.7), (0.8, 0.8, 0.8), (1, 1, 1)],
    ),
    material=gs.Material(diffuse=(0.7, 0.6, 0.5), specular=(0.8, 0.8, 0.8), shininess=8),
    viewer=(0, 0, 0, 1),
)
CAMERA = gs.Camera.look_at((2.5, 2.0, 3.0), (0, 0, 0), (0, 1, 0))

CASES: list[dict[str, Any]] = [
    {"transfer": "srgb"}, {"transfer": "gamma2.2"}, {"clamp": False, "light_scale": 1.83},
    {"specular": "phong"}, {"specular_gate": False}, {"lights_in": "world"},
    {"normals": "area"}, {"normals": "uniform"}, {"normals": "crease"}, {"cull": "back"},
    {"cull": "front"}, {"light_scale": 2.47}, {"light_scale": math.pi}, {"light_scale": 0.53},
    {"transfer": "srgb", "specular": "phong"}, {"transfer": "gamma2.2", "specular_gate": False},
    {"lights_in": "world", "light_scale": 0.57}, {"normals": "area", "transfer": "srgb"},
    {"normals": "crease", "transfer": "srgb"}, {"cull": "back", "specular": "phong"},
    {"normals": "uniform", "transfer": "gamma2.2"}, {"light_scale": math.pi, "transfer": "srgb"},
    {"winding": "cw"}, {"winding": "cw", "transfer": "srgb"}, {"winding": "cw", "cull": "back"},
    {"winding": "cw", "cull": "front"}, {"shininess_scale": 4.0},
    {"shininess_scale": 0.128}, {"shininess_scale": 7.8125, "transfer": "gamma2.2"},
    {"ambient_scale": 2.93}, {"ambient_scale": 0.0}, {"ambient_scale": 0.0, "light_scale": 2.09},
    # Flat shading ("shading" is the render as meant, not a switch).
    {"shading": "flat", "provoking_vertex": "first"},
    {"shading": "flat", "provoking_vertex": "centroid"},
    {"shading": "flat", "provoking_vertex": "centroid", "transfer": "srgb"},
]  # fmt: skip


def changed(switches: dict[str, Any]) -> gs.Scene:
    """SCENE with the planted switches, rebuilt from its public fields: every light's
    colours times the light scale, the specular model and gate, the shininess times its
    scale, the global ambient's RGB times the ambient scale."""
    k = switches.get("light_scale", 1.0)
    lights = SCENE.lights
    scaled = {name: getattr(lights, name).copy() for name in ("ambient", "diffuse", "specular")}
    for rgba in scaled.values():
        rgba[:, :3] *= k
    material = SCENE.material
    ambient = SCENE.global_ambient.copy()
    ambient[:3] *= switches.get("ambient_scale", 1.0)
    return gs.Scene(
        lights=gs.Lights(position=lights.position, **scaled),
        material=gs.Material(
            ambient=material.ambient, diffuse=material.diffuse, specular=material.specular,
            emission=material.emission,
            shininess=material.shininess * switches.get("shininess_scale", 1.0),
        ),
        global_ambient=ambient, viewer=SCENE.viewer,
        specular=switches.get("specular", "blinn"),
        specular_gate=switches.get("specular_gate", True),
    )  # fmt: skip


def planted(switches: dict[str, Any]) -> np.ndarray:
    """The picture the meant render becomes with `switches`, made independently of `explain`'s
    search: the scene changed by hand, the faces and normals computed, one `render` call."""
    scene = changed(switches)
    faces = F[:, ::-1].copy() if switches.get("winding") == "cw" else F
    kind = switches.get("normals", "angle")
    normals = (
        gs.crease_normals(V, faces, angle=30)
        if kind == "crease"
        else gs.vertex_normals(V, faces, kind)
    )
    shading = switches.get("shading", "phong")
    extra = {"provoking_vertex": switches.get("provoking_vertex", "last")}
    return np.asarray(gs.render(
        V, faces, scene, CAMERA, width=SIZE, height=SIZE, cull=switches.get("cull"),
        normals=None if shading == "flat" else normals, shading=shading,
        lights_in=switches.get("lights_in", "eye"), transfer=switches.get("transfer", "linear"),
        clamp=switches.get("clamp", True), **extra if shading == "flat" else {},
    ))  # fmt: skip


def named(found: dict[str, Any], planted_switches: dict[str, Any]) -> bool:
    if set(found) != set(planted_switches):
        return False
    for key, want in planted_switches.items():
        got = found[key]
        if isinstance(want, float) and not abs(got - want) <= 0.01 * want + 1e-3:
            return False
        if not isinstance(want, float) and got != want:
            return False
    return True


def test_it_names_the_planted_switches() -> None:
    hits = []
    for case in CASES:
        switches = {k: v for k, v in case.items() if k != "shading"}
        meant = {"shading": case.get("shading", "phong")}
        image = planted(case)
        assert np.abs(image - planted(meant)).mean() > 1e-3, f"{case} is not observable"
        e = gs.explain(image, (V, F), SCENE, CAMERA, **meant)
        assert e.explained and e.residual_after <= 1e-5, (switches, e.residual_after)
        assert e.residual_before > e.residual_after
        hits.append(named(e.switches, switches))
    assert sum(hits) >= 0.9 * len(CASES), [c for c, h in zip(CASES, hits, strict=True) if not h]
    assert len(CASES) >= 20
    searched = {"transfer", "clamp", "light_scale", "ambient_scale", "provoking_vertex"}
    # The shading model is planted in test_explain_models.py.
    every = searched | set(SWITCHES) - {"shading_model"}
    assert {k for c in CASES for k in c} >= every, "a switch is not planted"


def test_flat_vertex_colours_name_the_provoking_vertex() -> None:
    # With vertex colours a flat face takes its provoking vertex's colour: the renders without
    # light differ between provoking vertices too, and clockwise faces keep theirs.
    colors = np.random.default_rng(3).uniform(0.2, 1.0, (len(V), 3))
    for planted_switches in ({"provoking_vertex": "first"}, {"winding": "cw"}):
        winding = planted_switches.get("winding") == "cw"
        faces = F[:, [1, 0, 2]] if winding else F
        image = gs.render(V, faces, SCENE, CAMERA, width=SIZE, height=SIZE, shading="flat",
                          colors=colors, provoking_vertex=planted_switches.get(
                              "provoking_vertex", "last"))  # fmt: skip
        e = gs.explain(image, (V, F), SCENE, CAMERA, shading="flat", colors=colors)
        assert e.explained and e.switches == planted_switches, e.switches


def test_an_unplanted_render_needs_no_switch() -> None:
    e = gs.explain(planted({}), (V, F), SCENE, CAMERA)
    assert e.explained and e.switches == {} and e.residual_before <= 1e-12


@pytest.mark.parametrize("kind", ["noise", "another mesh", "tinted"])
def test_it_says_when_nothing_explains_the_image(kind: str) -> None:
    if kind == "noise":
        image = np.random.default_rng(5).uniform(0, 1, (SIZE, SIZE, 3))
    elif kind == "another mesh":
        image = np.asarray(gs.render(gs.meshes.icosphere(2), SCENE, CAMERA, width=SIZE,
                                     height=SIZE))  # fmt: skip
    else:
        image = planted({})
        image[..., 0] *= 0.6  # a colour no switch makes
    e = gs.explain(image, (V, F), SCENE, CAMERA)
    assert not e.explained and e.switches == {} and e.residual_interior > e.noise
    assert isinstance(e.closest, dict) and e.candidates[0] == (e.closest, e.residual_after)
    assert str(e).startswith("nothing explains it: the closest render, ")


def test_uint8_images_and_bad_shapes() -> None:
    image = (np.clip(planted({"transfer": "srgb"}), 0, 1) * 255).round().astype(np.uint8)
    e = gs.explain(image, (V, F), SCENE, CAMERA)
    assert e.switches == {"transfer": "srgb"} and e.residual_after < 1 / 255
    with pytest.raises(ValueError, match="image must have shape"):
        gs.explain(np.zeros((4, 4)), (V, F), SCENE, CAMERA)
    with pytest.raises(TypeError, match=r"scene must be a glshade.Scene, gltf.Scene, threejs"):
        gs.explain(np.zeros((4, 4, 4)), (V, F), "scene", CAMERA)  # type: ignore[arg-type]


def test_the_picture_s_own_rounding_decides() -> None:
    """An 8-bit picture (or one divided back to floats) is explained within half its step; a
    float picture that differs by more than float noise (2e-4 on average) is not."""
    truth = np.clip(planted({"transfer": "srgb"}), 0, 1)
    eight = np.round(truth * 255).astype(np.uint8)
    for image in (eight, eight / 255.0):
        e = gs.explain(image, (V, F), SCENE, CAMERA)
        assert e.explained and e.switches == {"transfer": "srgb"}, str(e)
        assert e.noise == pytest.approx(0.5 / 255 + 2e-4)
        assert 0 < e.residual_interior < 0.5 / 255
    sixteen = np.round(truth * 65535).astype(np.uint16)
    e = gs.explain(sixteen, (V, F), SCENE, CAMERA)
    assert e.explained and e.noise == pytest.approx(0.5 / 65535 + 2e-4)
    # The same picture with float noise of up to 2/255 a channel (no quantisation step to
    # allow it): beyond float arithmetic's, not explained.
    noisy = truth + np.random.default_rng(7).uniform(-2 / 255, 2 / 255, truth.shape)
    e = gs.explain(noisy, (V, F), SCENE, CAMERA)
    assert not e.explained and e.switches == {}, str(e)


def test_nan_pixels_are_left_out_and_counted() -> None:
    image = planted({"transfer": "gamma2.2"})
    holes = np.zeros(image.shape[:2], bool)
    holes[100:140, 60:200] = True
    image[holes, 1] = np.nan
    e = gs.explain(image, (V, F), SCENE, CAMERA)
    assert e.explained and e.switches == {"transfer": "gamma2.2"} and e.ignored == holes.sum()
    assert f"{holes.sum()} pixels with NaN left out" in str(e)
    with pytest.raises(ValueError, match="a NaN channel in each of its 16 pixels"):
        gs.explain(np.full((4, 4, 3), np.nan), (V, F), SCENE, CAMERA)


def test_an_explanation_shows_itself_small() -> None:
    e = gs.explain(planted({"specular": "phong"}), (V, F), SCENE, CAMERA)
    assert str(e).startswith("explained by specular='phong': the residual goes from ")
    assert len(repr(e)) < 600  # no picture in it
    html = e._repr_html_()
    assert html.count("<img ") == 2 and 'width="192"' in html and "best render" in html


# The world models' scenes, meant: lights in the world, an ambient term, a specular lobe.
WORLD = {
    "gltf": gs.gltf.Scene(
        [gs.gltf.DirectionalLight(color=(1, 0.95, 0.9), intensity=2.5, direction=(-1, -1, -2)),
         gs.gltf.PointLight(color=(0.6, 0.8, 1.0), intensity=9.0, position=(-2, 1, 1))],
        gs.gltf.Material(base_color=(0.7, 0.6, 0.5, 1), metallic=0.2, roughness=0.45),
        ambient_light=(0.08, 0.08, 0.1),
    ),
    "threejs": gs.threejs.Scene(
        [gs.threejs.DirectionalLight(intensity=2.0, position=(1, 1, 2)),
         gs.threejs.PointLight(color=(0.6, 0.5, 0.4), intensity=6.0, position=(-2, 1, 1)),
         gs.threejs.AmbientLight(intensity=0.3)],
        gs.threejs.MeshPhongMaterial(color=(0.7, 0.6, 0.5), shininess=20),  # back faces culled
    ),
}  # fmt: skip
WORLD_CASES: list[dict[str, Any]] = [
    {"transfer": "gamma2.2"}, {"transfer": "srgb", "light_scale": 2.31}, {"light_scale": 0.61},
    {"normals": "area"}, {"winding": "cw"}, {"ambient_scale": 0.0}, {"cull": "front"},
]  # fmt: skip


def world_planted(model: str, switches: dict[str, Any]) -> np.ndarray:
    """The world scene's picture with `switches`, made by hand: each direct light's intensity
    times the light scale and the ambient term times the ambient scale, rebuilt from the
    records' public fields; the faces, normals and culling given to one `render` call."""
    scene = WORLD[model]
    k, a = switches.get("light_scale", 1.0), switches.get("ambient_scale", 1.0)
    lights = []
    for light in scene.lights:
        fields = {f: getattr(light, f) for f in light.__dataclass_fields__}
        fields["intensity"] *= a if isinstance(light, gs.threejs.AmbientLight) else k
        lights.append(type(light)(**fields))
    if model == "gltf":
        ambient = tuple(a * x for x in WORLD["gltf"].ambient_light)
        changed_scene: Any = gs.gltf.Scene(lights, scene.material, ambient_light=ambient)
    else:
        changed_scene = gs.threejs.Scene(lights, scene.material)
    faces = F[:, ::-1].copy() if switches.get("winding") == "cw" else F
    normals = gs.vertex_normals(V, faces, switches.get("normals", "angle"))
    return np.asarray(gs.render(
        V, faces, changed_scene, CAMERA, width=SIZE, height=SIZE, normals=normals,
        cull=switches.get("cull"), transfer=switches.get("transfer", "linear"),
    ))  # fmt: skip


@pytest.mark.parametrize("model", list(WORLD))
def test_a_world_model_s_scene_is_searched_by_its_own_switches(model: str) -> None:
    """glTF's and three.js' scenes are searched without GL's equation's switches (specular
    model, gate, shininess, lights in the eye): the scales multiply their lights'
    intensities and their ambient terms."""
    hits = []
    for case in WORLD_CASES:
        image = world_planted(model, case)
        assert np.abs(image - world_planted(model, {})).mean() > 1e-3, f"{case} is not observable"
        e = gs.explain(image, (V, F), WORLD[model], CAMERA)
        assert e.explained and e.residual_after <= 1e-5, (model, case, str(e))
        hits.append(named(e.switches, case))
    assert all(hits), [c for c, h in zip(WORLD_CASES, hits, strict=True) if not h]
    e = gs.explain(world_planted(model, {}), (V, F), WORLD[model], CAMERA)
    assert e.explained and e.switches == {}
    assert not set(e.closest) & {"specular", "specular_gate", "shininess_scale", "lights_in"}
