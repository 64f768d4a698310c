#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Measured accuracy of the exact solvers over the verification suite (docs/explanation/methods/shooting.md,
"Accuracy over the suite"; docs/explanation/methods/fe.md, "Error estimate").

Runs the suite twice through `catena verify`, on copies of the scenes rewritten to run only the
exact solvers with chosen knobs (published values, checks and forced responses dropped):

  run "default":   shooting and frobenius at their defaults, fe at N = 4000 (+ 8000) with Richardson
  run "reference": shooting at rtol 1e-13, fe at its defaults

plus the mooring line of issue 12 (L = 1000 m, b = (700, 650) m) as one more scene. It then reports

  1. shooting at its defaults against each reference (fe at N = 4000, frobenius, shooting at rtol
     1e-13): the largest relative error, the worst case named, and every mode beyond --target;
  2. fe at its defaults: its error estimate over its actual error (against the best reference that
     ran: frobenius, else shooting at rtol 1e-13): min / median / max of the ratio, and every mode
     whose estimate is below its actual error.

Usage: scripts/solver_accuracy.py [--catena build/catena] [--scenes verification/scenes]
                                  [--work build-accuracy] [--target 1e-9] [--filter TEXT]
Exit 1 when shooting misses --target anywhere or fe's estimate is below its actual error anywhere.
"""
import argparse
import json
import math
import pathlib
import shutil
import statistics
import subprocess
import sys
import tomllib

RUNS = {
    "default": {"shooting": {}, "frobenius": {}, "fe": {"elements": 4000}},
    "reference": {"shooting": {"rtol": 1e-13}, "fe": {}},
}

MOORING = {
    "name": "issue12-mooring-700-650",
    "cable": {"length": 1000.0, "weight": 1000.0, "EA": 5.0e8, "mass": 120.0,
              "added_mass": 80.0, "a": [0.0, 0.0], "b": [700.0, 650.0]},
    "request": {"inplane_modes": 6, "outofplane_modes": 6},
}


def toml_value(value):
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, (int, float)):
        return repr(value)
    if isinstance(value, str):
        return json.dumps(value)
    if isinstance(value, list):
        return "[" + ", ".join(toml_value(v) for v in value) + "]"
    if isinstance(value, dict):
        return "{" + ", ".join(f"{k} = {toml_value(v)}" for k, v in value.items()) + "}"
    raise TypeError(f"cannot write {value!r} as TOML")


def write_toml(data, path):
    """A scene as TOML: top-level keys, then one [table] per dict (one level of nesting)."""
    lines = [f"{k} = {toml_value(v)}" for k, v in data.items() if not isinstance(v, dict)]
    for table, body in data.items():
        if isinstance(body, dict):
            lines.append(f"\n[{table}]")
            lines += [f"{k} = {toml_value(v)}" for k, v in body.items()]
    path.write_text("\n".join(lines) + "\n")


def rewrite_scene(scene, solvers):
    """The scene with only its modes asked, run by `solvers` (the scene's own knobs of a solver
    kept unless the run sets them); None when it asks for no modes."""
    own = scene.get("solvers", {})
    scene = {k: v for k, v in scene.items() if k not in ("published", "checks", "solvers")}
    request = dict(scene.get("request", {}))
    for key in ("forced", "shapes", "tension", "points"):
        request.pop(key, None)
    if request.get("inplane_modes", 0) + request.get("outofplane_modes", 0) == 0:
        return None
    scene["request"] = request
    scene["solvers"] = {name: {**own.get(name, {}), **knobs} for name, knobs in solvers.items()}
    return scene


def prepare(scenes_dir, work, run):
    out = work / f"scenes-{run}"
    shutil.rmtree(out, ignore_errors=True)
    for source in sorted(scenes_dir.rglob("*.toml")):
        scene = tomllib.loads(source.read_text())
        rewritten = rewrite_scene(scene, RUNS[run])
        if rewritten is None:
            continue
        target = out / source.relative_to(scenes_dir)
        target.parent.mkdir(parents=True, exist_ok=True)
        write_toml(rewritten, target)
    write_toml(rewrite_scene(MOORING, RUNS[run]), out / "issue12-mooring.toml")
    return out


def run_suite(catena, scenes, work, run, filter_text):
    out = work / f"report-{run}"
    command = [catena, "verify", "--scenes", str(scenes), "--out", str(out), "-q", "-j", "2"]
    if filter_text:
        command += ["--filter", filter_text]
    subprocess.run(command, check=False, stdout=subprocess.DEVNULL)
    return json.loads((out / "report.json").read_text())


def modes_of(report):
    """{(scene, solver, plane): [(index, omega, estimate)]} of every plane that converged."""
    table = {}
    for scene in report["scenes"]:
        for solver, output in scene.get("solvers", {}).items():
            for plane in ("inplane", "outofplane"):
                part = output.get(plane)
                if not part or part["summary"]["termination"] != "converged":
                    continue
                table[(scene["name"], solver, plane)] = [
                    (m["index"], m["omega_rad_s"], m["relative_error_estimate"])
                    for m in part["modes"]]
    return table


def compare(candidate, reference):
    """[(scene, plane, mode, relative difference, reference estimate)] where both ran."""
    rows = []
    for (scene, plane), modes in candidate.items():
        ref = {m[0]: m for m in reference.get((scene, plane), [])}
        for index, omega, _ in modes:
            if index in ref:
                rows.append((scene, plane, index, abs(omega - ref[index][1]) / ref[index][1],
                             ref[index][2]))
    return rows


def solver_table(all_modes, solver):
    return {(s, p): m for (s, name, p), m in all_modes.items() if name == solver}


def report_shooting(default, reference, target):
    shooting = solver_table(default, "shooting")
    references = {
        "fe N=4000 Richardson": solver_table(default, "fe"),
        "frobenius": solver_table(default, "frobenius"),
        "shooting rtol 1e-13": solver_table(reference, "shooting"),
    }
    print(f"shooting (defaults): {sum(len(m) for m in shooting.values())} modes in "
          f"{len(shooting)} planes")
    missed = False
    for name, table in references.items():
        rows = compare(shooting, table)
        if not rows:
            continue
        worst = max(rows, key=lambda r: r[3])
        print(f"  vs {name}: {len(rows)} modes, max relative difference {worst[3]:.2e} at "
              f"{worst[0]} {worst[1]} mode {worst[2]} (reference's estimate {worst[4]:.1e})")
        beyond = [r for r in rows if r[3] > target and r[4] < 0.1 * r[3]]
        for scene, plane, mode, error, estimate in sorted(beyond, key=lambda r: -r[3])[:20]:
            print(f"    beyond {target:.0e}: {scene} {plane} mode {mode}: {error:.2e} "
                  f"(reference's estimate {estimate:.1e})")
        missed = missed or bool(beyond)
    return missed


def best_reference(default, reference):
    """Per plane, the most accurate reference that ran: frobenius, else shooting at rtol 1e-13."""
    table = solver_table(reference, "shooting")
    table.update(solver_table(default, "frobenius"))
    return table


def report_fe_estimate(default, reference):
    fe = solver_table(reference, "fe")
    rows = compare(fe, best_reference(default, reference))
    estimates = {(s, p, m[0]): m[2] for (s, p), modes in fe.items() for m in modes}
    ratios, below = [], []
    for scene, plane, mode, actual, _ in rows:
        estimate = estimates[(scene, plane, mode)]
        if estimate < 0:
            continue
        if actual < 1e-14:  # the reference cannot resolve it: not a ratio
            continue
        ratios.append((estimate / actual, scene, plane, mode, estimate, actual))
        if estimate < actual:
            below.append(ratios[-1])
    if not ratios:
        print("fe (defaults): no modes to compare")
        return False
    values = [r[0] for r in ratios]
    lo, hi = min(ratios), max(ratios)
    print(f"fe (defaults): estimate / actual error over {len(ratios)} modes: min {lo[0]:.3g} "
          f"({lo[1]} {lo[2]} mode {lo[3]}), median {statistics.median(values):.3g}, max "
          f"{hi[0]:.3g} ({hi[1]} {hi[2]} mode {hi[3]}); above 1000: "
          f"{sum(v > 1000 for v in values)}")
    for ratio, scene, plane, mode, estimate, actual in sorted(below)[:20]:
        print(f"    estimate below actual: {scene} {plane} mode {mode}: estimate {estimate:.2e}, "
              f"actual {actual:.2e}")
    return bool(below)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--catena", default="build/catena")
    parser.add_argument("--scenes", default="verification/scenes")
    parser.add_argument("--work", default="build-accuracy")
    parser.add_argument("--target", type=float, default=1e-9)
    parser.add_argument("--filter", default="")
    args = parser.parse_args()
    work = pathlib.Path(args.work)
    work.mkdir(parents=True, exist_ok=True)
    reports = {}
    for run in RUNS:
        scenes = prepare(pathlib.Path(args.scenes), work, run)
        reports[run] = modes_of(run_suite(args.catena, scenes, work, run, args.filter))
    missed = report_shooting(reports["default"], reports["reference"], args.target)
    below = report_fe_estimate(reports["default"], reports["reference"])
    return 1 if missed or below else 0


if __name__ == "__main__":
    sys.exit(main())
