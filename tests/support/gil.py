"""Whether a call releases the GIL: how fast a Python counter runs in a second thread meanwhile."""

from __future__ import annotations

import threading
import time
from collections.abc import Callable


def count_while(work: Callable[[], object]) -> float:
    """Increments of a Python counter per second in a second thread while `work` runs."""
    count = 0
    stop = threading.Event()

    def spin() -> None:
        nonlocal count
        while not stop.is_set():
            count += 1

    thread = threading.Thread(target=spin)
    start = time.perf_counter()
    thread.start()
    work()
    elapsed = time.perf_counter() - start
    stop.set()
    thread.join()
    return count / elapsed
