# SPDX-License-Identifier: MIT
"""catena.sweep: the points of a SPEC solved on Dask (docs/how-to/sweep.md).

The client cuts the points into tasks of about `batch_seconds` (0.1 s) each, estimated from a
first small batch per worker, keeps a bounded window of tasks in flight (memory flat in the number
of points), and appends each finished task's rows to the journal once (_sweep_store.py). Dask
reruns a task whose worker died on another worker; only the client writes, so no point is lost or
written twice. A task that kills its workers repeatedly is split into single points, and a point
that still kills them is written with its error, not retried forever.
"""

import hashlib
import importlib
import json
import logging
import math
import os
import platform
import shutil
import tempfile
import time
import warnings
from typing import Any, Iterator, Optional

from ._catena import InvalidInput, __version__
from ._sweep_point import cell, columns, solve_batch
from ._sweep_progress import Progress
from ._sweep_spec import Spec, read_spec
from ._sweep_store import Store, status_counts

#: How long a scheduler address may take to answer before the sweep gives up [s].
CONNECT_TIMEOUT_S = 5.0
_PILOT_POINTS = 2  # points per worker in the first tasks, which time a point
_MAX_BATCH = 100_000


def _distributed() -> Any:
    """dask.distributed, untyped (an Any for mypy --strict); InvalidInput naming the Debian package."""
    try:
        return importlib.import_module("distributed")
    except ImportError as error:
        raise InvalidInput(f"catena sweep needs Dask (Debian: python3-distributed): {error}") from None


def _client(client: Any, scheduler: Optional[str], workers: Optional[int]) -> tuple[Any, Any, bool]:
    """(client, cluster or None, whether we own it)."""
    Client = _distributed().Client
    if client is not None:
        return client, None, False
    if scheduler:
        try:
            return Client(scheduler, timeout=CONNECT_TIMEOUT_S), None, True
        except (OSError, TimeoutError, ValueError) as error:
            raise InvalidInput(f"--scheduler {scheduler}: no Dask scheduler answered within {CONNECT_TIMEOUT_S:g} s "
                               f"({type(error).__name__}: {error})") from None
    count = workers if workers is not None else (os.cpu_count() or 1)
    if isinstance(count, bool) or not isinstance(count, int) or count < 1:
        raise InvalidInput(f"--workers {workers!r}: an integer >= 1")
    cluster = local_cluster(count)
    return Client(cluster), cluster, True


def local_cluster(workers: int) -> Any:
    """The LocalCluster of a sweep: `workers` processes of one thread each, no dashboard, and no
    statistical profiler in the workers (it samples every thread's stack every 10 ms: several
    percent of a worker's CPU, for a profile nobody reads here)."""
    distributed = _distributed()
    dask: Any = importlib.import_module("dask")
    with warnings.catch_warnings(), dask.config.set({"distributed.worker.profile.enabled": False}):
        # the scheduler's HTTP server falls back to a free port when 8787 is taken (another
        # cluster): nothing the user needs to act on
        warnings.filterwarnings("ignore", message="Port 8787 is already in use")
        return distributed.LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                                        dashboard_address=None, silence_logs=logging.ERROR)


def _points(spec: Spec, first: int, count: int) -> list[tuple[int, list[Any]]]:
    return [(p, spec.point_values(p)) for p in range(first, first + count)]


class _Runner:
    """Submits batches, writes what finishes, and splits batches that kill workers."""

    def __init__(self, client: Any, spec: Spec, store: Store, progress: Progress):
        self.client, self.spec, self.store, self.progress = client, spec, store, progress
        self.scene, self.axes, self.outputs = spec.scene, spec.axes, spec.outputs
        self.busy_s, self.cpu_s, self.solved, self.tasks, self.largest_batch = 0.0, 0.0, 0, 0, 0

    def submit(self, first: int, count: int) -> Any:
        self.tasks += 1
        future = self.client.submit(solve_batch, self.scene, self.axes, _points(self.spec, first, count),
                                    self.outputs, pure=False)
        future.catena_batch = (first, count)
        return future

    def collect(self, future: Any, pending: Any) -> None:
        KilledWorker = _distributed().KilledWorker
        first, count = future.catena_batch
        try:
            rows, busy, cpu = future.result()
        except KilledWorker:
            if count > 1:  # a point kills its worker: find it, and keep the others
                for point in range(first, first + count):
                    pending.add(self.submit(point, 1))
                return
            rows, busy, cpu = self._killer_row(first), 0.0, 0.0
        except ImportError as error:  # a worker of a user's cluster without catena (or numpy)
            raise InvalidInput(f"a Dask worker cannot import {error.name}: {error}; every worker of the cluster "
                               "needs the same catena importable (the points written so far are kept)") from None
        self.store.append(first, count, rows)
        self.busy_s += busy
        self.cpu_s += cpu
        self.solved += count
        self.progress.update(count)

    def _killer_row(self, point: int) -> str:
        import csv
        import io

        header = self.store.header
        row = [""] * len(header)
        row[0] = str(point)
        for i, value in enumerate(self.spec.point_values(point)):
            row[1 + i] = cell(value)
        row[header.index("error")] = "this point killed the Dask worker solving it on every try (a crash: please report it)"
        for solver in self.outputs.solvers:
            row[header.index(f"{solver}.status")] = "crashed"
        text = io.StringIO()
        csv.writer(text, lineterminator="\n").writerow(row)
        return text.getvalue()

    def batch_size(self, workers: int, batch_seconds: float, remaining: int) -> int:
        """Points in the next task: `batch_seconds` over the mean CPU time of the points solved so
        far (it corrects itself as the sweep goes: the first points carry one-off costs), and at
        most a quarter of the remaining points per worker, so that the end stays balanced. CPU time,
        not wall: with other load on the machine the wall time of a point grows, while a task's
        cost to the scheduler does not shrink, so tasks sized by wall time would be too small."""
        per_point = self.cpu_s / self.solved if self.solved else 0.0
        size = round(batch_seconds / per_point) if per_point > 0 else _MAX_BATCH
        size = max(1, min(_MAX_BATCH, size, math.ceil(remaining / (4 * workers))))
        self.largest_batch = max(self.largest_batch, size)
        return size

    def run(self, workers: int, batch_seconds: float) -> None:
        """Runs every missing point: first a task of a few points per worker, to time a point, then
        tasks sized by batch_size(), at most 2 per worker (+2) in flight."""
        as_completed = _distributed().as_completed
        runs = list(self.store.missing_runs())
        pilot, rest = [], []
        budget = _PILOT_POINTS * workers
        for first, count in runs:
            take = min(count, budget)
            if take:
                pilot += [(p, min(_PILOT_POINTS, first + take - p)) for p in range(first, first + take, _PILOT_POINTS)]
                budget -= take
            if count > take:
                rest.append((first + take, count - take))
        pending = as_completed([self.submit(f, c) for f, c in pilot])
        for future in pending:
            self.collect(future, pending)
        remaining = sum(c for _, c in rest)

        def batches() -> Iterator[tuple[int, int]]:
            nonlocal remaining
            for first, count in rest:
                start = first
                while start < first + count:
                    size = min(self.batch_size(workers, batch_seconds, remaining), first + count - start)
                    yield start, size
                    start, remaining = start + size, remaining - size

        queue = batches()
        pending = as_completed([self.submit(f, c) for f, c in _take(queue, 2 * workers + 2)])
        for future in pending:
            self.collect(future, pending)
            for f, c in _take(queue, 1):
                pending.add(self.submit(f, c))


def _take(iterator: Any, n: int) -> list[Any]:
    out = []
    for item in iterator:
        out.append(item)
        if len(out) == n:
            break
    return out


def _versions() -> dict[str, str]:
    # Imported by name, as everywhere in this module: a plain import makes mypy analyse Dask's
    # sources (a type check of the package took 24 s instead of 5).
    versions = {name: str(importlib.import_module(name).__version__)
                for name in ("dask", "distributed", "numpy")}
    return {"catena": __version__, **versions, "python": platform.python_version()}


def _json_safe(value: Any) -> Any:
    return json.loads(json.dumps(value, default=str))


def run_sweep(spec_source: Any, out: str, *, client: Any = None, scheduler: Optional[str] = None,
              workers: Optional[int] = None, progress: Optional[bool] = None,
              batch_seconds: float = 0.1) -> tuple[str, dict[str, Any]]:
    """Runs (or resumes) a sweep into `out`; returns (points.csv path, summary)."""
    spec = read_spec(spec_source)
    if not (isinstance(batch_seconds, (int, float)) and 0 < batch_seconds <= 3600):
        raise InvalidInput(f"batch_seconds = {batch_seconds!r}: in (0, 3600] s")
    header = columns(spec.axes, spec.outputs)
    digest = hashlib.sha256(f"{spec.digest()} {__version__} {','.join(header)}".encode()).hexdigest()
    start = time.perf_counter()
    connected = _client(client, scheduler, None) if client is None and scheduler else None  # fail before writing
    try:
        store = Store(out, digest, spec.points, header)
    except BaseException:
        if connected:
            connected[0].close()
        raise
    try:
        missing = spec.points - store.resumed
        used_workers, runner, started, solving = 0, None, 0.0, 0.0
        if missing:
            dask_client, cluster, owned = connected or _client(client, None, workers)
            connected = None
            started = time.perf_counter() - start
            reporter = Progress(missing, progress)
            try:
                used_workers = max(1, len(dask_client.scheduler_info().get("workers", {})))
                runner = _Runner(dask_client, spec, store, reporter)
                runner.run(used_workers, batch_seconds)
                solving = time.perf_counter() - start - started
            finally:
                reporter.finish()
                if owned:
                    dask_client.close()
                    if cluster is not None:
                        cluster.close()
        path = store.assemble()
    finally:
        store.close()
        if connected:  # connected to a scheduler, but nothing was left to solve
            connected[0].close()
    wall = time.perf_counter() - start
    counts, errors = status_counts(path, spec.outputs.solvers)
    busy = runner.busy_s if runner else 0.0
    summary = {
        "spec": _json_safe(spec.text), "scene": spec.scene_origin, "points": spec.points,
        "computed": missing, "resumed": store.resumed, "status_counts": counts, "points_with_error": errors,
        "wall_time_s": wall, "cluster_start_s": started, "run_time_s": solving, "workers": used_workers,
        "tasks": runner.tasks if runner else 0, "batch_points": runner.largest_batch if runner else 0, "solve_time_s": busy,
        "task_cpu_time_s": runner.cpu_s if runner else 0.0,
        # the workers' busy share of the run (after the cluster started): the rest is what the
        # scheduler, the transfers, the client's writes and idle workers at the end cost
        "worker_utilization": busy / (solving * used_workers) if used_workers and solving > 0 else None,
        "columns": header, "parquet": "not written: Parquet needs pyarrow or fastparquet, neither installed "
                                      "(Debian 12 packages neither); points.csv holds every value",
        "versions": _versions(),
    }
    with open(os.path.join(out, "summary.json.partial"), "w") as file:
        json.dump(summary, file, indent=2)
    os.replace(os.path.join(out, "summary.json.partial"), os.path.join(out, "summary.json"))
    return path, summary


def sweep(spec: Any, client: Any = None, *, out: Optional[str] = None, workers: Optional[int] = None,
          scheduler: Optional[str] = None, progress: Optional[bool] = False, batch_seconds: float = 0.1) -> Any:
    """Runs the sweep of a SPEC (path of a TOML file, or a dict with its structure) on Dask and returns
    points.csv as a pandas DataFrame, with every double exact (docs/how-to/sweep.md).

    client: a dask.distributed.Client to run on (default: a LocalCluster of `workers` processes, one
        thread each, all cores by default; or the scheduler at `scheduler`, an address such as
        "tcp://host:8786", which must answer within 5 s).
    out: the output directory (points.csv, summary.json, journal.csv); rerunning into it resumes.
        Default: a temporary directory, removed once read.
    progress: points done, rate and ETA on stderr (None: when stderr is a terminal).
    """
    pandas: Any = importlib.import_module("pandas")
    temporary = out is None
    directory = tempfile.mkdtemp(prefix="catena-sweep-") if out is None else os.fspath(out)
    try:
        path, _ = run_sweep(spec, directory, client=client, scheduler=scheduler, workers=workers,
                            progress=progress, batch_seconds=batch_seconds)
        return pandas.read_csv(path, float_precision="round_trip", keep_default_na=False,
                               na_values=[""])
    finally:
        if temporary:
            shutil.rmtree(directory, ignore_errors=True)
