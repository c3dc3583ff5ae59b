"""`Scene.plan` names the path float32's fast mode runs first: the lean arithmetic, or the
careful path alone where the scene is outside the lean arithmetic's range (Accuracy page, "The
lean arithmetic of float32")."""

from __future__ import annotations

import glshade as gs

LEAN = "lean float32 blocks"
CAREFUL = "; the careful path"


def scene(shininess: float, **light: float) -> gs.Scene:
    lights = [gs.Light(position=(1, 2, 3, 1), **light)]
    material = gs.Material(specular=(0.5, 0.5, 0.5), shininess=shininess)
    return gs.Scene(lights, material=material, viewer=(0, 0, 0, 1))


def test_float32_fast_runs_lean_blocks_first() -> None:
    plan = scene(32).plan("float32")
    assert LEAN in plan and CAREFUL not in plan


def test_a_shininess_above_128_or_a_tiny_constant_attenuation_runs_the_careful_path() -> None:
    assert CAREFUL in scene(129).plan("float32")
    assert CAREFUL in scene(32, constant_attenuation=1e-20).plan("float32")
    # Linear attenuation bounds 1/d·(k0 + k1·d) by the distance check instead.
    assert LEAN in scene(32, constant_attenuation=1e-20, linear_attenuation=1).plan("float32")


def test_float64_and_exact_name_no_float32_path() -> None:
    for plan in (scene(32).plan("float64"), scene(32).plan("float32", accuracy="exact")):
        assert LEAN not in plan and CAREFUL not in plan
