#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""What a Python user would write: SciPy's eigsh in shift-invert mode on Catena's exported fe
matrices. Usage: scipy_eigsh.py K.mtx M.mtx MODES REPEATS [WARMUP]; runs WARMUP untimed calls
(default 0: the first call of a process includes SciPy's own set-up), then prints the median wall
time [s] of REPEATS timed calls and the MODES lowest eigenvalues. Run by benchmarks/fe_vs_scipy.cpp."""
import statistics
import sys
import time

import scipy.io
import scipy.sparse.linalg

K = scipy.io.mmread(sys.argv[1]).tocsc()
M = scipy.io.mmread(sys.argv[2]).tocsc()
modes, repeats = int(sys.argv[3]), int(sys.argv[4])
warmup = int(sys.argv[5]) if len(sys.argv) > 5 else 0


def solve():
    return scipy.sparse.linalg.eigsh(K, k=modes, M=M, sigma=0.0, which="LM", tol=1e-10,
                                     return_eigenvectors=False)


for _ in range(warmup):
    solve()
times = []
for _ in range(repeats):
    start = time.perf_counter()
    values = solve()
    times.append(time.perf_counter() - start)
print(statistics.median(times))
for value in sorted(values):
    print(repr(float(value)))
