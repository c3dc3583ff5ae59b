"""`gs.explain` names the shading model a picture was drawn with: 30 pictures planted over the
four models (GL, glTF metallic-roughness, three.js Phong, PyTorch3D's Phong), from a scene of
each of the three scene types, alone or with another switch, must each be named exactly.

Each planted picture is made here without the search's code: the scene as meant is converted
by this file's own transcription of the conversion table in docs/pages/guide/explain.md
(`gl_world`, `to_gltf`, `to_threejs`, `to_pytorch3d`), built from the records' public fields,
and drawn with one `render` call."""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import pytest

import glshade as gs

pytestmark = pytest.mark.slow

SIZE = 128
RNG = np.random.default_rng(11)
# A coarse torus, jittered and cut (every switch shows on it), as test_explain.py draws.
V, F = gs.meshes.torus(16, 10, 1.0, 0.45)
V = V + RNG.normal(0, 0.03, V.shape)
F = F[40:]
CAMERA = gs.Camera.look_at((2.5, 2.0, 3.0), (0, 0, 0), (0, 1, 0))
EYE = (2.5, 2.0, 3.0, 1.0)

# GL's scene, lights in eye coordinates: a key light, a fill falling off as 1/d² (what every
# model can hold) and a back light; some emission, a global ambient.
GL = gs.Scene(
    lights=gs.Lights(
        position=[(1, 1, 2, 0), (-2, 1, -1, 1), (-2.5, -2.0, -3.0, 0)],
        diffuse=[(0.9, 0.85, 0.8), (3.0, 2.5, 2.0), (0.3, 0.3, 0.35)],
        specular=[(0.9, 0.85, 0.8), (3.0, 2.5, 2.0), (0.3, 0.3, 0.35)],
        constant_attenuation=[1.0, 0.0, 1.0],
        quadratic_attenuation=[0.0, 1.0, 0.0],
        ambient=[(0.02, 0.02, 0.02), (0, 0, 0), (0, 0, 0)],
    ),
    material=gs.Material(
        ambient=(0.7, 0.6, 0.5), diffuse=(0.7, 0.6, 0.5), specular=(0.6, 0.6, 0.6),
        emission=(0.03, 0.02, 0.0), shininess=24,
    ),
    global_ambient=(0.06, 0.06, 0.08, 1), viewer=(0, 0, 0, 1),
)  # fmt: skip
GLTF = gs.gltf.Scene(
    [gs.gltf.DirectionalLight(color=(1, 0.95, 0.9), intensity=2.5, direction=(-1, -1, -2)),
     gs.gltf.PointLight(color=(0.6, 0.8, 1.0), intensity=9.0, position=(-2, 1, 1)),
     gs.gltf.SpotLight(color=(1.0, 0.8, 0.6), intensity=12.0, position=(2, 2.5, 0.5),
                       direction=(-2, -2.5, -0.5), inner_cone_angle=0.2, outer_cone_angle=0.5)],
    gs.gltf.Material(base_color=(0.7, 0.6, 0.5, 1), metallic=0.2, roughness=0.45),
    ambient_light=(0.08, 0.08, 0.1),
)  # fmt: skip
THREEJS = gs.threejs.Scene(
    [gs.threejs.DirectionalLight(intensity=2.0, position=(1, 1, 2)),
     gs.threejs.PointLight(color=(0.6, 0.5, 0.4), intensity=6.0, position=(-2, 1, 1)),
     gs.threejs.AmbientLight(intensity=0.3)],
    gs.threejs.MeshPhongMaterial(color=(0.7, 0.6, 0.5), specular=(0.3, 0.3, 0.3), shininess=20),
)  # fmt: skip
SCENES: dict[str, Any] = {"gl": GL, "gltf": GLTF, "threejs": THREEJS}

# (scene as meant, planted switches): the model alone and with one or two other switches.
CASES: list[tuple[str, dict[str, Any]]] = [
    ("gl", {"shading_model": "gltf"}),
    ("gl", {"shading_model": "gltf", "transfer": "gamma2.2"}),
    ("gl", {"shading_model": "gltf", "light_scale": math.pi}),
    ("gl", {"shading_model": "gltf", "transfer": "srgb", "light_scale": 2.3}),
    ("gl", {"shading_model": "gltf", "cull": "back"}),
    ("gl", {"shading_model": "gltf", "normals": "area"}),
    ("gl", {"shading_model": "threejs"}),
    ("gl", {"shading_model": "threejs", "transfer": "srgb"}),
    ("gl", {"shading_model": "threejs", "light_scale": math.pi}),
    ("gl", {"shading_model": "threejs", "cull": "back", "transfer": "srgb"}),
    ("gl", {"shading_model": "threejs", "ambient_scale": 0.0}),
    ("gl", {"shading_model": "threejs", "winding": "cw"}),
    ("gl", {"shading_model": "pytorch3d"}),
    ("gl", {"shading_model": "pytorch3d", "normals": "area"}),
    ("gl", {"shading_model": "pytorch3d", "clamp": False, "light_scale": 1.7}),
    ("gl", {"shading_model": "pytorch3d", "normals": "area", "clamp": False}),
    ("gl", {"shading_model": "pytorch3d", "transfer": "srgb"}),
    ("gltf", {"shading_model": "gl"}),
    ("gltf", {"shading_model": "gl", "cull": "front"}),
    ("gltf", {"shading_model": "gl", "transfer": "srgb"}),
    ("gltf", {"shading_model": "threejs"}),
    ("gltf", {"shading_model": "threejs", "transfer": "srgb"}),
    ("gltf", {"shading_model": "pytorch3d"}),
    ("gltf", {"shading_model": "pytorch3d", "normals": "area"}),
    ("threejs", {"shading_model": "gl"}),
    ("threejs", {"shading_model": "gl", "transfer": "gamma2.2"}),
    ("threejs", {"shading_model": "gltf"}),
    ("threejs", {"shading_model": "gltf", "transfer": "gamma2.2"}),
    ("threejs", {"shading_model": "gltf", "light_scale": 2.2}),
    ("threejs", {"shading_model": "pytorch3d"}),
]


def rgba(rgb: Any, alpha: float = 1.0) -> tuple[float, ...]:
    return (*(float(x) for x in rgb[:3]), alpha)


def gl_world(name: str) -> gs.Scene:
    """The scene as meant, as a GL scene with its lights in world coordinates (the table's
    first half)."""
    if name == "gl":  # its lights are in eye coordinates: back into the world
        return GL.in_eye_space(np.linalg.inv(CAMERA.view))
    rows: list[dict[str, Any]] = []
    ambient = np.zeros(3)
    if name == "gltf":
        for light in GLTF.lights:
            row: dict[str, Any] = {"diffuse": np.multiply(light.color, light.intensity)}
            if isinstance(light, gs.gltf.DirectionalLight):
                row["position"] = (*(-np.asarray(light.direction)), 0.0)
            else:
                row["position"] = (*light.position, 1.0)
                row["constant_attenuation"], row["quadratic_attenuation"] = 0.0, 1.0
            if isinstance(light, gs.gltf.SpotLight):
                row["spot_direction"] = light.direction
                row["spot_cutoff"] = math.degrees(light.outer_cone_angle)
                row["spot_inner_cutoff"] = math.degrees(light.inner_cone_angle)
            rows.append(row)
        m = GLTF.material
        base = np.asarray(m.base_color)
        diffuse = rgba(base * (1 - m.metallic), base[3])
        material = gs.Material(
            ambient=diffuse, diffuse=diffuse, specular=rgba(0.04 + (base - 0.04) * m.metallic),
            emission=rgba(m.emissive), shininess=min(2 / m.roughness**4 - 2, 128),
        )  # fmt: skip
        ambient = GLTF.ambient_light
    else:
        for light in THREEJS.lights:
            if isinstance(light, gs.threejs.AmbientLight):
                ambient = ambient + np.multiply(light.color, light.intensity)
                continue
            row = {"diffuse": np.multiply(light.color, light.intensity)}
            if isinstance(light, gs.threejs.DirectionalLight):
                row["position"] = (*np.subtract(light.position, light.target), 0.0)
            else:  # decay 2: 1/d²
                row["position"] = (*light.position, 1.0)
                row["constant_attenuation"], row["quadratic_attenuation"] = 0.0, 1.0
            rows.append(row)
        m3 = THREEJS.material
        diffuse = rgba(m3.color, m3.opacity)
        material = gs.Material(
            ambient=diffuse, diffuse=diffuse, specular=rgba(m3.specular),
            emission=rgba(m3.emissive), shininess=m3.shininess,
        )  # fmt: skip
    lights = [
        gs.Light(**{**row, "diffuse": rgba(row["diffuse"]), "specular": rgba(row["diffuse"])})
        for row in rows
    ]
    return gs.Scene(
        lights=lights, material=material, global_ambient=rgba(ambient), viewer=(0, 0, 0, 1)
    )


def light_rows(scene: gs.Scene) -> list[dict[str, Any]]:
    return [
        {p: np.asarray(getattr(scene.lights, p))[i] for p in ("position", "diffuse", "specular",
         "ambient", "constant_attenuation", "quadratic_attenuation", "spot_direction",
         "spot_cutoff", "spot_inner_cutoff")}
        for i in range(len(scene.lights))
    ]  # fmt: skip


def ambient_sum(scene: gs.Scene) -> np.ndarray:
    return scene.global_ambient[:3] + sum(r["ambient"][:3] for r in light_rows(scene))


def to_gltf(world: gs.Scene, k: float) -> gs.gltf.Scene:
    lights: list[Any] = []
    for r in light_rows(world):
        p, color = r["position"], r["diffuse"][:3]
        if p[3] == 0:
            lights.append(gs.gltf.DirectionalLight(color=color, intensity=k, direction=-p[:3]))
        elif r["spot_cutoff"] == 180:
            lights.append(gs.gltf.PointLight(color=color, intensity=k, position=p[:3] / p[3]))
        else:
            outer = math.radians(r["spot_cutoff"])
            inner = min(math.radians(r["spot_inner_cutoff"]), outer)
            lights.append(gs.gltf.SpotLight(
                color=color, intensity=k, position=p[:3] / p[3], direction=r["spot_direction"],
                inner_cone_angle=inner, outer_cone_angle=outer,
            ))  # fmt: skip
    m = world.material
    return gs.gltf.Scene(
        lights,
        gs.gltf.Material(base_color=m.diffuse, metallic=0.0,
                         roughness=(2 / (m.shininess + 2)) ** 0.25, emissive=m.emission[:3]),
        ambient_light=ambient_sum(world),
    )  # fmt: skip


def to_threejs(world: gs.Scene, k: float) -> gs.threejs.Scene:
    lights: list[Any] = []
    for r in light_rows(world):
        p, color = r["position"], r["diffuse"][:3]
        if p[3] == 0:
            lights.append(gs.threejs.DirectionalLight(color=color, intensity=k, position=p[:3]))
            continue
        quadratic = r["quadratic_attenuation"] > 0
        decay, att = (2.0, r["quadratic_attenuation"]) if quadratic else (
            0.0, r["constant_attenuation"])  # fmt: skip
        where = p[:3] / p[3]
        light = {"color": color, "intensity": k / att, "decay": decay, "position": where}
        if r["spot_cutoff"] == 180:
            lights.append(gs.threejs.PointLight(**light))
        else:
            lights.append(gs.threejs.SpotLight(
                angle=math.radians(r["spot_cutoff"]),
                penumbra=1 - r["spot_inner_cutoff"] / r["spot_cutoff"],
                target=where + r["spot_direction"], **light,
            ))  # fmt: skip
    lights.append(gs.threejs.AmbientLight(color=ambient_sum(world)))
    m = world.material
    return gs.threejs.Scene(lights, gs.threejs.MeshPhongMaterial(
        color=m.diffuse[:3], specular=m.specular[:3], shininess=m.shininess,
        emissive=m.emission[:3], opacity=m.diffuse[3],
    ))  # fmt: skip


def to_pytorch3d(world: gs.Scene, k: float) -> gs.Scene:
    """PyTorch3D's Phong: each light unattenuated, no spot, no emission, Phong's reflection,
    the viewer at the camera (a world point)."""
    scaled = [{c: r[c] * [k, k, k, 1] for c in ("ambient", "diffuse", "specular")}
              for r in light_rows(world)]  # fmt: skip
    m = world.material
    return gs.Scene(
        lights=[gs.Light(position=r["position"], **c)
                for r, c in zip(light_rows(world), scaled, strict=True)],
        material=gs.Material(ambient=m.ambient, diffuse=m.diffuse, specular=m.specular,
                             shininess=m.shininess),
        global_ambient=world.global_ambient, viewer=EYE, specular="phong",
    )  # fmt: skip


def to_gl(world: gs.Scene, k: float) -> gs.Scene:
    rows = light_rows(world)
    return gs.Scene(
        lights=[gs.Light(**{**r, **{c: r[c] * [k, k, k, 1]
                                    for c in ("ambient", "diffuse", "specular")}})
                for r in rows],
        material=world.material, global_ambient=world.global_ambient, viewer=(0, 0, 0, 1),
    )  # fmt: skip


def planted(meant: str, switches: dict[str, Any]) -> np.ndarray:
    """The picture of the scene `meant` drawn with the planted model and switches."""
    model = switches["shading_model"]
    k = switches.get("light_scale", 1.0)
    world = gl_world(meant)
    scene: Any = {"gltf": to_gltf, "threejs": to_threejs, "pytorch3d": to_pytorch3d,
                  "gl": to_gl}[model](world, k)  # fmt: skip
    if "specular" in switches:  # GL's own switch, in the GL scene converted
        scene = gs.Scene(lights=scene.lights, material=scene.material,
                         global_ambient=scene.global_ambient, viewer=scene.viewer,
                         specular=switches["specular"])  # fmt: skip
    if switches.get("ambient_scale") == 0.0:  # three.js' ambient light off
        scene = gs.threejs.Scene(scene.lights[:-1], scene.material)
    faces = F[:, ::-1].copy() if switches.get("winding") == "cw" else F
    normals = gs.vertex_normals(V, faces, switches.get("normals", "angle"))
    return np.asarray(gs.render(
        V, faces, scene, CAMERA, width=SIZE, height=SIZE, normals=normals,
        cull=switches.get("cull", "none"), lights_in=switches.get("lights_in", "world"),
        transfer=switches.get("transfer", "linear"), clamp=switches.get("clamp", True),
    ))  # fmt: skip


def named(found: dict[str, Any], want: dict[str, Any]) -> bool:
    if set(found) != set(want):
        return False
    for key, value in want.items():
        if isinstance(value, float) and key.endswith("scale"):
            if not abs(found[key] - value) <= 0.01 * value + 1e-3:
                return False
        elif found[key] != value:
            return False
    return True


def test_gl_s_scene_moved_into_the_world_draws_as_meant() -> None:
    # This file's own step from eye to world coordinates (its lights, its viewer) is GL's.
    own = np.asarray(gs.render(V, F, GL, CAMERA, width=64, height=64))
    drawn = np.asarray(gs.render(V, F, to_gl(gl_world("gl"), 1.0), CAMERA, width=64, height=64,
                                 lights_in="world"))  # fmt: skip
    np.testing.assert_allclose(drawn, own, atol=1e-12)


def test_it_names_the_model_a_picture_was_drawn_with() -> None:
    assert len(CASES) >= 30
    assert {(m, c["shading_model"]) for m, c in CASES} >= {
        (m, other) for m in SCENES for other in ("gl", "gltf", "threejs", "pytorch3d") if m != other
    }
    missed = []
    for meant, switches in CASES:
        image = planted(meant, switches)
        # Every planted switch shows: the model against the scene as meant, the others
        # against the model alone.
        model = {"shading_model": switches["shading_model"]}
        as_meant = gs.render(V, F, SCENES[meant], CAMERA, width=SIZE, height=SIZE, cull="none")
        assert np.abs(planted(meant, model) - as_meant).mean() > 1e-3, (meant, model)
        if switches != model:
            assert np.abs(image - planted(meant, model)).mean() > 5e-4, (meant, switches)
        e = gs.explain(image, (V, F), SCENES[meant], CAMERA, cull="none")
        if not (e.explained and named(e.switches, switches) and e.residual_after <= 1e-5):
            missed.append((meant, switches, str(e)))
    assert not missed, missed


def test_a_scene_in_its_own_model_names_no_model() -> None:
    for meant, scene in SCENES.items():
        image = np.asarray(gs.render(V, F, scene, CAMERA, width=SIZE, height=SIZE, cull="none"))
        e = gs.explain(image, (V, F), scene, CAMERA, cull="none")
        assert e.explained and e.switches == {}, (meant, str(e))


def test_a_model_the_scene_s_own_switches_explain_is_not_named() -> None:
    """Without attenuation, spot or emission PyTorch3D's Phong is GL's with Phong's reflection:
    the GL scene's own switch is named, not another model."""
    plain = gs.Scene(
        lights=[gs.Light(position=(1, 1, 2, 0))],
        material=gs.Material(diffuse=(0.7, 0.6, 0.5), specular=(0.8, 0.8, 0.8), shininess=8),
        viewer=(0, 0, 0, 1), specular="phong",
    )  # fmt: skip
    meant = gs.Scene(lights=plain.lights, material=plain.material, viewer=plain.viewer)
    image = gs.render(V, F, plain, CAMERA, width=SIZE, height=SIZE)
    e = gs.explain(image, (V, F), meant, CAMERA)
    assert e.explained and e.switches == {"specular": "phong"}, str(e)


def test_a_model_that_cannot_hold_the_scene_is_not_a_candidate() -> None:
    """An attenuation of 1e-320 is an intensity of 1e320 in three.js, beyond its range: the
    search goes on without three.js' model, and still names glTF's."""
    faint = gs.Scene(
        lights=[gs.Light(position=(1, 1, 2, 0)),
                gs.Light(position=(-2, 1, -1, 1), constant_attenuation=0.0,
                         quadratic_attenuation=1e-320)],
        material=gs.Material(diffuse=(0.7, 0.6, 0.5), shininess=24),
    )  # fmt: skip
    world = faint.in_eye_space(np.linalg.inv(CAMERA.view))
    picture = gs.render(V, F, to_gltf(world, 1.0), CAMERA, width=64, height=64, cull="none")
    e = gs.explain(picture, (V, F), faint, CAMERA, cull="none")
    assert all(s.get("shading_model") != "threejs" for s, _ in e.candidates), str(e)
    assert e.closest.get("shading_model") == "gltf", str(e)
