"""``python -m glshade report --compare A.json B.json``: do two runs of the report agree?

A row agrees one way when one run's median lies within the other run's stated spread (its
smallest and largest round), both ways when each lies within the other's. Rows are matched by
scene class, dtype, accuracy mode and instruction set. Both figures are compared: the headline
``time_over_kernel`` (time over the calibration kernel's, per-round ratios) and the absolute
``time_ns``; a report of schema glshade-report/1 has only the absolute one.
"""

from __future__ import annotations

import json
import statistics
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

__all__ = ["FIGURES", "Agreement", "agreement", "compare", "load", "main"]

# Per figure: its median's field and its stated spread's lower and upper ends.
FIGURES = {
    "time_over_kernel": ("time_over_kernel", "time_over_kernel_low", "time_over_kernel_high"),
    "time_ns": ("time_ns", "time_low_ns", "time_high_ns"),
}
KEY = ("scene", "dtype", "accuracy", "isa")


@dataclass(frozen=True)
class Agreement:
    """How one figure of two reports agrees over the rows they share.

    Attributes
    ----------
    figure : str
        A key of `FIGURES`.
    rows : int
        Rows in both reports.
    b_in_a, a_in_b, both : int
        Rows with B's median within A's spread, A's within B's, and both.
    drift : float
        The median over the rows of B's median over A's (1.0: no drift of the whole run).
    width_a, width_b : float
        The median over the rows of the spread's width over the median, in A and in B: a wider
        spread agrees more easily, so it is quoted beside the shares.
    """

    figure: str
    rows: int
    b_in_a: int
    a_in_b: int
    both: int
    drift: float
    width_a: float
    width_b: float

    def share(self, count: int) -> float:
        """`count` over the rows compared."""
        return count / self.rows


def _index(rows: Sequence[Mapping[str, Any]], name: str) -> dict[tuple[Any, ...], Any]:
    """The rows by (scene, dtype, accuracy, isa); a repeated key is an error naming `name`."""
    index: dict[tuple[Any, ...], Any] = {}
    for row in rows:
        key = tuple(row[k] for k in KEY)
        if key in index:
            raise ValueError(f"{name} has the row {key} twice")
        index[key] = row
    return index


def _within(x: float, low: float, high: float) -> bool:
    return low <= x <= high


def agreement(
    a: Sequence[Mapping[str, Any]], b: Sequence[Mapping[str, Any]], figure: str
) -> Agreement:
    """Compares `figure` (a key of `FIGURES`) of two reports' rows (lists of row dicts, as in
    report.json) over the rows they share; ValueError when they share none."""
    if figure not in FIGURES:
        raise ValueError(f"figure must be one of {', '.join(FIGURES)}, got {figure!r}")
    median, low, high = FIGURES[figure]
    ia, ib = _index(a, "a"), _index(b, "b")
    common = [k for k in ia if k in ib]
    if not common:
        raise ValueError("a and b share no row (scene, dtype, accuracy, isa)")
    b_in_a = a_in_b = both = 0
    for k in common:
        ra, rb = ia[k], ib[k]
        one = _within(rb[median], ra[low], ra[high])
        other = _within(ra[median], rb[low], rb[high])
        b_in_a, a_in_b, both = b_in_a + one, a_in_b + other, both + (one and other)
    return Agreement(
        figure=figure,
        rows=len(common),
        b_in_a=b_in_a,
        a_in_b=a_in_b,
        both=both,
        drift=statistics.median(ib[k][median] / ia[k][median] for k in common),
        width_a=statistics.median((ia[k][high] - ia[k][low]) / ia[k][median] for k in common),
        width_b=statistics.median((ib[k][high] - ib[k][low]) / ib[k][median] for k in common),
    )


def compare(a: Mapping[str, Any], b: Mapping[str, Any]) -> dict[str, Agreement | None]:
    """Every figure of two report.json documents; None for a figure that a row of either lacks
    (the calibrated one before schema glshade-report/2)."""
    out: dict[str, Agreement | None] = {}
    for figure, names in FIGURES.items():
        present = all(n in row for doc in (a, b) for row in doc["rows"] for n in names)
        out[figure] = agreement(a["rows"], b["rows"], figure) if present else None
    return out


def load(path: str | Path, name: str) -> dict[str, Any]:
    """A report.json document; ValueError naming `name` when it is not one."""
    try:
        data = json.loads(Path(path).read_text(encoding="utf-8"))
    except (OSError, json.JSONDecodeError) as error:
        raise ValueError(f"{name}: cannot read a report from {path}: {error}") from error
    if not isinstance(data, dict) or not isinstance(data.get("rows"), list) or not data["rows"]:
        raise ValueError(f"{name}: {path} is not a glshade report.json (no rows)")
    missing = [k for k in (*KEY, *FIGURES["time_ns"]) if k not in data["rows"][0]]
    if missing:
        raise ValueError(f"{name}: the rows of {path} lack {', '.join(missing)}")
    return data


def main(a_path: str | Path, b_path: str | Path) -> int:
    """Prints, for each figure, the share of rows agreeing one way and both ways."""
    a, b = load(a_path, "A"), load(b_path, "B")
    for label, path, doc in (("A", a_path, a), ("B", b_path, b)):
        date = doc.get("machine", {}).get("date", "?")
        print(f"{label}: {path} ({doc.get('schema', '?')}, {len(doc['rows'])} rows, {date})")
    results = compare(a, b)
    for figure, result in results.items():
        if result is None:
            print(f"{figure}: not in both reports")
            continue
        print(
            f"{figure} ({result.rows} rows in both): B's median within A's spread "
            f"{result.b_in_a} ({result.share(result.b_in_a):.1%}), A's within B's "
            f"{result.a_in_b} ({result.share(result.a_in_b):.1%}), both ways {result.both} "
            f"({result.share(result.both):.1%}); B / A {result.drift:.3f} (median row); "
            f"spread / median {result.width_a:.1%} in A, {result.width_b:.1%} in B"
        )
    return 0
