"""A grandchild forked from a forked child shades as the parent did. Prints "ok" or "failed".

Usage: python tests/scripts/fork_grandchild.py
"""

from __future__ import annotations

import os
from typing import NoReturn

import numpy as np

import glshade as gs

p = np.random.default_rng(2).normal(size=(100_000, 3))
scene = gs.Scene(lights=[gs.Light(position=(1, 2, 3, 1))])
expected = gs.shade(p, p, scene)


def generation(depth: int) -> NoReturn:
    assert np.array_equal(gs.shade(p, p, scene), expected)
    if depth == 0:
        os._exit(0)
    pid = os.fork()
    if pid == 0:
        generation(depth - 1)
    _, status = os.waitpid(pid, 0)
    os._exit(os.waitstatus_to_exitcode(status))


def main() -> None:
    pid = os.fork()
    if pid == 0:
        generation(2)
    _, status = os.waitpid(pid, 0)
    print("ok" if os.waitstatus_to_exitcode(status) == 0 else "failed")


if __name__ == "__main__":
    main()
