# SPDX-License-Identifier: GPL-3.0-or-later
"""python3 -m validation list | run STUDY [--quick] [--jobs N] [--cli PATH] | check [STUDY ...]

list    the studies, what each is and what it keeps (docs/validation.md)
run     solves what the study's table lacks, then writes its generated tables, files and figures;
        --quick: small grids and few seeds into build/validation-quick/ (the repository untouched)
check   writes nothing and solves nothing (roughness reruns its CLI checks): the study's tables are those its manifest records,
        hold every solve, and give the committed generated files (constants refitted included);
        exit 1 with what differs. Without STUDY, every study.
"""
import argparse
import sys
import time

try:
    import numpy  # noqa: F401 (the studies' fits and surrogates; matplotlib draws the figures)
except ImportError:
    sys.exit(f"python3 -m validation: {sys.executable} has no numpy: run it with the system's "
             "/usr/bin/python3 (./Allwmake installs python3-numpy and python3-matplotlib)")

from . import tables  # noqa: E402
from .context import Context  # noqa: E402
from .studies import STUDIES, study  # noqa: E402


def main(argv=None):
    parser = argparse.ArgumentParser(prog="python3 -m validation", description=__doc__.split("\n\n")[0])
    sub = parser.add_subparsers(dest="command", required=True)
    listing = sub.add_parser("list", help="the studies")
    listing.add_argument("--names", action="store_true", help="the names alone, one a line (for CTest)")
    run = sub.add_parser("run", help="solve what is missing and write the generated files")
    run.add_argument("study")
    run.add_argument("--quick", action="store_true", help="small grids and few seeds, into build/validation-quick/")
    run.add_argument("--jobs", type=int, help="solves at once (default: the processors)")
    run.add_argument("--cli", help="the multiscaleContact to use (default: build/bin/multiscaleContact)")
    check = sub.add_parser("check", help="the committed files are what the committed data give")
    check.add_argument("study", nargs="*")
    check.add_argument("--cli", help="the multiscaleContact to use (default: build/bin/multiscaleContact)")
    args = parser.parse_args(argv)

    if args.command == "list" and args.names:
        print("\n".join(m.__name__.rsplit(".", 1)[1] for m in STUDIES))
        return 0
    if args.command == "list":
        width = max(len(m.__name__.rsplit(".", 1)[1]) for m in STUDIES)
        for m in STUDIES:
            name = m.__name__.rsplit(".", 1)[1]
            print(f"{name:<{width}}  {m.__doc__.strip().splitlines()[0]}")
        return 0
    if args.command == "run":
        ctx = Context(quick=args.quick, jobs=args.jobs, cli=args.cli)
        m = study(args.study)
        started = time.time()
        m.solve(ctx)
        out = m.outputs(ctx)
        out.write()
        print(f"{args.study}: wrote {len(out.texts)} files and {len(out.figures)} figures in "
              f"{time.time() - started:.0f} s", flush=True)
        return 0
    ctx = Context(checking=True, cli=args.cli)
    failed = []
    for m in [study(s) for s in args.study] or STUDIES:
        name = m.__name__.rsplit(".", 1)[1]
        started = time.time()
        problems = [p for p in (tables.verify(ctx.data, d) for d in getattr(m, "DATA", [])) if p]
        if not problems:
            m.solve(ctx)  # in check: that every solve is there
            problems = [f"{path} is not what the data give" for path in m.outputs(ctx).differences()]
        if problems:
            failed.append(name)
            for p in problems:
                print(f"{name}: {p}", file=sys.stderr)
            print(f"{name}: FAILED (python3 -m validation run {name} remakes it; review the difference)",
                  file=sys.stderr)
        else:
            print(f"{name}: the committed files are what the data give ({time.time() - started:.1f} s)", flush=True)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
