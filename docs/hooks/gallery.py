"""The gallery: jupytext Markdown notebooks under ``gallery/``, executed while the site builds.

Each notebook runs in a fresh Jupyter kernel (nbclient, ipykernel) in a temporary folder; a cell
that raises fails the build. Its page is the notebook as Markdown with every cell's outputs:
text as text blocks, images as files beside the page, HTML as it is. The executed notebook is
published beside its page (``gallery/<name>.ipynb``) for download.

Run one notebook alone, as the build runs it::

    python docs/hooks/gallery.py docs/pages/gallery/point-cloud.md

``GLSHADE_DOCS_GALLERY=0`` builds the pages without running them (no outputs), for a quick look
at the other pages; CI never sets it.
"""

from __future__ import annotations

import base64
import logging
import os
import sys
import tempfile
from pathlib import Path
from typing import Any

import jupytext
import nbformat
from jupyter_client.manager import KernelManager
from mkdocs.config.defaults import MkDocsConfig
from mkdocs.structure.files import File, Files
from nbclient import NotebookClient

log = logging.getLogger("mkdocs.hooks.gallery")

GALLERY = "gallery/"
TIMEOUT_S = 600  # per cell; the slowest cell (the report) takes about a minute on 2 cores


def is_notebook(path: Path) -> bool:
    """A page is a notebook when its front matter carries jupytext's metadata."""
    text = path.read_text(encoding="utf-8")
    return text.startswith("---\n") and "jupytext:" in text.split("\n---", 1)[0]


def execute(path: Path) -> nbformat.NotebookNode:
    """Reads the jupytext Markdown at `path` and runs it top to bottom in a fresh kernel."""
    notebook: nbformat.NotebookNode = jupytext.read(path)
    with tempfile.TemporaryDirectory(prefix="glshade-gallery-") as folder:
        # Figures come out as PNG outputs (ipykernel's inline backend, whatever the caller's
        # MPLBACKEND), and progress bars stay out of the page.
        env = {"MPLBACKEND": "module://matplotlib_inline.backend_inline", "TQDM_DISABLE": "1"}
        saved = {key: os.environ.get(key) for key in env}
        os.environ.update(env)
        try:
            # The kernel talks over a Unix socket in the folder, not over TCP on the loopback.
            kernel = KernelManager(kernel_name="python3", transport="ipc", ip=f"{folder}/kernel")
            try:
                NotebookClient(
                    notebook, km=kernel, timeout=TIMEOUT_S, resources={"metadata": {"path": folder}}
                ).execute()
            finally:
                if kernel.has_kernel:  # a client handed a kernel manager leaves it running
                    kernel.shutdown_kernel(now=True)
        finally:
            for key, value in saved.items():
                if value is None:
                    os.environ.pop(key, None)
                else:
                    os.environ[key] = value
    return notebook


def fence(text: str, language: str = "") -> str:
    """A fenced block that no backtick run inside `text` can close."""
    ticks = "```"
    while ticks in text:
        ticks += "`"
    return f"{ticks}{language}\n{text.rstrip()}\n{ticks}"


def render(notebook: nbformat.NotebookNode, stem: str) -> tuple[str, dict[str, bytes]]:
    """The page's Markdown and its images (file name under ``<stem>/`` → bytes)."""
    download = f"[Download this notebook]({stem}.ipynb){{ .md-button }}"
    parts: list[str] = []
    images: dict[str, bytes] = {}
    for index, cell in enumerate(notebook.cells):
        if cell.cell_type == "markdown":
            parts.append(cell.source)
            if len(parts) == 1:  # under the title and the introduction
                parts.append(download)
            continue
        if cell.cell_type != "code" or not cell.source.strip():
            continue
        parts.append(fence(cell.source, "python"))
        for number, output in enumerate(cell.get("outputs", [])):
            parts.extend(render_output(output, f"cell{index}-{number}", stem, images))
    if download not in parts:  # a notebook that opens with code
        parts.insert(0, download)
    return "\n\n".join(parts) + "\n", images


def render_output(output: Any, name: str, stem: str, images: dict[str, bytes]) -> list[str]:
    """One output of a code cell as Markdown; images go into `images`."""
    if output.output_type == "stream":
        return [fence(output.text, "text")]
    if output.output_type not in ("display_data", "execute_result"):
        return []
    data = output.get("data", {})
    # Jupyter's own order of preference: HTML, then images, then text.
    if "text/html" in data:
        return [f'<div class="gallery-output" markdown="0">\n{data["text/html"]}\n</div>']
    if "image/png" in data:
        images[f"{name}.png"] = base64.b64decode(data["image/png"])
        # The display size an output asks for (gs.Image's display_width), as Jupyter honours it.
        width = output.get("metadata", {}).get("image/png", {}).get("width")
        size = f'{{ width="{int(width)}" }}' if width else ""
        return [f"![output]({stem}/{name}.png){size}"]
    if "image/svg+xml" in data:
        images[f"{name}.svg"] = data["image/svg+xml"].encode()
        return [f"![output]({stem}/{name}.svg)"]
    if "text/plain" in data:
        return [fence(data["text/plain"], "text")]
    return []


def on_files(files: Files, config: MkDocsConfig) -> Files:
    """Replaces each gallery notebook by its executed page, images and .ipynb."""
    for file in list(files):
        if not (file.src_uri.startswith(GALLERY) and file.src_uri.endswith(".md")):
            continue
        path = Path(file.abs_src_path or "")
        if not is_notebook(path):
            continue
        if os.environ.get("GLSHADE_DOCS_GALLERY") == "0":
            log.info("not executing %s (GLSHADE_DOCS_GALLERY=0)", file.src_uri)
            notebook = jupytext.read(path)
        else:
            log.info("executing %s", file.src_uri)
            notebook = execute(path)
        stem = Path(file.src_uri).stem
        folder = Path(file.src_uri).parent.as_posix()
        markdown, images = render(notebook, stem)
        files.remove(file)
        files.append(File.generated(config, file.src_uri, content=markdown))
        for name, data in images.items():
            files.append(File.generated(config, f"{folder}/{stem}/{name}", content=data))
        files.append(
            File.generated(config, f"{folder}/{stem}.ipynb", content=nbformat.writes(notebook))
        )
    return files


if __name__ == "__main__":
    for argument in sys.argv[1:]:
        executed = execute(Path(argument))
        text, pictures = render(executed, Path(argument).stem)
        print(text)
        print(f"{argument}: ran; {len(pictures)} images", file=sys.stderr)
