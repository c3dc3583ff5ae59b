"""Every shading model goes through the one dispatch: each scene type is a `glshade._model.Model`,
and `shade`, `shade_mesh`, `render` and `Scene.plan` reach the binding's one `shade`,
`describe` and `render` with the scene's native scene, whatever its model. A scene type added
without a case here fails `test_every_scene_type_has_a_case`."""

from __future__ import annotations

from collections.abc import Callable, Iterator
from typing import Any

import numpy as np
import pytest

import glshade as gs
from glshade import _glshade
from glshade._model import Model

# One scene of each model, lit so that every call below computes something.
CASES: dict[type, Callable[[], Model]] = {
    gs.Scene: lambda: gs.Scene(lights=[gs.Light(position=(0, 1, 1, 0))]),
    gs.gltf.Scene: lambda: gs.gltf.Scene(
        lights=[gs.gltf.DirectionalLight(intensity=2.0, direction=(0, -1, -1))],
        material=gs.gltf.Material(metallic=0.0),
        camera_position=(0, 0, 5),
    ),
    gs.threejs.Scene: lambda: gs.threejs.Scene(
        lights=[gs.threejs.DirectionalLight(intensity=2.0, position=(0, 1, 1))],
        camera_position=(0, 0, 5),
    ),
}


def _scene_types(base: type) -> Iterator[type]:
    """Every concrete subclass of `base`: a class whose module is public (not ``glshade._…``,
    where the shared machinery of several models lives)."""
    for sub in base.__subclasses__():
        if not sub.__module__.rsplit(".", 1)[-1].startswith("_") or sub is gs.Scene:
            yield sub
        yield from _scene_types(sub)


def test_every_scene_type_has_a_case() -> None:
    assert set(_scene_types(Model)) == set(CASES)


@pytest.fixture
def calls(monkeypatch: pytest.MonkeyPatch) -> list[tuple[str, type]]:
    """The binding's entry points, each recording its name and the native scene's type."""
    seen: list[tuple[str, type]] = []
    for name in ("shade", "describe", "render"):
        native = getattr(_glshade, name)

        def recorded(*args: Any, _name: str = name, _native: Any = native, **kwargs: Any) -> Any:
            scene = kwargs["scene"] if "scene" in kwargs else args[0 if _name == "describe" else 2]
            seen.append((_name, type(scene)))
            return _native(*args, **kwargs)

        monkeypatch.setattr(_glshade, name, recorded)
    return seen


@pytest.mark.parametrize("kind", list(CASES), ids=lambda k: f"{k.__module__}.{k.__name__}")
def test_every_call_of_every_model_goes_through_the_one_entry(
    kind: type, calls: list[tuple[str, type]]
) -> None:
    scene = CASES[kind]()
    native = type(scene._native)
    mesh = gs.meshes.icosphere(1)
    rgba = gs.shade(np.zeros((4, 3)), (0, 0, 1.0), scene)
    assert rgba.shape[-1] == 4 and np.isfinite(rgba).all()
    gs.shade_mesh(mesh, scene=scene)
    image = gs.render(mesh, scene, width=16, height=12)
    assert image.shape == (12, 16, 4) and image[..., 3].any()
    assert scene.plan()
    assert calls == [
        ("shade", native),
        ("shade", native),
        ("render", native),
        ("describe", native),
    ]


def test_the_binding_has_one_entry_per_call_and_no_lab_instrument() -> None:
    exported = set(dir(_glshade))
    assert {"shade", "describe", "render", "stream"} <= exported
    per_model = {n for n in exported if n.endswith(("_gltf", "_threejs"))}
    assert per_model == set()
    assert "lean_directional" not in exported, "a lab build: the wheel carries no lab instrument"
