"""The README's Python examples run as written."""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest

README = Path(__file__).resolve().parents[2] / "README.md"
BLOCKS = re.findall(r"```python\n(.*?)```", README.read_text(encoding="utf-8"), flags=re.S)


def test_readme_has_examples() -> None:
    assert len(BLOCKS) >= 2


@pytest.mark.parametrize("index", range(len(BLOCKS)))
def test_readme_example_runs(index: int) -> None:
    namespace: dict[str, object] = {}
    prelude = "import numpy as np\nimport glshade as gs\n"
    exec(compile(prelude + BLOCKS[index], f"README.md block {index}", "exec"), namespace)


def test_the_first_example_gives_float32_and_lit_unsaturated_colours() -> None:
    namespace: dict[str, object] = {}
    exec(compile(BLOCKS[0], "README.md block 0", "exec"), namespace)
    rgba = namespace["rgba"]
    assert isinstance(rgba, np.ndarray)
    assert rgba.dtype == np.float32 and rgba.shape == (100_000, 4)
    rgb = rgba[:, :3]
    assert 0.0 <= rgb.min() and rgb.max() <= 1.0
    # Lit: the colours spread from the ambient floor to near-white highlights...
    assert np.ptp(rgb) > 0.7 and rgb.std() > 0.1
    # ...and few saturate: the sky light has no specular term to wash the front out.
    assert np.mean(rgb == 1.0) < 0.01
    # The side facing the bulb at (1, 2, 3) is brighter than the side facing away.
    normals = namespace["normals"]
    assert isinstance(normals, np.ndarray)
    towards = normals @ np.array([1.0, 2.0, 6.0]) > 0
    assert rgb[towards].mean() > 2 * rgb[~towards].mean()
