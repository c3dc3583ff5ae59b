"""One thread writes `out` while another shades an input that shares out's memory: the reader
gets ValueErrors (or nothing), never a panic. Prints the number of errors and the first.

Usage: python tests/scripts/out_race.py
"""

from __future__ import annotations

import threading

import numpy as np

import glshade as gs


def main() -> None:
    rng = np.random.default_rng(0)
    scene = gs.Scene(lights=[gs.Light(position=(1, 2, 3, 1), linear_attenuation=0.1)] * 8)
    n = 2_000_000
    out = np.zeros((n, 4), np.float32)
    normals = rng.normal(size=(n, 3)).astype(np.float32)
    # The first n * 3 floats of out, as a C-contiguous (n, 3) array: an input sharing out's memory.
    inner = out.reshape(-1)[: n * 3].reshape(n, 3)
    errors: list[str] = []
    done = threading.Event()

    def writer() -> None:
        for _ in range(6):
            gs.shade(normals, normals, scene, out=out)
        done.set()

    def reader() -> None:
        while not done.is_set():
            try:
                gs.shade(inner, normals[:1], scene)
            except ValueError as e:
                errors.append(str(e))

    threads = [threading.Thread(target=writer), threading.Thread(target=reader)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    print(len(errors), errors[:1])


if __name__ == "__main__":
    main()
