#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
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
    """Wall time of solving `files` on `threads` threads, and the process's CPU time over it: a
    ratio above 1 shows the threads running at once (the GIL released); on a machine whose other
    load leaves this process one core, the wall time cannot improve whatever the ratio could be."""
    start, cpu = time.perf_counter(), time.process_time()
    with ThreadPoolExecutor(max_workers=threads) as pool:
        results = list(pool.map(catena.solve, files))
    assert len(results) == len(files)
    return time.perf_counter() - start, time.process_time() - cpu


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--scenes", type=int, default=100)
    arguments = parser.parse_args()
    files = scene_files(arguments.scenes)
    wall_time(files[:10], 1)  # warm up
    runs = {1: [], 2: []}
    for _ in range(arguments.repeats):
        for threads in runs:
            runs[threads].append(wall_time(files, threads))
    print(f"{len(files)} scenes, {os.cpu_count()} CPUs, load average {os.getloadavg()[0]:.1f} before the last run")
    for threads, times in runs.items():
        walls = [wall for wall, _ in times]
        print(f"{threads} thread(s): wall {', '.join(f'{t:.2f}' for t in walls)} s (median "
              f"{statistics.median(walls):.2f} s); CPU/wall {', '.join(f'{c / w:.2f}' for w, c in times)}")
    one = statistics.median(w for w, _ in runs[1])
    two = statistics.median(w for w, _ in runs[2])
    print(f"speed-up of 2 threads over 1 (medians): {one / two:.2f}x")


if __name__ == "__main__":
    main()
