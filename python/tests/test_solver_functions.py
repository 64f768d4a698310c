# SPDX-License-Identifier: MIT
"""The functions solve_<name> (python/catena/_solver_functions.py) are written out by hand: this
checks them against the registry (catena.solvers(), the knob tables of src/solvers/*/): one per
solver and no other; each knob a keyword-only argument of the knob's type, None by default; the
numpydoc docstring giving every knob with its type, its default and its valid range; and a call
equal, bit for bit, to catena.run_solver with the same knobs."""

import ast
import inspect
import re
import typing

import pytest

import catena
from catena import _solver_functions

KIND_TYPES = {"integer": int, "real": float, "flag": bool}
COMMON = ["problem", "request", "statics", "time_limit_s"]


def choices(knob):
    """The values of a choice knob, from its valid text: '"rk" or "adams" or "bdf"'."""
    return [ast.literal_eval(c.strip()) for c in knob.valid.split(" or ")]


def docstring_entries(function):
    """{name: (type text, description)} of the Parameters section of a numpydoc docstring."""
    doc = inspect.getdoc(function)
    section = doc.split("Parameters\n----------\n", 1)[1].split("\n\n", 1)[0]
    entries, name = {}, None
    for line in section.splitlines():
        if not line.startswith(" "):
            name, _, kind = line.partition(" : ")
            entries[name] = [kind, ""]
        else:
            entries[name][1] += " " + line.strip()
    return entries


def test_one_function_per_solver_and_no_other():
    names = [info.name for info in catena.solvers()]
    public = sorted(n for n in dir(catena) if n.startswith("solve_") and n != "solve_statics" and n != "solve_sweep")
    assert public == sorted(f"solve_{n}" for n in names)
    assert _solver_functions.__all__ == [f"solve_{n}" for n in names]
    for name in names:
        function = getattr(catena, f"solve_{name}")
        assert inspect.isfunction(function) and function.__module__ == "catena._solver_functions"
        assert function.__name__ == f"solve_{name}" and f"solve_{name}" in catena.__all__


@pytest.mark.parametrize("info", catena.solvers(), ids=lambda info: info.name)
def test_signature_lists_the_knobs_with_their_types(info):
    function = getattr(catena, f"solve_{info.name}")
    parameters = inspect.signature(function).parameters
    assert list(parameters) == COMMON + [k.name for k in info.knobs]
    hints = typing.get_type_hints(function)
    assert hints["return"] is catena.SolverResult
    for knob in info.knobs:
        parameter = parameters[knob.name]
        assert parameter.kind is inspect.Parameter.KEYWORD_ONLY and parameter.default is None
        (kind,) = [a for a in typing.get_args(hints[knob.name]) if a is not type(None)]
        if knob.type == "choice":
            assert typing.get_origin(kind) is typing.Literal
            assert list(typing.get_args(kind)) == choices(knob), knob.name
        else:
            assert kind is KIND_TYPES[knob.type], knob.name


@pytest.mark.parametrize("info", catena.solvers(), ids=lambda info: info.name)
def test_docstring_gives_each_knob_its_type_default_and_range(info):
    function = getattr(catena, f"solve_{info.name}")
    doc = inspect.getdoc(function)
    for section in ("Parameters\n----------", "Returns\n-------", "Raises\n------"):
        assert section in doc
    entries = docstring_entries(function)
    assert list(entries) == COMMON + [k.name for k in info.knobs]
    assert "[s]" in entries["time_limit_s"][1]
    for knob in info.knobs:
        kind, description = entries[knob.name]
        type_text, _, default_text = kind.partition(", default ")
        default = ast.literal_eval(default_text)
        assert default == knob.default and type(default) in (type(knob.default), int), knob.name
        if knob.type == "choice":
            assert ast.literal_eval(type_text.replace("{", "[").replace("}", "]")) == choices(knob)
        else:
            assert type_text == KIND_TYPES[knob.type].__name__, knob.name
        if knob.type in ("integer", "real"):
            assert f"in {knob.valid}" in description, f"{knob.name}: range {knob.valid} not stated"
            assert re.search(r"\[[^\],]*\]", description.replace(knob.valid, "")), f"{knob.name}: no unit"


def test_a_knob_left_at_none_is_not_set_and_a_given_one_is():
    problem = catena.Problem(catena.Cable(length_m=1000.0, weight_n_per_m=1000.0, mass_kg_per_m=120.0,
                                          axial_stiffness_n=5e8), b_m=(900.0, 300.0))
    request = catena.Request(inplane_modes=2)
    plain = catena.run_solver("fe", problem, request)
    assert catena.solve_fe(problem, request).inplane.omega_rad_s.tolist() == plain.inplane.omega_rad_s.tolist()
    coarse = catena.run_solver("fe", problem, request, {"elements": 60, "richardson": False})
    typed = catena.solve_fe(problem, request, elements=60, richardson=False, kappa=None)
    assert typed.inplane.omega_rad_s.tolist() == coarse.inplane.omega_rad_s.tolist()
    assert typed.summary.resolution == coarse.summary.resolution != plain.summary.resolution
