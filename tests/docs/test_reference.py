"""The API reference documents every public name: each module's ``__all__`` has its entry."""

from __future__ import annotations

import importlib
import re

import pytest

from .pages import PAGES

pytestmark = pytest.mark.docs

REFERENCE = PAGES / "reference"
# Module → the page documenting it; the top-level package's submodules have pages of their own.
MODULES = {
    "glshade": "glshade.md",
    "glshade.presets": "presets.md",
    "glshade.glsl": "glsl.md",
    "glshade.gltf": "gltf.md",
    "glshade.threejs": "threejs.md",
    "glshade.relief": "relief.md",
    "glshade.dask": "dask.md",
    "glshade.lab.report": "lab.md",
    "glshade.lab.studies": "lab.md",
    "glshade.lab.timing": "lab.md",
    "glshade.lab.machine": "lab.md",
}
# Names the reference gives a page or a sentence of their own rather than an entry.
ELSEWHERE = {
    "glsl",
    "gltf",
    "threejs",
    "relief",
    "meshes",
    "presets",
    "__version__",
    "report",
    "Report",
}


def documented(page: str, module: str) -> set[str]:
    """The names a reference page renders for `module`: its ``::: module.name`` entries and the
    ``members`` lists under ``::: module``."""
    text = (REFERENCE / page).read_text(encoding="utf-8")
    names = set(re.findall(rf"^::: {re.escape(module)}\.(\w+)\s*$", text, flags=re.M))
    for block in re.finditer(rf"^::: {re.escape(module)}\s*\n((?:[ ]+.*\n)+)", text, flags=re.M):
        for members in re.findall(r"members: \[([^]]*)\]", block.group(1)):
            names |= {name.strip() for name in members.split(",")}
    return names


@pytest.mark.parametrize("module", sorted(MODULES))
def test_every_public_name_has_an_entry(module: str) -> None:
    public = set(importlib.import_module(module).__all__) - ELSEWHERE
    missing = public - documented(MODULES[module], module)
    assert not missing, (
        f"{module}: no entry in docs/pages/reference/{MODULES[module]} for {missing}"
    )


def test_the_meshes_page_lists_the_built_in_meshes() -> None:
    import glshade.meshes

    public = {name for name in ("icosphere", "torus", "grid") if hasattr(glshade.meshes, name)}
    assert public == documented("meshes.md", "glshade.meshes") == {"icosphere", "torus", "grid"}
