#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Compares the numbers of two verification reports: every natural frequency (omega_rad_s), the
decay rate of every damped mode (decay_rate_1_s, when not 0), forced max |tension|, statics H and
the fairlead's dynamic tension in waves (amplitude_n or std_n of each dynamic_tension entry), keyed
by scene, solver, plane and mode.

Each side is a report.json from `catena verify`, or a values file written by --write-values
(verification/baseline/values.json: the committed baseline, compared with the suite by the
`baseline_numbers` test). Prints the count compared, the largest relative difference and the worst
entries; exit 1 when a value differs by more than TOL (default 1e-12; with --frequencies-only only
frequencies count, as when showing that a refactor changes no frequency) or a value of OLD is
missing from NEW. Curves along the cable (kept in report.json only for scenes that ask for shapes,
docs/reference/json-layout.md) hold none of these keys; the `mutation` and `tolerance_reasons`
parts of the document are skipped.

Usage: compare_reports.py OLD NEW [TOL] [--frequencies-only]
       compare_reports.py REPORT.json --write-values OUT.json"""
import json
import sys

KEYS = ("omega_rad_s", "max_abs_tension_n", "horizontal_force_n")
# Zero on every undamped mode: kept only where a line is damped, so that undamped scenes add none.
NONZERO_KEYS = ("decay_rate_1_s",)
# Inside a dynamic_tension entry's "fairlead" only (the stations hold many more, kept out).
FAIRLEAD_KEYS = ("amplitude_n", "std_n")


def walk(node, path, out):
    if isinstance(node, dict):
        for k, v in node.items():
            number = isinstance(v, (int, float)) and not isinstance(v, bool)
            if number and (k in KEYS or (k in NONZERO_KEYS and v != 0)):
                out[path + "/" + k] = float(v)
            elif k == "fairlead" and isinstance(v, dict):
                for key in FAIRLEAD_KEYS:
                    if isinstance(v.get(key), (int, float)) and v[key] >= 0:
                        out[f"{path}/fairlead/{key}"] = float(v[key])
            else:
                walk(v, path + "/" + k, out)
    elif isinstance(node, list):
        for i, v in enumerate(node):
            key = i
            if isinstance(v, dict):
                key = v.get("name") or v.get("solver") or v.get("index") or i
                if "scene" in v and isinstance(v["scene"], str):
                    key = v["scene"]
            walk(v, f"{path}[{key}]", out)


def load(path):
    with open(path) as f:
        document = json.load(f)
    if "values" in document:  # a values file
        return {k: float(v) for k, v in document["values"].items()}
    out = {}
    walk({"scenes": document.get("scenes", [])}, "", out)
    return out


def write_values(report, out_path):
    values = load(report)
    with open(out_path, "w") as f:
        json.dump({"about": "verification suite numbers (scripts/compare_reports.py --write-values); "
                            "regenerate when a change moves them, with the reason in CHANGELOG.md",
                   "values": dict(sorted(values.items()))}, f, indent=0, sort_keys=False)
        f.write("\n")
    print(f"{len(values)} values written to {out_path}")
    return 0


def compare(old_path, new_path, tol, frequencies_only):
    old, new = load(old_path), load(new_path)
    common = set(old) & set(new)
    worst = sorted(((abs(old[k] - new[k]) / max(abs(old[k]), abs(new[k]), 1e-300), k, old[k], new[k])
                    for k in common), reverse=True)
    freq = [w for w in worst if w[1].endswith("omega_rad_s")]
    missing = sorted(set(old) - set(new))
    print(f"values compared: {len(common)} (omega: {len(freq)}); only in old: {len(missing)}; "
          f"only in new: {len(set(new) - set(old))}")
    print(f"max relative difference, omega: {freq[0][0] if freq else 0:.3e}; "
          f"all quantities: {worst[0][0] if worst else 0:.3e}")
    judged = freq if frequencies_only else worst
    bad = [w for w in judged if w[0] > tol]
    print(f"{'omega values' if frequencies_only else 'values'} beyond {tol:g}: {len(bad)}")
    for d, k, a, b in worst[:8]:
        print(f"  {d:.3e}  {k}  {a!r} -> {b!r}")
    for k in missing[:8]:
        print(f"  missing from new: {k}")
    return 1 if bad or missing else 0


def main(argv):
    if "--write-values" in argv:
        i = argv.index("--write-values")
        return write_values(argv[0], argv[i + 1])
    frequencies_only = "--frequencies-only" in argv
    args = [a for a in argv if a != "--frequencies-only"]
    if len(args) < 2:
        print(__doc__)
        return 2
    return compare(args[0], args[1], float(args[2]) if len(args) > 2 else 1e-12, frequencies_only)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
