# SPDX-License-Identifier: MIT
"""The dynamic tension in waves from Python (docs/reference/python.md, "Dynamic tension";
docs/explanation/dynamic-tension.md): the drag, tangential added mass, environment and motion
inputs with their errors (ValueError naming the field), what a solver that declines the dynamic
tension returns, and the conversion of a DynamicTension to numpy on values the test chose
(catena._catena._synthetic_dynamic_tension_output), independently of any solver."""

import math

import numpy
import pytest

import catena
from catena import _catena

CABLE = dict(length_m=100.0, weight_n_per_m=10.0, mass_kg_per_m=2.0, axial_stiffness_n=1e7,
             added_mass_kg_per_m=1.0)
DRAG = dict(diameter_m=0.1, drag_normal=1.2, drag_tangential=0.2, added_mass_tangential_kg_per_m=0.5)
B = (99.0, 10.0)
REGULAR = dict(direction=(1.0, 0.0), amplitude_m=2.0, periods_s=[8.0, 12.0])
RAO = dict(omega=[0.2, 0.6, 1.2], amplitude=[1.0, 0.8, 0.1], phase_deg=[0.0, 10.0, 20.0])


# --- inputs ---

def test_drag_and_tangential_added_mass_are_zero_by_default_and_kept_as_given():
    plain = catena.Cable(**CABLE)
    assert not plain.has_drag and plain.diameter_m == 0.0 and plain.added_mass_tangential_kg_per_m == 0.0
    assert "diameter" not in repr(plain)
    cable = catena.Cable(**CABLE, **DRAG)
    assert cable.has_drag and all(getattr(cable, k) == v for k, v in DRAG.items())
    assert cable.tangential_mass_kg_per_m == CABLE["mass_kg_per_m"] + DRAG["added_mass_tangential_kg_per_m"]
    assert "drag_normal=1.2" in repr(cable)
    segment = catena.LineSegment(**CABLE, **DRAG)
    assert segment.has_drag and all(getattr(segment, k) == v for k, v in DRAG.items())
    line = catena.Line([catena.LineSegment(**CABLE), segment])
    assert catena.Problem.from_line(line, b_m=(190.0, 20.0)).has_drag
    assert catena.Problem(cable, b_m=B).has_drag and not catena.Problem(plain, b_m=B).has_drag


def test_environment_defaults_and_is_carried_by_the_problem():
    default = catena.Problem(catena.Cable(**CABLE), b_m=B).environment
    assert default.water_density_kg_per_m3 == 1025.0 and default.gravity_m_per_s2 == 9.80665
    fresh = catena.Environment(water_density_kg_per_m3=1000.0, gravity_m_per_s2=9.81)
    problem = catena.Problem(catena.Cable(**CABLE), b_m=B, environment=fresh)
    assert problem.environment.water_density_kg_per_m3 == 1000.0
    assert problem.environment.gravity_m_per_s2 == 9.81
    line = catena.Line([catena.LineSegment(**CABLE)])
    assert catena.Problem.from_line(line, b_m=B, environment=fresh).environment.water_density_kg_per_m3 == 1000.0


@pytest.mark.parametrize("kwargs, field", [
    (dict(diameter_m=-0.1), "cable.diameter"),
    (dict(diameter_m=math.nan), "cable.diameter"),
    (dict(diameter_m=0.1, drag_normal=-1.0), "cable.drag_normal"),
    (dict(diameter_m=0.1, drag_tangential=math.inf), "cable.drag_tangential"),
    (dict(drag_normal=1.2), "cable.drag_normal"),  # a coefficient without a diameter
    (dict(added_mass_tangential_kg_per_m=-1.0), "cable.added_mass_tangential"),
])
def test_bad_cable_hydrodynamics_raise_value_error_naming_the_field(kwargs, field):
    with pytest.raises(ValueError, match=field.replace(".", r"\.")):
        catena.Cable(**CABLE, **kwargs)


@pytest.mark.parametrize("kwargs, field", [
    (dict(diameter_m=-0.1), "diameter"),
    (dict(diameter_m=0.1, drag_normal=-1.0), "drag_normal"),
    (dict(added_mass_tangential_kg_per_m=-1.0), "added_mass_tangential"),
])
def test_bad_segment_hydrodynamics_raise_value_error_naming_the_field(kwargs, field):
    with pytest.raises(catena.InvalidInput, match=field):
        catena.LineSegment(**CABLE, **kwargs)


@pytest.mark.parametrize("kwargs, field", [
    (dict(water_density_kg_per_m3=0.0), "environment.water_density"),
    (dict(water_density_kg_per_m3=math.nan), "environment.water_density"),
    (dict(gravity_m_per_s2=-9.8), "environment.gravity"),
])
def test_bad_environment_raises_value_error_naming_the_field(kwargs, field):
    with pytest.raises(ValueError, match=field.replace(".", r"\.")):
        catena.Environment(**kwargs)


def test_regular_and_irregular_motion_requests_read_back():
    regular = catena.MotionRequest(**REGULAR)
    assert not regular.irregular and regular.amplitude_m == 2.0 and regular.direction == (1.0, 0.0)
    assert list(regular.periods_s) == [8.0, 12.0] and regular.spectrum is None
    table = catena.MotionRequest(direction="out_of_plane",
                                 spectrum={"omega": [0.2, 0.6, 1.0], "density": [0.5, 1.0, 0.2]})
    assert table.irregular and table.direction == "out_of_plane" and table.amplitude_m is None
    assert list(table.spectrum["density"]) == [0.5, 1.0, 0.2] and table.jonswap is None
    sea = catena.MotionRequest(jonswap={"hs": 6.0, "tp": 12.0}, rao=dict(RAO, per_wave_height=True),
                               frequencies=64, duration_s=3600.0, tolerance=1e-6, max_iterations=50)
    assert sea.jonswap == {"hs": 6.0, "tp": 12.0, "gamma": 3.3}
    assert list(sea.rao["omega"]) == RAO["omega"] and sea.rao["per_wave_height"] is True
    assert (sea.frequencies, sea.duration_s, sea.tolerance, sea.max_iterations) == (64, 3600.0, 1e-6, 50)
    request = catena.Request(inplane_modes=2, motion=sea)
    assert request.motion is not None and request.motion.irregular
    assert "MotionRequest" in repr(request)
    request.motion = None
    assert request.motion is None


@pytest.mark.parametrize("kwargs, field", [
    (dict(amplitude_m=2.0, periods_s=[0.0]), r"request\.motion\.periods"),
    (dict(amplitude_m=2.0, periods_s=[-8.0]), r"request\.motion\.periods"),
    (dict(amplitude_m=-1.0, periods_s=[8.0]), r"request\.motion\.amplitude"),
    (dict(spectrum={"omega": [0.2, 0.6], "density": [0.5, -1.0]}), r"request\.motion\.spectrum\.density"),
    (dict(spectrum={"omega": [0.6, 0.2], "density": [0.5, 1.0]}), r"request\.motion\.spectrum\.omega"),
    (dict(spectrum={"omega": [0.2, 0.6]}), r"request\.motion\.spectrum: missing density"),
    (dict(spectrum={"omega": [0.2, 0.6], "densty": [1, 1]}), r"request\.motion\.spectrum\.densty: unknown"),
    (dict(jonswap={"hs": 0.0, "tp": 12.0}, rao=RAO), r"request\.motion\.jonswap\.hs"),
    (dict(jonswap={"hs": 6.0, "tp": -1.0}, rao=RAO), r"request\.motion\.jonswap\.tp"),
    (dict(jonswap={"hs": 6.0, "tp": 12.0}), r"request\.motion\.jonswap"),
    (dict(jonswap={"hs": 6.0, "tp": 12.0}, rao=dict(RAO, omega=[0.2, 1.2, 0.6])), r"request\.motion\.rao\.omega"),
    (dict(jonswap={"hs": 6.0, "tp": 12.0}, rao=dict(RAO, amplitude=[1.0, math.nan, 0.1])),
     r"request\.motion\.rao\.amplitude"),
    (dict(jonswap={"hs": 6.0, "tp": 12.0}, rao=dict(RAO, omega="fast")), r"request\.motion\.rao\.omega"),
    (dict(direction="sideways", amplitude_m=1.0, periods_s=[8.0]), r"request\.motion\.direction"),
    (dict(direction=(0.0, 0.0), amplitude_m=1.0, periods_s=[8.0]), r"request\.motion\.direction"),
    (dict(), r"request\.motion"),
])
def test_bad_motion_requests_raise_value_error_naming_the_field(kwargs, field):
    with pytest.raises(ValueError, match=field):
        catena.MotionRequest(**kwargs)


# --- solvers that decline the dynamic tension ---

def dragged_problem():
    return catena.Problem(catena.Cable(**CABLE, diameter_m=0.1, drag_normal=1.2), b_m=B)


@pytest.mark.parametrize("solver", ["asymptotic", "airy", "fe", "shooting", "frobenius"])
def test_a_solver_without_the_dynamic_tension_returns_none_and_says_so(solver):
    request = catena.Request(inplane_modes=2, motion=catena.MotionRequest(**REGULAR))
    result = catena.run_solver(solver, dragged_problem(), request)
    if result.dynamic_tension:
        # A solver that computes it returns one result per period, never one it did not converge
        # to without saying so.
        assert len(result.dynamic_tension) == 2
        for t, period in zip(result.dynamic_tension, REGULAR["periods_s"]):
            assert t.period_s == period and t.std_n is None and len(t.s_m) == request.points
            assert t.converged == (t.diagnostic == "")
    else:
        report = result.summary.message + " " + " ".join(result.summary.warnings)
        # Declined as a whole (e.g. asymptotic on a model it does not carry) or in its dynamic
        # tension part (the driver's "dynamic tension not computed").
        assert "dynamic tension" in report or result.summary.status == "not-applicable", report


def test_no_motion_asked_means_no_dynamic_tension():
    result = catena.run_solver("fe", dragged_problem(), catena.Request(inplane_modes=2))
    assert result.dynamic_tension == []
    assert result.inplane is not None and len(result.inplane) == 2  # drag never changes the modes


# --- conversion of a DynamicTension (values chosen here) ---

S = [0.0, 25.0, 50.0, 75.0, 100.0]
MEAN = [500.0, 510.0, 520.0, 530.0, 540.0]
TENSION = [10.0, 12.0, 15.0, 19.0, 24.0]
MOTION = [0.0, 0.5, 1.0, 1.5, 2.0]
C_N = [3.0, 3.5, 4.0, 4.5, 5.0]
C_T = [0.1, 0.2, 0.3, 0.4, 0.5]


def test_regular_dynamic_tension_converts_to_numpy():
    phase = [0.0, -5.0, -10.0, -15.0, -20.0]
    result = _catena._synthetic_dynamic_tension_output(False, S, MEAN, TENSION, phase, MOTION, C_N, C_T,
                                                       period_s=10.0, iterations=9, residual=3e-9)
    (t,) = result.dynamic_tension
    assert isinstance(t, catena.DynamicTension) and not t.irregular
    assert t.period_s == 10.0 and t.omega_rad_s == pytest.approx(2 * math.pi / 10.0, rel=1e-15)
    for name, expected in [("s_m", S), ("mean_n", MEAN), ("amplitude_n", TENSION), ("phase_deg", phase),
                           ("motion_m", MOTION), ("normal_damping_n_s_per_m2", C_N),
                           ("tangential_damping_n_s_per_m2", C_T)]:
        array = getattr(t, name)
        assert isinstance(array, numpy.ndarray) and array.dtype == numpy.float64, name
        assert list(array) == expected, name
        assert not array.flags.writeable, name
    assert t.std_n is None and t.spectrum_omega_rad_s is None and t.fairlead_spectrum_n2_s_per_rad is None
    assert (t.fairlead.s_m, t.fairlead.mean_n, t.fairlead.amplitude_n, t.fairlead.phase_deg) == (100.0, 540.0, 24.0, -20.0)
    assert (t.anchor.s_m, t.anchor.amplitude_n) == (0.0, 10.0)
    assert t.fairlead.std_n is None and t.fairlead.most_probable_max_n is None
    assert t.fairlead.zero_upcrossing_period_s is None
    assert (t.iterations, t.residual, t.converged, t.diagnostic) == (9, 3e-9, True, "")
    assert t.relative_error_estimate == 3e-9
    assert "period 10 s" in repr(t) and "converged" in repr(t)


def test_irregular_dynamic_tension_converts_to_numpy():
    omega = [0.3, 0.6, 0.9]
    result = _catena._synthetic_dynamic_tension_output(
        True, S, MEAN, TENSION, [], MOTION, C_N, C_T, spectrum_omega_rad_s=omega,
        fairlead_spectrum_n2_s_per_rad=[1.0, 4.0, 2.0], anchor_spectrum_n2_s_per_rad=[0.1, 0.4, 0.2],
        zero_upcrossing_period_s=9.5, most_probable_max_n=640.0)
    (t,) = result.dynamic_tension
    assert t.irregular and t.period_s is None and t.omega_rad_s is None
    assert list(t.std_n) == TENSION and t.amplitude_n is None and t.phase_deg is None
    assert list(t.spectrum_omega_rad_s) == omega
    assert list(t.fairlead_spectrum_n2_s_per_rad) == [1.0, 4.0, 2.0]
    assert list(t.anchor_spectrum_n2_s_per_rad) == [0.1, 0.4, 0.2]
    assert (t.fairlead.std_n, t.fairlead.zero_upcrossing_period_s, t.fairlead.most_probable_max_n) == (24.0, 9.5, 640.0)
    assert t.fairlead.amplitude_n is None and t.fairlead.phase_deg is None
    assert t.anchor.std_n == 10.0


def test_a_fixed_point_not_reached_is_reported_as_such():
    result = _catena._synthetic_dynamic_tension_output(False, S, MEAN, TENSION, [0.0] * 5, MOTION, C_N, C_T,
                                                       period_s=8.0, iterations=200, residual=0.02,
                                                       converged=False)
    (t,) = result.dynamic_tension
    assert not t.converged and t.residual == 0.02 and t.iterations == 200
    assert t.relative_error_estimate is None and "no fixed point" in t.diagnostic
    assert "not converged" in repr(t)
