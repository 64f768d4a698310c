# SPDX-License-Identifier: MIT
"""Every solver and every knob is reachable from Python, through the registry and the typed
conveniences, and the building blocks give what a scene gives."""

import math
import re

import pytest

import catena

CABLE = dict(length_m=1000.0, weight_n_per_m=1000.0, axial_stiffness_n=5e8, mass_kg_per_m=120.0,
             added_mass_kg_per_m=80.0)


def mooring_problem():
    return catena.Problem(catena.Cable(**CABLE), b_m=(900.0, 300.0))


def problem_for(solver):
    """A problem each solver applies to: frobenius needs an inextensible catenary, asymptotic and
    airy a taut inclined cable."""
    if solver == "frobenius":
        return catena.Problem.gale_sag(h_over_b=0.25, sag_param=0.8)
    if solver in ("asymptotic", "airy"):
        return catena.Problem.taut_inclined(eps=0.18, phi_deg=23.46, lambda2=100.0)
    return mooring_problem()


def test_registry_lists_five_solvers_with_typed_knobs():
    infos = catena.solvers()
    assert [s.name for s in infos] == ["fe", "shooting", "frobenius", "asymptotic", "airy"]
    fe = infos[0]
    assert fe.defaults()["elements"] == 400 and fe.defaults()["richardson"] is True
    shooting = infos[1].defaults()
    assert shooting["rtol"] == 1e-10 and shooting["method"] == "rk"
    for info in infos:
        assert info.description and info.knobs
        for knob in info.knobs:
            assert knob.type in ("integer", "real", "flag", "choice")
            assert isinstance(knob.default, {"integer": int, "real": float, "flag": bool, "choice": str}[knob.type])


@pytest.mark.parametrize("info", catena.solvers(), ids=lambda info: info.name)
def test_every_solver_runs_with_every_knob_at_its_default(info):
    problem = problem_for(info.name)
    request = catena.Request(inplane_modes=3, outofplane_modes=2)
    plain = catena.run_solver(info.name, problem, request)
    assert plain.summary.status == "converged", plain.summary.full_report()
    every_knob = catena.run_solver(info.name, problem, request, info.defaults())
    assert every_knob.inplane.omega_rad_s.tolist() == plain.inplane.omega_rad_s.tolist()
    typed = getattr(catena, f"solve_{info.name}")(problem, request, **info.defaults())
    assert typed.outofplane.omega_rad_s.tolist() == plain.outofplane.omega_rad_s.tolist()


def other_value(knob):
    """A valid value other than the default, from the knob's range as the registry states it."""
    if knob.type == "flag":
        return not knob.default
    if knob.type == "choice":
        return [c.strip('" ') for c in knob.valid.split(" or ") if c.strip('" ') != knob.default][0]
    low, high = (float(x) for x in re.match(r"[\[(]\s*([^,]+),\s*([^\])]+)[\])]", knob.valid).groups())
    target = low if low != knob.default else high  # toward the bottom: knobs bounded by others stay valid
    if math.isinf(target):
        target = 2 * knob.default if knob.default else 1
    value = knob.default + 0.1 * (target - knob.default) if knob.type == "real" else (knob.default + target) // 2
    assert value != knob.default and low <= value <= high
    return int(value) if knob.type == "integer" else value


@pytest.mark.parametrize("solver, knob", [(s, k) for s in catena.solvers() for k in s.knobs],
                         ids=lambda x: getattr(x, "name", ""))
def test_every_knob_is_reachable_and_checked(solver, knob):
    problem = problem_for(solver.name)
    request = catena.Request(inplane_modes=2)
    output = catena.run_solver(solver.name, problem, request, {knob.name: other_value(knob)})
    assert output.summary.usable, output.summary.full_report()
    if knob.type in ("integer", "real"):
        with pytest.raises(catena.InvalidInput, match=rf"\[solvers\.{solver.name}\]\.{knob.name} = -1"):
            catena.run_solver(solver.name, problem, request, {knob.name: -1})
    with pytest.raises(catena.InvalidInput, match=rf"\[solvers\.{solver.name}\]\.{knob.name}"):
        catena.run_solver(solver.name, problem, request, {knob.name: [1, 2]})


def test_knob_changes_the_answer():
    problem, request = mooring_problem(), catena.Request(inplane_modes=2)
    coarse = catena.solve_fe(problem, request, elements=50, richardson=False)
    fine = catena.solve_fe(problem, request, elements=400)
    assert coarse.inplane.omega_rad_s[0] != fine.inplane.omega_rad_s[0]
    assert coarse.summary.resolution != fine.summary.resolution


def test_unknown_solver_and_knob_name_themselves():
    with pytest.raises(catena.InvalidInput, match='solver "magic": unknown solver'):
        catena.run_solver("magic", mooring_problem())
    with pytest.raises(catena.InvalidInput, match=r"\[solvers\.fe\]\.bogus: unknown knob"):
        catena.run_solver("fe", mooring_problem(), None, {"bogus": 1})
    with pytest.raises(TypeError, match="bogus"):  # the typed functions name their knobs
        catena.solve_fe(mooring_problem(), bogus=1)  # type: ignore[call-arg]
    with pytest.raises(catena.InvalidInput, match=r"\[solvers\.fe\]: knobs must be a dict"):
        catena.run_solver("fe", mooring_problem(), None, [("elements", 10)])


def test_building_blocks_give_what_the_scene_gives(mooring_path):
    scene_result = catena.solve(mooring_path, solvers=["fe", "shooting"])
    problem = mooring_problem()
    statics = catena.solve_statics(problem)
    assert statics.converged
    assert statics.horizontal_force_n == scene_result.statics.horizontal_force_n
    request = catena.Request(inplane_modes=6, outofplane_modes=6)
    # The knobs the scene's [solvers] table sets (verification/scenes/physical/mooring-line-900m.toml).
    for name, knobs in (("fe", {"tolerance": 3e-9}), ("shooting", {})):
        alone = catena.run_solver(name, problem, request, knobs, statics=statics)
        assert alone.inplane.omega_rad_s.tolist() == scene_result[name].inplane.omega_rad_s.tolist()
        assert alone.outofplane.omega_rad_s.tolist() == scene_result[name].outofplane.omega_rad_s.tolist()


def test_statics_closed_forms_are_vectorised():
    problem = mooring_problem()
    statics = catena.solve_statics(problem)
    end = statics.position_m([0.0, problem.cable.length_m])
    assert end.shape == (2, 2)
    assert math.isclose(end[1, 0], 900.0, rel_tol=1e-12) and math.isclose(end[1, 1], 300.0, rel_tol=1e-12)
    tension = statics.tension_n([0.0, 1000.0])
    assert tension[0] == statics.tension_a_n and tension[1] == statics.tension_b_n
    groups = catena.dimensionless_groups(problem, statics)
    assert groups.mass_ratio == pytest.approx(0.6)


def test_forced_response_and_time_limit():
    problem = mooring_problem()
    request = catena.Request(inplane_modes=2, points=11,
                             forced=catena.ForcedRequest([0.1, 0.2], direction="normal", amplitude_m=0.5))
    output = catena.solve_shooting(problem, request)
    assert [f.omega_rad_s for f in output.forced] == [0.1, 0.2]
    assert output.forced[0].tension_n.shape == (11,)
    limited = catena.solve_shooting(problem, catena.Request(inplane_modes=200), time_limit_s=1e-6)
    assert limited.summary.status == "no-convergence" and "time limit" in limited.summary.message


def test_non_finite_knobs_are_rejected_by_name():
    problem = mooring_problem()
    for value in (float("nan"), float("inf")):
        with pytest.raises(catena.InvalidInput, match=r"\[solvers\.shooting\]\.rtol"):
            catena.solve_shooting(problem, rtol=value)
        with pytest.raises(catena.InvalidInput, match=r"\[solvers\.fe\]\.elements"):
            catena.solve_fe(problem, elements=value)
    with pytest.raises(catena.InvalidInput, match=r"\[solvers\.fe\]\.elements = \d+: out of the range"):
        catena.solve_fe(problem, elements=2**80)
