"""A page dropped into a section's folder joins that section of the navigation.

docs/mkdocs.yml orders the pages it lists; a page of the same folder that it does not list
(``guide/textures.md``, say) is appended to the section that holds its siblings, titled by its
first heading, so a new topic is one file.
"""

from __future__ import annotations

import re
from pathlib import Path
from typing import Any

from mkdocs.config.defaults import MkDocsConfig

TITLE = re.compile(r"^# (?P<title>.+)$", re.M)


def listed(entries: list[Any]) -> set[str]:
    """The pages a section (or the whole navigation) lists, at any depth."""
    found: set[str] = set()
    for entry in entries:
        value = next(iter(entry.values())) if isinstance(entry, dict) else entry
        if isinstance(value, list):
            found |= listed(value)
        elif isinstance(value, str):
            found.add(value)
    return found


def folder(entries: list[Any]) -> str | None:
    """The one folder a section's pages share, if they share one."""
    folders = {str(Path(page).parent) for page in listed(entries)}
    return folders.pop() if len(folders) == 1 and "." not in folders else None


def title(page: Path) -> str:
    match = TITLE.search(page.read_text(encoding="utf-8"))
    return match.group("title").strip() if match else page.stem.replace("-", " ").capitalize()


def on_config(config: MkDocsConfig) -> MkDocsConfig:
    """Appends each unlisted page to the section whose folder holds it."""
    nav = config["nav"] or []
    every = listed(nav)
    docs = Path(config["docs_dir"])
    for entry in nav:
        if not isinstance(entry, dict):
            continue
        section = next(iter(entry.values()))
        if not isinstance(section, list) or (name := folder(section)) is None:
            continue
        for page in sorted((docs / name).glob("*.md")):
            uri = page.relative_to(docs).as_posix()
            if uri not in every:
                section.append({title(page): uri})
    return config
