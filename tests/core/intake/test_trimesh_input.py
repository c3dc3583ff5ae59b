"""trimesh as it comes: uint8 colours scaled to [0, 1], a mesh's own vertex and face colours in
render, faces optional for a mesh, a trimesh.Scene flattened by its graph."""

from __future__ import annotations

import numpy as np
import pytest
from conftest import require

import glshade as gs

trimesh = require("trimesh")

SCENE = gs.Scene(lights=[gs.Light(position=(0.3, 0.4, 1, 0))])
CAMERA = gs.Camera.look_at((0.4, 0.6, 3.0), fovy=40)


def test_uint8_colours_are_scaled_to_unit_range_in_shade() -> None:
    rng = np.random.default_rng(0)
    p, n = rng.normal(size=(2, 50, 3))
    c8 = rng.integers(0, 256, (50, 4), dtype=np.uint8)
    got = gs.shade(p, n, SCENE, colors=c8)
    np.testing.assert_array_equal(got, gs.shade(p, n, SCENE, colors=c8 / 255.0))
    assert not (got == 1).all()  # before: every vertex (1, 1, 1, 1)
    # Other dtypes are the values themselves, and warn when they look like bytes.
    with pytest.warns(gs.ColorRangeWarning, match="shade colors .* looks like 0-255"):
        wide = gs.shade(p, n, SCENE, colors=c8.astype(np.int64))
    with pytest.warns(gs.ColorRangeWarning, match="shade colors .* looks like 0-255"):
        floats = gs.shade(p, n, SCENE, colors=c8.astype(np.float64))
    np.testing.assert_array_equal(wide, floats)


def test_render_takes_the_meshs_vertex_colours_and_faces_are_optional() -> None:
    mesh = trimesh.creation.icosphere(subdivisions=2)
    rng = np.random.default_rng(1)
    mesh.visual.vertex_colors = rng.integers(0, 256, (len(mesh.vertices), 4), dtype=np.uint8)
    own = gs.render(mesh, SCENE, CAMERA, width=48, height=40)
    given = gs.render(mesh.vertices, mesh.faces, SCENE, CAMERA, width=48, height=40,
                      colors=mesh.visual.vertex_colors / 255.0)  # fmt: skip
    np.testing.assert_array_equal(own, given)
    keyword = gs.render(mesh, scene=SCENE, camera=CAMERA, width=48, height=40)
    np.testing.assert_array_equal(own, keyword)
    plain = gs.render(mesh, SCENE, CAMERA, width=48, height=40, colors=False)
    np.testing.assert_array_equal(plain, gs.render(mesh.vertices, mesh.faces, SCENE, CAMERA,
                                                   width=48, height=40))  # fmt: skip
    assert not np.array_equal(own, plain)


@pytest.mark.parametrize("shading", ["flat", "gouraud", "phong"])
def test_face_colours_colour_their_faces(shading: str) -> None:
    """A face's uint8 colour: the pixels it covers are that colour times the lighting of a
    grey render (diffuse and ambient both track the colour; no specular, nothing clamped)."""
    mesh = trimesh.creation.box()
    colours = np.random.default_rng(2).integers(30, 200, (len(mesh.faces), 4), dtype=np.uint8)
    colours[:, 3] = 255
    mesh.visual.face_colors = colours
    image = gs.render(mesh, SCENE, CAMERA, width=64, height=64, shading=shading)  # type: ignore[arg-type]
    grey = gs.render(mesh, SCENE, CAMERA, width=64, height=64, shading=shading,  # type: ignore[arg-type]
                     colors=np.full((len(mesh.vertices), 4), 0.5))  # fmt: skip
    # Every covered pixel is one of the face colours times the grey render's / 0.5.
    covered = grey[..., 3] > 0
    ratio = 0.5 * image[covered][:, :3] / np.maximum(grey[covered][:, :3], 1e-9)
    distance = np.abs(ratio[:, None, :] - colours[None, :, :3] / 255.0).max(axis=2).min(axis=1)
    assert covered.sum() > 500 and distance.max() < 1e-5


def test_a_trimesh_scene_is_flattened_with_its_transforms() -> None:
    a = trimesh.creation.icosphere(subdivisions=2)
    b = trimesh.creation.box()
    move = trimesh.transformations.translation_matrix((1.5, 0, 0))
    scene = trimesh.Scene()
    scene.add_geometry(a)
    scene.add_geometry(b, transform=move)
    flat = trimesh.util.concatenate([a, b.copy().apply_transform(move)])
    got = gs.render(scene, SCENE, CAMERA, width=64, height=48, colors=False)
    expected = gs.render(flat.vertices, flat.faces, SCENE, CAMERA, width=64, height=48)
    np.testing.assert_allclose(got, expected, atol=1e-12)
    normals = gs.vertex_normals(scene)
    assert normals.shape == (len(flat.vertices), 3)
    with pytest.raises(ValueError, match=r"the trimesh\.Scene holds no geometry"):
        gs.render(trimesh.Scene(), SCENE, CAMERA)


def test_colour_rows_must_match_the_mesh() -> None:
    mesh = trimesh.creation.box()
    with pytest.raises(ValueError, match=r"colors must have one row per vertex \(8\)"):
        gs.render(mesh, SCENE, CAMERA, width=8, height=8, colors=np.ones((5, 4)))
    with pytest.raises(TypeError, match="faces is required unless the first argument is a mesh"):
        gs.render(np.zeros((3, 3)), SCENE, CAMERA)
