# SPDX-License-Identifier: MIT
"""catena.check: the `catena check` comparison from Python. The same library calls as the CLI, so
the same JSON and the same messages; a synthetic biased code is recovered; rows, columns and files
agree; bad rows raise naming the field."""

import csv
import json
import math
import subprocess
import sys
import threading
import time

import numpy as np
import pytest

import catena
from conftest import SOURCE_DIR

EXAMPLES = SOURCE_DIR / "docs" / "examples"
RESULTS_CSV = EXAMPLES / "other-code-results.csv"


@pytest.fixture(scope="module")
def example_scene(cli, tmp_path_factory):
    """Line 1 of the example MoorDyn deck as a Catena scene, imported by the CLI (as the README does)."""
    out = tmp_path_factory.mktemp("example")
    subprocess.run([cli, "import", "moordyn", str(EXAMPLES / "moordyn-v2-semitaut.txt"), "--out", str(out)],
                   check=True, capture_output=True)
    return out / "moordyn-v2-semitaut-line-1.toml"


@pytest.fixture(scope="module")
def example_check(example_scene):
    return catena.check(str(RESULTS_CSV), str(example_scene))


def without_creation_time(text):
    document = json.loads(text)
    del document["created_utc"]
    return document


def test_json_equals_the_cli_json(cli, example_scene, example_check, tmp_path):
    out = tmp_path / "check.json"
    run = subprocess.run([cli, "check", str(RESULTS_CSV), "--scene", str(example_scene), "--json", str(out), "-q"],
                         capture_output=True, text=True)
    assert run.returncode == 1, run.stderr  # the example's mode 2 converges to a wrong limit
    expected = without_creation_time(out.read_text())
    assert without_creation_time(example_check.to_json()) == expected
    assert len(expected["modes"]) == 6


def test_objects_carry_the_comparison(example_check):
    assert example_check.error is None and example_check.failed
    assert example_check.rtol == 1e-3
    assert [r.plane for r in example_check.references] == ["in-plane", "out-of-plane"]
    for reference in example_check.references:
        assert reference.solver in ("shooting", "fe") and reference.solver in reference.reason
        assert np.all(reference.relative_error_estimate > 0) and np.all(np.diff(reference.omega_rad_s) > 0)
    wrong = [m for m in example_check.modes if m.verdict == "converges to a wrong limit"]
    assert [(m.plane, m.mode) for m in wrong] == [("in-plane", 2)]
    mode = wrong[0]
    assert mode.failed and mode.resolution == 80 and [r.resolution for r in mode.resolutions] == [10, 20, 40, 80]
    assert mode.mac is None and mode.study.trustworthy
    assert mode.observed_order == pytest.approx(2.0, rel=1e-3)
    assert mode.bias_relative == pytest.approx(5e-3, rel=1e-3)
    assert mode.limit_frequency_hz == pytest.approx(mode.reference_frequency_hz * 1.005, rel=1e-6)
    assert mode.relative_error == pytest.approx(mode.frequency_hz / mode.reference_frequency_hz - 1, rel=1e-9)
    assert all(m.verdict == "converged" for m in example_check.modes if (m.plane, m.mode) != ("in-plane", 2))


def biased_rows(reference, bias, c=1.5, resolutions=(10, 20, 40, 80)):
    """A synthetic code converging at second order (h = 1/N) to reference * (1 + bias)."""
    return [{"plane": "in-plane", "mode": k + 1, "resolution": n,
             "omega_rad_s": float(omega) * (1.0 + bias[k]) * (1.0 - c / n ** 2)}
            for k, omega in enumerate(reference) for n in resolutions]


def reference_omegas(scene):
    """Catena's certified reference for in-plane modes 1 to 3 (asked as the checks below ask)."""
    first = catena.check([{"plane": "in-plane", "mode": k, "omega_rad_s": 1.0} for k in (1, 2, 3)], scene)
    return first.references[0].omega_rad_s[:3]


def test_synthetic_biased_code_recovers_order_and_bias(example_scene):
    reference = reference_omegas(str(example_scene))
    bias = [0.0, 0.02, -0.004]
    result = catena.check(biased_rows(reference, bias), str(example_scene))
    assert result.failed
    for mode, b in zip(result.modes, bias):
        assert mode.reference_omega_rad_s == reference[mode.mode - 1]
        assert mode.observed_order == pytest.approx(2.0, rel=1e-6)
        if b == 0.0:
            assert abs(mode.bias_relative) < 1e-9
            assert mode.verdict == "converged"  # finest error 1.5 / 80^2 = 2.3e-4 <= 1e-3
        else:
            assert mode.bias_relative == pytest.approx(b, rel=1e-3)
            assert mode.verdict == "converges to a wrong limit"


def test_unbiased_code_converged_or_not_yet(example_scene):
    rows = biased_rows(reference_omegas(str(example_scene)), [0.0, 0.0, 0.0])
    assert [m.verdict for m in catena.check(rows, str(example_scene)).modes] == ["converged"] * 3
    tight = catena.check(rows, str(example_scene), rtol=1e-4)  # 2.3e-4 > 1e-4
    assert [m.verdict for m in tight.modes] == ["converges, not yet within tolerance"] * 3
    assert tight.failed


def test_rows_columns_and_files_agree(example_scene, tmp_path):
    rows = biased_rows(reference_omegas(str(example_scene)), [0.0, 0.01, 0.0])
    csv_path = tmp_path / "results.csv"
    with open(csv_path, "w", newline="") as file:
        writer = csv.DictWriter(file, fieldnames=["plane", "mode", "resolution", "omega_rad_s"])
        writer.writeheader()
        writer.writerows({k: repr(v) if isinstance(v, float) else v for k, v in row.items()} for row in rows)
    json_path = tmp_path / "results.json"
    json_path.write_text(json.dumps({"results": rows}))
    columns = {key: np.array([row[key] for row in rows]) for key in rows[0]}

    def modes(result):
        return json.loads(result.to_json())["modes"]

    from_rows = modes(catena.check(rows, str(example_scene)))
    assert modes(catena.check(str(csv_path), str(example_scene))) == from_rows
    assert modes(catena.check(json_path, str(example_scene))) == from_rows
    assert modes(catena.check(columns, str(example_scene))) == from_rows
    assert modes(catena.check({"results": rows}, catena.load_scene(str(example_scene)))) == from_rows


BAD_ROWS = [
    ([{"plane": "sideways", "mode": 1, "frequency_hz": 0.1}], "results[0].plane"),
    ([{"plane": "in-plane", "mode": 1, "frequency_hz": 0.1}, {"plane": "in-plane", "mode": 0, "frequency_hz": 0.2}],
     "results[1].mode"),
    ([{"plane": "in-plane", "mode": "two", "frequency_hz": 0.1}], "results[0].mode"),
    ([{"plane": "in-plane", "mode": 1, "frequency_hz": math.nan}], "results[0].frequency_hz"),
    ([{"plane": "in-plane", "mode": 1, "frequency_hz": -0.1}], "results[0]"),
    ([{"plane": "in-plane", "mode": 1}], "'frequency_hz'"),
    ([{"plane": "in-plane", "mode": 1, "freq_hz": 0.1, "frequency_hz": 0.1}], "unknown key 'freq_hz'"),
    ([{"plane": "in-plane", "mode": 1, "frequency_hz": 0.1}] * 2, "results[1]"),
    ([{"plane": "in-plane", "mode": 1, "frequency_hz": object()}], "results[0].frequency_hz"),
    ({"plane": ["in-plane"], "mode": [1, 2], "frequency_hz": [0.1, 0.2]}, "different lengths"),
    ({"plane": "in-plane", "mode": [1], "frequency_hz": [0.1]}, "column 'plane'"),
    ([], "non-empty"),
]


@pytest.mark.parametrize("rows, field", BAD_ROWS)
def test_bad_rows_raise_naming_the_field(example_scene, rows, field):
    with pytest.raises(catena.InvalidInput, match="<results>") as error:
        catena.check(rows, str(example_scene))
    assert field in str(error.value)


def test_bad_file_raises_the_cli_message(cli, example_scene, tmp_path):
    bad = tmp_path / "bad.csv"
    bad.write_text("plane,mode,frequency_hz\nin-plane,1,0.08\nin-plane,2,fast\n")
    run = subprocess.run([cli, "check", str(bad), "--scene", str(example_scene)], capture_output=True, text=True)
    assert run.returncode == 2
    with pytest.raises(catena.InvalidInput) as error:
        catena.check(str(bad), str(example_scene))
    assert "row 2 (line 3), column 'frequency_hz'" in str(error.value)
    assert str(error.value) in run.stderr


@pytest.mark.parametrize("kwargs, error", [({"rtol": 0.0}, catena.InvalidInput), ({"rtol": 1.5}, catena.InvalidInput),
                                           ({"rtol": "tight"}, TypeError),
                                           ({"shapes": "shapes.csv"}, catena.InvalidInput)])
def test_bad_arguments_raise(example_scene, kwargs, error):
    with pytest.raises(error):
        catena.check([{"plane": "in-plane", "mode": 1, "frequency_hz": 0.1}], str(example_scene), **kwargs)


def test_missing_files_and_wrong_types():
    with pytest.raises(FileNotFoundError):
        catena.check("no-such-results.csv", SOURCE_DIR / "verification/scenes/analytic/taut-string.toml")
    with pytest.raises(TypeError):
        catena.check(42, SOURCE_DIR / "verification/scenes/analytic/taut-string.toml")


def test_the_gil_is_released_during_the_reference_solve(example_scene):
    """Another thread keeps running Python while the reference is solved."""
    rows = [{"plane": "in-plane", "mode": k, "omega_rad_s": 1.0 * k} for k in range(1, 40)]
    finished, durations = threading.Event(), []

    def run():
        start = time.perf_counter()
        catena.check(rows, str(example_scene))
        durations.append(time.perf_counter() - start)
        finished.set()

    worker = threading.Thread(target=run)
    last, longest = time.perf_counter(), 0.0
    worker.start()
    while not finished.is_set():
        now = time.perf_counter()
        longest, last = max(longest, now - last), now
    worker.join()
    # As in test_threads.py: the solve must outlast the thread switch interval many times over.
    assert durations[0] > 20 * sys.getswitchinterval(), durations[0]
    assert longest < 0.5 * durations[0], (longest, durations[0])
