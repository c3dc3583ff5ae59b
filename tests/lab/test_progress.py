"""Which progress bar the report shows where: tqdm's widget in a Jupyter kernel with ipywidgets,
none in a kernel without (no "IProgress not found"), text elsewhere. A kernel is faked with a
stub IPython; no notebook runs."""

from __future__ import annotations

import io
import sys
import types
import warnings
from typing import Any

import pytest
from conftest import require

from glshade.lab import progress
from glshade.lab.progress import Progress

pytestmark = pytest.mark.lab


def _ipython(monkeypatch: pytest.MonkeyPatch, config: dict[str, Any] | None) -> None:
    """A stub IPython module whose shell has `config` (None: no shell running)."""
    stub = types.ModuleType("IPython")
    shell = None if config is None else types.SimpleNamespace(config=config)
    stub.get_ipython = lambda: shell  # type: ignore[attr-defined]
    monkeypatch.setitem(sys.modules, "IPython", stub)


def test_a_kernel_is_told_from_a_terminal_ipython(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delitem(sys.modules, "IPython", raising=False)
    assert not progress.in_notebook()
    _ipython(monkeypatch, None)
    assert not progress.in_notebook()
    _ipython(monkeypatch, {"TerminalInteractiveShell": {}})
    assert not progress.in_notebook()
    _ipython(monkeypatch, {"IPKernelApp": {"connection_file": "kernel-1.json"}})
    assert progress.in_notebook()


def test_widgets_need_tqdm_and_ipywidgets(monkeypatch: pytest.MonkeyPatch) -> None:
    require("tqdm")
    require("ipywidgets")
    assert progress.has_widgets()
    monkeypatch.setitem(sys.modules, "ipywidgets", None)
    assert not progress.has_widgets()


@pytest.mark.parametrize(
    ("notebook", "widgets", "expected"),
    [
        (True, True, "notebook"),
        (True, False, "none"),
        (False, True, "text"),
        (False, False, "text"),
    ],
)
def test_the_choice(
    monkeypatch: pytest.MonkeyPatch, notebook: bool, widgets: bool, expected: str
) -> None:
    monkeypatch.setattr(progress, "in_notebook", lambda: notebook)
    monkeypatch.setattr(progress, "has_widgets", lambda: widgets)
    assert progress.kind() == expected


class FakeBar:
    """What Progress calls on tqdm's notebook bar, recorded."""

    def __init__(self) -> None:
        self.updates: list[int] = []
        self.notes: list[str] = []
        self.closed = False

    def update(self, n: int) -> None:
        self.updates.append(n)

    def set_postfix_str(self, note: str, refresh: bool) -> None:
        self.notes.append(note)

    def close(self) -> None:
        self.closed = True


def test_a_notebook_with_widgets_gets_the_widget(
    monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    monkeypatch.setattr(progress, "kind", lambda: "notebook")
    bar = FakeBar()
    made: list[tuple[int, str]] = []

    def notebook_bar(total: int, description: str) -> FakeBar:
        made.append((total, description))
        return bar

    monkeypatch.setattr(progress, "_notebook_bar", notebook_bar)
    with Progress(3, "work") as p:
        p.step("one")
        p.step("two", n=2)
    assert p.kind == "notebook" and made == [(3, "work")]
    assert bar.updates == [1, 2] and bar.notes == ["one", "two"] and bar.closed
    assert capsys.readouterr() == ("", "")  # the widget draws, the streams stay empty


def test_a_notebook_without_widgets_shows_nothing_and_does_not_warn(
    monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    _ipython(monkeypatch, {"IPKernelApp": {}})
    monkeypatch.setitem(sys.modules, "ipywidgets", None)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with Progress(3, "work") as p:
            p.step("one")
            p.step("two", n=2)
    assert p.kind == "none" and p.done == 3
    assert capsys.readouterr() == ("", "")


def test_elsewhere_the_text_bar_counts_on_the_stream(monkeypatch: pytest.MonkeyPatch) -> None:
    require("tqdm")
    monkeypatch.setattr(progress, "in_notebook", lambda: False)
    stream = io.StringIO()
    monkeypatch.setattr(sys, "stderr", stream)
    with Progress(3, "work") as p:
        p.step("one")
        p.step("two", n=2)
    assert p.kind == "text"
    text = stream.getvalue()
    assert "work" in text and "3/3" in text and text.endswith("\n")


def test_disabled_shows_nothing_anywhere(
    monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    monkeypatch.setattr(progress, "kind", lambda: "notebook")
    with Progress(2, "work", enabled=False) as p:
        p.step()
        p.step()
    assert p.kind == "none" and p.done == 2
    assert capsys.readouterr() == ("", "")
