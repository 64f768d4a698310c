# SPDX-License-Identifier: MIT
"""`python3 -m catena sweep SPEC.toml --out DIR`, which `catena sweep` runs (docs/how-to/sweep.md).

Exit codes as the catena CLI's: 0 done, 2 bad input or usage (the message names the field),
130 interrupted (what was written is kept: rerun the same command to resume).
"""

import argparse
import os
import sys

HELP = """Solve a scene at every point of a SPEC's axes on Dask, into DIR/points.csv (one row per
point, in the spec's order), DIR/summary.json and DIR/journal.csv. Rerunning the same command
resumes: only the points not yet written are solved. A journal of another SPEC is refused.
SPEC format and the columns: docs/how-to/sweep.md."""


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="catena sweep", description=HELP,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("spec", metavar="SPEC.toml", help="the sweep's SPEC (TOML)")
    parser.add_argument("--out", metavar="DIR", required=True,
                        help="output directory (created; an existing sweep of the same SPEC in it is resumed)")
    where = parser.add_mutually_exclusive_group()
    where.add_argument("--workers", metavar="N", type=int,
                       help=f"local Dask cluster of N worker processes, one thread each (default: all "
                            f"cores, here {os.cpu_count()})")
    where.add_argument("--scheduler", metavar="ADDRESS",
                       help="an existing Dask scheduler, e.g. tcp://host:8786 (its workers need catena "
                            "importable); it must answer within 5 s")
    parser.add_argument("--quiet", action="store_true", help="no progress line on stderr")
    parser.add_argument("--batch-seconds", metavar="S", type=float, default=0.1,
                        help="target solve time of one Dask task [s] (default 0.1)")
    return parser


def sweep_main(argv: list[str]) -> int:
    arguments = _parser().parse_args(argv)
    from . import InvalidInput
    from ._sweep_run import run_sweep

    if not arguments.out.strip():
        print("error: --out: an empty directory name", file=sys.stderr)
        return 2
    try:
        path, summary = run_sweep(arguments.spec, arguments.out, scheduler=arguments.scheduler,
                                  workers=arguments.workers, progress=None if not arguments.quiet else False,
                                  batch_seconds=arguments.batch_seconds)
    except InvalidInput as error:
        print(f"error: {error}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print(f"\ninterrupted: the points written so far are kept in {arguments.out}/journal.csv; "
              "rerun the same command to resume", file=sys.stderr)
        return 130
    if not arguments.quiet:
        print(f"sweep: {summary['points']} points ({summary['computed']} solved now, {summary['resumed']} "
              f"resumed) in {summary['wall_time_s']:.1f} s on {summary['workers']} worker(s): {path}",
              file=sys.stderr)
    return 0


def main(argv: list[str]) -> int:
    if not argv or argv[0] in ("-h", "--help"):
        print("usage: python3 -m catena sweep SPEC.toml --out DIR [--workers N | --scheduler ADDRESS] [--quiet]\n"
              "       python3 -m catena sweep --help")
        return 0 if argv else 2
    if argv[0] != "sweep":
        print(f"error: unknown command {argv[0]!r}; python3 -m catena has one command: sweep", file=sys.stderr)
        return 2
    try:
        return sweep_main(argv[1:])
    except SystemExit as exit_:  # argparse: usage errors exit 2, --help 0
        return int(exit_.code or 0)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
