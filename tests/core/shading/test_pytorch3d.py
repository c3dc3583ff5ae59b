"""`gs.presets.pytorch3d` against a float64 transcription of PyTorch3D's Phong shading, written
here from pytorch3d/renderer/lighting.py (``diffuse``, ``specular``; commit 04d318d8) and
pytorch3d/renderer/mesh/shading.py (``_apply_lighting``, ``phong_shading``,
``gouraud_shading``, ``flat_shading``; commit 17ce7d7b), with its ``F.normalize(eps=1e-6)``,
its area-weighted ``verts_normals`` and its face centroids; within 1e-12 in float64 and 1e-5
in float32 (the values reach 1.2, never clamped)."""

from __future__ import annotations

import numpy as np
import pytest

import glshade as gs

TOL = {np.float64: 1e-12, np.float32: 1e-5}


def normalize(x: np.ndarray) -> np.ndarray:
    """torch.nn.functional.normalize(x, p=2, dim=-1, eps=1e-6)."""
    return x / np.maximum(np.linalg.norm(x, axis=-1, keepdims=True), 1e-6)


def apply_lighting(p: np.ndarray, n: np.ndarray, light: dict, material: dict, camera: np.ndarray):
    """PyTorch3D's ``_apply_lighting``: ambient, diffuse and specular colours."""
    direction = light["location"] - p if "location" in light else np.broadcast_to(
        light["direction"], p.shape
    )  # fmt: skip
    n, d = normalize(n), normalize(direction)
    cos = np.sum(n * d, axis=-1)
    diffuse = light["diffuse_color"] * np.maximum(cos, 0)[:, None]
    mask = (cos > 0).astype(float)
    v = normalize(camera - p)
    r = -d + 2 * (cos[:, None] * n)
    alpha = np.maximum(np.sum(v * r, axis=-1), 0) * mask
    specular = light["specular_color"] * (alpha ** material["shininess"])[:, None]
    return (
        material["ambient_color"] * light["ambient_color"],
        material["diffuse_color"] * diffuse,
        material["specular_color"] * specular,
    )


def case(seed: int) -> tuple[dict, dict, np.ndarray]:
    rng = np.random.default_rng(seed)
    light = {
        "ambient_color": rng.uniform(0, 0.6, 3),
        "diffuse_color": rng.uniform(0, 0.6, 3),
        "specular_color": rng.uniform(0, 0.6, 3),
    }
    if seed % 2:
        light["location"] = rng.uniform(-3, 3, 3)
    else:
        light["direction"] = rng.normal(size=3)
    material = {
        "ambient_color": rng.uniform(0, 1, 3),
        "diffuse_color": rng.uniform(0, 1, 3),
        "specular_color": rng.uniform(0, 1, 3),
        "shininess": float(rng.choice([1.0, 10.0, 64.0, rng.uniform(0.5, 100)])),
    }
    return light, material, rng.uniform(-5, 5, 3)


def preset(light: dict, material: dict, camera: np.ndarray) -> gs.presets.Preset:
    return gs.presets.pytorch3d(
        location=light.get("location"), direction=light.get("direction"),
        ambient_color=light["ambient_color"], diffuse_color=light["diffuse_color"],
        specular_color=light["specular_color"],
        material_ambient_color=material["ambient_color"],
        material_diffuse_color=material["diffuse_color"],
        material_specular_color=material["specular_color"],
        shininess=material["shininess"], camera_position=camera,
    )  # fmt: skip


@pytest.mark.parametrize("dtype", [np.float64, np.float32])
@pytest.mark.parametrize("seed", range(12))
def test_phong_shading_with_texels(seed: int, dtype: type) -> None:
    light, material, camera = case(seed)
    rng = np.random.default_rng(100 + seed)
    p = rng.uniform(-2, 2, (500, 3)).astype(dtype)
    n = rng.normal(size=(500, 3)).astype(dtype)
    texels = rng.uniform(0, 1, (500, 3)).astype(dtype)
    ambient, diffuse, specular = apply_lighting(p.astype(float), n.astype(float), light,
                                                material, camera)  # fmt: skip
    want = (ambient + diffuse) * texels + specular
    got = preset(light, material, camera).shade(p, n, colors=texels)
    assert got.dtype == dtype
    np.testing.assert_allclose(got[:, :3], want, rtol=0, atol=TOL[dtype] * max(1, want.max()))
    plain = preset(light, material, camera).shade(p, n)
    np.testing.assert_allclose(plain[:, :3], ambient + diffuse + specular, rtol=0,
                               atol=TOL[dtype] * 2)  # fmt: skip


def verts_normals(v: np.ndarray, f: np.ndarray) -> np.ndarray:
    """PyTorch3D's ``Meshes.verts_normals``: per corner the cross product of its two edges
    (twice the face area times its normal), summed, normalised."""
    out = np.zeros_like(v)
    for i in range(3):
        a, b, c = v[f[:, i]], v[f[:, (i + 1) % 3]], v[f[:, (i + 2) % 3]]
        np.add.at(out, f[:, i], np.cross(b - a, c - a))
    return normalize(out)


def test_gouraud_and_flat_shading() -> None:
    light, material, camera = case(3)
    v, f = gs.meshes.torus(24, 12, 1.0, 0.4)
    model = preset(light, material, camera)
    ambient, diffuse, specular = apply_lighting(v, verts_normals(v, f), light, material, camera)
    np.testing.assert_allclose(model.shade_mesh(v, f)[:, :3], ambient + diffuse + specular,
                               rtol=0, atol=1e-12)  # fmt: skip
    centroids = v[f].mean(axis=1)
    a, b, c = (v[f[:, i]] for i in range(3))
    face_normals = normalize(np.cross(b - a, c - b))
    ambient, diffuse, specular = apply_lighting(centroids, face_normals, light, material, camera)
    np.testing.assert_allclose(model.shade_mesh(v, f, per="face")[:, :3],
                               ambient + diffuse + specular, rtol=0, atol=1e-12)  # fmt: skip


def test_defaults_are_pytorch3ds() -> None:
    model = gs.presets.pytorch3d()
    light = model.scene.lights[0]
    np.testing.assert_array_equal(light.position, [0, 1, 0, 1])
    np.testing.assert_array_equal(light.ambient[:3], [0.5] * 3)
    np.testing.assert_array_equal(light.diffuse[:3], [0.3] * 3)
    np.testing.assert_array_equal(light.specular[:3], [0.2] * 3)
    assert model.scene.material.shininess == 64
    assert model.weighting == "area" and dict(model.shade_kwargs) == {
        "normalize": True, "clamp": False,
    }  # fmt: skip


def test_bad_arguments() -> None:
    with pytest.raises(TypeError, match="exactly one of direction"):
        gs.presets.pytorch3d(direction=(0, 1, 0))
    with pytest.raises(ValueError, match="shininess must be > 0"):
        gs.presets.pytorch3d(shininess=0)
    with pytest.raises(ValueError, match="direction must be a nonzero vector"):
        gs.presets.pytorch3d(location=None, direction=(0, 0, 0))
