"""The scale-out tests' fixtures: the 4·10⁶ vertices on disk and `glshade.dask`."""

from __future__ import annotations

import importlib
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from conftest import require

import glshade as gs
from support.scale_out import SCENE, VERTICES, write_vertices


@pytest.fixture(scope="session")
def data(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, Path, np.ndarray]:
    """The 4*10^6 vertices on disk, and one local gs.shade call over them (once a session: the
    cluster's tests and the process pools' share them)."""
    positions, normals = write_vertices(tmp_path_factory.mktemp("scale_out"), VERTICES)
    expected = gs.shade(np.load(positions, mmap_mode="r"), np.load(normals, mmap_mode="r"), SCENE)
    assert expected.dtype == np.float32 and np.ptp(expected[:, :3]) > 0.5
    return positions, normals, expected


@pytest.fixture(scope="module")
def gsd() -> Any:
    """glshade.dask, which needs dask[array]."""
    require("dask.array")
    return importlib.import_module("glshade.dask")
