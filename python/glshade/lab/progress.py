"""A progress bar for long work: tqdm's (a widget in a notebook) when tqdm is installed, else
one line on stderr rewritten in place."""

from __future__ import annotations

import sys
import time
from types import TracebackType
from typing import Any, TextIO

__all__ = ["Progress"]


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
        Where the fallback line goes (default ``sys.stderr``).
    """

    def __init__(
        self, total: int, description: str, *, enabled: bool = True, stream: TextIO | None = None
    ) -> None:
        self.total, self.done, self.description = total, 0, description
        self._stream = stream if stream is not None else sys.stderr
        self._start = time.perf_counter()
        self._bar: Any = None
        self._enabled = enabled
        if enabled:
            try:
                from tqdm.auto import tqdm  # type: ignore[import-untyped,unused-ignore]
            except ImportError:
                self._draw("")
            else:
                self._bar = tqdm(total=total, desc=description, leave=True)

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
