# SPDX-License-Identifier: MIT
"""catena.sweep and `catena sweep` (docs/how-to/sweep.md): the points of a SPEC on a local Dask
cluster equal a serial loop of catena.solve bit for bit, also when a worker is killed mid-run; a
resumed sweep solves only the points it had not written; bad SPECs are refused before anything
runs, naming the field."""

import math
import os
import signal
import subprocess
import sys
import threading
import time

import pytest

import catena
from catena._sweep_spec import read_spec

distributed = pytest.importorskip("distributed", reason="Dask is not installed (Debian: python3-distributed)")
pandas = pytest.importorskip("pandas", reason="pandas is not installed (Debian: python3-pandas)")

SOLVERS = ["shooting", "asymptotic", "airy"]
SCENE = {
    "taut_inclined": {"eps": 0.3, "phi_deg": 30.0, "lambda2": 10.0},
    "request": {"inplane_modes": 2, "outofplane_modes": 1},
    "solvers": {name: {} for name in SOLVERS},
}


def grid_spec(lambda2_points=20, eps_values=(0.05, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9)):
    return {
        "scene": SCENE,
        "axes": [{"key": "taut_inclined.lambda2", "from": 0.5, "to": 200.0, "points": lambda2_points,
                  "spacing": "log"},
                 {"key": "taut_inclined.eps", "values": list(eps_values)}],
        "outputs": {"differences": "most_accurate"},
    }


@pytest.fixture(scope="module")
def client():
    cluster = distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None)
    with distributed.Client(cluster) as dask_client:
        yield dask_client
    cluster.close()


def same(a, b):
    """Equal doubles, NaN equal to NaN (a missing value on both sides)."""
    return (math.isnan(a) and math.isnan(b)) if isinstance(a, float) and math.isnan(a) else a == b


def assert_equals_serial_loop(frame, spec):
    """Every value of `frame` equals catena.solve of the point's scene, solved here, one by one."""
    parsed = read_spec(spec)
    assert list(frame["point"]) == list(range(parsed.points))  # each point once, in order
    for point in range(parsed.points):
        row = frame.iloc[point]
        result = catena.solve(parsed.scene_at(point), solvers=SOLVERS)
        for axis, value in zip(parsed.axes, parsed.point_values(point)):
            assert row[axis.key] == value
        for name in SOLVERS:
            assert row[f"{name}.status"] == result[name].summary.status
            for plane, count in (("inplane", 2), ("outofplane", 1)):
                modes = getattr(result[name], plane)
                for k in range(1, count + 1):
                    column = f"{name}.{plane}.mode{k}"
                    omega = float(modes.omega_rad_s[k - 1]) if modes is not None and len(modes.omega_rad_s) >= k else math.nan
                    estimate = (float(modes.relative_error_estimate[k - 1])
                                if modes is not None and len(modes.omega_rad_s) >= k else math.nan)
                    assert same(row[f"{column}.omega_rad_s"], omega), (point, column)
                    assert same(row[f"{column}.relative_error_estimate"], estimate), (point, column)
        assert row["statics.horizontal_force_n"] == result.statics.horizontal_force_n
        assert row["groups.lambda2"] == result.groups.lambda2


def test_200_points_on_2_workers_equal_a_serial_loop_even_with_a_worker_killed(client, tmp_path):
    """A worker is killed (SIGKILL) once the first tasks are written: its task runs again elsewhere,
    and points.csv still holds each of the 200 points once, equal to catena.solve bit for bit."""
    spec, out = grid_spec(), tmp_path / "out"
    pids = client.run(os.getpid)
    killed = {}

    def kill_a_worker_mid_run():
        journal = out / "journal.csv"
        deadline = time.monotonic() + 120
        while time.monotonic() < deadline:
            written = journal.read_text().count("#batch") if journal.exists() else 0
            if written >= 2:
                killed["points_written"] = sum(int(line.split()[2]) for line in journal.read_text().splitlines()
                                               if line.startswith("#batch "))
                os.kill(next(iter(pids.values())), signal.SIGKILL)
                return
            time.sleep(0.005)

    killer = threading.Thread(target=kill_a_worker_mid_run)
    killer.start()
    frame = catena.sweep(spec, client, out=out, batch_seconds=0.02)
    killer.join()
    assert 0 < killed["points_written"] < 200, "the worker was not killed mid-run"
    assert len(frame) == 200
    assert_equals_serial_loop(frame, spec)
    # differences against the most accurate exact solver (here the only one, shooting)
    row = frame[frame["airy.status"] == "converged"].iloc[-1]
    assert row["reference.inplane"] == "shooting"
    assert row["shooting.inplane.mode1.relative_difference"] == 0.0
    expected = abs(row["airy.inplane.mode1.omega_rad_s"] - row["shooting.inplane.mode1.omega_rad_s"]) / \
        row["shooting.inplane.mode1.omega_rad_s"]
    assert row["airy.inplane.mode1.relative_difference"] == expected


def without_times(path):
    """points.csv's lines without their last column, wall_time_s (a time differs run to run)."""
    lines = path.read_text().splitlines()
    assert lines[0].endswith(",wall_time_s")
    return [line.rsplit(",", 1)[0] for line in lines]


def test_a_resumed_sweep_solves_only_the_missing_points(tmp_path, monkeypatch):
    """A journal cut in the middle of a block (a client killed while writing) is resumed: only the
    points of the blocks not written are solved again, and points.csv is the same file."""
    spec = grid_spec(lambda2_points=6, eps_values=(0.1, 0.5))  # 12 points
    spec["outputs"] = {"solvers": ["asymptotic", "airy"]}
    out = tmp_path / "out"
    with distributed.Client(processes=False, n_workers=1, threads_per_worker=1, dashboard_address=":0") as local:
        catena.sweep(spec, local, out=out, batch_seconds=1e-6)  # a point or two a task
        complete = without_times(out / "points.csv")
        lines = (out / "journal.csv").read_text().splitlines(keepends=True)
        blocks = [i for i, line in enumerate(lines) if line.startswith("#batch ")]
        # 5 blocks, then the rows of a 6th without its "#batch" line, and half a row
        kept = lines[:blocks[4] + 1] + lines[blocks[4] + 1:blocks[5]] + ["11,200.0,conver"]
        (out / "journal.csv").write_text("".join(kept))
        written = sum(int(lines[i].split()[2]) for i in blocks[:5])
        (out / "points.csv").unlink()
        solved = []
        real_solve = catena.solve
        monkeypatch.setattr(catena, "solve", lambda scene, **kw: solved.append(scene) or real_solve(scene, **kw))
        catena.sweep(spec, local, out=out)
    assert 5 <= written < 12 and len(solved) == 12 - written
    assert without_times(out / "points.csv") == complete
    # the same SPEC again: nothing to solve; another SPEC into the same directory is refused
    solved.clear()
    catena.sweep(spec, None, out=out)
    assert not solved
    spec["axes"][1]["values"] = [0.1, 0.6]
    with pytest.raises(catena.InvalidInput, match="another SPEC"):
        catena.sweep(spec, None, out=out)


def bad(spec, match, tmp_path):
    with pytest.raises(catena.InvalidInput, match=match):
        catena.sweep(spec, None, out=tmp_path / "never")
    assert not (tmp_path / "never").exists()  # refused before anything ran or was written


@pytest.mark.parametrize("axis, match", [
    ({"key": "taut_inclined.epss", "values": [0.1]}, r"axes\[0\].*epss"),
    ({"key": "taut_incline.eps", "values": [0.1]}, r"axes\[0\].key = 'taut_incline.eps': 'taut_incline' is not a key of the scene \(close: taut_inclined\)"),
    ({"key": "taut_inclined.eps", "values": []}, r"axes\[0\].values: empty"),
    ({"key": "taut_inclined.eps", "from": 0.0, "to": 1.0, "points": 5, "spacing": "log"}, r"axes\[0\].from = 0.0: a log spacing needs bounds > 0"),
    ({"key": "taut_inclined.phi_deg", "from": 10.0, "to": 95.0, "points": 3},
     r"axes\[0\] \(key 'taut_inclined.phi_deg'\) at its last value 95.0: the scene .* is refused: .*phi_deg"),
    ({"key": "line.segments.1.EA", "values": [1e9]}, r"'line' is not a key of the scene"),
])
def test_bad_axes_are_refused_naming_the_field(axis, match, tmp_path):
    spec = grid_spec()
    spec["axes"][0] = axis
    bad(spec, match, tmp_path)


def test_bad_specs_are_refused_naming_the_field(tmp_path):
    spec = grid_spec()
    spec["zip"] = True
    bad(spec, r"zip = true: the axes must have equal lengths \(axes\[0\] 20, axes\[1\] 10\)", tmp_path)
    spec = grid_spec()
    spec["outputs"] = {"solvers": ["shootin"]}
    bad(spec, r"outputs.solvers\[0\] = 'shootin': not a solver \(close: shooting\)", tmp_path)
    spec = grid_spec()
    spec["outputs"] = {"modes": 3}
    bad(spec, r"outputs.modes = 3: more than the scene's request.inplane_modes = 2", tmp_path)
    spec = grid_spec()
    spec["axis"] = spec.pop("axes")
    bad(spec, r"axis: unknown SPEC key", tmp_path)


def test_an_unreachable_scheduler_is_an_error_within_seconds(tmp_path):
    start = time.monotonic()
    with pytest.raises(catena.InvalidInput, match=r"--scheduler tcp://127.0.0.1:9: no Dask scheduler answered within 5 s"):
        catena.sweep(grid_spec(), scheduler="tcp://127.0.0.1:9", out=tmp_path / "out")
    assert time.monotonic() - start < 20


def test_points_of_grids_zips_and_samples():
    spec = read_spec({"scene": SCENE, "zip": True,
                      "axes": [{"key": "taut_inclined.eps", "values": [0.1, 0.2, 0.3]},
                               {"key": "taut_inclined.lambda2", "samples": 3, "from": 1.0, "to": 2.0, "seed": 4,
                                "sampling": "latin_hypercube"}]})
    assert spec.points == 3
    assert [spec.point_values(p)[0] for p in range(3)] == [0.1, 0.2, 0.3]
    samples = sorted(spec.point_values(p)[1] for p in range(3))  # one sample in each third of [1, 2]
    assert [math.floor((s - 1.0) * 3) for s in samples] == [0, 1, 2]
    grid = read_spec(grid_spec(lambda2_points=3, eps_values=(0.1, 0.2)))
    assert grid.points == 6
    assert grid.point_values(1) == [0.5, 0.2]  # the last axis varies fastest
    assert grid.point_values(5)[0] == pytest.approx(200.0)


def test_the_cli_reaches_the_sweep(cli, tmp_path):
    spec = tmp_path / "spec.toml"
    (tmp_path / "base.toml").write_text('[taut_inclined]\neps = 0.3\nphi_deg = 30.0\nlambda2 = 10.0\n'
                                        '[request]\ninplane_modes = 1\n')
    spec.write_text('scene = "base.toml"\n[[axes]]\nkey = "taut_inclined.lambda2"\nvalues = [5.0, 50.0]\n'
                    '[outputs]\nsolvers = ["asymptotic"]\n')
    done = subprocess.run([cli, "sweep", str(spec), "--out", str(tmp_path / "out"), "--workers", "1", "--quiet"],
                          capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    frame = pandas.read_csv(tmp_path / "out" / "points.csv", float_precision="round_trip")
    assert list(frame["taut_inclined.lambda2"]) == [5.0, 50.0]
    assert frame["asymptotic.inplane.mode1.omega_rad_s"][1] == \
        catena.solve(read_spec(spec).scene_at(1), solvers=["asymptotic"])["asymptotic"].inplane.omega_rad_s[0]
    spec.write_text('scene = "base.toml"\n[[axes]]\nkey = "taut_inclined.lambda2"\nvalues = []\n')
    done = subprocess.run([cli, "sweep", str(spec), "--out", str(tmp_path / "bad")], capture_output=True, text=True,
                          timeout=300)
    assert done.returncode == 2 and "axes[0].values: empty" in done.stderr, done.stderr
