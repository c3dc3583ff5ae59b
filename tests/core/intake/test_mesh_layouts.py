"""Every mesh function (normals, `shade_mesh`, `render`) takes vertices and faces in any layout."""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest

import glshade as gs
from support.boundary import MIXED, misaligned

CUBE = np.array([[x, y, z] for x in (-0.5, 0.5) for y in (-0.5, 0.5) for z in (-0.5, 0.5)])
CUBE_FACES = np.array(
    [
        [0, 1, 3], [0, 3, 2], [4, 6, 7], [4, 7, 5], [0, 4, 5], [0, 5, 1],
        [2, 3, 7], [2, 7, 6], [0, 2, 6], [0, 6, 4], [1, 5, 7], [1, 7, 3],
    ]
)  # fmt: skip
MESH_FUNCTIONS = {
    "face_normals": lambda v, f: gs.face_normals(v, f),
    "vertex_normals": lambda v, f: gs.vertex_normals(v, f),
    "shade_mesh": lambda v, f: gs.shade_mesh(v, f, scene=MIXED),
    "shade_mesh_per_face": lambda v, f: gs.shade_mesh(v, f, scene=MIXED, per="face"),
    "render": lambda v, f: gs.render(
        v, f, MIXED, gs.Camera.look_at((2, 1.5, 3)), width=24, height=20
    ),
}
LAYOUTS = {
    "fortran": np.asfortranarray,
    "reversed_view": lambda a: a[::-1][::-1],
    "strided": lambda a: np.repeat(a, 2, axis=0)[::2],
    "misaligned": misaligned,
    "byteswapped": lambda a: a.astype(a.dtype.newbyteorder()),
    "list": lambda a: a.tolist(),
}


@pytest.mark.parametrize("function", MESH_FUNCTIONS)
@pytest.mark.parametrize("layout", LAYOUTS)
@pytest.mark.parametrize("dtype", [np.float32, np.float64])
def test_mesh_functions_take_any_layout(function: str, layout: str, dtype: Any) -> None:
    call = MESH_FUNCTIONS[function]
    v = CUBE.astype(dtype)
    expected = call(v, CUBE_FACES)
    arrange = LAYOUTS[layout]
    got = call(arrange(v), arrange(CUBE_FACES.astype(np.int32)))
    assert got.dtype == (np.float64 if layout == "list" else dtype)
    np.testing.assert_allclose(got, expected, rtol=0, atol=0 if layout != "list" else 1e-6)
