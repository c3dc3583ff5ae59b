"""Runs tests/scripts/<name>.py in a fresh interpreter: for cases that could crash or hang the
test process (fork, allocation failure, races, Ctrl-C) or that need a process of their own
(rayon's thread count is fixed per process)."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

SCRIPTS = Path(__file__).resolve().parent.parent / "scripts"


def script(name: str) -> str:
    """The path of tests/scripts/<name>.py."""
    path = SCRIPTS / f"{name}.py"
    assert path.is_file(), path
    return str(path)


def run_script(
    name: str, *args: str, timeout: float = 120, threads: int | None = None
) -> subprocess.CompletedProcess[str]:
    """Runs the script with `args` (under RAYON_NUM_THREADS=threads if given); a crash shows as
    a signal in the return code."""
    env = None if threads is None else {**os.environ, "RAYON_NUM_THREADS": str(threads)}
    return subprocess.run(
        [sys.executable, script(name), *args],
        capture_output=True,
        text=True,
        timeout=timeout,
        check=False,
        env=env,
    )


def passes(name: str, *args: str, timeout: float = 120, threads: int | None = None) -> str:
    """The script's stdout; it must exit 0."""
    result = run_script(name, *args, timeout=timeout, threads=threads)
    assert result.returncode == 0, f"exit {result.returncode}\n{result.stdout}\n{result.stderr}"
    return result.stdout
