# SPDX-License-Identifier: MIT
"""A general line (catena.Line) built in Python gives what the same [line] scene gives, and bad
segments or points are a ValueError naming the field (docs/reference/python.md, "General lines")."""

import math

import pytest

import catena

CHAIN = dict(length_m=250.0, weight_n_per_m=1400.0, axial_stiffness_n=7.5e8, mass_kg_per_m=160.0,
             added_mass_kg_per_m=25.0)
WIRE = dict(length_m=600.0, weight_n_per_m=60.0, axial_stiffness_n=2.0e8, mass_kg_per_m=8.0,
            added_mass_kg_per_m=4.0)
CLUMP = dict(s_m=400.0, mass_kg=20000.0, weight_n=1.5e5)
A, B = (0.0, -300.0), (800.0, 0.0)


def clump_line():
    return catena.Line([catena.LineSegment(**CHAIN), catena.LineSegment(**WIRE)],
                       points=[catena.PointAttachment(**CLUMP)])


def clump_scene():
    """The same line as a dict scene (docs/reference/scene-format.md, [line])."""
    def segment(s):
        return {"length": s["length_m"], "weight": s["weight_n_per_m"], "EA": s["axial_stiffness_n"],
                "mass": s["mass_kg_per_m"], "added_mass": s["added_mass_kg_per_m"]}
    point = {"s": CLUMP["s_m"], "mass": CLUMP["mass_kg"], "weight": CLUMP["weight_n"]}
    return {"name": "clump", "line": {"a": list(A), "b": list(B), "segments": [segment(CHAIN), segment(WIRE)],
                                      "points": [point]},
            "request": {"inplane_modes": 3, "outofplane_modes": 3}}


def test_line_problem_has_the_scene_statics():
    problem = catena.Problem.from_line(clump_line(), b_m=B, a_m=A)
    assert not problem.is_uniform and problem.line.length_m == 850.0
    statics = catena.solve_statics(problem)
    scene = catena.solve(clump_scene(), solvers=["fe"])
    assert statics.is_line and statics.converged
    assert statics.horizontal_force_n == scene.statics.horizontal_force_n
    assert statics.vertical_force_a_n == scene.statics.vertical_force_a_n
    end = statics.position_m([problem.length_m])[0]
    assert math.hypot(end[0] - B[0], end[1] - B[1]) < 1e-9 * problem.length_m
    # V jumps by the clump's weight at s = 400 m: the side of b carries it.
    v = statics.vertical_force_n([399.999999, 400.0])
    assert v[1] - v[0] == pytest.approx(CLUMP["weight_n"] + 1e-6 * WIRE["weight_n_per_m"], rel=1e-6)


def test_run_solver_on_a_line_matches_the_scene():
    problem = catena.Problem.from_line(clump_line(), b_m=B, a_m=A)
    request = catena.Request(inplane_modes=3, outofplane_modes=3)
    mine = catena.run_solver("fe", problem, request)
    assert mine.summary.status == "converged", mine.summary.full_report()
    scene = catena.solve(clump_scene(), solvers=["fe"])["fe"]
    assert mine.inplane.omega_rad_s.tolist() == scene.inplane.omega_rad_s.tolist()
    assert mine.outofplane.omega_rad_s.tolist() == scene.outofplane.omega_rad_s.tolist()


def test_a_uniform_cable_split_in_two_segments_keeps_its_statics():
    cable = dict(length_m=1000.0, weight_n_per_m=1000.0, axial_stiffness_n=5e8, mass_kg_per_m=120.0,
                 added_mass_kg_per_m=80.0)
    half = dict(cable, length_m=500.0)
    uniform = catena.solve_statics(catena.Problem(catena.Cable(**cable), b_m=(900.0, 300.0)))
    split = catena.solve_statics(catena.Problem.from_line(
        catena.Line([catena.LineSegment(**half), catena.LineSegment(**half)]), b_m=(900.0, 300.0)))
    assert split.horizontal_force_n == pytest.approx(uniform.horizontal_force_n, rel=1e-12)
    assert split.vertical_force_a_n == pytest.approx(uniform.vertical_force_a_n, rel=1e-12)


def test_statics_of_another_line_is_refused():
    problem = catena.Problem.from_line(clump_line(), b_m=B, a_m=A)
    other = catena.Problem.from_line(catena.Line([catena.LineSegment(**CHAIN), catena.LineSegment(**WIRE)]),
                                     b_m=B, a_m=A)
    with pytest.raises(catena.InvalidInput, match="another line"):
        catena.run_solver("fe", problem, statics=catena.solve_statics(other))


@pytest.mark.parametrize("build, field", [
    (lambda: catena.LineSegment(**dict(CHAIN, length_m=-1.0)), "length"),
    (lambda: catena.LineSegment(**dict(CHAIN, mass_kg_per_m=math.nan)), "mass"),
    (lambda: catena.Line([catena.LineSegment(**CHAIN)], points=[catena.PointAttachment(s_m=300.0)]), "points[0].s"),
    (lambda: catena.Line([]), "segments"),
])
def test_bad_line_input_is_a_value_error_naming_the_field(build, field):
    with pytest.raises(ValueError, match=field.replace("[", r"\[").replace("]", r"\]").replace(".", r"\.")):
        build()
