"""One thread rewrites faces while another computes normals and renders from them: each call
succeeds or raises IndexError, never panics. Prints the outcomes' counts.

Usage: python tests/scripts/face_race.py
"""

from __future__ import annotations

import threading

import numpy as np

import glshade as gs


def main() -> None:
    rng = np.random.default_rng(0)
    v = rng.normal(size=(200_000, 3))
    faces = rng.integers(0, 200_000, (400_000, 3))
    stop = threading.Event()
    outcomes = {"ok": 0, "IndexError": 0}

    def mutate() -> None:
        while not stop.is_set():
            faces[rng.integers(0, len(faces), 1000)] = 10**9
            faces[faces == 10**9] = 0

    def normals() -> None:
        for _ in range(30):
            for function in (gs.vertex_normals, gs.face_normals):
                try:
                    function(v, faces)
                    outcomes["ok"] += 1
                except IndexError:
                    outcomes["IndexError"] += 1
        for _ in range(5):
            try:
                gs.render(v, faces, gs.Scene(), gs.Camera(), width=64, height=64)
                outcomes["ok"] += 1
            except IndexError:
                outcomes["IndexError"] += 1
        stop.set()

    threads = [threading.Thread(target=mutate), threading.Thread(target=normals)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    print(outcomes)


if __name__ == "__main__":
    main()
