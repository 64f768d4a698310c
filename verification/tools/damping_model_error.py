#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The model-error map of the analytic models' light damping (issue 29).

`asymptotic` and `airy` damp their own undamped modes by first-order perturbation
(src/solvers/common/modal_damping.hpp; docs/explanation/methods/asymptotic.md, "Damping"). This
script measures that perturbation against an exact solver: it sweeps the damping ratio of the first
in-plane mode (zeta from 1e-4 to 0.3) and the non-proportional ratio c_t/c_n on a few taut and
sagging `[taut_inclined]` scenes, runs `catena solve --json` on each generated scene, and writes

  - a CSV of every mode: |delta_model - delta_exact| / delta_exact and the same for omega_d, with
    each model's own estimates (decay_rate_error_estimate, relative_error_estimate);
  - a Markdown table of the largest relative error of delta per (model, c_t/c_n, zeta) and its
    fitted order in zeta, for docs/explanation/methods/asymptotic.md.

It needs an exact solver that handles damping (shooting, fe or frobenius, tried in that order).
Until one does, every exact run is `not-applicable` and the script says so and writes no table.

    python3 verification/tools/damping_model_error.py --catena build/catena --out build/damping-map
"""

import argparse
import json
import math
import subprocess
import sys
import tempfile
from pathlib import Path

MODELS = ["asymptotic", "airy"]
EXACT = ["shooting", "fe", "frobenius"]

# name: (eps, phi_deg, lambda2, mass_ratio h = m/M). Taut ones, one near cross-over, sagging ones
# (eps near the models' warning threshold 0.3 and above it).
SCENES = {
    "taut-eps0.05-phi30": (0.05, 30.0, 100.0, 0.8),
    "crossover-eps0.18-phi23.46": (0.18, 23.46, 38.0, 1.0),
    "sagging-eps0.3-phi45": (0.3, 45.0, 60.0, 0.6),
    "sagging-eps0.49-phi45": (0.49, 45.0, 150.0, 1.0),
}


def scene_text(name, form, modes, eta_t, eta_n, solvers):
    eps, phi, lambda2, h = form
    lines = [
        f'name = "{name}"',
        f'description = "damping model-error map: {name}, eta_t = {eta_t:.6g}, eta_n = {eta_n:.6g}"',
        'tags = ["damping-map"]',
        "",
        "[taut_inclined]",
        f"eps = {eps!r}",
        f"phi_deg = {phi!r}",
        f"lambda2 = {lambda2!r}",
        f"mass_ratio = {h!r}",
    ]
    # In the form's units (L = 1, T0 = 1, M = 1) c = eta (docs/reference/scene-format.md).
    if eta_t > 0.0:
        lines.append(f"eta_tangential = {eta_t!r}")
    if eta_n > 0.0:
        lines.append(f"eta_normal = {eta_n!r}")
    lines += ["", "[request]", f"inplane_modes = {modes}", "", "[solvers]"]
    lines += [f"{solver} = {{}}" for solver in solvers]
    return "\n".join(lines) + "\n"


def solve(catena, text, workdir, tag):
    scene = Path(workdir) / f"{tag}.toml"
    out = Path(workdir) / f"{tag}.json"
    scene.write_text(text)
    run = subprocess.run([catena, "solve", str(scene), "--json", str(out), "--quiet"],
                         capture_output=True, text=True)
    if not out.exists():
        raise RuntimeError(f"catena solve failed on {scene}: {run.stderr.strip()}")
    doc = json.loads(out.read_text())
    scenes = doc.get("scenes", [doc]) if isinstance(doc, dict) else doc
    return scenes[0]["solvers"]


def inplane(solvers, name):
    output = solvers.get(name)
    if not output or not output.get("inplane"):
        return None, (output or {}).get("summary", {}).get("message", "not run")
    plane = output["inplane"]
    if plane["summary"]["termination"] not in ("converged", "no-convergence"):
        return None, plane["summary"]["message"]
    return plane["modes"], ""


def nearest(mode, modes):
    return min(modes, key=lambda other: abs(other["omega_rad_s"] - mode["omega_rad_s"]))


def rel(a, b):
    return abs(a - b) / abs(b) if b else math.inf


def measure(args, workdir):
    rows, declined = [], []
    exact_solvers = args.exact
    models = [m for m in MODELS if m not in exact_solvers]
    solvers = models + exact_solvers
    for scene, form in SCENES.items():
        h = form[3]
        undamped = solve(args.catena, scene_text(scene, form, args.modes, 0.0, 0.0, exact_solvers),
                         workdir, f"{scene}-undamped")
        omega1 = None
        for exact in exact_solvers:
            modes, _ = inplane(undamped, exact)
            if modes:
                omega1 = modes[0]["omega_rad_s"]
                break
        if omega1 is None:
            declined.append(f"{scene}: no exact solver gave the undamped modes")
            continue
        for ratio in args.ratios:
            # c_t / c_n = ratio * h: ratio 1 is proportional (c_t = alpha m, c_n = alpha M).
            for zeta in args.zetas:
                eta_n = 2.0 * zeta * omega1  # delta ~ c_n / 2M, M = 1 in the form's units
                eta_t = ratio * h * eta_n
                tag = f"{scene}-r{ratio:g}-z{zeta:.3g}"
                out = solve(args.catena, scene_text(tag, form, args.modes, eta_t, eta_n, solvers),
                            workdir, tag)
                reference, reasons = None, []
                for exact in exact_solvers:
                    reference, why = inplane(out, exact)
                    if reference:
                        break
                    reasons.append(f"{exact}: {why}")
                if not reference:
                    declined.append(f"{tag}: " + "; ".join(reasons))
                    continue
                for model in models:
                    modes, why = inplane(out, model)
                    if not modes:
                        declined.append(f"{tag}: {model}: {why}")
                        continue
                    for mode in modes:
                        ref = nearest(mode, reference)
                        rows.append({
                            "scene": scene, "ratio": ratio, "zeta": zeta, "model": model,
                            "mode": mode["index"], "delta_model": mode["decay_rate_1_s"],
                            "delta_exact": ref["decay_rate_1_s"],
                            "delta_error": rel(mode["decay_rate_1_s"], ref["decay_rate_1_s"]),
                            "delta_estimate": mode.get("decay_rate_error_estimate", -1.0),
                            "omega_error": rel(mode["omega_rad_s"], ref["omega_rad_s"]),
                            "omega_estimate": mode["relative_error_estimate"]})
    return rows, declined


def order(points):
    """Least-squares slope of log(error) against log(zeta)."""
    pts = [(math.log(z), math.log(e)) for z, e in points if e > 0.0 and math.isfinite(e)]
    if len(pts) < 2:
        return float("nan")
    mx = sum(x for x, _ in pts) / len(pts)
    my = sum(y for _, y in pts) / len(pts)
    sxx = sum((x - mx) ** 2 for x, _ in pts)
    return sum((x - mx) * (y - my) for x, y in pts) / sxx if sxx else float("nan")


def write(rows, declined, out):
    out.mkdir(parents=True, exist_ok=True)
    keys = list(rows[0].keys()) if rows else []
    with open(out / "damping-model-error.csv", "w") as f:
        f.write("# verification/tools/damping_model_error.py: perturbation delta vs an exact solver\n")
        f.write(",".join(keys) + "\n")
        for row in rows:
            f.write(",".join(f"{row[k]:.6g}" if isinstance(row[k], float) else str(row[k])
                             for k in keys) + "\n")
    zetas = sorted({row["zeta"] for row in rows})
    lines = ["| model | c_t/c_n (x m/M) | " + " | ".join(f"zeta {z:.0e}" for z in zetas) +
             " | order |", "|---|---|" + "---|" * (len(zetas) + 1)]
    for model in sorted({row["model"] for row in rows}):
        for ratio in sorted({row["ratio"] for row in rows}):
            worst = []
            for zeta in zetas:
                errors = [r["delta_error"] for r in rows
                          if r["model"] == model and r["ratio"] == ratio and r["zeta"] == zeta]
                worst.append(max(errors) if errors else float("nan"))
            lines.append(f"| {model} | {ratio:g} | " + " | ".join(f"{e:.2e}" for e in worst) +
                         f" | {order(list(zip(zetas, worst))):.2f} |")
    text = "\n".join(lines) + "\n"
    if declined:
        text += "\nNot measured:\n" + "\n".join(f"- {d}" for d in declined) + "\n"
    (out / "damping-model-error.md").write_text(text)
    print(text)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--catena", default="build/catena")
    parser.add_argument("--out", type=Path, default=Path("build/damping-model-error"))
    parser.add_argument("--modes", type=int, default=4)
    parser.add_argument("--zetas", type=float, nargs="+",
                        default=[1e-4, 3e-4, 1e-3, 3e-3, 1e-2, 3e-2, 0.1, 0.3])
    # Multiples of the proportional c_t/c_n = m/M: 1 proportional, 0 normal drag only.
    parser.add_argument("--ratios", type=float, nargs="+", default=[1.0, 0.0, 0.5, 2.0])
    # The reference, the first that answers (a model named here is taken out of the compared ones:
    # `--exact airy` exercises the script with asymptotic against airy before the exact solvers
    # handle damping).
    parser.add_argument("--exact", nargs="+", default=EXACT)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as workdir:
        rows, declined = measure(args, workdir)
    if not rows:
        print("no exact solver handles damping yet: nothing to compare", file=sys.stderr)
        for d in declined[:5]:
            print("  " + d, file=sys.stderr)
        return 1
    write(rows, declined, args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
