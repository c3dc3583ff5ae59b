"""The native scene objects: lights, materials, scenes, presets, images and cameras pickle (also
out of band, from misaligned buffers) and deepcopy to equal objects; equality is by value,
lights index as sequences, parameters are read-only, defaults are GL's."""

from __future__ import annotations

import copy
import inspect
import pickle
from typing import Any

import numpy as np
import pytest

import glshade as gs
from support.boundary import MIXED, TWO_SIDED, misaligned, rows

_LIGHTS = np.random.default_rng(13)  # its own seed: the objects do not depend on test order
OBJECTS = [
    gs.Light(position=(1, 2, 3, 1), spot_cutoff=30, spot_exponent=2, ambient=(0.1, 0.2, 0.3)),
    gs.Lights(position=_LIGHTS.normal(size=(5, 4)), diffuse=_LIGHTS.uniform(size=(5, 3))),
    gs.Lights(count=0),
    gs.Material(specular=(1, 0.5, 0.2, 0.9), shininess=64, emission=(0.1, 0, 0)),
    MIXED,
    TWO_SIDED,
]


@pytest.mark.parametrize("obj", OBJECTS, ids=lambda o: type(o).__name__)
@pytest.mark.parametrize("protocol", [2, pickle.HIGHEST_PROTOCOL])
def test_scene_objects_pickle_and_deepcopy_to_equal_objects(
    obj: Any, protocol: int, rng: np.random.Generator
) -> None:
    for clone in (pickle.loads(pickle.dumps(obj, protocol)), copy.deepcopy(obj), copy.copy(obj)):
        assert type(clone) is type(obj)
        assert clone == obj
        assert repr(clone) == repr(obj)
    if isinstance(obj, gs.Scene):
        p, n = rows(rng, 30)
        np.testing.assert_array_equal(
            gs.shade(p, n, pickle.loads(pickle.dumps(obj))), gs.shade(p, n, obj)
        )


def test_out_of_band_pickles_unpickle_from_misaligned_buffers(rng: np.random.Generator) -> None:
    # Pickle protocol 5 hands the arrays' bytes over as buffers, which a receiver may place at
    # any offset: the scene rebuilt from them must shade as the original.
    for obj in OBJECTS:
        buffers: list[pickle.PickleBuffer] = []
        data = pickle.dumps(obj, protocol=5, buffer_callback=buffers.append)
        arrays = [np.frombuffer(b.raw(), np.float64) for b in buffers]
        shifted = [misaligned(a) if a.size else a for a in arrays]
        clone = pickle.loads(data, buffers=shifted)
        assert clone == obj
        if isinstance(obj, gs.Scene):
            p, n = rows(rng, 30)
            np.testing.assert_array_equal(gs.shade(p, n, clone), gs.shade(p, n, obj))


PRESETS = [
    gs.presets.learnopengl(model=np.diag([2.0, 1.0, 1.0, 1.0])),
    gs.presets.opengl([gs.Light()], gs.Material(shininess=9), local_viewer=True),
    gs.presets.directx11(
        l_a=(0.1, 0.1, 0.1),
        l_d=(1, 1, 1),
        l_s=(1, 1, 1),
        m_a=(1, 0, 0),
        m_d=(1, 0, 0),
        m_s=(1, 1, 1),
        p=16,
        eye_position=(0, 0, 5),
        light_vector=(0, 0, -1),
    ),
    gs.presets.phong_illumination(
        k_a=0.1,
        k_d=0.7,
        k_s=0.2,
        n=10,
        I_a=(1, 1, 1),
        I_l=(1, 1, 1),
        viewer_position=(0, 0, 5),
        light_position=(1, 2, 3),
        attenuation="inverse_square",
    ),
]


@pytest.mark.parametrize("preset", PRESETS, ids=lambda p: sorted(p.shade_kwargs))
def test_presets_pickle_and_deepcopy_to_equal_presets(
    preset: gs.presets.Preset, rng: np.random.Generator
) -> None:
    p, n = rows(rng, 20)
    for clone in (pickle.loads(pickle.dumps(preset)), copy.deepcopy(preset)):
        assert type(clone) is gs.presets.Preset and clone == preset
        np.testing.assert_array_equal(clone.shade(p, n), preset.shade(p, n))
    other = gs.presets.learnopengl(model=np.diag([3.0, 1.0, 1.0, 1.0]))
    assert other != PRESETS[0] and PRESETS[0] == PRESETS[0]


def test_images_pickle_and_deepcopy_to_equal_images() -> None:
    vertices = np.array([[0, 0, 1], [1, 0, -0.5], [-1, 0.5, -0.5], [0, -1, -0.5]], np.float32)
    faces = np.array([[0, 1, 2], [0, 2, 3], [0, 3, 1], [1, 3, 2]])
    camera = gs.Camera.look_at((0.3, 0.2, 4))
    image = gs.render(vertices, faces, MIXED, camera, width=9, height=7)
    assert np.ptp(np.asarray(image)) > 0
    for clone in (pickle.loads(pickle.dumps(image)), copy.deepcopy(image)):
        assert type(clone) is gs.Image and clone.shape == (7, 9, 4)
        np.testing.assert_array_equal(clone, image)


CAMERAS = [
    gs.Camera(),
    gs.Camera(view=np.diag([1.0, 2.0, 1.0, 1.0]), projection=np.diag([1.0, 1.0, -1.0, 1.0])),
    gs.Camera.look_at((1, 2, 3), fovy=30, near=0.5, far=20),
    gs.Camera.look_at((1, 2, 3), (0, 1, 0), aspect=1.5),
    gs.Camera.look_at_orthographic((0, 0, 5), height=3, near=-1, far=9),
]


@pytest.mark.parametrize("camera", CAMERAS, ids=repr)
def test_cameras_pickle_and_deepcopy_to_equal_cameras(camera: gs.Camera) -> None:
    for clone in (pickle.loads(pickle.dumps(camera)), copy.deepcopy(camera)):
        assert clone == camera and repr(clone) == repr(camera)
        np.testing.assert_array_equal(clone.view, camera.view)
        for size in ((640, 480), (3, 7)):
            np.testing.assert_array_equal(
                clone.projection_matrix(*size), camera.projection_matrix(*size)
            )
        assert not clone.view.flags.writeable
        assert not clone.projection_matrix(1, 1).flags.writeable or camera._lens[0] != "projection"
    assert camera != gs.Camera.look_at((9, 9, 9))


def test_equality_is_by_value() -> None:
    assert gs.Light(position=(1, 2, 3, 1)) == gs.Light(position=[1.0, 2, 3, 1])
    assert gs.Light(position=(1, 2, 3, 1)) != gs.Light(position=(1, 2, 3, 0))
    assert gs.Material(shininess=2) == gs.Material(shininess=2.0)
    assert gs.Scene(lights=[gs.Light()]) == gs.Scene(lights=gs.Lights(count=1))
    assert gs.Scene(two_side=True) != gs.Scene()


def test_lights_index_and_slice_as_sequences_do() -> None:
    lights = gs.Lights(position=np.c_[np.arange(5.0), np.zeros((5, 2)), np.ones(5)])
    assert isinstance(lights[0], gs.Light) and lights[-1].position[0] == 4
    picked = lights[1:3]
    assert isinstance(picked, gs.Lights) and len(picked) == 2
    assert "2 lights" in repr(picked)
    np.testing.assert_array_equal(lights[[4, 0]].position[:, 0], [4, 0])
    np.testing.assert_array_equal(lights[lights.position[:, 0] > 2].position[:, 0], [3, 4])
    with pytest.raises(IndexError, match="5"):
        lights[5]
    with pytest.raises(TypeError, match="light"):
        lights["sun"]


def test_parameters_are_read_only() -> None:
    light = gs.Light()
    with pytest.raises(ValueError, match="read-only"):
        light.position[0] = 5
    with pytest.raises(AttributeError):
        MIXED.two_side = True  # type: ignore[misc]


def test_defaults_are_gl_s_and_shown_in_the_signatures() -> None:

    params = inspect.signature(gs.Light).parameters
    assert params["position"].default == (0.0, 0.0, 1.0, 0.0)
    assert params["spot_cutoff"].default == 180.0
    assert inspect.signature(gs.Material).parameters["ambient"].default == (0.2, 0.2, 0.2, 1.0)
    assert inspect.signature(gs.Scene).parameters["viewer"].default == (0.0, 0.0, 1.0, 0.0)
    light = gs.Light()
    np.testing.assert_array_equal(light.diffuse, (1, 1, 1, 1))
    np.testing.assert_array_equal(light.ambient, (0, 0, 0, 1))


def test_soft_edges_and_ranges_per_light_and_their_errors() -> None:
    lights = gs.Lights(
        position=[(0, 0, 1, 1), (0, 1, 0, 1), (0, 0, 1, 0)],
        spot_cutoff=[30.0, 40.0, 90.0],
        spot_inner_cutoff=[20.0, 180.0, 0.0],
        range=[2.0, np.inf, 5.0],
    )
    np.testing.assert_array_equal(lights.spot_inner_cutoff, [20, 180, 0])
    np.testing.assert_array_equal(lights.range, [2, np.inf, 5])
    assert gs.Light().range == np.inf and gs.Light().spot_inner_cutoff == 180
    bad = [
        ({"spot_cutoff": 30.0, "spot_inner_cutoff": 40.0}, "spot_inner_cutoff"),
        ({"spot_cutoff": 30.0, "spot_inner_cutoff": 95.0}, "spot_inner_cutoff"),
        ({"range": 0.0}, "range"),
        ({"range": -1.0}, "range"),
        ({"range": np.nan}, "range"),
    ]
    for kwargs, name in bad:
        with pytest.raises(ValueError, match=name):
            gs.Light(position=(0, 0, 1, 1), **kwargs)
