"""The one timer of the demo, the report, the studies and the benchmarks: a warm-up call, then
rounds in rotating order, each method once per round; the median and the spread of the rounds.

Every round runs every method, so all methods see the same load on a shared machine, and ratios
are taken within a round. The order rotates from round to round and runs backwards every other
round, so every method takes every place and follows two different methods. `time_calibrated`
also times a fixed kernel beside each method, in the same turn, so that the per-round ratio of
the two cancels what the machine's speed does between turns, rounds and runs.
"""

from __future__ import annotations

import statistics
import time
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import Any

__all__ = ["BURST", "Calibrated", "Timing", "ratio", "time_calibrated", "time_rounds"]

# Calls per turn in `bench shade` and the report, the fastest counting: the first call after a
# single-threaded method pays for waking the idle second core and, often, for fresh pages.
BURST = 3


@dataclass(frozen=True)
class Timing:
    """Seconds per call of one method over the rounds.

    Attributes
    ----------
    seconds : tuple of float
        One time per round, in round order.
    """

    seconds: tuple[float, ...]

    @property
    def median(self) -> float:
        """The median over the rounds, in seconds."""
        return statistics.median(self.seconds)

    @property
    def low(self) -> float:
        """The fastest round, in seconds: the lower end of the spread."""
        return min(self.seconds)

    @property
    def high(self) -> float:
        """The slowest round, in seconds: the upper end of the spread."""
        return max(self.seconds)

    def as_dict(self, scale: float = 1.0) -> dict[str, Any]:
        """``median``, ``low``, ``high`` and ``rounds`` (the per-round times), times `scale`.

        Parameters
        ----------
        scale : float
            The factor every time is multiplied by (1e9 for nanoseconds).

        Returns
        -------
        dict
            ``median``, ``low`` and ``high`` (floats) and ``rounds`` (a list of floats).
        """
        return {
            "median": self.median * scale,
            "low": self.low * scale,
            "high": self.high * scale,
            "rounds": [s * scale for s in self.seconds],
        }


def _fastest(call: Callable[[], Any], burst: int) -> float:
    """Seconds of the fastest of `burst` calls in a row."""
    fastest = float("inf")
    for _ in range(burst):
        start = time.perf_counter()
        call()
        fastest = min(fastest, time.perf_counter() - start)
    return fastest


def _rounds(
    turns: Mapping[str, tuple[Callable[[], Any], ...]],
    rounds: int,
    settle: float,
    burst: int,
    on_round: Callable[[], None] | None,
) -> dict[str, list[tuple[float, ...]]]:
    """Per name, per round, the seconds of each call of its turn (in the order given)."""
    if rounds < 1 or burst < 1:
        raise ValueError(f"rounds and burst must be >= 1, got {rounds} and {burst}")
    for calls in turns.values():
        for call in calls:
            call()  # warm-up: first-touch of pages, thread start, compilation
    names = list(turns)
    times: dict[str, list[tuple[float, ...]]] = {name: [] for name in names}
    for r in range(rounds):
        shift = r % len(names) if names else 0
        order = names[shift:] + names[:shift]
        for name in order[::-1] if r % 2 else order:
            if settle:
                time.sleep(settle)
            calls = turns[name]
            # Within a turn the order flips every round too: neither call always goes first.
            index = range(len(calls))[::-1] if r % 2 else range(len(calls))
            seconds = {i: _fastest(calls[i], burst) for i in index}
            times[name].append(tuple(seconds[i] for i in range(len(calls))))
        if on_round is not None:
            on_round()
    return times


def time_rounds(
    methods: Mapping[str, Callable[[], Any]],
    rounds: int,
    *,
    settle: float = 0.0,
    burst: int = 1,
    on_round: Callable[[], None] | None = None,
) -> dict[str, Timing]:
    """Times each method once per round, after one warm-up call of each.

    Parameters
    ----------
    methods : mapping of str to callable
        The calls to time, by name; each is called with no arguments.
    rounds : int
        Rounds (>= 1); each gives one time per method.
    settle : float
        Seconds of idle before each timed turn: numpy's OpenBLAS keeps its threads spinning for
        about 0.1 s after a call, and on a 2-core machine they would take a core from whichever
        method runs next.
    burst : int
        Calls per turn (>= 1); the fastest counts: a method's steady rate, without what its
        first call pays to wake a core that idled while a single-threaded method ran.
    on_round : callable, optional
        Called after each round (a progress bar's step).

    Returns
    -------
    dict of str to Timing
        Per method, in the order given.
    """
    turns = {name: (call,) for name, call in methods.items()}
    times = _rounds(turns, rounds, settle, burst, on_round)
    return {name: Timing(tuple(t for (t,) in ts)) for name, ts in times.items()}


@dataclass(frozen=True)
class Calibrated:
    """A method's rounds and those of its calibration kernel, timed in the same turns.

    Attributes
    ----------
    own : Timing
        The method's seconds per call, one per round.
    calibration : Timing
        The calibration kernel's, in the same rounds, each right beside the method's.
    """

    own: Timing
    calibration: Timing

    @property
    def relative(self) -> Timing:
        """The per-round ratios own / calibration: the method's time in units of the kernel's,
        with the machine's speed in that round cancelled."""
        return ratio(self.own, self.calibration)


def time_calibrated(
    methods: Mapping[str, tuple[Callable[[], Any], Callable[[], Any]]],
    rounds: int,
    *,
    burst: int = 1,
    on_round: Callable[[], None] | None = None,
) -> dict[str, Calibrated]:
    """Times each method and its calibration kernel in the same turn of every round.

    As `time_rounds` (a warm-up, rotating rounds, the fastest of `burst` calls), but each turn
    runs the method and then its kernel, or the kernel and then the method every other round,
    so that both see the same state of a shared machine.

    Parameters
    ----------
    methods : mapping of str to (callable, callable)
        Per name: the call to time and its calibration kernel, each called with no arguments.
    rounds : int
        As in `time_rounds`.
    burst : int
        As in `time_rounds`.
    on_round : callable, optional
        As in `time_rounds`.

    Returns
    -------
    dict of str to Calibrated
        Per method, in the order given.
    """
    times = _rounds(methods, rounds, 0.0, burst, on_round)
    return {
        name: Calibrated(Timing(tuple(o for o, _ in ts)), Timing(tuple(c for _, c in ts)))
        for name, ts in times.items()
    }


def ratio(baseline: Timing, own: Timing) -> Timing:
    """The per-round ratios baseline / own (a speed-up), as a Timing of ratios.

    Parameters
    ----------
    baseline : Timing
        The times to divide.
    own : Timing
        The times to divide by, round for round (as many rounds as `baseline`).

    Returns
    -------
    Timing
        One ratio per round, in round order.

    Raises
    ------
    ValueError
        When the two have different numbers of rounds.
    """
    return Timing(tuple(b / o for b, o in zip(baseline.seconds, own.seconds, strict=True)))
