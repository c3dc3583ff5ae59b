"""The metallic-roughness model against its transcription (`support.gltf_reference`, pyrender's
mesh.frag in extended precision), unclamped and clamped, on random scenes with roughness and
metallic at 0, 1 and between, grazing angles, vertex colours and every light kind; finite where
a light sits on the vertex.

The bounds: float64, and float32 with exact accuracy (computed in float64, rounded once),
within 1e-12 relative to max(1, |value|) plus half an ulp of the result; float32 with fast
accuracy (float32 arithmetic) within the Accuracy page's bound (`fast_bound`), which grows at
grazing angles, where |n·v| ≈ 10⁻³ is known only to 6·10⁻⁸ / 10⁻³, and at the highlight of
roughness 0.04, where 1 - (n·h)² meets alpha² = 2.6·10⁻⁶.
"""

from __future__ import annotations

import re

import numpy as np
import pytest

import glshade as gs
from support.gltf_reference import fast_bound, mesh_frag, random_scene

TOL = 1e-12
SEEDS = 60
VERTICES = 400


def vertices(rng: np.random.Generator, scene: gs.gltf.Scene, k: int) -> tuple[np.ndarray, ...]:
    """Positions in [-2, 2]³ and normals: random, and a quarter at grazing angles to the view
    (n ⟂ v up to 1e-3)."""
    p = rng.uniform(-2, 2, (k, 3))
    n = rng.normal(size=(k, 3))
    v = scene.camera_position - p[: k // 4]
    tangent = np.cross(v, rng.normal(size=(k // 4, 3)))
    n[: k // 4] = tangent / np.linalg.norm(tangent, axis=1, keepdims=True)
    n[: k // 4] += 1e-3 * rng.normal(size=(k // 4, 3))
    return p, n


def error(got: np.ndarray, want: np.ndarray) -> float:
    """The largest error relative to max(1, |want|), less half an ulp of `got`'s dtype (the
    result's own rounding)."""
    excess = np.abs(got.astype(np.longdouble) - want)
    rounding = np.abs(want) * float(np.finfo(got.dtype).epsneg)
    return float(np.max((excess - rounding) / np.maximum(1, np.abs(want))))


def assert_within_fast_bound(got: np.ndarray, want: np.ndarray, bound: np.ndarray) -> None:
    """float32 fast mode's colours (RGB) within `fast_bound`; alpha within its two roundings
    (the factor's to float32 and the product's)."""
    excess = np.abs(got.astype(np.longdouble) - want)
    over = excess[:, :3] / bound
    worst = np.unravel_index(np.argmax(over), over.shape)
    assert over.max() <= 1, f"{float(over.max()):.3g} of the bound at {worst}"
    assert (excess[:, 3] <= np.abs(want[:, 3]) * 2.0**-23).all()


@pytest.mark.parametrize("dtype", [np.float64, np.float32])
@pytest.mark.parametrize("seed", range(SEEDS))
def test_agrees_with_mesh_frag(seed: int, dtype: type) -> None:
    rng = np.random.default_rng(seed)
    scene = random_scene(rng, lights=int(rng.integers(1, 5)))
    p, n = (a.astype(dtype) for a in vertices(rng, scene, VERTICES))
    colors = rng.uniform(0, 1, (VERTICES, 4)).astype(dtype) if seed % 3 == 0 else None
    want = mesh_frag(p, n, scene, colors)
    exact = gs.shade(p, n, scene, colors=colors, clamp=False, accuracy="exact")
    assert exact.dtype == dtype
    assert error(exact, want) <= TOL, scene
    clamped = gs.shade(p, n, scene, colors=colors, accuracy="exact")
    assert error(clamped, np.clip(want, 0, 1)) <= TOL, scene
    got = gs.shade(p, n, scene, colors=colors, clamp=False)
    if dtype == np.float64:
        np.testing.assert_array_equal(got, exact)
        return
    bound = fast_bound(p, n, scene, colors)
    assert_within_fast_bound(got, want, bound)
    assert_within_fast_bound(gs.shade(p, n, scene, colors=colors), np.clip(want, 0, 1), bound)


@pytest.mark.parametrize("dtype", [np.float64, np.float32])
def test_smooth_highlights_at_the_least_roughness(dtype: type) -> None:
    """Roughness 0 (0.04 in use) near the mirror direction, where D = a²/(π·den²) peaks at
    1/(π a²) ≈ 1.2·10⁵ (3.1 after F·G/4 and the intensity) and 1 - (n·h)² cancels."""
    rng = np.random.default_rng(7)
    light = gs.gltf.DirectionalLight(intensity=1e-4, direction=(0, 0, -1))
    scene = gs.gltf.Scene(
        [light], gs.gltf.Material(metallic=1.0, roughness=0.0), camera_position=(0, 0, 1e3)
    )
    p = rng.uniform(-1, 1, (2000, 3)) * 1e-2
    n = np.array([0, 0, 1.0]) + rng.normal(size=(2000, 3)) * np.logspace(-8, -1, 2000)[:, None]
    p, n = p.astype(dtype), n.astype(dtype)
    want = mesh_frag(p, n, scene)
    assert want[:, 0].max() > 3, "the highlight's peak is sampled"
    assert error(gs.shade(p, n, scene, clamp=False, accuracy="exact"), want) <= TOL
    fast = gs.shade(p, n, scene, clamp=False)
    if dtype == np.float32:
        assert_within_fast_bound(fast, want, fast_bound(p, n, scene))
    else:
        assert error(fast, want) <= TOL


@pytest.mark.parametrize("dtype", [np.float64, np.float32])
@pytest.mark.parametrize("kind", ["point", "spot"])
def test_a_light_at_the_vertex_is_finite(kind: str, dtype: type) -> None:
    """Its direction is taken as zero: a point light's 1/d² saturates (white once clamped); a
    spot's cone factor is 0 there (no direction lies inside the cone)."""
    at = (0.25, -0.5, 1.0)
    light = (
        gs.gltf.PointLight(intensity=10.0, position=at)
        if kind == "point"
        else gs.gltf.SpotLight(intensity=10.0, position=at, direction=(0, 0, 1))
    )
    scene = gs.gltf.Scene([light], gs.gltf.Material(metallic=0.0), camera_position=(0, 0, 5))
    p = np.array([at, at, (0.25, -0.5, 1.0 + 1e-30)], dtype)
    n = np.array([(0, 0, 1), (1, 0, 0), (0, 0, 1)], dtype)
    for clamp in (True, False):
        c = gs.shade(p, n, scene, clamp=clamp)
        assert np.isfinite(c).all(), c
    lit = gs.shade(p, n, scene)[:, :3]
    if kind == "point":
        assert (lit == 1).all(), "saturated, then clamped to 1"
    else:
        assert (lit[:2] == 0).all(), "outside the cone"


def test_clamp_false_keeps_values_above_one() -> None:
    light = gs.gltf.DirectionalLight(intensity=20.0, direction=(0, 0, -1))
    scene = gs.gltf.Scene([light], gs.gltf.Material(metallic=0.0), camera_position=(0, 0, 5))
    p = np.zeros((3, 3))
    n = np.array([(0, 0, 1), (0, 0.6, 0.8), (0, 0.999, 0.0447)])
    hdr = gs.shade(p, n, scene, clamp=False)
    assert hdr[0, 0] > 1
    clamped = gs.shade(p, n, scene)
    inside = (hdr > 0) & (hdr < 1)
    assert inside.any()
    np.testing.assert_array_equal(clamped[inside], hdr[inside])
    np.testing.assert_array_equal(clamped, np.clip(hdr, 0, 1))


def test_non_finite_inputs_give_nan_rows_only() -> None:
    rng = np.random.default_rng(3)
    scene = random_scene(rng)
    p, n = vertices(rng, scene, 64)
    p[3, 1] = np.nan
    n[5, 2] = np.inf
    got = gs.shade(p, n, scene)
    bad = np.zeros(64, bool)
    bad[[3, 5]] = True
    assert np.isnan(got[bad]).all()
    assert np.isfinite(got[~bad]).all()


def test_exact_rounds_the_float64_result_once() -> None:
    rng = np.random.default_rng(11)
    scene = random_scene(rng)
    p, n = (a.astype(np.float32) for a in vertices(rng, scene, 256))
    exact = gs.shade(p, n, scene, accuracy="exact")
    assert exact.dtype == np.float32
    np.testing.assert_array_equal(
        exact, gs.shade(p.astype(float), n.astype(float), scene).astype(np.float32)
    )
    out = np.empty_like(exact)
    assert gs.shade(p, n, scene, accuracy="exact", out=out) is out
    np.testing.assert_array_equal(out, exact)


def test_plan_names_the_terms_that_run() -> None:
    lights = [
        gs.gltf.DirectionalLight(direction=(0, 0, -1)),
        gs.gltf.PointLight(intensity=0.0),
        gs.gltf.SpotLight(position=(0, 0, 3)),
    ]
    metal = gs.gltf.Scene(lights, gs.gltf.Material(metallic=1.0))
    line = metal.plan()
    assert "light 0 directional (l constant): specular" in line
    assert "light 1" not in line, "a light of zero intensity is skipped"
    assert "light 2 spot (l, 1/d², cone): specular" in line
    assert "ambient" not in line
    plastic = gs.gltf.Scene(lights[:1], gs.gltf.Material(metallic=0.5), ambient_light=(0.1,) * 3)
    assert "diffuse+specular" in plastic.plan("float64")
    assert "fast, float32 arithmetic, " in plastic.plan("float32")
    assert "exact, float64 arithmetic (float32 arrays widened)" in plastic.plan(
        "float32", accuracy="exact"
    )
    assert plastic.plan().endswith("; ambient and emission")
    dark = gs.gltf.Scene([], gs.gltf.Material(emissive=(0.5, 0, 0)))
    assert "reads normals only" in dark.plan()


def test_a_skipped_term_changes_no_bit() -> None:
    """A light of zero intensity, a black ambient light and a metallic material's missing
    diffuse part leave the same bits as the scene without them."""
    rng = np.random.default_rng(5)
    scene = random_scene(rng)
    m = scene.material
    metal = gs.gltf.Material(m.base_color, 1.0, m.roughness, m.emissive)
    plain = gs.gltf.Scene(scene.lights, metal, camera_position=scene.camera_position)
    padded = gs.gltf.Scene(
        [*scene.lights, gs.gltf.PointLight(intensity=0.0)],
        metal,
        ambient_light=(0, 0, 0),
        camera_position=scene.camera_position,
    )
    p, n = vertices(rng, scene, 300)
    np.testing.assert_array_equal(gs.shade(p, n, plain), gs.shade(p, n, padded))


@pytest.mark.parametrize(
    ("make", "message"),
    [
        (lambda: gs.gltf.Material(metallic=1.5), "metallic must be in [0, 1], got 1.5"),
        (lambda: gs.gltf.Material(base_color=(1, 0, 0, 2)), "base_color must be in [0, 1]"),
        (lambda: gs.gltf.Material(emissive=(-1, 0, 0)), "emissive must be finite and >= 0"),
        (lambda: gs.gltf.PointLight(intensity=-1), "intensity of light 0 must be finite"),
        (lambda: gs.gltf.DirectionalLight(direction=(0, 0, 0)), "direction of light 0 must be"),
        (
            lambda: gs.gltf.SpotLight(inner_cone_angle=1.0, outer_cone_angle=0.5),
            "0 <= inner_cone_angle <= outer_cone_angle <= pi/2",
        ),
        (lambda: gs.gltf.Scene(ambient_light=(-1, 0, 0)), "ambient_light must be finite"),
        (lambda: gs.gltf.Scene(camera_position=(np.nan, 0, 0)), "camera_position must be"),
        (lambda: gs.gltf.Material(base_color=(1, 0)), "base_color must have shape (3,) or (4,)"),
    ],
)
def test_bad_values_name_themselves(make: object, message: str) -> None:
    with pytest.raises(ValueError, match=re.escape(message)):
        make()  # type: ignore[operator]


def test_gl_options_are_refused() -> None:
    scene = gs.gltf.Scene([gs.gltf.DirectionalLight()])
    with pytest.raises(TypeError, match="normalize applies to the GL model"):
        gs.shade(np.zeros((1, 3)), (0, 0, 1), scene, normalize=True)
    with pytest.raises(TypeError, match="modelview applies to the GL model"):
        gs.shade(np.zeros((1, 3)), (0, 0, 1), scene, modelview=np.eye(4))
    with pytest.raises(TypeError, match=r"lights\[0\] must be a glshade\.gltf"):
        gs.gltf.Scene([gs.Light()])  # type: ignore[list-item]


def test_scenes_compare_and_pickle() -> None:
    import pickle

    rng = np.random.default_rng(2)
    scene = random_scene(rng)
    again = pickle.loads(pickle.dumps(scene))
    assert again == scene
    assert scene.with_camera((1, 2, 3)) != scene
    p, n = vertices(rng, scene, 50)
    np.testing.assert_array_equal(gs.shade(p, n, again), gs.shade(p, n, scene))


@pytest.mark.parametrize("shading", ["phong", "gouraud", "flat"])
def test_render_clamp_false_keeps_values_above_one(shading: str) -> None:
    scene = gs.gltf.Scene(
        [gs.gltf.DirectionalLight(intensity=30.0, direction=(-1, -1, -1))],
        gs.gltf.Material((0.9, 0.8, 0.7, 1.0), 0.2, 0.3),
    )
    mesh = gs.meshes.torus(32, 16, 1.0, 0.4)
    hdr = gs.render(mesh, scene, width=48, height=40, shading=shading, clamp=False)
    clamped = gs.render(mesh, scene, width=48, height=40, shading=shading)
    assert hdr[..., :3].max() > 1.5
    if shading == "gouraud":
        # GL clamps the vertex colours before interpolating them: a pixel between a vertex
        # above 1 and one below differs; at the vertices it is `shade`'s rule (tested above).
        assert (clamped <= 1).all() and (hdr >= clamped - 1e-15).all()
        return
    inside = (hdr > 0) & (hdr < 1)
    assert inside[..., :3].sum() > 100
    np.testing.assert_allclose(clamped[inside], hdr[inside], rtol=0, atol=1e-15)
    np.testing.assert_allclose(clamped, np.clip(hdr, 0, 1), rtol=0, atol=1e-15)
