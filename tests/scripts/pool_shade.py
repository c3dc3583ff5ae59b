"""A multiprocessing pool shades memory-mapped .npy rows chunk by chunk into a memory-mapped
output, each worker unpickling the scene once.

Usage: python tests/scripts/pool_shade.py {fork,spawn} POSITIONS NORMALS OUTPUT COUNT CHUNK SCENE
(POSITIONS, NORMALS: (COUNT, 3) float32 .npy files; OUTPUT: the (COUNT, 4) float32 .npy written;
SCENE: a pickled gs.Scene)
"""

from __future__ import annotations

import multiprocessing
import pickle
import sys
from pathlib import Path

import numpy as np

import glshade as gs

SCENE = gs.Scene()


def start(scene_bytes: bytes) -> None:
    global SCENE  # each worker unpickles the scene once
    SCENE = pickle.loads(scene_bytes)


def shade_rows(task: tuple[str, str, str, int, int]) -> int | None:
    positions, normals, output, begin, end = task
    p = np.load(positions, mmap_mode="r")[begin:end]
    n = np.load(normals, mmap_mode="r")[begin:end]
    out = np.load(output, mmap_mode="r+")
    gs.shade(p, n, SCENE, out=out[begin:end])
    out.flush()
    return multiprocessing.current_process().pid


def main(argv: list[str]) -> None:
    method, positions, normals, output, count_arg, chunk_arg, scene_path = argv
    count, chunk = int(count_arg), int(chunk_arg)
    np.lib.format.open_memmap(output, "w+", np.float32, (count, 4)).flush()
    tasks = [(positions, normals, output, b, min(b + chunk, count)) for b in range(0, count, chunk)]
    context = multiprocessing.get_context(method)
    gs.shade(np.zeros((1, 3)), (0, 0, 1), gs.Scene())  # the parent's thread pool exists
    scene_bytes = Path(scene_path).read_bytes()
    with context.Pool(2, initializer=start, initargs=(scene_bytes,)) as pool:
        pool.map(shade_rows, tasks)


if __name__ == "__main__":
    main(sys.argv[1:])
