#!/usr/bin/env python3
"""Speed-up of solving 100 scenes on 2 threads against 1 (the GIL is released during solves).

    PYTHONPATH=build/python /usr/bin/python3 python/bench/parallel_speedup.py [--repeats 3]

The 100 scenes are the first 100 files (sorted by path) of verification/scenes/{analytic,gale,
grinfogel,physical}. Each repeat times 1 thread then 2 threads; the medians are reported.
"""

import argparse
import os
import pathlib
import statistics
import time
from concurrent.futures import ThreadPoolExecutor

import catena

SCENES = pathlib.Path(__file__).resolve().parents[2] / "verification/scenes"


def scene_files(count):
    files = sorted(p for family in ("analytic", "gale", "grinfogel", "physical")
                   for p in (SCENES / family).glob("*.toml"))
    return files[:count]


def wall_time(files, threads):
    start = time.perf_counter()
    with ThreadPoolExecutor(max_workers=threads) as pool:
        results = list(pool.map(catena.solve, files))
    assert len(results) == len(files)
    return time.perf_counter() - start


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--scenes", type=int, default=100)
    arguments = parser.parse_args()
    files = scene_files(arguments.scenes)
    wall_time(files[:10], 1)  # warm up
    one, two = [], []
    for _ in range(arguments.repeats):
        one.append(wall_time(files, 1))
        two.append(wall_time(files, 2))
    print(f"{len(files)} scenes, {os.cpu_count()} CPUs, load average {os.getloadavg()[0]:.1f}")
    print(f"1 thread:  {', '.join(f'{t:.2f}' for t in one)} s (median {statistics.median(one):.2f} s)")
    print(f"2 threads: {', '.join(f'{t:.2f}' for t in two)} s (median {statistics.median(two):.2f} s)")
    print(f"speed-up (medians): {statistics.median(one) / statistics.median(two):.2f}x")


if __name__ == "__main__":
    main()
