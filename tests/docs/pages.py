"""The documentation's Markdown: which files there are, their Python blocks, the built site."""

from __future__ import annotations

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
README = ROOT / "README.md"
DOCS = ROOT / "docs"
PAGES = DOCS / "pages"
CONFIG = DOCS / "mkdocs.yml"

# A fenced block, possibly indented (inside a list or an admonition), closed by the same fence.
FENCE = re.compile(
    r"^(?P<indent>[ ]*)(?P<ticks>```+)(?P<language>[\w+-]*)[^\n]*\n"
    r"(?P<body>.*?)^(?P=indent)(?P=ticks)[ ]*$",
    re.M | re.S,
)


def is_notebook(path: Path) -> bool:
    """A gallery notebook: jupytext Markdown, run by the site's build rather than by the tests."""
    text = path.read_text(encoding="utf-8")
    return text.startswith("---\n") and "jupytext:" in text.split("\n---", 1)[0]


def markdown_files() -> list[Path]:
    """README.md and every page of the site that is not a notebook."""
    pages = sorted(p for p in PAGES.rglob("*.md") if not is_notebook(p))
    return [README, *pages]


def notebooks() -> list[Path]:
    """The gallery's notebooks."""
    return sorted(p for p in PAGES.rglob("*.md") if is_notebook(p))


def python_blocks(path: Path) -> list[str]:
    """The ```python blocks of a Markdown file, dedented, in order."""
    blocks = []
    for match in FENCE.finditer(path.read_text(encoding="utf-8")):
        if match.group("language") == "python":
            indent = len(match.group("indent"))
            lines = match.group("body").splitlines(keepends=True)
            blocks.append("".join(line[indent:] for line in lines))
    return blocks


def run_blocks(path: Path) -> dict[str, object]:
    """Runs a file's Python blocks in order in one namespace, in the current folder."""
    namespace: dict[str, object] = {"__name__": "__main__"}
    for index, block in enumerate(python_blocks(path)):
        name = f"{path.relative_to(ROOT)}, Python block {index + 1}"
        exec(compile(block, name, "exec"), namespace)
    return namespace


if __name__ == "__main__":
    # Redraws the README's pictures: its examples write them into the current folder.
    import os

    os.chdir(PAGES / "images")
    run_blocks(README)
