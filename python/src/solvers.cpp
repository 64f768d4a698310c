// SPDX-License-Identifier: MIT
// The solver registry from Python: each solver's description and knobs (KnobSpec), and any solver
// run on its own with its knobs through catena::run_solver, the same driver the CLI uses.
#include <fmt/format.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <climits>
#include <optional>

#include "bindings.hpp"
#include "catena/core/error.hpp"
#include "catena/solvers/solver_registry.hpp"
#include "catena/statics/statics_match.hpp"

namespace catena::python {
namespace {

std::string type_name(py::handle value) { return py::str(value.get_type().attr("__name__")); }

// A Python knob value as a scene would hold it: bool, integer, real or string; anything else is
// InvalidInput naming `[solvers.<name>].<knob>`.
KnobValue to_knob_value(py::handle value, const std::string& where) {
  // A handle (no destructor): released never, not after the interpreter has finalized.
  static const py::handle numpy_bool =
      py::object(py::module_::import("numpy").attr("bool_")).release();
  if (PyBool_Check(value.ptr()) || py::isinstance(value, numpy_bool)) return py::cast<bool>(value);
  if (py::isinstance<py::str>(value)) return py::cast<std::string>(value);
  if (PyFloat_Check(value.ptr())) return py::cast<double>(value);
  if (PyIndex_Check(value.ptr())) {
    int overflow = 0;
    const long integer = PyLong_AsLongAndOverflow(
        py::reinterpret_steal<py::object>(PyNumber_Index(value.ptr())).ptr(), &overflow);
    if (overflow != 0)
      throw InvalidInput(fmt::format("{} = {}: out of the range of a 64-bit integer", where,
                                     std::string(py::str(value))));
    return integer;
  }
  if (PyNumber_Check(value.ptr())) return py::cast<double>(value);  // numpy floating scalars
  throw InvalidInput(fmt::format("{}: a knob must be a number, a boolean or a string, got {}",
                                 where, type_name(value)));
}

SolverKnobs to_knobs(const std::string& solver, const py::object& knobs) {
  SolverKnobs result;
  if (knobs.is_none()) return result;
  if (!py::isinstance<py::dict>(knobs)) {
    throw InvalidInput(
        fmt::format("[solvers.{}]: knobs must be a dict, got {}", solver, type_name(knobs)));
  }
  for (const auto& [key, value] : knobs.cast<py::dict>()) {
    if (!py::isinstance<py::str>(key)) {
      throw InvalidInput(
          fmt::format("[solvers.{}]: knob names must be strings, got {}", solver, type_name(key)));
    }
    const std::string name = py::cast<std::string>(key);
    result[name] = to_knob_value(value, fmt::format("[solvers.{}].{}", solver, name));
  }
  return result;
}

const SolverEntry& solver_named(const std::string& name) {
  if (const SolverEntry* entry = find_solver(name)) return *entry;
  std::string known;
  for (const auto& e : solver_registry()) known += (known.empty() ? "" : ", ") + e.name;
  throw InvalidInput(fmt::format("solver \"{}\": unknown solver (known: {})", name, known));
}

// Given statics must be the problem's equilibrium (every field it was solved for, compared by the
// one check the solver driver makes too: catena/statics/statics_match.hpp) and usable for dynamics.
void check_given_statics(const Problem& problem, const StaticSolution& statics) {
  check_statics_match(problem, statics);
  if (!statics.converged) throw InvalidInput("statics: did not converge (" + statics.message + ")");
}

// Everything below runs without the GIL on C++ copies of the arguments.
SolverOutput run_released(const SolverEntry& entry,
                          const Problem& problem,
                          const SolveRequest& request,
                          const SolverKnobs& knobs,
                          std::optional<StaticSolution> statics,
                          std::optional<double> time_limit_s) {
  entry.validate_knobs(knobs);
  request.validate();
  std::optional<RunLimits> limits;
  if (time_limit_s) limits = RunLimits::time_limit(*time_limit_s);
  if (!statics) {
    statics = solve_statics(problem);
    if (!statics->converged) {
      SolverOutput failed;
      failed.solver = entry.name;
      failed.summary.solver = entry.name;
      failed.summary.message = "the statics did not converge: " + statics->message;
      return failed;
    }
  }
  const DimensionlessGroups groups = compute_dimensionless_groups(problem, *statics);
  const SolveContext context{problem, *statics, groups, request, limits ? &*limits : nullptr};
  return run_solver(entry, context, knobs);
}

SolverOutput run_named_solver(const std::string& name,
                              Problem problem,
                              std::optional<SolveRequest> request,
                              const py::object& knobs,
                              std::optional<StaticSolution> statics,
                              std::optional<double> time_limit_s) {
  const SolverEntry& entry = solver_named(name);
  const SolverKnobs cpp_knobs = to_knobs(name, knobs);
  problem.validate();
  if (statics) check_given_statics(problem, *statics);
  const SolveRequest cpp_request = request.value_or(SolveRequest{});
  const py::gil_scoped_release release;
  return run_released(entry, problem, cpp_request, cpp_knobs, std::move(statics), time_limit_s);
}

py::list registry_description() {
  py::list solvers;
  for (const SolverEntry& entry : solver_registry()) {
    py::list knobs;
    for (const KnobSpec& knob : entry.knobs) {
      knobs.append(
          py::make_tuple(knob.name, knob.description, knob.type, knob.default_value, knob.valid));
    }
    solvers.append(py::make_tuple(entry.name, entry.description, knobs));
  }
  return solvers;
}

}  // namespace

void bind_solvers(py::module_& module) {
  module.def("_registry", &registry_description,
             "[(name, description, [(knob, description, type, default as text, valid)])] in "
             "registry order");
  module.def(
      "run_solver", &run_named_solver, py::arg("name"), py::arg("problem"),
      py::arg("request") = py::none(), py::arg("knobs") = py::none(), py::kw_only(),
      py::arg("statics") = py::none(), py::arg("time_limit_s") = py::none(),
      "Runs one solver (by name: catena.solvers()) on `problem` with `knobs` (a dict, as in a "
      "scene's "
      "[solvers.<name>]), through the same driver as the CLI. `request`: a Request (default: 6 "
      "in-plane "
      "modes). `statics`: catena.solve_statics(problem), solved here when None. `time_limit_s`: a "
      "cooperative wall-clock budget [s]. Bad input raises catena.InvalidInput naming the field; "
      "numerical trouble is a status in the result's summary. The GIL is released while it runs.");
}

}  // namespace catena::python
