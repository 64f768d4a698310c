# SPDX-License-Identifier: MIT
"""Statics given to a solver must be the problem's (issue 32): every field the statics was solved
for, changed alone, makes the solve raise catena.InvalidInput (a ValueError) naming that field; the
problem's own statics is accepted. Before, the statics of a problem with its fairlead at (800, 300)
instead of (900, 300) gave "converged" frequencies 30 % off."""

import pytest

import catena

CABLE = dict(length_m=1000.0, weight_n_per_m=1000.0, mass_kg_per_m=120.0, axial_stiffness_n=5e8,
             added_mass_kg_per_m=80.0)
B = (900.0, 300.0)
A = (0.0, -50.0)
REQUEST = catena.Request(inplane_modes=1)


def problem(b_m=B, a_m=A, seabed=None, **changes):
    return catena.Problem(catena.Cable(**{**CABLE, **changes}), b_m=b_m, a_m=a_m, seabed=seabed)


@pytest.mark.parametrize("solver", ["shooting", "fe", "asymptotic"])
def test_statics_of_another_fairlead_is_refused(solver):
    with pytest.raises(catena.InvalidInput, match=r"supports\.b_m = \(900, 300\) m here"):
        catena.run_solver(solver, problem(), REQUEST, statics=catena.solve_statics(problem(b_m=(800.0, 300.0))))


@pytest.mark.parametrize("other, field", [
    (dict(length_m=1001.0), "cable.length_m"),
    (dict(weight_n_per_m=999.0), "cable.weight_n_per_m"),
    (dict(axial_stiffness_n=4e8), "cable.axial_stiffness_n"),
    (dict(mass_kg_per_m=121.0), "cable.mass_kg_per_m"),
    (dict(added_mass_kg_per_m=81.0), "cable.added_mass_kg_per_m"),
    (dict(added_mass_tangential_kg_per_m=1.0), "cable.added_mass_tangential_kg_per_m"),
    (dict(damping_normal_n_s_per_m2=1.0), "cable.damping.normal_n_s_per_m2"),
    (dict(diameter_m=0.1, drag_normal=1.2), "cable.drag.diameter_m"),
    (dict(b_m=(900.0, 300.000001)), "supports.b_m"),
    (dict(a_m=(0.0, -49.0), b_m=(900.0, 301.0)), r"supports.a_m = \(0, -(50|49)\) m here"),
    (dict(seabed=catena.Seabed(-60.0)), r"seabed (present|absent) here, (absent|present) in the statics"),
])
def test_each_field_changed_alone_is_named(other, field):
    here = problem()
    there = problem(**other)
    for given, solved in ((here, there), (there, here)):
        with pytest.raises(catena.InvalidInput, match=field):
            catena.run_solver("shooting", given, REQUEST, statics=catena.solve_statics(solved))


def test_seabed_fields_are_compared():
    here = problem(seabed=catena.Seabed(-60.0, friction=0.5))
    there = problem(seabed=catena.Seabed(-60.0, friction=0.6))
    with pytest.raises(catena.InvalidInput, match="seabed.friction = 0.5 here, 0.6 in the statics"):
        catena.run_solver("shooting", here, REQUEST, statics=catena.solve_statics(there))


def test_line_segments_and_points_are_compared():
    chain = dict(length_m=400.0, weight_n_per_m=1000.0, mass_kg_per_m=120.0, axial_stiffness_n=5e8)
    wire = dict(length_m=600.0, weight_n_per_m=60.0, mass_kg_per_m=8.0, axial_stiffness_n=2e8)

    def line_problem(point_weight=1e4, wire_length=600.0):
        line = catena.Line([catena.LineSegment(**chain), catena.LineSegment(**{**wire, "length_m": wire_length})],
                           points=[catena.PointAttachment(s_m=500.0, mass_kg=1e3, weight_n=point_weight)])
        return catena.Problem.from_line(line, b_m=B, a_m=A)

    with pytest.raises(catena.InvalidInput, match=r"line.points\[0\].weight_n"):
        catena.run_solver("shooting", line_problem(), REQUEST, statics=catena.solve_statics(line_problem(2e4)))
    with pytest.raises(catena.InvalidInput, match=r"line.segments\[1\].length_m"):
        catena.run_solver("shooting", line_problem(), REQUEST,
                          statics=catena.solve_statics(line_problem(wire_length=601.0)))


def test_prescribed_end_forces_are_compared():
    here = catena.Problem.taut_inclined(eps=0.1, phi_deg=30.0, lambda2=10.0)
    there = catena.Problem.taut_inclined(eps=0.1, phi_deg=30.0, lambda2=11.0)
    with pytest.raises(catena.InvalidInput, match="statics: solved for"):
        catena.run_solver("shooting", here, REQUEST, statics=catena.solve_statics(there))


def test_the_problems_own_statics_is_accepted():
    for p in (problem(), problem(seabed=catena.Seabed(-60.0, friction=0.5)),
              catena.Problem.taut_inclined(eps=0.1, phi_deg=30.0, lambda2=10.0)):
        out = catena.run_solver("shooting", p, REQUEST, statics=catena.solve_statics(p))
        assert out.summary.status == "converged", out.summary.full_report()
