#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Overhead of a Python catena.solve(path) call against the same C++ work (read the scene file,
run_scene with the same options), measured in one process, alternating blocks, medians.

    PYTHONPATH=build/python /usr/bin/python3 python/bench/solve_overhead.py [--rounds 10 --block 10]

The C++ side is timed inside the module (catena._catena._time_native_solve, the GIL released), so
both sides run the same compiled code on the same machine state. Two cases: the whole mooring scene
(every solver: the target, < 5% or 50 us), and the same file with only `asymptotic` (which declines
it at once), where the C++ work is small and the difference is the binding's own cost.
"""

import argparse
import pathlib
import statistics
import time

import catena
from catena import _catena

SCENE = pathlib.Path(__file__).resolve().parents[2] / "verification/scenes/physical/mooring-line-900m.toml"


def python_times(path, repetitions, solvers):
    times = []
    for _ in range(repetitions):
        start = time.perf_counter()
        catena.solve(path, solvers=solvers)
        times.append(time.perf_counter() - start)
    return times


def measure(path, rounds, block, solvers):
    python, native = [], []
    catena.solve(path, solvers=solvers)  # warm up
    for _ in range(rounds):
        python += python_times(path, block, solvers)
        native += _catena._time_native_solve(str(path), block, solvers or [])
    return statistics.median(python), statistics.median(native), len(python)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=10)
    parser.add_argument("--block", type=int, default=10)
    arguments = parser.parse_args()
    cases = [("mooring scene, all solvers", None, arguments.block),
             ("mooring file, asymptotic only (declines)", ["asymptotic"], arguments.block * 50)]
    for title, solvers, block in cases:
        py, cpp, count = measure(SCENE, arguments.rounds, block, solvers)
        overhead = py - cpp
        print(f"{title}: {count} calls each; median Python {py * 1e3:.4f} ms, C++ {cpp * 1e3:.4f} ms, "
              f"overhead {overhead * 1e6:.1f} us = {100 * overhead / cpp:.2f}% "
              f"(target: < max(5%, 50 us) = {max(0.05 * cpp, 50e-6) * 1e6:.0f} us)")


if __name__ == "__main__":
    main()
