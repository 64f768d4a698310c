# SPDX-License-Identifier: MIT
"""Independent 30-digit statics of the W-shaped line of MoorPy's tests/case6.dat.

The line: 660 + 330 + 330 m of chain (0.2 m, 500 kg/m, EA = 2e9 N; submerged weight
w = (500 - 1025 pi 0.01) 9.81 N/m), a buoy of 200 m^3 (1025 * 9.81 * 200 N up) at the first joint,
both ends at z = 0, 400 sqrt(2) m apart, over a flat seabed 300 m deep.

Written from the equations of an elastic catenary with end forces (H, V0), independently of
Catena's C++ (docs/explanation/physics.md, "Seabed contact", is the model: tangential contact,
grounded stretches straight at tension H). Six unknowns, solved together by mpmath.findroot
(multidimensional Newton) with mp.dps = 30, no symmetry assumed:

    H       horizontal force of the suspended parts
    V_A     vertical force at end A
    t0      touchdown of the arc from A       (V(t0) = 0, z(t0) = seabed)
    l1, t1  lift-off and touchdown of the arc held up by the buoy (V = 0 and z = seabed at both)
    l2      lift-off of the arc into B        (V(l2) = 0, z(L) = z_B)

and the horizontal closure. Usage:

    python3 scripts/contact_statics_reference.py            # prints the reference (JSON)
    python3 scripts/contact_statics_reference.py --check build/catena
        # solves the same line with `catena solve --json -` and compares (exit 1 beyond 1e-12)
"""
import json
import os
import subprocess
import sys
import tempfile

import mpmath as mp

mp.mp.dps = 30

G = mp.mpf("9.81")
RHO = mp.mpf(1025)
W = (500 - RHO * mp.pi * mp.mpf("0.01")) * G  # chain submerged weight [N/m]
EA = mp.mpf("2e9")
BUOY = -RHO * G * 200  # point weight of the buoy [N] (negative: it floats)
DEPTH = mp.mpf(300)
SPAN = 400 * mp.sqrt(2)
LENGTHS = [mp.mpf(660), mp.mpf(330), mp.mpf(330)]
L = sum(LENGTHS)
S_BUOY = LENGTHS[0]


def arc(H, V0, s):
    """Offset (dx, dz) after unstretched length s of chain started with force (H, V0)."""
    V1 = V0 + W * s
    dx = H * s / EA + H / W * (mp.asinh(V1 / H) - mp.asinh(V0 / H))
    dz = (V0 * s + W * s * s / 2) / EA + (mp.sqrt(H * H + V1 * V1) - mp.sqrt(H * H + V0 * V0)) / W
    return dx, dz


def residuals(H, V_A, t0, l1, t1, l2):
    """The six conditions, each zero at the equilibrium (lengths in m, forces scaled by w L)."""
    scale = W * L
    # Arc from A: it reaches the seabed at t0 with V = 0.
    xa, za = arc(H, V_A, t0)
    # The buoy's arc: up from l1 (V = 0) to the buoy, the buoy's jump, down to t1 (V = 0).
    x1, z1 = arc(H, mp.mpf(0), S_BUOY - l1)
    V_after = W * (S_BUOY - l1) + BUOY
    x2, z2 = arc(H, V_after, t1 - S_BUOY)
    # Arc into B from l2 (V = 0).
    xb, zb = arc(H, mp.mpf(0), L - l2)
    grounded_x = ((l1 - t0) + (l2 - t1)) * (1 + H / EA)
    return [
        (V_A + W * t0) / scale,
        (za + DEPTH) / L,
        (V_after + W * (t1 - S_BUOY)) / scale,
        (z1 + z2) / L,
        (zb - DEPTH) / L,
        (xa + x1 + x2 + grounded_x + xb - SPAN) / L,
    ]


def solve():
    guess = [mp.mpf("1.3e5"), -W * 330, 330, 440, 880, 990]
    H, V_A, t0, l1, t1, l2 = mp.findroot(lambda *u: residuals(*u), guess, tol=mp.mpf(10) ** -50)
    worst = max(abs(r) for r in residuals(H, V_A, t0, l1, t1, l2))
    T_A = mp.sqrt(H * H + V_A * V_A)
    V_B = W * (L - l2)
    T_B = mp.sqrt(H * H + V_B * V_B)
    buoy_z = -DEPTH + arc(H, mp.mpf(0), S_BUOY - l1)[1]
    joints = [mp.mpf(0), LENGTHS[0], LENGTHS[0] + LENGTHS[1], L]
    intervals = [(t0, l1), (t1, l2)]
    grounded_per_line = [
        sum(max(mp.mpf(0), min(e, joints[k + 1]) - max(b, joints[k])) for b, e in intervals)
        for k in range(3)
    ]
    return {
        "residual": float(worst),
        "H_n": mp.nstr(H, 25),
        "V_A_n": mp.nstr(V_A, 25),
        "tension_a_n": mp.nstr(T_A, 25),
        "tension_b_n": mp.nstr(T_B, 25),
        "buoy_z_m": mp.nstr(buoy_z, 25),
        "contact_intervals": [[mp.nstr(b, 25), mp.nstr(e, 25)] for b, e in intervals],
        "grounded_per_line_m": [mp.nstr(g, 12) for g in grounded_per_line],
    }


SCENE = """# MoorPy tests/case6.dat's W shape, written as one line in its vertical plane.
name = "w-shape-reference"
description = "W shape: two ends at the surface, a buoy at the first joint"

[line]
a = [0.0, 0.0]
b = [{span!r}, 0.0]

[[line.segments]]
length = 660.0
weight = {w!r}
EA = 2.0e9
mass = 500.0

[[line.segments]]
length = 330.0
weight = {w!r}
EA = 2.0e9
mass = 500.0

[[line.segments]]
length = 330.0
weight = {w!r}
EA = 2.0e9
mass = 500.0

[[line.points]]
s = 660.0
weight = {buoy!r}

[seabed]
z = -300.0

[request]
inplane_modes = 0
outofplane_modes = 0
"""


def relative(a, b):
    return abs(a - b) / max(abs(b), 1e-300)


def check(cli, reference):
    """Solves the scene with Catena and compares; returns the worst relative difference."""
    with tempfile.TemporaryDirectory() as folder:
        scene = os.path.join(folder, "w-shape.toml")
        with open(scene, "w") as out:
            out.write(SCENE.format(span=float(SPAN), w=float(W), buoy=float(BUOY)))
        run = subprocess.run([cli, "solve", scene, "--json", "-", "--quiet"],
                             capture_output=True, text=True)
        if run.returncode != 0:
            print(run.stdout, run.stderr)
            raise SystemExit(f"catena solve exited {run.returncode}")
        result = json.loads(run.stdout)
    statics = result["scenes"][0]["statics"]
    seabed = statics["seabed"]
    length = float(L)
    pairs = [
        ("H", statics["horizontal_force_n"], float(reference["H_n"]), None),
        ("T_A", statics["tension_a_n"], float(reference["tension_a_n"]), None),
        ("T_B", statics["tension_b_n"], float(reference["tension_b_n"]), None),
    ]
    if len(seabed["contact_intervals"]) != len(reference["contact_intervals"]):
        raise SystemExit("catena found a different number of contact intervals")
    buoy = [n for n in statics["nodes"] if n["kind"] == "point"][0]
    pairs.append(("buoy z", buoy["z_m"], float(reference["buoy_z_m"]), length))
    for i, interval in enumerate(seabed["contact_intervals"]):
        begin, end = reference["contact_intervals"][i]
        pairs.append((f"interval {i} s_begin", interval["s_begin_m"], float(begin), length))
        pairs.append((f"interval {i} s_end", interval["s_end_m"], float(end), length))
    # Forces relative to themselves, lengths and heights relative to the line's length.
    worst = 0.0
    for name, ours, theirs, scale in pairs:
        difference = abs(ours - theirs) / (abs(theirs) if scale is None else scale)
        worst = max(worst, difference)
        print(f"{name:22s} catena {ours:.17g}  reference {theirs:.17g}  relative {difference:.2e}")
    return worst


def main():
    reference = solve()
    if len(sys.argv) >= 3 and sys.argv[1] == "--check":
        worst = check(sys.argv[2], reference)
        print(f"worst relative difference {worst:.2e} (limit 1e-12)")
        return 0 if worst <= 1e-12 else 1
    # MoorPy's published equilibrium of tests/case6.dat (issue 31): end tension 1.509 MN and
    # 113 / 111 / 2.4 m resting on the seabed on its three lines.
    reference["moorpy_published"] = {"tension_n": 1.509e6, "grounded_per_line_m": [113, 111, 2.4]}
    print(json.dumps(reference, indent=2))
    return 0


if __name__ == "__main__":
    sys.exit(main())
