#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""What a scene costs per solver as it asks for more modes (issue 17): 1, 6 and 20 modes in one
plane at a time, each solver at its defaults, timed by the wall_time_s of the plane's summary that
`catena solve --json` writes (the solver's own time, statics excluded), each run in a fresh
process, medians of --repeats runs (alternating the cases, so that a burst of load on the machine
spreads over all of them). Scenes: the SI mooring line (fe, shooting; the inextensible and
shallow-cable solvers decline it) and Gale's inextensible catenary of Table B-3 with h/b = 1,
sag parameter 0.98 (frobenius, asymptotic, airy, and shooting again).

  python3 benchmarks/modes_cost.py [--catena build/catena] [--repeats 5] [--out FILE] [--tiny]

--tiny: one repeat, 1 mode, the mooring line only (keeps the script working; no timing checked).
Writes a plain-text table to --out (default benchmarks/results/modes-cost.txt)."""
import argparse
import json
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
CASES = [
    ("verification/scenes/physical/mooring-line-900m.toml", ["fe", "shooting"]),
    ("verification/scenes/gale/gale-b-3-hb1.00-sag0.98.toml", ["frobenius", "asymptotic", "airy", "shooting"]),
]


def solvers_at_defaults(text):
    """The scene's text with each solver's knobs in [solvers] emptied (`fe = { tolerance = 3e-9 }`
    becomes `fe = {}`): the scenes tune their solvers for the suite, this script measures the
    defaults."""
    head, sep, rest = text.partition("\n[solvers]\n")
    if not sep:
        return text
    table, sep2, tail = rest.partition("\n[")
    table = re.sub(r"(?m)^(\w+)[ \t]*=[ \t]*\{.*\}[ \t]*$", r"\1 = {}", table)
    return head + sep + table + sep2 + tail


def scene_with_modes(path, inplane, outofplane):
    """The scene's text with its solvers at their defaults and its [request] mode counts replaced."""
    text = solvers_at_defaults(open(os.path.join(ROOT, path)).read())
    text = re.sub(r"(?m)^\s*(inplane_modes|outofplane_modes)\s*=.*$", "", text)
    counts = f"inplane_modes = {inplane}\noutofplane_modes = {outofplane}\n"
    if re.search(r"(?m)^\[request\]\s*$", text):
        return re.sub(r"(?m)^\[request\]\s*$", "[request]\n" + counts, text, count=1)
    return text + "\n[request]\n" + counts


def run_once(catena, scene_text, solver, plane, work):
    scene = os.path.join(work, "scene.toml")
    out = os.path.join(work, "out.json")
    with open(scene, "w") as f:
        f.write(scene_text)
    if os.path.exists(out):
        os.remove(out)
    # Exit 1 (a check of the scene failed, e.g. a published value it does not reach) still writes
    # the results; only their absence is an error here.
    subprocess.run([catena, "solve", scene, "--solver", solver, "--json", out, "-q"], check=False)
    result = json.load(open(out))
    summary = result["scenes"][0]["solvers"][solver][plane]["summary"]
    return summary["wall_time_s"], summary["termination"], summary.get("operations", -1)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--catena", default=os.path.join(ROOT, "build", "catena"))
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--out", default=os.path.join(HERE, "results", "modes-cost.txt"))
    parser.add_argument("--tiny", action="store_true")
    args = parser.parse_args()
    counts = [1] if args.tiny else [1, 6, 20]
    cases = CASES[:1] if args.tiny else CASES
    repeats = 1 if args.tiny else args.repeats
    rows = []
    for path, solvers in cases:
        for solver in solvers:
            for plane in ("inplane", "outofplane"):
                for n in counts:
                    text = scene_with_modes(path, n if plane == "inplane" else 0, n if plane == "outofplane" else 0)
                    rows.append({"scene": os.path.basename(path)[:-5], "solver": solver, "plane": plane,
                                 "modes": n, "text": text, "times": [], "status": ""})
    with tempfile.TemporaryDirectory() as work:
        for _ in range(repeats):
            for row in rows:
                try:
                    seconds, status, operations = run_once(args.catena, row["text"], row["solver"], row["plane"], work)
                except (KeyError, OSError, ValueError):
                    seconds, status, operations = float("nan"), "no result", -1
                row["times"].append(seconds)
                row["status"] = status
                row["operations"] = operations
    load = os.getloadavg()
    lines = [f"# {time.strftime('%Y-%m-%d %H:%M')}, {os.cpu_count()} hardware threads, load average "
             f"{load[0]:.2f} (1 min) {load[1]:.2f} (5 min) at the end",
             "# the plane's wall_time_s from `catena solve --json` (solver defaults, one plane asked), "
             f"median of {repeats} fresh processes; operations: the summary's own work count (shooting: RHS",
             "# evaluations, fe: eigen-solver operations, frobenius: determinant evaluations, airy: scan evaluations;",
             "# -1: not counted), independent of the load",
             f"{'scene':<28} {'solver':<11} {'plane':<11} {'modes':>5} {'ms':>10} {'operations':>11}  status"]
    for row in rows:
        ms = 1e3 * statistics.median(row["times"])
        lines.append(f"{row['scene']:<28} {row['solver']:<11} {row['plane']:<11} {row['modes']:>5} "
                     f"{ms:>10.3f} {row['operations']:>11}  {row['status']}")
    text = "\n".join(lines) + "\n"
    os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)
    with open(args.out + ".tmp", "w") as f:
        f.write(text)
    os.replace(args.out + ".tmp", args.out)
    sys.stdout.write(text)


if __name__ == "__main__":
    main()
