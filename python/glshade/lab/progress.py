"""A progress bar for long work, of the kind the place it runs in shows well: tqdm's widget in a
Jupyter notebook with ipywidgets (the ``notebook`` extra), a text line elsewhere (tqdm's when
tqdm is installed, else one line rewritten in place), none in a notebook without ipywidgets,
where tqdm's widget would only warn "IProgress not found"."""

from __future__ import annotations

import importlib
import sys
import time
import warnings
from types import TracebackType
from typing import Any, Literal, TextIO

__all__ = ["Progress", "kind"]

Kind = Literal["notebook", "text", "none"]


def in_notebook() -> bool:
    """True inside a Jupyter kernel (a notebook, JupyterLab, VS Code's notebooks): IPython is
    running with a kernel app, which a terminal IPython does not have."""
    ipython = sys.modules.get("IPython")
    get = getattr(ipython, "get_ipython", None)
    shell = get() if get is not None else None
    if shell is None:
        return False
    try:
        return "IPKernelApp" in shell.config
    except Exception:  # an unusual shell without the usual config: not a kernel we know
        return False


def has_widgets() -> bool:
    """True when tqdm's notebook bar can draw: tqdm and ipywidgets both import."""
    try:
        importlib.import_module("tqdm")
        importlib.import_module("ipywidgets")
    except ImportError:
        return False
    return True


def kind() -> Kind:
    """Which bar fits where this runs: "notebook" in a Jupyter kernel with ipywidgets, "none"
    in one without (a text bar there is drawn into the cell's output, and tqdm's widget only
    warns), "text" anywhere else: a terminal, or a stream redirected to a file or a pipe,
    which gets the same line rewritten with carriage returns (a log keeps the last one)."""
    if in_notebook():
        return "notebook" if has_widgets() else "none"
    return "text"


class Progress:
    """Counts `total` steps with a description; a context manager that closes the bar.

    Parameters
    ----------
    total : int
        The number of steps.
    description : str
        What the work is, shown before the count.
    enabled : bool
        False shows nothing (the steps are still counted).
    stream : text file, optional
        Where a text bar goes (default ``sys.stderr``). Given explicitly, the bar is text
        wherever this runs.

    Attributes
    ----------
    kind : {"text", "notebook", "none"}
        The bar shown: `kind`'s choice, "text" for an explicit `stream`, "none" when not
        `enabled`.
    """

    def __init__(
        self, total: int, description: str, *, enabled: bool = True, stream: TextIO | None = None
    ) -> None:
        self.total, self.done, self.description = total, 0, description
        self._stream = stream if stream is not None else sys.stderr
        self._start = time.perf_counter()
        self._bar: Any = None
        self.kind: Kind = "none" if not enabled else "text" if stream is not None else kind()
        self._enabled = self.kind != "none"
        if self.kind == "notebook":
            self._bar = _notebook_bar(total, description)
            if self._bar is None:
                self.kind, self._enabled = "none", False
        elif self.kind == "text":
            try:
                from tqdm import tqdm  # type: ignore[import-untyped,unused-ignore]
            except ImportError:
                self._draw("")
            else:
                self._bar = tqdm(total=total, desc=description, leave=True, file=self._stream)

    def step(self, note: str = "", n: int = 1) -> None:
        """Counts `n` steps done; `note` says what is running now."""
        self.done += n
        if self._bar is not None:
            self._bar.set_postfix_str(note, refresh=False)
            self._bar.update(n)
        elif self._enabled:
            self._draw(note)

    def _draw(self, note: str) -> None:
        elapsed = time.perf_counter() - self._start
        line = f"{self.description}: {self.done}/{self.total} ({elapsed:.0f} s) {note}"
        self._stream.write("\r" + line[:100].ljust(100))
        self._stream.flush()

    def close(self) -> None:
        """Ends the bar (the fallback line gets its newline)."""
        if self._bar is not None:
            self._bar.close()
            self._bar = None
        elif self._enabled:
            self._stream.write("\n")
            self._stream.flush()
        self._enabled = False

    def __enter__(self) -> Progress:
        return self

    def __exit__(
        self,
        kind: type[BaseException] | None,
        value: BaseException | None,
        traceback: TracebackType | None,
    ) -> None:
        self.close()


def _notebook_bar(total: int, description: str) -> Any:
    """tqdm's widget bar, or None where it cannot draw (an ipywidgets tqdm does not support:
    tqdm would warn and fall back to text in the cell)."""
    from tqdm import TqdmWarning  # type: ignore[import-untyped,unused-ignore]

    with warnings.catch_warnings():
        warnings.simplefilter("error", TqdmWarning)
        try:
            from tqdm.notebook import tqdm  # type: ignore[import-untyped,unused-ignore]

            return tqdm(total=total, desc=description, leave=True)
        except (ImportError, TqdmWarning):
            return None
