"""`render` of a pyrender scene against stock pyrender (its own glTF metallic-roughness shader,
Mesa llvmpipe through EGL), on the interior pixels of `support.pyrender_rays`: where a pixel's
centre and its four MSAA samples all hit one face, pyrender's resolved colour is its
fragment's at the centre, so the two images must agree there within pyrender's 8-bit rounding
(0.5/255) and float32's rounding through the final gamma.

Scenes: a metallic/roughness sweep from 0 to 1, vertex colours (trimesh's, through pyrender's
own ``Mesh.from_trimesh``), emission, each light kind alone, three lights with an ambient light;
every material double-sided, so the inside of the cut meshes is drawn (and lit through |n·v|).
A light 2% too bright must fail the comparison.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest
from conftest import require

import glshade as gs
from support import glpeers  # first: it sets PYOPENGL_PLATFORM=egl before OpenGL is imported
from support.pyrender_rays import (
    HEIGHT,
    ROUNDING,
    WIDTH,
    YFOV,
    ZFAR,
    ZNEAR,
    interior,
    interior_of,
    mesh,
)  # fmt: skip

pytestmark = pytest.mark.gl

trimesh = require("trimesh")
pyrender = require("pyrender")

# float32 arithmetic in llvmpipe and its pow(c, 1/2.2), on the 8-bit scale's units.
FLOAT32 = 2e-5
SEEDS = (0, 1, 2)


@pytest.fixture
def renderer() -> Any:
    return glpeers.pyrender_renderer(WIDTH, HEIGHT)


def pose(position: tuple[float, float, float], target: tuple[float, float, float]) -> np.ndarray:
    """A node pose at `position` whose -z axis points at `target` (a light's direction)."""
    forward = np.subtract(target, position)
    forward = forward / np.linalg.norm(forward)
    up = (0.0, 1.0, 0.0) if abs(forward[1]) < 0.9 else (1.0, 0.0, 0.0)
    right = np.cross(forward, up)
    right /= np.linalg.norm(right)
    result = np.eye(4)
    result[:3, 0], result[:3, 1], result[:3, 2] = right, np.cross(right, forward), -forward
    result[:3, 3] = position
    return result


CENTRE = (0.0, 0.0, -3.5)


def light(kind: str, intensity_scale: float = 1.0) -> tuple[Any, np.ndarray]:
    """One light of `kind`, lighting the mesh around CENTRE from the upper left."""
    if kind == "directional":
        return pyrender.DirectionalLight(
            color=(1.0, 0.95, 0.9), intensity=3.0 * intensity_scale
        ), pose((0, 0, 0), (-1.0, -1.5, -3.0))
    if kind == "point":
        return pyrender.PointLight(color=(0.6, 0.8, 1.0), intensity=12.0 * intensity_scale), pose(
            (1.5, 1.2, -1.0), CENTRE
        )
    return pyrender.SpotLight(
        color=(1.0, 0.7, 0.5), intensity=25.0 * intensity_scale, innerConeAngle=0.15,
        outerConeAngle=0.45,
    ), pose((-1.0, 0.8, -0.5), (0.2, -0.2, -3.5))  # fmt: skip


def material(**factors: Any) -> Any:
    return pyrender.MetallicRoughnessMaterial(alphaMode="OPAQUE", doubleSided=True, **factors)


def scene_of(
    seed: int,
    lights: list[str],
    mat: Any = None,
    *,
    colored: bool = False,
    ambient: tuple[float, float, float] = (0.0, 0.0, 0.0),
    intensity_scale: float = 1.0,
) -> Any:
    """mesh(seed) seen from the identity pose (the rays' camera), with `lights`."""
    scene = pyrender.Scene(bg_color=(0, 0, 0, 0), ambient_light=ambient)
    m = mesh(seed)
    if colored:
        rng = np.random.default_rng(seed)
        colors = rng.integers(40, 256, (len(m.vertices), 4), dtype=np.uint8)
        colors[:, 3] = 255
        m = trimesh.Trimesh(
            m.vertices, m.faces, vertex_normals=m.vertex_normals, vertex_colors=colors,
            process=False,
        )  # fmt: skip
        node = pyrender.Mesh.from_trimesh(m, smooth=True)
        node.primitives[0].material.doubleSided = True
    else:
        node = pyrender.Mesh.from_trimesh(m, material=mat, smooth=True)
    scene.add(node)
    scene.add(pyrender.PerspectiveCamera(yfov=YFOV, znear=ZNEAR, zfar=ZFAR), pose=np.eye(4))
    for kind in lights:
        made, where = light(kind, intensity_scale)
        scene.add(made, pose=where)
    return scene


def worst(renderer: Any, scene: Any, seed: int, ours_scene: Any = None) -> tuple[float, int]:
    """The largest difference on the interior pixels, in 1/255, and how many were compared."""
    theirs = np.asarray(renderer.render(scene)[0], dtype=np.float64) / 255
    ours = gs.render(scene if ours_scene is None else ours_scene, width=WIDTH, height=HEIGHT)
    _, inside = interior(seed)
    lit = theirs[inside].max(axis=1) > 0.1
    assert lit.sum() > 300, f"only {lit.sum()} interior pixels are lit"
    difference = np.abs(ours[..., :3] - theirs)[inside]
    return float(difference.max() * 255), int(inside.sum())


SWEEP = [(0.0, 0.0), (0.0, 1.0), (1.0, 0.0), (1.0, 1.0), (0.5, 0.5), (0.2, 0.8)]


@pytest.mark.parametrize(("metallic", "roughness"), SWEEP)
def test_metallic_roughness_sweep(renderer: Any, metallic: float, roughness: float) -> None:
    seed = SWEEP.index((metallic, roughness)) % 3
    mat = material(
        baseColorFactor=(0.85, 0.45, 0.25, 1.0), metallicFactor=metallic, roughnessFactor=roughness
    )
    scene = scene_of(seed, ["directional", "point", "spot"], mat, ambient=(0.03, 0.03, 0.03))
    error, compared = worst(renderer, scene, seed)
    assert compared > 2000
    assert error <= (ROUNDING + FLOAT32) * 255, error


@pytest.mark.parametrize("kind", ["directional", "point", "spot"])
def test_each_light_kind(renderer: Any, kind: str) -> None:
    seed = ["directional", "point", "spot"].index(kind)
    mat = material(baseColorFactor=(0.7, 0.7, 0.75, 1.0), metallicFactor=0.1, roughnessFactor=0.4)
    error, _ = worst(renderer, scene_of(seed, [kind], mat), seed)
    assert error <= (ROUNDING + FLOAT32) * 255, error


def test_vertex_colors(renderer: Any) -> None:
    error, _ = worst(renderer, scene_of(1, ["directional", "spot"], colored=True), 1)
    assert error <= (ROUNDING + FLOAT32) * 255, error


def test_emission(renderer: Any) -> None:
    mat = material(
        baseColorFactor=(0.3, 0.5, 0.3, 1.0), metallicFactor=0.0, roughnessFactor=0.6,
        emissiveFactor=(0.4, 0.1, 0.25),
    )  # fmt: skip
    error, _ = worst(renderer, scene_of(2, ["point"], mat), 2)
    assert error <= (ROUNDING + FLOAT32) * 255, error


def test_three_lights_and_ambient(renderer: Any) -> None:
    mat = material(baseColorFactor=(0.9, 0.8, 0.6, 1.0), metallicFactor=0.6, roughnessFactor=0.3)
    scene = scene_of(0, ["directional", "point", "spot"], mat, ambient=(0.08, 0.1, 0.12))
    error, _ = worst(renderer, scene, 0)
    assert error <= (ROUNDING + FLOAT32) * 255, error


def test_a_light_two_percent_off_fails(renderer: Any) -> None:
    """The same comparison sees a 2% error in one light's intensity."""
    mat = material(baseColorFactor=(0.9, 0.8, 0.6, 1.0), metallicFactor=0.6, roughnessFactor=0.3)
    scene = scene_of(0, ["directional", "point", "spot"], mat, ambient=(0.08, 0.1, 0.12))
    off = scene_of(0, ["directional", "point", "spot"], mat, ambient=(0.08, 0.1, 0.12))
    for node in off.light_nodes:
        if isinstance(node.light, pyrender.PointLight):
            node.light.intensity *= 1.02
    error, _ = worst(renderer, scene, 0, ours_scene=off)
    assert error > (ROUNDING + FLOAT32) * 255, error


def test_many_meshes_in_one_frame(renderer: Any) -> None:
    """Meshes that hide one another, each with its material and pose, one of them instanced
    (a primitive with poses) and single-sided: every draw in one depth-tested frame as
    pyrender draws them."""
    rng = np.random.default_rng(7)
    scene = pyrender.Scene(bg_color=(0, 0, 0, 0), ambient_light=(0.04, 0.05, 0.06))
    world = []
    cut = mesh(0)
    scene.add(pyrender.Mesh.from_trimesh(cut, material=material(
        baseColorFactor=(0.8, 0.5, 0.3, 1.0), metallicFactor=0.7, roughnessFactor=0.35
    ), smooth=True))  # fmt: skip
    world.append(cut)
    ball = trimesh.creation.icosphere(subdivisions=3, radius=0.35)
    poses = np.tile(np.eye(4), (2, 1, 1))
    poses[:, :3, 3] = (-0.45, 0.3, 0.9), (0.5, -0.25, 0.6)
    single = pyrender.MetallicRoughnessMaterial(
        alphaMode="OPAQUE", baseColorFactor=(0.3, 0.6, 0.9, 1.0), metallicFactor=0.1,
        roughnessFactor=0.6,
    )  # fmt: skip
    node_pose = np.eye(4)
    node_pose[:3, :3] = trimesh.transformations.rotation_matrix(0.4, (0, 1, 0))[:3, :3]
    node_pose[:3, 3] = CENTRE
    scene.add(pyrender.Mesh.from_trimesh(ball, material=single, poses=poses), pose=node_pose)
    world += [ball.copy().apply_transform(node_pose @ p) for p in poses]
    box = trimesh.creation.box((0.5, 0.5, 0.5))
    box_pose = trimesh.transformations.random_rotation_matrix(rng.random(3))
    box_pose[:3, 3] = (0.35, 0.35, -3.0)
    scene.add(pyrender.Mesh.from_trimesh(box, material=material(
        baseColorFactor=(0.9, 0.9, 0.4, 1.0), metallicFactor=0.0, roughnessFactor=0.8
    )), pose=box_pose)  # fmt: skip
    world.append(box.copy().apply_transform(box_pose))
    scene.add(pyrender.PerspectiveCamera(yfov=YFOV, znear=ZNEAR, zfar=ZFAR), pose=np.eye(4))
    for kind in ("directional", "point", "spot"):
        made, where = light(kind)
        scene.add(made, pose=where)
    assert sum(len(n.mesh.primitives) for n in scene.mesh_nodes) == 3

    theirs = np.asarray(renderer.render(scene)[0], dtype=np.float64) / 255
    ours = gs.render(scene, width=WIDTH, height=HEIGHT)
    projection = scene.main_camera_node.camera.get_projection_matrix(WIDTH, HEIGHT)
    hits, inside = interior_of(trimesh.util.concatenate(world), projection)
    faces = np.cumsum([0] + [len(m.faces) for m in world])
    seen = {int(np.searchsorted(faces, f, side="right")) - 1 for f in hits.face[inside]}
    assert seen == {0, 1, 2, 3}, f"every mesh and instance shows: {seen}"
    lit = theirs[inside].max(axis=1) > 0.1
    assert lit.sum() > 2000
    error = float(np.abs(ours[..., :3] - theirs)[inside].max())
    assert error <= ROUNDING + FLOAT32, error * 255


GREY = (0.1, 0.1, 0.1)


@pytest.mark.parametrize("seed", SEEDS)
def test_compare_reads_pyrenders_opaque_background_and_depth(renderer: Any, seed: int) -> None:
    """pyrender's picture over an opaque background, given to `compare` with that background,
    is labelled exactly as its transparent picture is (silhouettes are edges, no coverage
    difference off them), within the 8-bit default tolerance; its depth, eye distances with 0
    where nothing is drawn, compares with render's window depth once its convention is named,
    and is refused, naming the convention, when it is not."""
    scene = scene_of(seed, ["directional", "point"], ambient=(0.05, 0.05, 0.05))
    rgba, their_depth = renderer.render(scene, flags=pyrender.RenderFlags.RGBA)
    ours, depth = gs.render(scene, width=WIDTH, height=HEIGHT, depth=True)
    transparent = gs.compare(ours, rgba)
    assert transparent.tolerance == pytest.approx(0.5 / 255 + 1e-4, rel=1e-12)
    scene.bg_color = np.array((*GREY, 1.0))
    rgb, _ = renderer.render(scene)
    assert rgb.shape == (HEIGHT, WIDTH, 3) and (rgb[0, 0] == 26).all()
    opaque_ours = gs.render(scene, width=WIDTH, height=HEIGHT)
    assert (opaque_ours[..., 3] == 1).all()
    opaque = gs.compare(opaque_ours, rgb, background=GREY)
    np.testing.assert_array_equal(opaque.labels, transparent.labels)
    assert opaque.counts["coverage, edge"] > 100 and opaque.counts["coverage, interior"] == 0
    unnamed = gs.compare(opaque_ours, rgb)  # the background not given: said what to pass
    assert any("pass background=(0.1, 0.1, 0.1)" in note for note in unnamed.notes)
    assert any("pass background=(0.102, 0.102, 0.102)" in note for note in unnamed.notes)

    linear = {"reference_depth_convention": "linear", "near": ZNEAR, "far": ZFAR}
    result = gs.compare(ours, rgba, depth=depth, reference_depth=their_depth, **linear)
    assert result.counts["depth, interior"] == 0 and result.counts["coverage, interior"] == 0
    assert result.counts["color, interior"] <= transparent.counts["color, interior"]
    # Coverage from depth (pyrender reads one sample of four) is a little less than alpha's.
    assert result.compared >= 0.9 * transparent.compared > 0.05 * WIDTH * HEIGHT
    with pytest.raises(ValueError, match="reference_depth_convention='linear' with near="):
        gs.compare(ours, rgba, depth=depth, reference_depth=their_depth)


@pytest.mark.parametrize("seed", SEEDS[:2])
def test_explain_does_not_take_a_metallic_roughness_picture_for_gl(
    renderer: Any, seed: int
) -> None:
    """pyrender's metallic-roughness picture, given a GL scene of the same lights, camera and
    colours that no conversion makes pyrender's exactly (the lights' intensities left out,
    shininess 20 for roughness 0.5, the fill attenuated as 1/(1 + d²)): GL's switches do not
    explain it; the closest render is glTF's model, and that explains it (with a light scale
    that averages the two lights') or nothing does."""
    mat = material(baseColorFactor=(0.8, 0.6, 0.4, 1.0), metallicFactor=0.0, roughnessFactor=0.5)
    scene = scene_of(seed, ["directional", "point"], mat, ambient=(0.05, 0.05, 0.05))
    rgb, _ = renderer.render(scene)
    (_, key_pose), (_, fill_pose) = light("directional"), light("point")
    gl = gs.Scene(
        lights=[
            gs.Light(position=(*key_pose[:3, 2], 0), diffuse=(1, 0.95, 0.9),
                     specular=(1, 0.95, 0.9)),
            gs.Light(position=(*fill_pose[:3, 3], 1), diffuse=(0.6, 0.8, 1.0),
                     specular=(0.6, 0.8, 1.0), quadratic_attenuation=1.0),
        ],
        material=gs.Material(diffuse=(0.8, 0.6, 0.4), specular=(0.5, 0.5, 0.5), shininess=20),
        global_ambient=(0.05, 0.05, 0.05, 1), viewer=(0, 0, 0, 1),
    )  # fmt: skip
    projection = pyrender.PerspectiveCamera(yfov=YFOV, znear=ZNEAR, zfar=ZFAR)
    camera = gs.Camera(np.eye(4), projection.get_projection_matrix(WIDTH, HEIGHT))
    m = mesh(seed)
    e = gs.explain(rgb, (m.vertices, m.faces), gl, camera)
    assert e.residual_after < 0.5 * e.residual_before  # the search came nearer
    assert e.closest["shading_model"] == "gltf", str(e)
    if e.explained:
        assert e.switches == e.closest, str(e)
    else:
        assert e.switches == {} and str(e).startswith("nothing explains it"), str(e)
    # GL's own switches, the model held, come nowhere near the picture's rounding.
    gl_only = [r for s, r in e.candidates if s.get("shading_model", "gl") == "gl"]
    assert all(r > 2 * e.noise for r in gl_only), str(e)


@pytest.mark.parametrize("seed", SEEDS[:2])
def test_explain_names_pyrenders_model(renderer: Any, seed: int) -> None:
    """pyrender's metallic-roughness picture, given the GL scene a user would write for it (the
    lights' colour times intensity, the fill falling off as 1/d², shininess 30, which trimesh's
    and pyrender's rule (2/(s + 2))^(1/4) makes roughness 0.5): `explain` names glTF's model and
    pyrender's gamma 2.2, within the 8-bit picture's rounding away from the silhouettes."""
    mat = material(baseColorFactor=(0.8, 0.6, 0.4, 1.0), metallicFactor=0.0, roughnessFactor=0.5)
    scene = scene_of(seed, ["directional", "point"], mat, ambient=(0.05, 0.05, 0.05))
    rgb, _ = renderer.render(scene)
    (key, key_pose), (fill, fill_pose) = light("directional"), light("point")
    key_rgb, fill_rgb = key.color * key.intensity, fill.color * fill.intensity
    gl = gs.Scene(
        lights=[
            gs.Light(position=(*key_pose[:3, 2], 0), diffuse=key_rgb, specular=key_rgb),
            gs.Light(position=(*fill_pose[:3, 3], 1), diffuse=fill_rgb, specular=fill_rgb,
                     constant_attenuation=0.0, quadratic_attenuation=1.0),
        ],
        material=gs.Material(diffuse=(0.8, 0.6, 0.4), specular=(0.5, 0.5, 0.5), shininess=30),
        global_ambient=(0.05, 0.05, 0.05, 1), viewer=(0, 0, 0, 1),
    )  # fmt: skip
    projection = pyrender.PerspectiveCamera(yfov=YFOV, znear=ZNEAR, zfar=ZFAR)
    camera = gs.Camera(np.eye(4), projection.get_projection_matrix(WIDTH, HEIGHT))
    m = mesh(seed)
    e = gs.explain(rgb, (m.vertices, m.faces), gl, camera)
    assert e.explained, str(e)
    assert e.switches == {"shading_model": "gltf", "transfer": "gamma2.2"}, str(e)
