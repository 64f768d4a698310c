#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The validity-limit scans of issue 32 (docs/explanation/methods/{shooting,airy,asymptotic}.md).

Each scan writes `[taut_inclined]` scenes, runs `catena solve --json` on each and prints, per
solver and plane, the largest relative frequency error against a reference, the largest error
estimate, and error / estimate (above 1: the estimate does not bound the error):

  - strain: shooting against fe at static strains T0/EA up to 2.5e11 (eps 0.01, 0.1, 0.5; phi_a 0,
    30, 60 deg; lambda^2 1e-4 to 1e-12);
  - small-eps: shooting and airy in plane against eq. (21) (the asymptotic solver, exact to
    eps^2 + T0/(2 EA); only rows where that is <= 1e-13 count) at eps 1e-12 to 1e-6;
  - axial: asymptotic and airy in plane against fe, mode by mode with kL over the first axial
    mode's, at lambda^2 0.1, 1, 10 and strains 1e-3 to 0.098 (14 modes).

    python3 verification/tools/validity_limits_scan.py --catena build/catena --scan small-eps
"""

import argparse
import itertools
import json
import math
import os
import subprocess
import tempfile


def solve(catena, folder, eps, phi, lambda2, solvers, inplane, outofplane):
    path = os.path.join(folder, f"scan_{eps:g}_{phi:g}_{lambda2:g}.toml")
    with open(path, "w", encoding="utf-8") as f:
        f.write(f'name = "scan"\n[taut_inclined]\neps = {eps!r}\nphi_deg = {phi!r}\n'
                f'lambda2 = {lambda2!r}\nmass_ratio = 1.0\n[request]\ninplane_modes = {inplane}\n'
                f'outofplane_modes = {outofplane}\n[solvers]\n' +
                "".join(f"{s} = {{}}\n" for s in solvers))
    subprocess.run([catena, "solve", path, "--json", path + ".json", "-q"], check=False,
                   capture_output=True)
    with open(path + ".json", encoding="utf-8") as f:
        return json.load(f)["scenes"][0]


def compare(scene, solver, reference, plane):
    out = scene["solvers"].get(solver) or {}
    part = out.get(plane)
    if not part:
        return f"{solver} {plane}: none ({out.get('summary', {}).get('message', '')[:100]})"
    ref = {m["index"]: m["omega_rad_s"] for m in (scene["solvers"][reference].get(plane) or {}).get("modes", [])}
    worst = (0.0, 0.0, 0.0)
    for m in part.get("modes", []):
        if m["index"] not in ref:
            continue
        err = abs(m["omega_rad_s"] - ref[m["index"]]) / ref[m["index"]]
        est = m["relative_error_estimate"]
        ratio = err / est if est > 0 else math.inf
        worst = max(worst, (ratio, err, est))
    status = part["summary"]["termination"]
    return (f"{solver} {plane}: {status}, {len(part.get('modes', []))} modes, max error "
            f"{worst[1]:.2e}, estimate {worst[2]:.2e}, error/estimate {worst[0]:.2g}")


def scan_strain(catena, folder):
    for eps, phi, lambda2 in itertools.product([0.01, 0.1, 0.5], [0.0, 30.0, 60.0],
                                               [1e-4, 1e-6, 1e-8, 1e-10, 1e-12]):
        scene = solve(catena, folder, eps, phi, lambda2, ["fe", "shooting"], 4, 2)
        for plane in ("inplane", "outofplane"):
            print(f"eps {eps} phi {phi} lambda2 {lambda2:g}:", compare(scene, "shooting", "fe", plane))


def scan_small_eps(catena, folder):
    for eps, phi, lambda2 in itertools.product([1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-12],
                                               [10.0, 30.0, 60.0, 89.0], [1e-4, 1.0, 100.0]):
        if eps * eps / lambda2 > 1e-13:  # eq. (21)'s own error would count
            continue
        scene = solve(catena, folder, eps, phi, lambda2, ["asymptotic", "shooting", "airy"], 4, 0)
        for solver in ("shooting", "airy"):
            print(f"eps {eps:g} phi {phi} lambda2 {lambda2:g}:",
                  compare(scene, solver, "asymptotic", "inplane"))


def scan_axial(catena, folder):
    for lambda2, strain in itertools.product([0.1, 1.0, 10.0], [1e-3, 1e-2, 0.05, 0.098]):
        eps, phi = math.sqrt(strain * lambda2), 30.0
        scene = solve(catena, folder, eps, phi, lambda2, ["fe", "asymptotic", "airy"], 14, 0)
        axial = math.sqrt(lambda2) / (eps * math.cos(math.radians(phi)))  # kL/pi, mass ratio 1
        fe = {m["index"]: m for m in (scene["solvers"]["fe"].get("inplane") or {}).get("modes", [])}
        for solver in ("asymptotic", "airy"):
            for m in (scene["solvers"][solver].get("inplane") or {}).get("modes", []):
                if m["index"] not in fe:
                    continue
                err = abs(m["omega_rad_s"] - fe[m["index"]]["omega_rad_s"]) / fe[m["index"]]["omega_rad_s"]
                print(f"{solver} lambda2 {lambda2} strain {strain} mode {m['index']} kL/axial "
                      f"{m['k_l_over_pi'] / axial:.3f} error {err:.2e} estimate "
                      f"{m['relative_error_estimate']:.2e}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--catena", default="build/catena")
    parser.add_argument("--scan", choices=["strain", "small-eps", "axial"], required=True)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as folder:
        {"strain": scan_strain, "small-eps": scan_small_eps, "axial": scan_axial}[args.scan](
            args.catena, folder)


if __name__ == "__main__":
    main()
