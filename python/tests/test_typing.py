# SPDX-License-Identifier: MIT
"""The package is typed (PEP 561): py.typed, the extension's stubs python/catena/_catena.pyi and the
annotations of the pure-Python modules. Checked two ways:

- always: every public name of the stubs exists in the module at run time and the other way round,
  class by class and member by member (the stubs are written by hand from python/src/*.cpp);
- with mypy (Debian: python3-mypy, which scripts/setup.sh installs): stubtest compares the stubs
  with the module (kinds of members, properties, signatures where the runtime shows them), and
  `mypy --strict` checks the package and a script using it; skipped without mypy.
"""

import ast
import importlib.util
import inspect
import os
import pathlib
import subprocess
import sys
import textwrap

import pytest

import catena
from catena import _catena

PACKAGE = pathlib.Path(catena.__file__).resolve().parent
STUB = PACKAGE / "_catena.pyi"
# What every pybind11 class has, declared or not.
IMPLICIT_DUNDERS = {"__init__", "__repr__"}


def stub_tree():
    return ast.parse(STUB.read_text())


def stub_names(body):
    """Names a stub body declares: classes, functions, annotated variables."""
    names = set()
    for node in body:
        if isinstance(node, (ast.ClassDef, ast.FunctionDef)):
            names.add(node.name)
        elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name):
            names.add(node.target.id)
    return names


def runtime_names(obj):
    own = set(vars(obj)) if inspect.isclass(obj) else set(dir(obj))
    return {n for n in own if not n.startswith("__") or (inspect.isclass(obj) and n in ("__len__", "__getitem__", "__contains__"))}


def test_py_typed_and_stubs_sit_next_to_the_package():
    assert (PACKAGE / "py.typed").is_file()
    assert STUB.is_file()


# The stubs' own type aliases.
ALIASES = {"_Array", "_ComplexArray", "_Field", "_ArrayLike", "_Point", "_KnobValue"}


def test_module_names_match_the_stubs():
    declared = stub_names(stub_tree().body) - ALIASES - {"__version__"}
    runtime = runtime_names(_catena)
    assert sorted(declared - runtime) == [], "in the stubs, not in the module"
    assert sorted(runtime - declared) == [], "in the module, not in the stubs"


@pytest.mark.parametrize("node", [n for n in stub_tree().body if isinstance(n, ast.ClassDef)],
                         ids=lambda node: node.name)
def test_class_members_match_the_stubs(node):
    runtime_class = getattr(_catena, node.name)
    if issubclass(runtime_class, BaseException):
        return
    declared = stub_names(node.body) - IMPLICIT_DUNDERS
    runtime = {n for n in runtime_names(runtime_class) if n not in ("_pybind11_conduit_v1_",)}
    assert sorted(declared - runtime) == [], f"{node.name}: in the stubs, not at run time"
    assert sorted(runtime - declared) == [], f"{node.name}: at run time, not in the stubs"


def test_public_names_of_the_package_exist_and_are_annotated():
    for name in catena.__all__:
        value = getattr(catena, name)
        if inspect.isfunction(value):
            hints = inspect.get_annotations(value)
            assert "return" in hints, f"catena.{name} has no return annotation"
            missing = [p for p in inspect.signature(value).parameters if p not in hints]
            assert missing == [], f"catena.{name}: parameters without annotations: {missing}"


mypy = pytest.mark.skipif(importlib.util.find_spec("mypy") is None,
                          reason="mypy is not installed (Debian: python3-mypy)")


def mypy_environment():
    """The package is found on MYPYPATH in a build tree (PYTHONPATH=<build>/python); installed, mypy
    finds it in the interpreter's site-packages itself (and refuses them on MYPYPATH)."""
    if PACKAGE.parent.name in ("site-packages", "dist-packages"):
        return dict(os.environ)
    return dict(os.environ, MYPYPATH=str(PACKAGE.parent))


def run_mypy(arguments, tmp_path):
    environment = mypy_environment()
    command = [sys.executable, "-m", *arguments]
    done = subprocess.run(command, capture_output=True, text=True, env=environment, cwd=tmp_path)
    assert done.returncode == 0, f"{' '.join(command)}\n{done.stdout}{done.stderr}"


@mypy
def test_stubtest_finds_the_stubs_equal_to_the_module(tmp_path):
    allowlist = pathlib.Path(__file__).with_name("stubtest_allowlist.txt")
    run_mypy(["mypy.stubtest", "catena._catena", "--allowlist", str(allowlist)], tmp_path)


# A user's script: mypy --strict must accept it with the package's types, and find the mistakes.
USAGE = textwrap.dedent('''
    import math
    import catena

    problem = catena.Problem(catena.Cable(length_m=1000.0, weight_n_per_m=1000.0, mass_kg_per_m=120.0),
                             b_m=(900.0, 300.0))
    out: catena.SolverResult = catena.solve_shooting(problem, catena.Request(inplane_modes=3),
                                                     method="bdf", rtol=1e-9)
    modes = out.inplane
    if modes is not None:
        estimate: float | None = modes.modes[0].relative_error_estimate
        worst: float = float(modes.relative_error_estimate.max())
        ok = estimate is not None and not math.isnan(worst)
    result = catena.solve("scene.toml", solvers=["fe"])
    infos: list[catena.SolverInfo] = catena.solvers()
''')
MISTAKES = textwrap.dedent('''
    import catena

    problem = catena.Problem.gale_sag(h_over_b=0.25, sag_param=0.8)
    catena.solve_shooting(problem, method="euler")
    catena.solve_fe(problem, elements="many")
    total: float = catena.solve_fe(problem).summary.wall_time_s
''')


@mypy
def test_mypy_strict_accepts_the_package_and_a_script_using_it(tmp_path):
    (tmp_path / "usage.py").write_text(USAGE)
    cache = ["--cache-dir", str(tmp_path / "mypy-cache")]
    run_mypy(["mypy", "--strict", "-p", "catena", *cache], tmp_path)
    run_mypy(["mypy", "--strict", "usage.py", *cache], tmp_path)


@mypy
def test_mypy_finds_wrong_knob_values_and_unchecked_missing_values(tmp_path):
    (tmp_path / "mistakes.py").write_text(MISTAKES)
    environment = mypy_environment()
    done = subprocess.run([sys.executable, "-m", "mypy", "--strict", "mistakes.py", "--cache-dir",
                           str(tmp_path / "mypy-cache")], capture_output=True, text=True, env=environment,
                          cwd=tmp_path)
    errors = [line for line in done.stdout.splitlines() if ": error:" in line]
    assert [line.split(":")[1] for line in errors] == ["5", "6", "7"], done.stdout
