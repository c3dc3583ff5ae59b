"""Command line: ``python -m glshade demo|report|bench ...``, the benches being ``shade``,
``normals``, ``render``, ``cluster``, ``relief`` and ``builds``."""

from __future__ import annotations

import argparse
from collections.abc import Sequence
from pathlib import Path

__all__ = ["main"]


def _positive(text: str) -> int:
    value = int(text)
    if value < 1:
        raise argparse.ArgumentTypeError(f"must be a positive integer, got {value}")
    return value


def _sizes(text: str) -> list[int]:
    """Vertex counts separated by commas, each a positive integer."""
    return [_positive(part) for part in text.split(",") if part.strip()]


def _at_least_two(text: str) -> int:
    value = int(text)
    if value < 2:
        raise argparse.ArgumentTypeError(f"must be at least 2, got {value}")
    return value


def _not_negative(text: str) -> float:
    value = float(text)
    if not value >= 0:
        raise argparse.ArgumentTypeError(f"must not be negative, got {text}")
    return value


def _positive_seconds(text: str) -> float:
    value = float(text)
    if not value > 0:
        raise argparse.ArgumentTypeError(f"must be a positive number of seconds, got {text}")
    return value


def _names(text: str) -> list[str]:
    """Names separated by commas, none empty."""
    names = [part.strip() for part in text.split(",")]
    if not all(names):
        raise argparse.ArgumentTypeError(f"expected names separated by commas, got {text!r}")
    return names


def _render_parts(text: str) -> list[str]:
    from .bench import RENDER_PARTS

    parts = _names(text)
    unknown = [p for p in parts if p not in RENDER_PARTS]
    if unknown:
        raise argparse.ArgumentTypeError(
            f"unknown part {unknown[0]!r}: the parts are {', '.join(RENDER_PARTS)}"
        )
    return parts


def _scenes(text: str) -> list[str]:
    from .scenes import scene_names

    try:
        return scene_names(text)
    except ValueError as error:
        raise argparse.ArgumentTypeError(str(error)) from None


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="python -m glshade", description=__doc__)
    commands = parser.add_subparsers(dest="command", required=True)
    run = commands.add_parser(
        "demo", help="shade and render a built-in scene, print timings, write PNGs"
    )
    run.add_argument("--size", type=_positive, default=1024, help="image size (default 1024)")
    run.add_argument("--repeat", type=_positive, default=7, help="timed rounds (default 7)")
    run.add_argument(
        "--output",
        default="glshade-demo.png",
        help="PNG path of the shaded sphere (default ./glshade-demo.png), its folder created "
        "if missing; the renders go beside it with -flat, -gouraud and -phong added to the name",
    )
    rep = commands.add_parser(
        "report",
        help="error against run time of every scene class, dtype, accuracy mode and "
        "instruction set, with studies; writes report.md, .json, .csv and figures",
    )
    rep.add_argument("--out", default="glshade-report", help="directory (default ./glshade-report)")
    rep.add_argument(
        "--vertices", type=_positive, default=100_000, help="per scene class (default 10^5)"
    )
    rep.add_argument("--rounds", type=_positive, default=9, help="timed rounds (default 9)")
    rep.add_argument(
        "--isa",
        nargs="+",
        choices=["avx512", "avx2", "baseline"],
        help="instruction sets (default: every one this CPU runs)",
    )
    rep.add_argument("--no-studies", action="store_true", help="leave out the two studies")
    rep.add_argument("--quiet", action="store_true", help="no progress bar")
    rep.add_argument(
        "--compare",
        nargs=2,
        metavar=("A.json", "B.json"),
        help="measure nothing: print the share of rows on which two report.json files agree",
    )
    bench = commands.add_parser("bench", help="time glshade beside its baselines in the same run")
    which = bench.add_subparsers(dest="what", required=True)
    shade = which.add_parser(
        "shade", help="gs.shade beside numpy, numba, Dr.Jit and JAX, each checked first"
    )
    shade.add_argument(
        "--sizes",
        type=_sizes,
        nargs="+",
        default=[[10_000, 100_000, 1_000_000, 4_000_000]],
        help="vertex counts, separated by spaces or commas (default 10^4 10^5 10^6 4*10^6)",
    )
    shade.add_argument(
        "--scenes",
        type=_scenes,
        default="all",
        help='comma-separated scenes and groups: "bench" (the three scenes "1 directional", '
        '"1 point, local viewer" and "8 mixed"), "extra" ("16 mixed", "2 directional", '
        '"spot 2.5", "32 point"), "all" (default: both)',
    )
    shade.add_argument(
        "--no-threads-check",
        action="store_true",
        help="leave out glshade on 8 mixed at the largest size with 1 and 2 threads",
    )
    normals = which.add_parser("normals", help="vertex and face normals beside trimesh")
    normals.add_argument("--faces", type=_at_least_two, default=1_000_000, help="default 10^6")
    normals.add_argument(
        "--settle",
        type=_not_negative,
        default=0.25,
        help="seconds of idle before each timed call (default 0.25)",
    )
    render = which.add_parser("render", help="gs.render beside moderngl on Mesa's llvmpipe")
    render.add_argument("--faces", type=_at_least_two, default=100_000, help="default 10^5")
    render.add_argument("--size", type=_positive, default=1024, help="image size (default 1024)")
    render.add_argument(
        "--scenes",
        type=_render_parts,
        default="torus,pyrender,texture",
        help="which parts, comma-separated: torus (beside moderngl on llvmpipe), pyrender "
        "(pyrender scenes beside pyrender's OffscreenRenderer), texture (textures of growing "
        "size); default all three",
    )
    cluster = which.add_parser(
        "cluster", help="glshade.dask on a LocalCluster beside one gs.shade call, memmap to memmap"
    )
    cluster.add_argument(
        "--vertices", type=_positive, default=100_000_000, help="float32 vertices (default 10^8)"
    )
    cluster.add_argument(
        "--chunk", type=_positive, default=2_000_000, help="rows per task (default 2*10^6)"
    )
    cluster.add_argument("--workers", type=_positive, default=2, help="processes (default 2)")
    cluster.add_argument(
        "--dir", help="where the scratch .npy files go (default: the temporary directory)"
    )
    relief = which.add_parser("relief", help="glshade.relief beside matplotlib's LightSource")
    relief.add_argument("--size", type=_at_least_two, default=2048, help="grid side (default 2048)")
    builds = which.add_parser(
        "builds",
        help="builds of glshade's core against each other: the scenes of bench shade with each "
        "built extension module in turn, alternating",
    )
    builds.add_argument(
        "build",
        nargs="+",
        help="two or more built extension modules (copies of python/glshade/_glshade.abi3.so "
        "after `maturin develop --release`)",
    )
    builds.add_argument(
        "--labels", type=_names, help="a name per build, comma-separated (default: file names)"
    )
    builds.add_argument(
        "--repeat", type=_positive, default=2, help="rounds, the builds alternating (default 2)"
    )
    builds.add_argument(
        "--vertices", type=_positive, default=1_000_000, help="vertices per call (default 10^6)"
    )
    builds.add_argument(
        "--scenes", type=_scenes, default="all", help="as for bench shade (default all)"
    )
    builds.add_argument(
        "--dtype", choices=("float32", "float64"), default="float32", help="default float32"
    )
    builds.add_argument(
        "--threads", type=_positive, default=1, help="glshade's threads per build (default 1)"
    )
    builds.add_argument(
        "--seconds",
        type=_positive_seconds,
        default=1.5,
        help="how long each scene is called per build and round; the median call counts "
        "(default 1.5)",
    )
    builds.add_argument(
        "--json",
        default="glshade-bench-builds.json",
        help="where the results go, with the machine (default ./glshade-bench-builds.json)",
    )
    beside = {"shade": "; a .csv of one row per scene, size and method beside it"}
    benches = (
        (shade, "shade"), (normals, "normals"), (render, "render"), (cluster, "cluster"),
        (relief, "relief"),
    )  # fmt: skip
    for sub, name in benches:
        sub.add_argument("--repeat", type=_positive, default=7, help="rounds (default 7)")
        sub.add_argument(
            "--json",
            default=f"glshade-bench-{name}.json",
            help=f"where the results go, with the machine (default ./glshade-bench-{name}.json)"
            f"{beside.get(name, '')}",
        )
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    """Parses `argv` (default: the command line) and runs the command; its exit status."""
    parser = _parser()
    args = parser.parse_args(argv)
    if args.command == "report" and args.compare:
        from .report_compare import main as compare

        try:
            return compare(*args.compare)
        except ValueError as error:
            parser.error(f"--compare: {error}")
    if args.command == "report":
        import glshade as gs

        result = gs.report(
            vertices=args.vertices,
            rounds=args.rounds,
            isas=args.isa,
            studies=not args.no_studies,
            progress=not args.quiet,
        )
        for path in result.write(Path(args.out)):
            print(f"wrote {path}")
        return 0
    if args.command == "bench":
        from . import bench, bench_shade

        if args.what == "shade":
            return bench_shade.bench_shade(
                tuple(size for group in args.sizes for size in group),
                args.repeat,
                args.json,
                scenes=args.scenes,
                threads_check=not args.no_threads_check,
            )
        if args.what == "builds":
            from .bench_builds import bench_builds

            try:
                return bench_builds(
                    args.build,
                    labels=args.labels,
                    rounds=args.repeat,
                    vertices=args.vertices,
                    scenes=args.scenes,
                    dtype=args.dtype,
                    threads=args.threads,
                    seconds=args.seconds,
                    json_path=args.json,
                )
            except (ValueError, RuntimeError) as error:  # a build that does not import or run
                parser.error(str(error))
        if args.what == "render":
            return bench.bench_render(
                args.faces, args.size, args.repeat, args.json, tuple(args.scenes)
            )
        if args.what == "relief":
            from .bench_relief import bench_relief

            return bench_relief(args.size, args.repeat, args.json)
        if args.what == "cluster":
            from .bench_cluster import bench_cluster

            return bench_cluster(
                args.vertices, args.chunk, args.workers, args.repeat, args.json, args.dir
            )
        return bench.bench_normals(args.faces, args.repeat, args.settle, args.json)
    from .demo import demo

    folder = Path(args.output).parent
    try:
        # Before the work, not after it: a missing folder is made, one that cannot be is named.
        folder.mkdir(parents=True, exist_ok=True)
    except OSError as error:
        in_the_way = isinstance(error, (FileExistsError, NotADirectoryError))
        reason = "a file is in the way" if in_the_way else error.strerror
        parser.error(f"--output: cannot create the folder {folder} ({reason}: {error.filename})")
    return demo(args.size, args.repeat, args.output)
