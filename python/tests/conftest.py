# SPDX-License-Identifier: MIT
"""Shared fixtures of the Python tests (run by ctest as python_tests: python/CMakeLists.txt sets
PYTHONPATH to <build>/python, CATENA_CLI to the build's `catena` binary and CATENA_SOURCE_DIR)."""

import math
import os
import pathlib
import tomllib

import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("CATENA_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
SCENES = SOURCE_DIR / "verification" / "scenes"
MOORING = SCENES / "physical" / "mooring-line-900m.toml"


@pytest.fixture(scope="session")
def cli():
    path = os.environ.get("CATENA_CLI")
    if not path or not os.access(path, os.X_OK):
        pytest.fail("CATENA_CLI must name the build's catena binary (ctest sets it)")
    return path


@pytest.fixture(scope="session")
def mooring_path():
    return MOORING


@pytest.fixture
def mooring_dict():
    """The mooring scene's TOML as a dict (a fresh copy per test)."""
    with open(MOORING, "rb") as file:
        return tomllib.load(file)


def modal_values(result):
    """Every frequency, error estimate and status of a Result, as plain Python values."""
    values = {"H": result.statics.horizontal_force_n, "V_A": result.statics.vertical_force_a_n}
    for name in result.solvers:
        output = result[name]
        values[name] = output.summary.status
        for plane in ("inplane", "outofplane"):
            modes = getattr(output, plane)
            if modes is not None:
                # NaN (no estimate) never equals itself: compared as None
                estimates = [None if math.isnan(e) else e for e in modes.relative_error_estimate.tolist()]
                values[name, plane] = (modes.omega_rad_s.tolist(), estimates, modes.summary.status,
                                       modes.summary.max_relative_error_estimate)
    return values
