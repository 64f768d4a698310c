#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""catena sweep on Dask against a serial Python loop: throughput per core, speed-up of 2 workers
over 1, the scheduler's share, and peak memory (RSS) at 1e4 and 1e5 points.

    PYTHONPATH=build/python /usr/bin/python3 python/bench/sweep_scaling.py [--points 2000] [--repeats 2]

Every ratio is between runs of the same points in the same process, one after the other (the
machine's other load changes between runs: the load average is printed). The sweep's times are
its run after the cluster started (summary.json's run_time_s); the cluster's start is given apart.
The clusters are catena.sweep's own (catena._sweep_run.local_cluster). The serial loop calls catena.solve on each point's scene with the same solvers, as a task does.
Prints Markdown (benchmarks/results/sweep-scaling.md).
"""

import argparse
import os
import resource
import statistics
import tempfile
import time

import catena
from catena._sweep_run import local_cluster, run_sweep
from catena._sweep_spec import read_spec
from distributed import Client

SCENE = {"taut_inclined": {"eps": 0.3, "phi_deg": 30.0, "lambda2": 10.0},
         "request": {"inplane_modes": 3, "outofplane_modes": 3}}


def spec(points, solvers):
    """A grid of lambda2 x eps with `points` points (points divisible by 20)."""
    eps = [0.05 + 0.9 * i / 19 for i in range(20)]
    return {"scene": SCENE, "outputs": {"solvers": solvers},
            "axes": [{"key": "taut_inclined.lambda2", "from": 0.5, "to": 500.0, "points": points // 20,
                      "spacing": "log"},
                     {"key": "taut_inclined.eps", "values": eps}]}


def serial(sweep_spec):
    """(wall, CPU time) [s] of solving the points one by one in this process."""
    parsed = read_spec(sweep_spec)
    start, cpu = time.perf_counter(), time.process_time()
    for point in range(parsed.points):
        catena.solve(parsed.scene_at(point), solvers=parsed.outputs.solvers, checks=False)
    return time.perf_counter() - start, time.process_time() - cpu


def on_dask(sweep_spec, workers):
    """A sweep on a fresh local cluster: its summary, plus the cluster's start [s], the CPU time of the
    workers (every thread of their processes) and of this process (client and scheduler) during the
    sweep [s], and each worker's peak RSS [MB]."""
    with tempfile.TemporaryDirectory() as out:
        start = time.perf_counter()
        with local_cluster(workers) as cluster, Client(cluster) as client:
            started = time.perf_counter() - start
            before, cpu = client.run(time.process_time), time.process_time()
            _, summary = run_sweep(sweep_spec, out, client=client, progress=False)
            client_cpu = time.process_time() - cpu
            after = client.run(time.process_time)
            peaks = client.run(lambda: resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024)
    summary.update(cluster_start_s=started, worker_cpu_s=sum(after[w] - before[w] for w in after),
                   client_cpu_s=client_cpu)
    return summary, sorted(peaks.values())


def client_peak_mb():
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024


def scaling(points, repeats):
    sweep_spec = spec(points, ["shooting", "asymptotic", "airy"])
    rows = []
    for _ in range(repeats):
        load = os.getloadavg()[0]
        loop = serial(sweep_spec)
        rows.append((load, loop, on_dask(sweep_spec, 1)[0], on_dask(sweep_spec, 2)[0]))
    print(f"\n## Throughput and speed-up: {points} points, shooting + asymptotic + airy, 3 + 3 modes\n")
    print("CPU columns: the serial loop's CPU time over the workers' (every thread of their processes) "
          "during the sweep, i.e. the throughput of a busy core; and this process's (client and "
          "scheduler) CPU over the loop's. Wall columns: the run after the cluster started.\n")
    print("| load avg before | serial loop wall / CPU [s] | workers | run wall [s] | cluster start [s] | "
          "per-core throughput (CPU) | per-core throughput (wall) | client+scheduler CPU | batch | tasks |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for load, (wall, cpu), one, two in rows:
        for n, run in ((1, one), (2, two)):
            print(f"| {load:.1f} | {wall:.2f} / {cpu:.2f} | {n} | {run['run_time_s']:.2f} | {run['cluster_start_s']:.1f} | "
                  f"{cpu / run['worker_cpu_s']:.0%} | {wall / (n * run['run_time_s']):.0%} | "
                  f"{run['client_cpu_s'] / cpu:.0%} | {run['batch_points']} | {run['tasks']} |")
    efficiency = [cpu / one["worker_cpu_s"] for _, (_, cpu), one, _ in rows]
    efficiency2 = [cpu / two["worker_cpu_s"] for _, (_, cpu), _, two in rows]
    speedups = [one["run_time_s"] / two["run_time_s"] for *_, one, two in rows]
    print(f"\nMedians: per-core throughput (CPU) {statistics.median(efficiency):.0%} with 1 worker, "
          f"{statistics.median(efficiency2):.0%} with 2; wall speed-up of 2 workers over 1: "
          f"{statistics.median(speedups):.2f}x ({', '.join(f'{s:.2f}' for s in speedups)}).")


def memory(counts):
    print("\n## Peak memory (RSS), asymptotic only, 1 + 1 modes, 2 workers\n")
    print("| points | run [s] | points/s | client peak RSS [MB] | worker peak RSS [MB] | batch [points] | tasks |")
    print("|---|---|---|---|---|---|---|")
    for count in counts:
        sweep_spec = spec(count, ["asymptotic"])
        sweep_spec["scene"] = dict(SCENE, request={"inplane_modes": 1, "outofplane_modes": 1})
        summary, workers = on_dask(sweep_spec, 2)
        print(f"| {count} | {summary['run_time_s']:.1f} | {count / summary['run_time_s']:.0f} | {client_peak_mb():.0f} | "
              f"{', '.join(f'{w:.0f}' for w in workers)} | {summary['batch_points']} | {summary['tasks']} |")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--points", type=int, default=2000)
    parser.add_argument("--repeats", type=int, default=2)
    parser.add_argument("--memory-points", type=int, nargs="*", default=[10_000, 100_000])
    arguments = parser.parse_args()
    print(f"# catena sweep: scaling\n\n{os.cpu_count()} CPUs; catena {catena.__version__}; "
          f"`PYTHONPATH=build/python /usr/bin/python3 python/bench/sweep_scaling.py --points {arguments.points} "
          f"--repeats {arguments.repeats}`")
    scaling(arguments.points, arguments.repeats)
    memory(arguments.memory_points)


if __name__ == "__main__":
    main()
