// SPDX-License-Identifier: MIT
// Scenes from Python: read from a file or from scene text (a Python dict is written as TOML text
// by python/catena/_scene_dict.py, so that both go through the one strict reader,
// src/io/scene_reader.cpp), run by catena::run_scene as `catena solve` runs them, and the Result.
#include <fmt/format.h>
#include <pybind11/chrono.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <chrono>

#include "bindings.hpp"
#include "catena/core/error.hpp"
#include "catena/io/findings_reader.hpp"
#include "catena/io/json_writer.hpp"
#include "catena/io/scene_reader.hpp"
#include "catena/io/tolerance_reader.hpp"
#include "catena/verification/scene_runner.hpp"

namespace catena::python {
namespace {

// The compiled-in tables of `catena solve`, read once (thread-safe static initialisation).
const ToleranceTable& tolerances() {
  static const ToleranceTable table = builtin_tolerance_table();
  return table;
}
const FindingsTable& findings() {
  static const FindingsTable table = builtin_findings_table();
  return table;
}

SceneRunOptions run_options(const std::vector<std::string>& only_solvers,
                            std::optional<double> time_limit_s,
                            bool checks) {
  for (const auto& name : only_solvers) {
    if (!find_solver(name))
      throw InvalidInput(fmt::format("solvers: \"{}\" is not a solver", name));
  }
  if (time_limit_s) RunLimits::check_time_limit(*time_limit_s, "time_limit_s");
  SceneRunOptions options;
  options.only_solvers = only_solvers;
  options.time_limit_s = time_limit_s;
  options.checks = checks;
  if (checks) {
    options.tolerances = tolerances();
    options.findings = findings();
  }
  return options;
}

std::vector<Scene> read_file_released(const std::filesystem::path& path) {
  const py::gil_scoped_release release;
  return read_scene_file(path);
}

std::vector<Scene> parse_text_released(const std::string& text, const std::string& origin) {
  const py::gil_scoped_release release;
  return parse_scene_text(text, origin);
}

// Bad input discovered at run time (e.g. a chord longer than an inextensible cable) raises, as it
// does before the run; a statics that fails numerically stays a status (Result.error).
SceneResult run_scene_released(Scene scene,
                               const std::vector<std::string>& only_solvers,
                               std::optional<double> time_limit_s,
                               bool checks) {
  const SceneRunOptions options = run_options(only_solvers, time_limit_s, checks);
  SceneResult result;
  {
    const py::gil_scoped_release release;
    result = run_scene(scene, options);
  }
  if (result.error_kind == SceneError::BadInput) throw InvalidInput(result.error);
  return result;
}

// Benchmark hook (python/bench/solve_overhead.py): the C++ work of catena.solve(path) -- read the
// file, run the scene with the same options -- timed in C++ `repetitions` times, in seconds.
std::vector<double> time_native_solve(const std::filesystem::path& path,
                                      int repetitions,
                                      const std::vector<std::string>& only_solvers) {
  const SceneRunOptions options = run_options(only_solvers, std::nullopt, true);
  std::vector<double> seconds;
  const py::gil_scoped_release release;
  for (int i = 0; i < repetitions; ++i) {
    const auto start = std::chrono::steady_clock::now();
    const std::vector<Scene> scenes = read_scene_file(path);
    const SceneResult result = run_scene(scenes.front(), options);
    seconds.push_back(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  return seconds;
}

void bind_scene_class(py::module_& module) {
  py::class_<Scene>(module, "Scene",
                    "One scene as read from TOML or a dict (docs/reference/scene-format.md).")
      .def_readonly("name", &Scene::name)
      .def_readonly("description", &Scene::description)
      .def_readonly("file", &Scene::file, "the file it was read from, or '<dict>'")
      .def_readonly("problem", &Scene::problem)
      .def_readonly("request", &Scene::request,
                    "as written (forcing frequencies in the scene's unit)")
      .def_readonly("solvers", &Scene::solvers,
                    "{solver: {knob: value}} from [solvers]; empty: all solvers")
      .def_readonly("tags", &Scene::tags)
      .def_property_readonly(
          "sweep_point", [](const Scene& s) { return s.sweep_point; },
          "(parameter, value) for a member of a sweep, else None")
      .def("solver_names", &Scene::solver_names, "the solvers it runs")
      .def("__repr__", [](const Scene& s) { return fmt::format("Scene('{}')", s.name); });
}

std::vector<std::string> solver_names(const SceneResult& result) {
  std::vector<std::string> names;
  for (const SolverOutput& output : result.outputs) names.push_back(output.solver);
  return names;
}

py::object solver_output(const SceneResult& result, const std::string& name) {
  for (const SolverOutput& output : result.outputs) {
    if (output.solver == name) return py::cast(output);
  }
  std::string ran;
  for (const SolverOutput& output : result.outputs)
    ran += (ran.empty() ? "" : ", ") + output.solver;
  throw py::key_error(
      fmt::format("solver \"{}\" did not run in scene {} (ran: {})", name, result.scene.name, ran));
}

void bind_result(py::module_& module) {
  using R = SceneResult;
  py::class_<R>(module, "Result",
                "The results of one scene: statics, groups, each solver's SolverResult "
                "(result[\"fe\"]) and the "
                "checks. Layout as docs/reference/json-layout.md.")
      .def_readonly("scene", &R::scene)
      .def_property_readonly("name", [](const R& r) { return r.scene.name; })
      .def_readonly("statics", &R::statics, "Statics, None when the statics failed (see error)")
      .def_readonly("groups", &R::groups, "Groups, None when the statics failed")
      .def_readonly("request", &R::request, "the request in SI units")
      .def_readonly("outputs", &R::outputs, "every SolverResult, in registry order")
      .def_readonly("checks", &R::checks, "the cross-checks (list of Check)")
      .def_property_readonly(
          "error",
          [](const R& r) { return r.error.empty() ? std::nullopt : std::optional(r.error); },
          "why the scene could not be solved (numerical failure of the statics), else None")
      .def_readonly("wall_time_s", &R::wall_time_s)
      .def_property_readonly("failed_checks", &R::failed_checks)
      .def_property_readonly("solvers", &solver_names,
                             "names of the solvers that ran, in registry order")
      .def("keys", &solver_names,
           "names of the solvers that ran (result[name] is each one's SolverResult)")
      .def("__getitem__", &solver_output, py::arg("solver"))
      .def("__contains__",
           [](const R& r, const std::string& name) {
             for (const auto& output : r.outputs)
               if (output.solver == name) return true;
             return false;
           })
      .def(
          "to_json", [](const R& r, int indent) { return results_to_json({r}, indent); },
          py::arg("indent") = 2,
          "The document `catena solve --json` writes for this scene "
          "(docs/reference/json-layout.md).")
      .def("__repr__", [](const R& r) {
        return fmt::format("Result('{}', {} solvers)", r.scene.name, r.outputs.size());
      });
}

}  // namespace

void bind_scene(py::module_& module) {
  bind_scene_class(module);
  bind_result(module);
  module.def("_read_scene_file", &read_file_released, py::arg("path"));
  module.def("_parse_scene_text", &parse_text_released, py::arg("text"), py::arg("origin"));
  module.def("_run_scene", &run_scene_released, py::arg("scene"), py::arg("solvers"),
             py::arg("time_limit_s"), py::arg("checks"));
  module.def("_time_native_solve", &time_native_solve, py::arg("path"), py::arg("repetitions"),
             py::arg("solvers") = std::vector<std::string>{});
}

}  // namespace catena::python
