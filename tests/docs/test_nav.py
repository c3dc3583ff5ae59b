"""A new page is one file: docs/hooks/nav.py puts it into its folder's section."""

from __future__ import annotations

import importlib.util
from pathlib import Path
from typing import Any

import pytest

from .pages import DOCS, PAGES

pytestmark = pytest.mark.docs


def hook() -> Any:
    spec = importlib.util.spec_from_file_location("nav", DOCS / "hooks" / "nav.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_an_unlisted_page_joins_its_section(tmp_path: Path) -> None:
    (tmp_path / "guide").mkdir()
    for name, text in [
        ("index", "# Guide\n"),
        ("shading", "# Shading\n"),
        ("textures", "# Textures\n"),
    ]:
        (tmp_path / "guide" / f"{name}.md").write_text(text)
    (tmp_path / "index.md").write_text("# Home\n")
    nav = [{"Home": "index.md"}, {"Guide": ["guide/index.md", {"Shading": "guide/shading.md"}]}]
    config = hook().on_config({"nav": nav, "docs_dir": str(tmp_path)})
    assert config["nav"][1]["Guide"][-1] == {"Textures": "guide/textures.md"}
    assert config["nav"][0] == {"Home": "index.md"}  # a page outside a section stays as it is


def test_the_site_lists_every_page() -> None:
    """With the hook, every page of docs/pages is in the navigation."""
    import yaml  # mkdocs' own dependency

    config = yaml.safe_load((DOCS / "mkdocs.yml").read_text())
    nav = hook().on_config({"nav": config["nav"], "docs_dir": str(PAGES)})["nav"]
    pages = {p.relative_to(PAGES).as_posix() for p in PAGES.rglob("*.md")}
    assert pages == hook().listed(nav)
