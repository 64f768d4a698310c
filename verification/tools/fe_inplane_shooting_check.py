#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Naive, independent check of the in-plane frequency ratios of Gale's inextensible catenary
# (evidence for the Table B-3 entries that disagree with the fe solver; see
# verification/comparisons/fe-gale-B3-B4-comparison.csv). Pure Python, no dependencies, no catena code.
#
# Cartesian linearisation of docs/explanation/physics.md ("Linear dynamics") with EA = inf (a = H/W0 = 1 m, W0 = 1 N/m,
# m = M = 1 kg/m, so w is Gale's ratio): with s = sigma = V/H in [sigma(xi1), sigma(xi2)],
# T = sqrt(1 + s^2), t = (1, s)/T, n = (-s, 1)/T:
#     Phi' = n (n . F) / T,     F' = -w^2 Phi          (F = A Phi', the dynamic force)
# Principal solutions Phi(sigma1) = 0, F(sigma1) = e1 or e2, classical RK4 with 3000 steps;
# natural frequencies are the sign changes of det[Phi_1(sigma2), Phi_2(sigma2)] (scan step 0.01,
# then bisection).
# Run: python3 verification/tools/fe_inplane_shooting_check.py   (about 3 minutes)
# Output (2026-11-23), against Gale's printed B-3 rows and the fe solver (from the printed xi):
#   -0.5 0.5 ['2.5890', '4.2307', '5.8722', '7.3978', '8.9736', '10.4869']
#        Gale 2.59 4.23 5.87 7.40 8.97 10.49; fe 2.5890 4.2307 5.8722 7.3978 8.9736 10.4869
#   -0.6 0.6 ['2.3050', '3.8223', '5.3106', '6.7045', '8.1324', '9.5118']
#        Gale 2.30 3.82 5.31 6.70 8.13 9.15 (w6: digits transposed?); fe ... 9.5118
#   -0.297 0.779 ['2.5458', '4.1652', '5.7865', '7.2924', '8.8470', '10.3398']
#        Gale 2.54 4.17 5.80 7.09 8.57 10.34 (w3..w5 disagree); fe 2.5458 4.1652 5.7865 7.2924 8.8470 10.3398
import math

def det_at(w, s1, s2, n=3000):
    h = (s2 - s1) / n
    def f(s, y):
        T = math.sqrt(1 + s * s)
        nx, nz = -s / T, 1 / T
        out = []
        for k in (0, 4):
            px, pz, fx, fz = y[k:k + 4]
            nf = (nx * fx + nz * fz) / T
            out += [nx * nf, nz * nf, -w * w * px, -w * w * pz]
        return out
    y = [0, 0, 1, 0, 0, 0, 0, 1]
    s = s1
    for _ in range(n):
        k1 = f(s, y)
        k2 = f(s + h / 2, [a + h / 2 * b for a, b in zip(y, k1)])
        k3 = f(s + h / 2, [a + h / 2 * b for a, b in zip(y, k2)])
        k4 = f(s + h, [a + h * b for a, b in zip(y, k3)])
        y = [a + h / 6 * (b + 2 * c + 2 * d + e) for a, b, c, d, e in zip(y, k1, k2, k3, k4)]
        s += h
    return y[0] * y[5] - y[1] * y[4]

def sigma(xi):
    return math.copysign(math.sqrt((1 + abs(xi)) ** 2 - 1), xi)

def roots(xi1, xi2, count=6, step=0.01, w_max=40.0):
    s1, s2 = sigma(xi1), sigma(xi2)
    found, w = [], step
    d0 = det_at(w, s1, s2)
    while len(found) < count and w < w_max:
        d1 = det_at(w + step, s1, s2)
        if d0 * d1 < 0:
            lo, hi, dlo = w, w + step, d0
            for _ in range(30):
                mid = 0.5 * (lo + hi)
                dm = det_at(mid, s1, s2)
                if dlo * dm <= 0:
                    hi = mid
                else:
                    lo, dlo = mid, dm
            found.append(0.5 * (lo + hi))
        w += step
        d0 = d1
    return found

if __name__ == "__main__":
    for xi1, xi2 in [(-0.5, 0.5), (-0.6, 0.6), (-0.297, 0.779)]:
        print(xi1, xi2, ["%.4f" % r for r in roots(xi1, xi2)], flush=True)
