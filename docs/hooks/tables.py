"""Timing tables rendered from data files, so that no measured number is hand-kept prose.

A line of a page that holds only ::

    {{ bench_table("data/shade-2026-12-03.json") }}

(the path relative to the page's folder) becomes a Markdown table and a caption line: the
command, the CPU, the date and time (UTC), the machine's notes and a link to the file. Lines
inside fenced code blocks are left alone. Two kinds of file:

- the JSON that ``python -m glshade bench shade|normals|render|cluster|builds --json PATH``
  writes
  (``{"bench", "machine", "settings", "results"}``, see ``glshade.lab.bench.save``); the
  command is rebuilt from the bench's name and settings;
- a measurement transcribed from elsewhere (the old README's tables): a JSON object with
  ``"command"``, ``"cpu"``, ``"date"``, ``"notes"`` (strings), ``"columns"`` (the header) and
  ``"rows"`` (lists of cells, as written: strings keep ``10⁴`` and ``1,280`` as they
  were measured), and optionally ``"after"``, a sentence printed under the table.

A missing or malformed file fails the build with a message that names it.
"""

from __future__ import annotations

import json
import re
from collections.abc import Callable
from pathlib import Path
from typing import Any

from mkdocs.config.defaults import MkDocsConfig
from mkdocs.exceptions import PluginError
from mkdocs.structure.files import Files
from mkdocs.structure.pages import Page

DIRECTIVE = re.compile(r'^\{\{\s*bench_table\(\s*"(?P<path>[^"]+)"\s*\)\s*\}\}\s*$')
FENCE = re.compile(r"^\s*(`{3,}|~{3,})")
SUPERSCRIPT = str.maketrans("0123456789", "⁰¹²³⁴⁵⁶⁷⁸⁹")
TIMES, DASH, MINUS = "\N{MULTIPLICATION SIGN}", "\N{EN DASH}", "\N{MINUS SIGN}"
TRANSCRIBED = ("command", "cpu", "date", "notes", "columns", "rows")
# A cell that reads as a number (a count, a time, a ratio): its column is right-aligned.
NUMBER = re.compile(rf"[-{MINUS}]?[\d.,]+(·10[⁰¹²³⁴⁵⁶⁷⁸⁹]+|[⁰¹²³⁴⁵⁶⁷⁸⁹]+)?\s*({TIMES}|x|%|ms|s)?")

Table = tuple[list[str], list[list[str]], str]  # header, rows, a line under the table ("": none)


def count(n: int) -> str:
    """`n` as the tables write it: 10⁴ and 4·10⁶ for round numbers, 502,681 otherwise."""
    digits = str(n)
    zeros = len(digits) - len(digits.rstrip("0"))
    if n > 0 and zeros >= 3 and len(digits) == zeros + 1:
        power = "10" + str(zeros).translate(SUPERSCRIPT)
        return power if digits[0] == "1" else f"{digits[0]}·{power}"
    return f"{n:,}"


def spread(t: dict[str, Any], unit: str = " ms", digits: int = 1) -> str:
    """A timing's median with the fastest and slowest round: ``25.5 ms (24.9 to 31.0)``."""
    return f"{t['median']:.{digits}f}{unit} ({t['low']:.{digits}f}{DASH}{t['high']:.{digits}f})"


def shade_table(data: dict[str, Any]) -> Table:
    """``bench shade``: million vertices/s per scene and size, and the ratios it prints. Files
    written before Dr.Jit and JAX joined have a display column instead of theirs; files with
    the peers also give each method's largest error on the smooth set."""
    peers = any("drjit" in row["mvert_s"] or "jax" in row["mvert_s"] for row in scenes(data))
    methods = ["numpy", "numba", "drjit", "jax"] if peers else ["numpy", "numba"]
    if any("c" in row["mvert_s"] for row in scenes(data)):  # files since the C loop joined
        methods.insert(2, "c")
    header = ["scene", "vertices", "glshade", *methods, "stream"]
    header += [f"{TIMES} {m}" for m in methods] + ["of stream"]
    header += ["f64 exact"] if peers else ["display", "f64 exact"]
    if peers:
        header.append("max error, glshade (largest peer)")
    rows, previous = [], None
    for row in scenes(data):
        rate, ratio = row["mvert_s"], {k: r["median"] for k, r in row["speedup"].items()}
        cells = ["" if row["scene"] == previous else row["scene"], count(row["vertices"])]
        cells += [f"{rate[m]:.1f}" if m in rate else DASH for m in ["glshade", *methods]]
        cells.append(f"{rate['stream']:.1f}")
        cells += [times(ratio[m]) if m in ratio else DASH for m in methods]
        cells.append(f"{ratio['stream']:.2f}")
        if not peers:
            cells.append(f"{1 / ratio['display']:.2f}{TIMES}")
        cells.append(f"{1 / ratio['exact64']:.2f}{TIMES}")
        if peers:
            errors = row.get("error_smooth", {})
            others = [v for k, v in errors.items() if k in methods and v == v]
            cells.append(
                f"{errors['glshade']:.1e} ({max(others):.1e})" if "glshade" in errors else DASH
            )
        rows.append(cells)
        previous = row["scene"]
    results = data["results"]
    after = (
        f"Per-call overhead {results['call_overhead_us']:.1f} µs (16 vertices, one light, "
        f"median); the first call after 50 ms of idle {results['wake_ms']['after_idle']:.2f} ms, "
        f"the next {results['wake_ms']['next']:.2f} ms (10⁶ vertices, one light, medians)."
    )
    threads = results.get("threads")
    if threads:
        one, *more = threads["threads"]

        def label(t: int) -> str:
            return f"{t} thread{'s' if t > 1 else ''}"

        rates = ", ".join(
            f"{label(t)} {threads['mvert_s'][str(t)]:.1f}" for t in threads["threads"]
        )
        ups = ", ".join(f"{threads['speedup'][str(t)]['median']:.2f}{TIMES}" for t in more)
        after += (
            f" Threads, {threads['scene']} at {count(threads['vertices'])} vertices (a child "
            f"process per count, interleaved rounds): {rates} million vertices/s; {ups} "
            f"{label(one)}'s speed (median of the per-round ratios)."
        )
    return header, rows, after


def times(x: float) -> str:
    """A speed-up: three significant digits (69.3, 1.71)."""
    return f"{x:.1f}" if x >= 10 else f"{x:.2f}"


def scenes(data: dict[str, Any]) -> list[dict[str, Any]]:
    """The rows of a ``bench shade`` file, one per scene and size."""
    rows: list[dict[str, Any]] = data["results"]["scenes"]
    return rows


def normals_table(data: dict[str, Any]) -> Table:
    """``bench normals``: each method's median and spread, and the speed-ups over trimesh."""
    results = data["results"]
    rows = [[name, spread(t)] for name, t in results["ms"].items()]
    after = ""
    if "speedup_over_trimesh" in results:
        speedups = "; ".join(
            f"{label} {r['median']:.1f}{TIMES} ({r['low']:.1f}{TIMES} to {r['high']:.1f}{TIMES})"
            for label, r in results["speedup_over_trimesh"].items()
        )
        after = (
            f"Speed-up over trimesh, median of the per-round ratios (their range): {speedups}. "
            f"Largest |glshade {MINUS} trimesh|, angle weighting, float64: "
            f"{results['max_difference_from_trimesh']:.1e}."
        )
    return ["method", f"median (fastest{DASH}slowest round)"], rows, after


def render_table(data: dict[str, Any]) -> Table:
    """``bench render``: one row per scene and method beside its baseline (moderngl on
    llvmpipe for the torus, pyrender's own renderer for pyrender scenes, the smallest texture
    for the texture sizes), the speed-up over it and their agreement. Files written before the
    bench had parts hold the torus alone."""
    results = data["results"]
    parts = {"torus": results} if "ms" in results else results
    header = ["scene", "glshade, ms", "baseline", "baseline, ms", f"{TIMES} baseline", "agreement"]
    rows = []
    torus = parts.get("torus")
    if torus:
        ms, speedup = torus["ms"], torus.get("speedup_over_llvmpipe", {})
        agreeing = torus.get("agreeing_pixels", {})
        for shading in ("flat", "gouraud", "phong"):
            rows.append([
                f"torus, {shading}",
                spread(ms[f"glshade {shading}"], ""),
                "moderngl on llvmpipe",
                spread(ms[f"llvmpipe {shading}"], "") if f"llvmpipe {shading}" in ms else DASH,
                f"{speedup[shading]['median']:.2f}" if shading in speedup else DASH,
                f"{agreeing[shading]:.3%} within 1e-4" if shading in agreeing else DASH,
            ])  # fmt: skip
    for name, scene in parts.get("pyrender", {}).items():
        rows.append([
            f"pyrender: {name}",
            spread(scene["ms"]["glshade"], ""),
            "pyrender OffscreenRenderer",
            spread(scene["ms"]["pyrender"], ""),
            f"{scene['speedup_over_pyrender']['median']:.2f}",
            f"{scene['max_interior_difference_255']:.2f}/255 at most, interior",
        ])  # fmt: skip
    texture = parts.get("texture")
    if texture:
        first = next(iter(texture["ms"]))
        for name, t in texture["ms"].items():
            rows.append([
                f"64x64 render, {name} texture",
                spread(t, "", 2),
                f"{first} texture",
                spread(texture["ms"][first], "", 2),
                f"{1 / texture['over_first'][name]['median']:.2f}",
                DASH,
            ])  # fmt: skip
    return header, rows, ""


def cluster_table(data: dict[str, Any]) -> Table:
    """``bench cluster``: one local call and the cluster, seconds and million vertices/s."""
    results = dict(data["results"])
    same = results.pop("bit_identical")
    rows = [[name, spread(t, " s", 2), f"{t['mvert_s']:.1f}"] for name, t in results.items()]
    after = f"Cluster output bit-identical to the local call's: {same}."
    return ["method", f"median (fastest{DASH}slowest round)", "Mvert/s"], rows, after


def builds_table(data: dict[str, Any]) -> Table:
    """``bench builds``: million vertices/s per build, round and scene, and under the table
    each build's speed over the first's (medians of per-round ratios)."""
    settings, results = data["settings"], data["results"]
    names = settings["scenes"]
    header = ["build", "round", *names]
    rows = [
        [row["build"], str(row["round"]), *(f"{row['mvert_s'][s]:.1f}" for s in names)]
        for row in results["rows"]
    ]
    first = settings["labels"][0]
    after = " ".join(
        f"{label} over {first} (medians of per-round ratios): "
        + ", ".join(f"{s} {times(x)}{TIMES}" for s, x in by_scene.items())
        + "."
        for label, by_scene in results["ratios"].items()
    )
    return header, rows, after


BENCHES: dict[str, tuple[Callable[[dict[str, Any]], Table], tuple[str, ...]]] = {
    # The table, and the settings that are flags of the command, in the command's order.
    "shade": (shade_table, ("sizes", "scenes", "rounds")),
    "normals": (normals_table, ("faces", "settle_s", "rounds")),
    "render": (render_table, ("faces", "size", "scenes", "rounds")),
    "cluster": (cluster_table, ("vertices", "chunk", "workers", "repeat")),
    "builds": (
        builds_table,
        ("builds", "labels", "rounds", "vertices", "scenes", "dtype", "threads", "seconds"),
    ),
}
FLAGS = {"rounds": "repeat", "settle_s": "settle"}  # settings saved under another name


def bench_caption(data: dict[str, Any], name: str) -> tuple[str, str, str, str]:
    """Command, CPU, date and notes of a bench's own JSON."""
    bench, settings, machine = data["bench"], data["settings"], data["machine"]
    flags = []
    for key in BENCHES[bench][1]:
        if key not in settings:  # a setting an older bench did not have
            continue
        values = settings[key] if isinstance(settings[key], list) else [settings[key]]
        if key == "scenes":
            flags.append(f"--scenes '{','.join(values)}'")
        elif key == "builds":  # the positional paths, as the files were named
            flags.append(" ".join(values))
        elif key == "labels":
            flags.append(f"--labels '{','.join(values)}'")
        else:
            flags.append(f"--{FLAGS.get(key, key)} {' '.join(map(str, values))}")
    command = f"python -m glshade bench {bench} {' '.join(flags)} --json {name}"
    date = machine["date"].replace("T", " ").replace("+00:00", " UTC") + " (results saved)"
    # `bench builds` runs each build in a child with threads of its own.
    threads = settings["threads"] if bench == "builds" else machine["threads"]
    notes = (
        f"{machine['usable_cpus']} of {machine['logical_cpus']} CPUs usable; glshade "
        f"{machine['glshade']} ({machine['instruction_set']}, {threads} threads), "
        f"numpy {machine['numpy']}, Python {machine['python']}; {machine['platform']}"
    )
    if "numba" in settings:
        numba = settings["numba"]
        notes += (
            f"; numba {numba['version']} ({numba['threads']} threads, {numba['threading_layer']} "
            f"layer, OMP_WAIT_POLICY={numba['OMP_WAIT_POLICY']})"
        )
    if "compiler" in settings.get("c", {}):
        c = settings["c"]
        notes += f"; C loop: {c['compiler']}, {c['flags']} ({c['threads']} threads)"
    # A peer that could not run is recorded as {"unavailable": why}: said so, not read.
    for peer in ("drjit", "jax"):
        if "unavailable" in settings.get(peer, {}):
            notes += f"; {'Dr.Jit' if peer == 'drjit' else 'JAX'} unavailable"
    if "version" in settings.get("drjit", {}):
        drjit = settings["drjit"]
        notes += f"; Dr.Jit {drjit['version']} (LLVM {drjit['llvm']}, {drjit['threads']} threads)"
    if "version" in settings.get("jax", {}):
        jax = settings["jax"]
        notes += f"; JAX {jax['version']}, jaxlib {jax['jaxlib']} ({jax['threads']} threads)"
    return command, machine["cpu"], date, notes


def cell(value: Any) -> str:
    """A cell's Markdown: pipes escaped, so that ``|n|²`` stays in its cell."""
    return str(value).replace("|", "\\|")


def to_markdown(header: list[str], rows: list[list[str]]) -> str:
    """A Markdown table; columns of numbers only are right-aligned."""

    def numeric(i: int) -> bool:
        cells = [str(row[i]) for row in rows if str(row[i])]
        return bool(cells) and all(NUMBER.fullmatch(c) for c in cells)

    rule = ["---:" if numeric(i) else "---" for i in range(len(header))]
    lines = [header, rule, *rows]
    return "\n".join("| " + " | ".join(cell(c) for c in line) + " |" for line in lines)


def table(path: Path, name: str) -> str:
    """The Markdown of the data file at `path` (linked as `name`): table, line, caption."""
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError) as error:
        raise PluginError(f"bench_table: cannot read {path}: {error}") from error
    try:
        if isinstance(data, dict) and "bench" in data:
            if data["bench"] not in BENCHES:
                raise ValueError(f"unknown bench {data['bench']!r}")
            header, rows, after = BENCHES[data["bench"]][0](data)
            command, cpu, date, notes = bench_caption(data, path.name)
        else:
            missing = [key for key in TRANSCRIBED if key not in data]
            if missing:
                raise ValueError(f"missing {', '.join(missing)}")
            header, rows, after = list(data["columns"]), list(data["rows"]), data.get("after", "")
            command, cpu, date, notes = (str(data[key]) for key in TRANSCRIBED[:4])
            for i, row in enumerate(rows):
                if not isinstance(row, list) or len(row) != len(header):
                    raise ValueError(f"row {i + 1} is not a list of {len(header)} cells: {row!r}")
    except (KeyError, TypeError, ValueError, AttributeError) as error:
        raise PluginError(f"bench_table: {path} is malformed: {error!r}") from error
    caption = (
        f"*Command:* `{command}` · *CPU:* {cpu} · *Date:* {date} · *Notes:* {notes} · "
        f"[data]({name})"
    )
    return "\n\n".join(part for part in (to_markdown(header, rows), after, caption) if part)


def on_page_markdown(markdown: str, *, page: Page, config: MkDocsConfig, files: Files) -> str:
    """Replaces each ``{{ bench_table("...") }}`` line outside code blocks with its table."""
    folder = Path(page.file.abs_src_path or "").parent
    lines, fence = [], ""
    for line in markdown.split("\n"):
        opened = FENCE.match(line)
        if opened and (not fence or opened.group(1).startswith(fence)):
            fence = "" if fence else opened.group(1)
        match = None if fence else DIRECTIVE.match(line)
        try:
            lines.append(table(folder / match["path"], match["path"]) if match else line)
        except PluginError as error:
            raise PluginError(f"{page.file.src_uri}: {error}") from error
    return "\n".join(lines)
