"""Command line: ``python -m glshade demo``."""

from __future__ import annotations

import argparse
import sys
from collections.abc import Sequence

from ._bench import bench_normals, bench_render
from ._bench_shade import SIZES, bench_shade
from ._demo import demo
from ._report import report


def main(argv: Sequence[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m glshade", description=__doc__)
    commands = parser.add_subparsers(dest="command", required=True)
    run = commands.add_parser(
        "demo", help="shade and render a built-in scene, print timings, write PNGs"
    )
    run.add_argument("--size", type=int, default=1024, help="image size in pixels (default 1024)")
    run.add_argument("--repeat", type=int, default=7, help="timed runs per dtype (default 7)")
    run.add_argument(
        "--output",
        default="glshade-demo.png",
        help="PNG path of the shaded sphere (default ./glshade-demo.png); the renders go beside "
        "it with -flat, -gouraud and -phong added to the name",
    )
    rep = commands.add_parser(
        "report", help="error against run time of every accuracy mode and dtype, with studies"
    )
    rep.add_argument("--vertices", type=int, default=200_000, help="per scene (default 2*10^5)")
    rep.add_argument("--repeat", type=int, default=7, help="timed calls per row (default 7)")
    rep.add_argument(
        "--output",
        default="glshade-report.md",
        help="Markdown path (default ./glshade-report.md); the plot goes beside it as .png",
    )
    bench = commands.add_parser("bench", help="time glshade beside its baselines in the same run")
    bench.add_argument(
        "what",
        choices=["shade", "normals", "render"],
        help="shade: gs.shade beside numpy and numba; normals: vertex and face normals beside "
        "trimesh; render: gs.render beside moderngl on Mesa's llvmpipe",
    )
    bench.add_argument(
        "--sizes",
        type=int,
        nargs="+",
        default=list(SIZES),
        help="shade: vertex counts (default 10^4 10^5 10^6 4*10^6)",
    )
    bench.add_argument(
        "--faces", type=int, help="mesh size (default 10^6 for normals, 10^5 for render)"
    )
    bench.add_argument("--size", type=int, default=1024, help="render: image size (default 1024)")
    bench.add_argument("--repeat", type=int, default=7, help="rounds (default 7)")
    bench.add_argument(
        "--settle",
        type=float,
        default=0.25,
        help="normals: seconds of idle before each timed call (default 0.25)",
    )
    args = parser.parse_args(argv)
    if args.repeat < 1:
        parser.error("--repeat must be positive")
    if getattr(args, "size", 1) < 1:
        parser.error("--size must be positive")
    if args.command == "report":
        if args.vertices < 1:
            parser.error("--vertices must be positive")
        return report(args.vertices, args.repeat, args.output)
    if args.command == "bench" and args.what == "shade":
        if min(args.sizes) < 1:
            parser.error("--sizes must be positive")
        return bench_shade(tuple(args.sizes), args.repeat)
    if args.command == "bench":
        faces = args.faces or (1_000_000 if args.what == "normals" else 100_000)
        if faces < 2:
            parser.error("--faces must be at least 2")
        if not args.settle >= 0:
            parser.error("--settle must not be negative")
        if args.what == "render":
            return bench_render(faces, args.size, args.repeat)
        return bench_normals(faces, args.repeat, args.settle)
    return demo(args.size, args.repeat, args.output)


if __name__ == "__main__":
    sys.exit(main())
