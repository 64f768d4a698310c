# SPDX-License-Identifier: MIT
"""Bad input raises catena.InvalidInput (a ValueError) naming the field, or TypeError for a Python
value of the wrong type; nothing crashes the interpreter."""

import math
import random

import pytest

import catena

GOOD = dict(length_m=1000.0, weight_n_per_m=1000.0, mass_kg_per_m=120.0, axial_stiffness_n=5e8)


def test_invalid_input_is_a_value_error_and_parse_error_an_invalid_input():
    assert issubclass(catena.InvalidInput, ValueError)
    assert issubclass(catena.ParseError, catena.InvalidInput)


@pytest.mark.parametrize("field, value", [("length_m", -1.0), ("length_m", math.nan), ("weight_n_per_m", 0.0),
                                          ("mass_kg_per_m", math.inf), ("axial_stiffness_n", -5.0),
                                          ("added_mass_kg_per_m", -1.0), ("length_m", 1e300)])
def test_bad_cable_values_name_the_field(field, value):
    with pytest.raises(catena.InvalidInput, match=field):
        catena.Cable(**{**GOOD, field: value})
    cable = catena.Cable(**GOOD)
    setattr(cable, field, value)  # bypassing the constructor is caught before any solve
    with pytest.raises(catena.InvalidInput, match=field):
        catena.solve_statics(_problem_with(cable))


def _problem_with(cable):
    problem = catena.Problem(catena.Cable(**GOOD), b_m=(900.0, 300.0))
    problem.cable = cable
    return problem


def test_wrong_python_types_raise_type_error():
    with pytest.raises(TypeError):
        catena.Cable(**{**GOOD, "length_m": "long"})
    with pytest.raises(TypeError):
        catena.Problem("not a cable", b_m=(1.0, 0.0))
    with pytest.raises(TypeError):
        catena.Request(inplane_modes=2.5)
    with pytest.raises(TypeError):
        catena.solve(42)
    with pytest.raises(TypeError):
        catena.run_solver("fe", None)


def test_unreachable_and_degenerate_problems():
    cable = catena.Cable(**{**GOOD, "axial_stiffness_n": math.inf})
    with pytest.raises(catena.InvalidInput):
        catena.solve_statics(catena.Problem(cable, b_m=(2000.0, 0.0)))  # chord longer than the cable
    with pytest.raises(catena.InvalidInput, match="b_m|coincide|Supports"):
        catena.Problem(cable, b_m=(0.0, 0.0))
    with pytest.raises(catena.InvalidInput, match="eps"):
        catena.Problem.taut_inclined(eps=-1.0, phi_deg=30.0, lambda2=10.0)


def test_scene_with_unreachable_chord_raises_at_run_time(mooring_dict):
    mooring_dict["cable"]["EA"] = "inf"
    mooring_dict["cable"]["b"] = [2000.0, 0.0]
    with pytest.raises(catena.InvalidInput):
        catena.solve(mooring_dict)


def test_request_and_run_options_name_the_field(mooring_path):
    with pytest.raises(catena.InvalidInput, match="inplane_modes"):
        catena.Request(inplane_modes=-1)
    with pytest.raises(catena.InvalidInput, match="points"):
        catena.Request(points=1)
    with pytest.raises(catena.InvalidInput, match="end"):
        catena.ForcedRequest([1.0], end="c")
    with pytest.raises(catena.InvalidInput, match="direction"):
        catena.ForcedRequest([1.0], direction="sideways")
    with pytest.raises(catena.InvalidInput, match="time_limit_s"):
        catena.solve(mooring_path, time_limit_s=-1.0)
    with pytest.raises(catena.InvalidInput, match="solvers"):
        catena.solve(mooring_path, solvers=["magic"])


def test_files_that_cannot_be_read(tmp_path):
    with pytest.raises(FileNotFoundError):
        catena.solve(tmp_path / "missing.toml")
    with pytest.raises(catena.ParseError, match="cannot read"):
        catena.solve(tmp_path)  # a directory
    broken = tmp_path / "broken.toml"
    broken.write_text("[cable\nlength = ")
    with pytest.raises(catena.ParseError, match="broken.toml"):
        catena.solve(broken)


def test_a_message_quoting_bytes_of_another_encoding_is_still_the_real_error(tmp_path):
    latin1 = tmp_path / "latin1.toml"
    latin1.write_bytes(b'[cable]\nlength = "\xff"\n')  # a Latin-1 byte in a string
    with pytest.raises(catena.ParseError) as raised:
        catena.solve(latin1)
    assert "latin1.toml" in str(raised.value)


def test_given_statics_must_belong_to_the_problem():
    problem = catena.Problem(catena.Cable(**GOOD), b_m=(900.0, 300.0))
    other = catena.Problem(catena.Cable(**{**GOOD, "length_m": 1100.0}), b_m=(900.0, 300.0))
    with pytest.raises(catena.InvalidInput, match="statics"):
        catena.run_solver("fe", problem, statics=catena.solve_statics(other))


def test_random_garbage_never_crashes(mooring_dict):
    """Random values of random types in every field of the scene: each raises a Python exception
    (ValueError, TypeError) or solves; the interpreter survives them all."""
    generator = random.Random(16)
    garbage = [None, -1, 0, 1e308, -math.inf, math.nan, "", "inf", [], [1], [1, 2, 3], {}, {"x": 1}, True,
               2**63, -(2**63) - 1, "\u0000", "\ud800", [[[]]], 1e-320]
    fields = [(t, k) for t in ("cable", "request") for k in mooring_dict[t]] + [("request", "points"),
                                                                              ("request", "shapes")]
    for _ in range(150):
        scene = {t: dict(v) for t, v in mooring_dict.items() if isinstance(v, dict)}
        table, key = generator.choice(fields)
        scene[table][key] = generator.choice(garbage)
        scene["solvers"] = {"asymptotic": {}}  # fast: the point is the reader and the statics
        try:
            catena.solve(scene, checks=False)
        except (ValueError, TypeError):
            pass
