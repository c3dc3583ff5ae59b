"""``python -m glshade report``: error against run time for every accuracy mode and dtype.

Four scenes (the benchmark's three and a highlight of shininess 10^4) are shaded in float32 and
float64, ``accuracy="fast"`` and ``"exact"``; each row gives the speed (median of timed calls),
the largest and mean error against a reference evaluated in numpy's long double (x87 extended
on x86-64: 64-bit significand) with the stable power ``exp(s * log1p(-|n^ - h^|^2 / 2))``, and the
fraction of channels whose 8-bit value differs from the reference's. The area-light and
Gouraud-Phong studies follow. Markdown and a PNG plot (error against time, log-log) are written.
"""

from __future__ import annotations

import functools
import statistics
import sys
import time
from pathlib import Path
from typing import Any, Literal

import numpy as np
from numpy.typing import NDArray

from ._bench_shade import bench_scenes, bench_vertices, numpy_shade
from ._png import write_png
from ._scene import Light, Material, Scene
from ._shade import shade
from ._studies import area_light_convergence, gouraud_vs_phong

LD = np.longdouble
MODES: list[tuple[str, Literal["fast", "exact"]]] = [
    ("float32", "fast"),
    ("float32", "exact"),
    ("float64", "fast"),
    ("float64", "exact"),
]
COLOURS = {  # plot colour per mode, RGBA
    ("float32", "fast"): (0.85, 0.3, 0.1, 1.0),
    ("float32", "exact"): (0.95, 0.7, 0.1, 1.0),
    ("float64", "fast"): (0.1, 0.4, 0.85, 1.0),
    ("float64", "exact"): (0.3, 0.75, 0.9, 1.0),
}


def report_scenes() -> dict[str, Scene]:
    """The benchmark's scenes and a narrow highlight (shininess 10^4, one directional light)."""
    scenes = bench_scenes()
    scenes["highlight, s = 10^4"] = Scene(
        [Light(position=(0.0, 0.0, 1.0, 0.0))],
        material=Material(diffuse=(0.3, 0.3, 0.3), specular=(0.7, 0.7, 0.7), shininess=1e4),
    )
    return scenes


def report_vertices(name: str, n: int) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """The benchmark's vertices; for the highlight, normals within 0.03 rad of +z, where
    cos^10^4 falls from 1 to 0.01."""
    p, normals = bench_vertices(n)
    if name.startswith("highlight"):
        rng = np.random.default_rng(1)
        tilt = rng.uniform(0, 0.03, n)
        turn = rng.uniform(0, 2 * np.pi, n)
        normals = np.c_[np.sin(tilt) * np.cos(turn), np.sin(tilt) * np.sin(turn), np.cos(tilt)]
    return p.astype(np.float64), np.asarray(normals, np.float64)


def stable_power(normals: NDArray[Any], h: NDArray[Any], s: Any) -> NDArray[Any]:
    """(n . h)^s = |n|^s (1 - x)^s with x = |n^ - h|^2 / 2, which has no cancellation near the
    highlight: exp(s (log1p(-x) + log |n|)), 0 where n . h <= 0."""
    length = np.sqrt(np.einsum("ij,ij->i", normals, normals))[:, None]
    d = normals / length - h
    x = np.einsum("ij,ij->i", d, d)[:, None] / 2
    with np.errstate(divide="ignore"):  # x = 1: log 0, then masked
        power = np.exp(s * (np.log1p(-np.minimum(x, 1)) + np.log(length)))
    out: NDArray[Any] = np.where(x < 1, power, 0)
    return out


def reference_shade(p: NDArray[Any], n: NDArray[Any], scene: Scene) -> NDArray[np.float64]:
    """The GL equation (Blinn, GL's gate, one side) in long double with the stable power."""
    rgb = numpy_shade(p.astype(LD), n.astype(LD), scene, power=stable_power)[:, :3]
    return rgb.astype(np.float64)


def _median_seconds(call: Any, repeat: int) -> float:
    call()
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        call()
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def measure(n: int, repeat: int, progress: Any = None) -> list[dict[str, Any]]:
    """One row per scene, dtype and mode: speed and error against the long-double reference."""
    rows: list[dict[str, Any]] = []
    scenes = report_scenes()
    steps = len(scenes) * len(MODES)
    for name, scene in scenes.items():
        p, normals = report_vertices(name, n)
        references = {}
        for dtype, accuracy in MODES:
            if progress:
                progress(f"[{len(rows) + 1}/{steps}] {name}, {dtype}, {accuracy}")
            pd, nd = p.astype(dtype), normals.astype(dtype)
            if dtype not in references:  # the reference of the inputs as rounded
                references[dtype] = reference_shade(pd, nd, scene)
            reference = references[dtype]
            got = shade(pd, nd, scene, accuracy=accuracy)[:, :3].astype(np.float64)
            call = functools.partial(shade, pd, nd, scene, accuracy=accuracy)
            seconds = _median_seconds(call, repeat)
            error = np.abs(got - reference)
            rows.append(
                {
                    "scene": name,
                    "dtype": dtype,
                    "accuracy": accuracy,
                    "mvert_s": n / seconds / 1e6,
                    "max_error": float(error.max()),
                    "mean_error": float(error.mean()),
                    "levels8_wrong": float(
                        (np.round(got * 255) != np.round(reference * 255)).mean()
                    ),
                }
            )
    return rows


def plot(rows: list[dict[str, Any]], path: Path, size: int = 480) -> Path:
    """Max error (log, 1e-17..1e-3, up) against ns per vertex (log, 1..1000, right): one dot
    per row, coloured by mode; grid lines at every decade."""
    image = np.ones((size, size, 4))
    margin = 30

    def to_pixel(ns: float, err: float) -> tuple[int, int]:
        x = margin + (np.log10(max(ns, 1.0)) / 3) * (size - 2 * margin)
        y = size - margin - (np.log10(max(err, 1e-17)) + 17) / 14 * (size - 2 * margin)
        return int(np.clip(y, 0, size - 1)), int(np.clip(x, 0, size - 1))

    for decade in range(4):
        _, x = to_pixel(10.0**decade, 1e-17)
        image[margin : size - margin, x] = (0.8, 0.8, 0.8, 1)
    for decade in range(-17, -2):
        y, _ = to_pixel(1.0, 10.0**decade)
        image[y, margin : size - margin] = (0.8, 0.8, 0.8, 1)
    for row in rows:
        y, x = to_pixel(1e3 / row["mvert_s"], row["max_error"])
        image[max(y - 4, 0) : y + 5, max(x - 4, 0) : x + 5] = COLOURS[
            (row["dtype"], row["accuracy"])
        ]
    return write_png(path, image)


def markdown(rows: list[dict[str, Any]], studies: dict[str, list[dict[str, Any]]]) -> str:
    lines = [
        "| scene | dtype | accuracy | Mvert/s | max error | mean error | 8-bit levels wrong |",
        "|---|---|---|---:|---:|---:|---:|",
    ]
    for r in rows:
        lines.append(
            f"| {r['scene']} | {r['dtype']} | {r['accuracy']} | {r['mvert_s']:.1f} | "
            f"{r['max_error']:.2e} | {r['mean_error']:.2e} | {r['levels8_wrong']:.2%} |"
        )
    lines += ["", "Area light sampled by k points (float64) against k = 16384:", ""]
    lines += ["| k | max error | mean error | ms per call |", "|---:|---:|---:|---:|"]
    for r in studies["area"]:
        lines.append(f"| {r['k']} | {r['max_error']:.2e} | {r['mean_error']:.2e} | {r['ms']:.2f} |")
    lines += ["", "Gouraud against per-pixel Phong shading of an icosphere (512 x 512):", ""]
    lines += [
        "| triangles | widest edge (deg) | max error | mean error | 8-bit levels wrong "
        "| Gouraud ms | Phong ms |",
        "|---:|---:|---:|---:|---:|---:|---:|",
    ]
    for r in studies["gouraud"]:
        lines.append(
            f"| {r['triangles']} | {r['edge_degrees']:.1f} | {r['max_error']:.2e} | "
            f"{r['mean_error']:.2e} | {r['levels8_wrong']:.2%} | {r['gouraud_ms']:.1f} | "
            f"{r['phong_ms']:.1f} |"
        )
    return "\n".join(lines) + "\n"


def report(n: int, repeat: int, output: str) -> int:
    """Runs the report, prints the Markdown and writes it with the plot beside it."""
    start = time.perf_counter()

    def progress(message: str) -> None:
        print(f"{time.perf_counter() - start:6.1f} s  {message}", file=sys.stderr, flush=True)

    rows = measure(n, repeat, progress)
    progress("area light convergence")
    area = area_light_convergence()
    progress("Gouraud against Phong")
    gouraud = gouraud_vs_phong()
    text = markdown(rows, {"area": area, "gouraud": gouraud})
    path = Path(output)
    path.write_text(text)
    png = plot(rows, path.with_suffix(".png"))
    print(text)
    colours = ", ".join(
        f"{d} {a}: rgb{tuple(round(c * 255) for c in v[:3])}" for (d, a), v in COLOURS.items()
    )
    print(f"wrote {path} and {png} (max error against ns per vertex, log-log; {colours})")
    progress("done")
    return 0
