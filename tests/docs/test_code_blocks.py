"""Every Python block of the README and of the documentation's pages runs as written.

The blocks of one file run in order in one namespace, as a reader pastes them into one session,
in a fresh working folder. The gallery's notebooks run when the site builds (docs/hooks/gallery.py),
not here.
"""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest
from conftest import require

from .pages import PAGES, README, ROOT, markdown_files, notebooks, python_blocks, run_blocks

pytestmark = pytest.mark.docs

FILES = [path for path in markdown_files() if python_blocks(path)]


def marks(path: Path) -> list[pytest.MarkDecorator]:
    """What a file's blocks need, as the suite's markers (pyproject.toml)."""
    text = "\n".join(python_blocks(path))
    needs = []
    if "glsl.render(" in text or "glsl.shade(" in text or "moderngl" in text or "pyrender" in text:
        needs.append(pytest.mark.gl)
    if "LocalCluster" in text:
        needs.append(pytest.mark.cluster)
    return needs


@pytest.mark.parametrize(
    "path",
    [pytest.param(path, marks=marks(path), id=str(path.relative_to(ROOT))) for path in FILES],
)
def test_blocks_run(path: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)
    run_blocks(path)


def test_the_documentation_has_examples() -> None:
    """The README has its three examples, the guide has examples on most pages, and the gallery
    has its notebooks: an empty selection cannot pass for a tested one."""
    assert len(python_blocks(README)) >= 3
    assert sum(1 for path in FILES if "guide" in path.parts) >= 8
    assert 4 <= len(notebooks()) <= 8


def test_the_first_example_shades_a_lit_sphere(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The README's first example gives what its text says: a float32 RGBA image of a lit
    sphere, brighter towards the light, transparent outside."""
    monkeypatch.chdir(tmp_path)
    namespace = run_blocks(README)
    rgba = np.asarray(namespace["rgba"])
    assert rgba.dtype == np.float32 and rgba.ndim == 3 and rgba.shape[2] == 4
    inside = rgba[..., 3] > 0
    assert 0.5 < inside.mean() < 0.9  # a disc inside the square
    rgb = rgba[..., :3][inside]
    assert 0.0 <= rgb.min() and rgb.max() <= 1.0 and np.ptp(rgb) > 0.5


@pytest.mark.gl
def test_the_readme_shows_what_its_examples_draw(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Each picture of the README is the file its examples write, to within one 8-bit level
    (another CPU's instruction set may round a few values the other way)."""
    image = require("PIL.Image")
    monkeypatch.chdir(tmp_path)
    run_blocks(README)
    pictures = re.findall(r"!\[[^]]*\]\(docs/pages/images/([^)]+\.png)\)", README.read_text())
    assert len(pictures) == 3
    for name in pictures:
        drawn = np.asarray(image.open(tmp_path / name), dtype=np.int16)
        shown = np.asarray(image.open(PAGES / "images" / name), dtype=np.int16)
        assert drawn.shape == shown.shape, name
        assert np.abs(drawn - shown).max() <= 1, (
            f"{name} is not what the README's examples draw: redraw the pictures with "
            "`python tests/docs/pages.py`"
        )
