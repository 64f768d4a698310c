# SPDX-License-Identifier: MIT
"""Solves release the GIL: 8 threads solving scenes concurrently give exactly what serial runs give."""

import sys
import threading
import time
from concurrent.futures import ThreadPoolExecutor

import catena
from conftest import SCENES, modal_values

SCENE_FILES = [
    SCENES / "physical" / "mooring-line-900m.toml",
    SCENES / "analytic" / "taut-string.toml",
    SCENES / "analytic" / "longitudinal-bar.toml",
    SCENES / "gale" / "gale-b-3-hb0.25-sag0.80.toml",
    SCENES / "gale" / "gale-b-3-hb0.50-sag0.90.toml",
    SCENES / "grinfogel" / "grinfogel-eps0.18-phi23.46-lambda2-100.toml",
    SCENES / "grinfogel" / "grinfogel-eps0.49-phi45.0-lambda2-30.toml",
    SCENES / "gale" / "gale-b-3-hb1.00-sag0.80.toml",
]


def solve_values(path):
    return modal_values(catena.solve(path))


def test_eight_threads_give_the_serial_results():
    serial = [solve_values(path) for path in SCENE_FILES]
    jobs = SCENE_FILES * 3  # 24 solves on 8 threads, several of the same scene at once
    with ThreadPoolExecutor(max_workers=8) as pool:
        parallel = list(pool.map(solve_values, jobs))
    assert parallel == serial * 3


def test_threads_building_blocks_concurrently():
    problem = catena.Problem(catena.Cable(length_m=1000.0, weight_n_per_m=1000.0, axial_stiffness_n=5e8,
                                          mass_kg_per_m=120.0, added_mass_kg_per_m=80.0), b_m=(900.0, 300.0))
    request = catena.Request(inplane_modes=4, outofplane_modes=2)

    def run(name):
        return catena.run_solver(name, problem, request).inplane.omega_rad_s.tolist()

    names = ["fe", "shooting"] * 8
    serial = [run(name) for name in names]
    with ThreadPoolExecutor(max_workers=8) as pool:
        assert list(pool.map(run, names)) == serial


def test_the_gil_is_released_while_solving():
    """While one thread solves, another keeps running Python: the longest pause it sees is far
    shorter than the solve (holding the GIL, it would be blocked for the whole solve)."""
    problem = catena.Problem(catena.Cable(length_m=1000.0, weight_n_per_m=1000.0, axial_stiffness_n=5e8,
                                          mass_kg_per_m=120.0, added_mass_kg_per_m=80.0), b_m=(900.0, 300.0))
    finished, durations = threading.Event(), []

    def solve():
        start = time.perf_counter()
        catena.solve_fe(problem, catena.Request(inplane_modes=60, outofplane_modes=60), elements=4000)
        durations.append(time.perf_counter() - start)
        finished.set()

    worker = threading.Thread(target=solve)
    last, longest = time.perf_counter(), 0.0
    worker.start()
    while not finished.is_set():
        now = time.perf_counter()
        longest, last = max(longest, now - last), now
    worker.join()
    # The solve must outlast the interpreter's thread switch interval (5 ms) many times over, or a
    # solve holding the GIL could not be told from one releasing it. (It was "> 0.2 s" until fe
    # got faster and the solve took 0.196 s.)
    assert durations[0] > 20 * sys.getswitchinterval(), durations[0]
    assert longest < 0.5 * durations[0], (longest, durations[0])
