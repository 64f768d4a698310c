# SPDX-License-Identifier: MIT
"""A value a solver did not produce is None (a scalar) or NaN (in an array) in Python, never the -1
the C++ structs hold (docs/reference/python.md, "Missing values"): so a test of the estimates
against a tolerance fails for modes that have none, instead of passing."""

import math

import numpy
import pytest

import catena


def mooring_problem():
    return catena.Problem(catena.Cable(length_m=1000.0, weight_n_per_m=1000.0, mass_kg_per_m=120.0,
                                       axial_stiffness_n=5e8), b_m=(900.0, 300.0))


def test_modes_without_an_error_estimate_fail_a_tolerance_test():
    # Without Richardson, fe estimates its error from N/2 elements: with N = 8 too few for 4
    # modes, so it has no estimate (src/solvers/fe/fe_summary.cpp says so in a warning). No
    # accuracy target (tolerance = 0), so that fe keeps this mesh instead of refining.
    modes = catena.solve_fe(mooring_problem(), catena.Request(inplane_modes=4), elements=8,
                            richardson=False, tolerance=0.0).inplane
    assert modes.summary.status == "converged"
    assert any("no error estimate" in w for w in modes.summary.warnings)
    estimates = modes.relative_error_estimate
    assert estimates.shape == (4,) and numpy.isnan(estimates).all()
    assert not (estimates < 1e-3).any()
    assert all(mode.relative_error_estimate is None for mode in modes.modes)
    assert modes.summary.max_relative_error_estimate is None


def test_measures_a_method_does_not_have_are_none():
    problem = catena.Problem.taut_inclined(eps=0.18, phi_deg=23.46, lambda2=100.0)
    modes = catena.solve_airy(problem, catena.Request(inplane_modes=3)).inplane
    assert modes.summary.max_residual is None and modes.summary.iterations is None
    assert modes.proved_count_below_top is None
    assert modes.summary.accuracy_target is None
    assert not numpy.isnan(modes.relative_error_estimate).any()  # airy does estimate


def test_tension_and_modal_mass_are_none_unless_asked():
    problem = mooring_problem()
    plain = catena.solve_shooting(problem, catena.Request(inplane_modes=2)).inplane
    assert plain.max_abs_tension_n is None and plain.modal_mass_kg is None
    assert plain.modes[0].max_abs_tension_n is None and plain.modes[0].modal_mass_kg is None
    shapes = catena.solve_shooting(problem, catena.Request(inplane_modes=2, shapes=True, points=21)).inplane
    assert shapes.max_abs_tension_n is None and shapes.modes[0].max_abs_tension_n is None
    assert (shapes.modal_mass_kg > 0).all() and shapes.modes[0].modal_mass_kg > 0


@pytest.mark.parametrize("info", catena.solvers(), ids=lambda info: info.name)
def test_no_negative_sentinel_reaches_python(info):
    problem = {"frobenius": catena.Problem.gale_sag(h_over_b=0.25, sag_param=0.8),
               "asymptotic": catena.Problem.taut_inclined(eps=0.18, phi_deg=23.46, lambda2=100.0),
               "airy": catena.Problem.taut_inclined(eps=0.18, phi_deg=23.46, lambda2=100.0)}.get(
                   info.name, mooring_problem())
    out = catena.run_solver(info.name, problem, catena.Request(inplane_modes=3, outofplane_modes=2))
    summaries = [out.summary] + [m.summary for m in (out.inplane, out.outofplane) if m is not None]
    for summary in summaries:
        for field in ("iterations", "operations", "max_relative_error_estimate", "max_residual",
                      "accuracy_target", "wall_time_s"):
            value = getattr(summary, field)
            assert value is None or value >= 0, f"{summary.solver} {field} = {value}"
    for modes in (out.inplane, out.outofplane):
        assert modes.proved_count_below_top is None or modes.proved_count_below_top >= 0
        estimates = modes.relative_error_estimate
        assert numpy.all(numpy.isnan(estimates) | (estimates >= 0))
        for mode in modes.modes:
            assert mode.relative_error_estimate is None or not math.isnan(mode.relative_error_estimate)
