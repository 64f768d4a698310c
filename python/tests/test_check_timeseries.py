# SPDX-License-Identifier: MIT
"""catena.check_timeseries (docs/how-to/check-time-series.md, docs/reference/python.md): a free
decay built here from Catena's own damped modes of the damped mooring line (catena.solve, so no
frequency is hard-coded) agrees when given as arrays and as a MoorDyn-format file, as the CLI reads
it; one frequency 1 % off disagrees; bad input raises InvalidInput with the CLI's messages."""

import json
import math

import numpy
import pytest

import catena
from conftest import SCENES

DAMPED = SCENES / "damped" / "mooring-line-900m-damped.toml"


@pytest.fixture(scope="module")
def decay():
    """(time_s, samples) of 1e6 + sum_k e^(-delta t) cos(omega_d t + k) over Catena's first three
    in-plane damped modes, with mode 2's frequency scaled by `factor`, plus white noise."""
    modes = catena.solve(DAMPED, solvers=["shooting"])["shooting"].inplane
    f, zeta = modes.frequency_hz[:3], modes.damping_ratio[:3]

    def make(factor=1.0):
        t = numpy.arange(0.0, 300.0 + 1e-9, 0.1)
        x = numpy.full_like(t, 1.0e6) + numpy.random.default_rng(3).normal(0.0, 0.5, t.size)
        for k in range(3):
            omega = 2 * math.pi * f[k] * (factor if k == 1 else 1.0)
            delta = zeta[k] * omega / math.sqrt(1 - zeta[k] ** 2)
            x += 3e4 / (k + 1) * numpy.exp(-delta * t) * numpy.cos(omega * t + k)
        return t, x
    return make


def test_arrays_of_catenas_decay_agree(decay):
    t, x = decay()
    check = catena.check_timeseries({"FAIRTEN1": x}, DAMPED, time_s=t, window=(1.0, None))
    assert not check.failed, check.modes
    assert [m.mode for m in check.modes] == [1, 2, 3]
    for m in check.modes:
        assert m.verdict == "agrees", m.note
        assert abs(m.frequency_error_hz) <= m.frequency_uncertainty_hz + m.catena_frequency_error_hz
    assert check.window_s[0] == pytest.approx(1.0)
    document = json.loads(check.to_json())
    assert document["modes"][0]["verdict"] == "agrees"


def test_a_moordyn_file_is_read_as_the_cli_reads_it_and_one_percent_off_disagrees(decay, tmp_path):
    t, x = decay(1.01)
    path = tmp_path / "decay.out"
    rows = "".join(f"{ti:10.4f}{xi:20.7e}\n" for ti, xi in zip(t, x))
    path.write_text(f"{'Time':>10}{'FAIRTEN1':>20}\n{'(s)':>10}{'(N)':>20}\n" + rows)
    check = catena.check_timeseries(path, DAMPED, "FAIRTEN1")
    assert check.failed
    assert [m.verdict for m in check.modes] == ["agrees", "disagrees", "agrees"]


@pytest.mark.parametrize("kwargs, message", [
    ({"channels": ["FAIRTEN2"]}, r"no channel 'FAIRTEN2' \(1 channels; closest: FAIRTEN1\)"),
    ({"window": (10.0, 20.0)}, "shorter than two periods"),
    ({"window": (0.0, 400.0)}, "not within the record"),
    ({"plane": "sideways"}, "plane = 'sideways'"),
])
def test_bad_input_raises_with_the_cli_messages(decay, kwargs, message):
    t, x = decay()
    with pytest.raises(catena.InvalidInput, match=message):
        catena.check_timeseries({"time": t, "FAIRTEN1": x}, DAMPED, **kwargs)


def test_bad_samples_are_refused(decay):
    t, x = decay()
    x = x.copy()
    x[17] = math.nan
    with pytest.raises(ValueError, match=r"sample 18 \(time 1.7 s\), channel 'FAIRTEN1'"):
        catena.check_timeseries({"FAIRTEN1": x}, DAMPED, time_s=t)
    with pytest.raises(catena.InvalidInput, match="time must increase strictly"):
        catena.check_timeseries({"FAIRTEN1": x[:3]}, DAMPED, time_s=[0.0, 0.2, 0.1])
    with pytest.raises(catena.InvalidInput, match="time_s: give the sample times"):
        catena.check_timeseries({"FAIRTEN1": x}, DAMPED)
