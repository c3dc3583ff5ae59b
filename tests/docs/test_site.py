"""The built documentation site, opened page by page in Debian's headless Chromium.

Every page must load with every image decoded, every link inside the site pointing at a file
the site has (and at an element of that page, for a link with an anchor), and no error in the
browser's console. The site is the one `.ci/run` built (``GLSHADE_DOCS_SITE``), or one this
test builds when that is not set.
"""

from __future__ import annotations

import functools
import http.server
import os
import subprocess
import sys
import threading
from collections.abc import Iterator
from html.parser import HTMLParser
from pathlib import Path
from typing import Any
from urllib.parse import unquote, urljoin, urlsplit

import pytest
from conftest import require

from support.chromium import chromium

from .pages import CONFIG

pytestmark = [pytest.mark.docs, pytest.mark.subprocess]


@pytest.fixture(scope="module")
def site(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The built site's folder."""
    built = os.environ.get("GLSHADE_DOCS_SITE")
    if built:
        folder = Path(built)
        assert (folder / "index.html").is_file(), f"GLSHADE_DOCS_SITE={built} holds no site"
        return folder
    require("mkdocs")
    folder = tmp_path_factory.mktemp("site")
    command = [sys.executable, "-m", "mkdocs", "build", "--strict", "-q", "-f", str(CONFIG)]
    done = subprocess.run([*command, "-d", str(folder)], capture_output=True, text=True)
    assert done.returncode == 0, f"mkdocs build failed:\n{done.stdout}\n{done.stderr}"
    return folder


@pytest.fixture(scope="module")
def server(site: Path) -> Iterator[str]:
    """The site over HTTP on the loopback, as a reader's browser gets it."""
    handler = functools.partial(_QuietHandler, directory=str(site))
    httpd = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    thread = threading.Thread(target=httpd.serve_forever, daemon=True)
    thread.start()
    yield f"http://127.0.0.1:{httpd.server_address[1]}/"
    httpd.shutdown()
    thread.join()
    httpd.server_close()


class _QuietHandler(http.server.SimpleHTTPRequestHandler):
    def log_message(self, format: str, *args: Any) -> None:
        pass


@pytest.fixture(scope="module")
def browser() -> Iterator[Any]:
    """Headless Chromium driven by selenium, keeping the console's messages."""
    with chromium("--disable-gpu") as driver:
        yield driver


def pages(site: Path) -> list[str]:
    """Every page of the site, as a path below its root."""
    found = sorted(p.relative_to(site).as_posix() for p in site.rglob("index.html"))
    return [page.removesuffix("index.html") for page in found]


class _Anchors(HTMLParser):
    """The ids (and old-style names) of a page's elements."""

    def __init__(self) -> None:
        super().__init__()
        self.ids: set[str] = set()

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        for name, value in attrs:
            if name == "id" or (tag == "a" and name == "name"):
                self.ids.add(value or "")


@functools.cache
def anchors(path: Path) -> frozenset[str]:
    parser = _Anchors()
    parser.feed(path.read_text(encoding="utf-8"))
    return frozenset(parser.ids)


def target(site: Path, path: str) -> Path:
    """The file a URL path of the site names."""
    file = site / unquote(path).lstrip("/")
    return file / "index.html" if path.endswith("/") or file.is_dir() else file


def test_the_site_has_its_pages(site: Path) -> None:
    every = pages(site)
    for page in ("", "getting-started/", "guide/shading/", "gallery/", "performance/",
                 "development/", "reference/glshade/"):  # fmt: skip
        assert page in every
    assert len(every) >= 30


def test_every_page_loads_whole(site: Path, server: str, browser: Any) -> None:
    problems: list[str] = []
    checked_links = 0
    for page in pages(site):
        url = urljoin(server, page)
        browser.get(url)
        broken = browser.execute_script(
            "return Array.from(document.images)"
            ".filter(i => !(i.complete && i.naturalWidth > 0)).map(i => i.src)"
        )
        problems += [f"{page}: the image {src} does not load" for src in broken]
        links = browser.execute_script(
            "return Array.from(document.querySelectorAll('a[href], link[href], script[src]'))"
            ".map(e => e.href || e.src)"
        )
        for link in links:
            parts = urlsplit(link)
            if f"{parts.scheme}://{parts.netloc}/" != server:
                continue  # another site: not fetched, the test runs offline
            checked_links += 1
            file = target(site, parts.path)
            if not file.is_file():
                problems.append(f"{page}: the link {link} leads to no file")
            elif parts.fragment and file.suffix == ".html":
                if unquote(parts.fragment) not in anchors(file):
                    problems.append(f"{page}: the link {link} names no element of its page")
        for entry in browser.get_log("browser"):
            if entry["level"] in ("SEVERE", "ERROR"):
                problems.append(f"{page}: console {entry['level']}: {entry['message']}")
    assert not problems, "\n".join(problems)
    assert checked_links > 1000


def test_the_search_finds_a_guide_page(server: str, browser: Any) -> None:
    """The search index loads, and a query finds the page that defines the term."""
    browser.get(urljoin(server, "?q=rescale_normal"))
    results = browser.execute_async_script(
        "const done = arguments[arguments.length - 1];"
        "const poll = (n) => { const r = document.querySelectorAll('.md-search-result__item');"
        "  if (r.length || n == 0) done(Array.from(r).map(e => e.textContent));"
        "  else setTimeout(() => poll(n - 1), 100); };"
        "poll(100);"
    )
    assert any("Shading" in text or "shade" in text for text in results), results
