#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Compares two catena report.json files (from `catena verify`): every natural frequency
(omega_rad_s), forced max |tension| and statics H, keyed by scene, solver, plane and mode.
Prints the count compared, the largest relative difference and the worst entries; exit 1 when a
frequency differs by more than TOL (default 1e-12) or a value of OLD is missing from NEW.
Used to show that a refactor changes no result. Each value is compared when present in OLD: curves
along the cable (kept in report.json only for scenes that ask for shapes, docs/reference/json-layout.md) hold
none of these keys, and the `mutation` and `tolerance_reasons` parts of the document are skipped.
Usage: compare_reports.py OLD.json NEW.json [TOL]"""
import json, sys

def walk(node, path, out):
    if isinstance(node, dict):
        for k, v in node.items():
            if k in ("omega_rad_s", "max_abs_tension_n", "horizontal_force_n") and isinstance(v, (int, float)):
                out[path + "/" + k] = float(v)
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

def load(p):
    out = {}
    document = json.load(open(p))
    walk({"scenes": document.get("scenes", [])}, "", out)
    return out

old, new = load(sys.argv[1]), load(sys.argv[2])
tol = float(sys.argv[3]) if len(sys.argv) > 3 else 1e-12
common = set(old) & set(new)
worst = []
for k in common:
    a, b = old[k], new[k]
    d = abs(a - b) / max(abs(a), abs(b), 1e-300)
    worst.append((d, k, a, b))
worst.sort(reverse=True)
freq = [w for w in worst if w[1].endswith("omega_rad_s")]
print(f"values compared: {len(common)} (omega: {len(freq)}); only in old: {len(set(old)-set(new))}; only in new: {len(set(new)-set(old))}")
print(f"max relative difference, omega: {freq[0][0] if freq else 0:.3e}; all quantities: {worst[0][0] if worst else 0:.3e}")
bad = [w for w in freq if w[0] > tol]
print(f"omega values beyond {tol:g}: {len(bad)}")
for d, k, a, b in worst[:8]:
    print(f"  {d:.3e}  {k}  {a!r} -> {b!r}")
sys.exit(1 if bad or len(set(old)-set(new)) else 0)
