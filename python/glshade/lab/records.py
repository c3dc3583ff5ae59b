"""The report's records: `Row`, one (scene class, dtype, accuracy mode, instruction set), and
`ReportData`, the rows with the machine, the settings and the studies, as JSON and CSV.
`report.Report` adds writing the files; `report_files` and `figures` read these records."""

from __future__ import annotations

import csv
import io
import json
from dataclasses import asdict, dataclass, fields
from typing import Any

import numpy as np

__all__ = ["SCHEMA", "ReportData", "Row"]

SCHEMA = "glshade-report/2"


@dataclass(frozen=True)
class Row:
    """One (scene class, dtype, accuracy mode, instruction set) of the report.

    Errors are over the RGB channels of every vertex, against the reference: absolute
    (``|got - reference|``) and in ulps (that over the spacing of the dtype at the reference's
    value); a NaN where the reference has NaN counts 0, anywhere else infinity. ``bound`` is the
    mode's bound on unit normals and colours in [0, 1] (`bounds.BOUNDS`);
    ``max_error_over_bound`` the largest error over its channel's own bound (<= 1 when every
    channel is within it), leaving out the ``flipped`` vertices: those within `bounds.EDGE` of a
    discontinuity that land on its other side.

    Times come from ``rounds`` rounds, each one call on ``vertices`` vertices and, in the same
    turn, one of the calibration kernel (`KERNEL`, on the report's vertex count). The headline
    is ``time_over_kernel``: the row's time per vertex over the kernel's, the median of the
    per-round ratios, with the smallest and largest ratio (``time_over_kernel_low``,
    ``_high``) as its stated spread; it is the figure two runs are compared on
    (`report_compare`). ``time_ns`` is the median ns per vertex with the fastest and slowest
    round as its spread (``time_low_ns``, ``time_high_ns``): seconds, as the machine ran
    then. ``kernel_ns`` (and its spread) is the kernel's ns per vertex in the row's rounds.

    Attributes
    ----------
    scene : str
        The scene class's name.
    kind : str
        ``"typical"`` or ``"stiff"``.
    dtype : str
        ``"float32"`` or ``"float64"``.
    accuracy : str
        The accuracy mode: ``"fast"`` or ``"exact"``.
    isa : str
        The instruction set the row ran with (``"avx512"``, ``"avx2"`` or ``"baseline"``).
    vertices : int
        The vertices shaded per call.
    max_error, mean_error, p999_error : float
        The largest, mean and 99.9th-percentile absolute error.
    max_ulps, mean_ulps, p999_ulps : float
        The same errors in ulps of the dtype at the reference's value.
    bound : float
        The mode's bound on unit normals and colours in [0, 1].
    max_error_over_bound : float
        The largest error over its channel's own bound, the ``flipped`` vertices left out.
    flipped : int
        The vertices within `bounds.EDGE` of a discontinuity that land on its other side.
    time_ns, time_low_ns, time_high_ns : float
        Nanoseconds per vertex: the median round, the fastest and the slowest.
    time_over_kernel, time_over_kernel_low, time_over_kernel_high : float
        The time per vertex over the kernel's: the median of the per-round ratios, the
        smallest and the largest.
    kernel_ns, kernel_low_ns, kernel_high_ns : float
        The kernel's nanoseconds per vertex in the row's rounds: median, fastest, slowest.
    rounds : int
        The number of timed rounds.
    """

    scene: str
    kind: str
    dtype: str
    accuracy: str
    isa: str
    vertices: int
    max_error: float
    mean_error: float
    p999_error: float
    max_ulps: float
    mean_ulps: float
    p999_ulps: float
    bound: float
    max_error_over_bound: float
    flipped: int
    time_ns: float
    time_low_ns: float
    time_high_ns: float
    time_over_kernel: float
    time_over_kernel_low: float
    time_over_kernel_high: float
    kernel_ns: float
    kernel_low_ns: float
    kernel_high_ns: float
    rounds: int

    @property
    def mvert_s(self) -> float:
        """Million vertices per second, from the median time."""
        return 1e3 / self.time_ns


@dataclass(frozen=True)
class ReportData:
    """What a `report.Report` holds, with its JSON and CSV: everything but writing its files,
    which `report_files` and `figures` do from these records."""

    rows: tuple[Row, ...]
    machine: dict[str, Any]
    settings: dict[str, Any]
    area_lights: tuple[dict[str, Any], ...] = ()
    gouraud_phong: tuple[dict[str, Any], ...] = ()

    def to_dicts(self) -> list[dict[str, Any]]:
        """The rows as plain dicts (the fields of `Row` and ``mvert_s``), in order."""
        return [{**asdict(r), "mvert_s": r.mvert_s} for r in self.rows]

    def to_json(self, indent: int | None = 2) -> str:
        """Everything as JSON, in the schema of ``report.schema.json`` beside this module:
        ``schema``, ``machine``, ``settings``, ``rows`` and ``studies``; infinities as
        ``null``.

        Parameters
        ----------
        indent : int, optional
            As for `json.dumps`: spaces per level; None writes one line.

        Returns
        -------
        str
            The JSON text.
        """

        def finite(x: Any) -> Any:
            if isinstance(x, float) and not np.isfinite(x):
                return None
            if isinstance(x, dict):
                return {k: finite(v) for k, v in x.items()}
            if isinstance(x, list | tuple):
                return [finite(v) for v in x]
            return x

        data = {
            "schema": SCHEMA,
            "machine": self.machine,
            "settings": self.settings,
            "rows": self.to_dicts(),
            "studies": {
                "area_lights": list(self.area_lights),
                "gouraud_phong": list(self.gouraud_phong),
            },
        }
        return json.dumps(finite(data), indent=indent, allow_nan=False)

    def to_csv(self) -> str:
        """The rows as CSV with a header line (the machine is in `to_json` and the Markdown)."""
        buffer = io.StringIO()
        names = [f.name for f in fields(Row)] + ["mvert_s"]
        writer = csv.DictWriter(buffer, names, lineterminator="\n")
        writer.writeheader()
        writer.writerows(self.to_dicts())
        return buffer.getvalue()
