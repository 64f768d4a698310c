// SPDX-License-Identifier: MIT
#include "catena/solvers/solver_registry.hpp"

#include "solvers/common/solver_driver.hpp"
#include "solvers/common/solver_entries.hpp"

namespace catena {
namespace {

using Computations = std::map<std::string, std::string>;

// One id per code path, per quantity the harness compares (docs/reference/verdicts.md,
// "Independence"). Written side by side so that a shared path would be visible at a glance. Today
// no two solvers share one: asymptotic's out-of-plane modes are its WKB string
// (asymptotic_wkb_string.hpp), airy's its own Bessel-function string of linear tension
// (airy_tension_string.hpp).
Computations declared_computations(const std::string& solver) {
  Computations paths = {{"frequency-in-plane", solver + "-in-plane"},
                        {"frequency-out-of-plane", solver + "-out-of-plane"},
                        {"shape-in-plane", solver + "-in-plane"},
                        {"shape-out-of-plane", solver + "-out-of-plane"},
                        {"tension", solver + "-in-plane"},
                        {"forced", solver + "-forced"}};
  if (solver == "asymptotic") {
    paths["frequency-out-of-plane"] = paths["shape-out-of-plane"] = "asymptotic-wkb-string";
  }
  if (solver == "airy") {
    paths["frequency-out-of-plane"] = paths["shape-out-of-plane"] = "airy-bessel-string";
  }
  if (solver == "asymptotic" || solver == "airy") paths.erase("forced");  // no forced response
  return paths;
}

SolverEntry with_computations(SolverEntry entry) {
  entry.computations = declared_computations(entry.name);
  return entry;
}

}  // namespace

const std::vector<std::string>& compared_quantities() {
  static const std::vector<std::string> quantities = {"frequency-in-plane",
                                                      "frequency-out-of-plane",
                                                      "shape-in-plane",
                                                      "shape-out-of-plane",
                                                      "tension",
                                                      "forced"};
  return quantities;
}

const std::vector<SolverEntry>& solver_registry() {
  static const std::vector<SolverEntry> entries = {
      with_computations(internal::make_fe_entry()),
      with_computations(internal::make_shooting_entry()),
      with_computations(internal::make_frobenius_entry()),
      with_computations(internal::make_asymptotic_entry()),
      with_computations(internal::make_airy_entry()),
  };
  return entries;
}

const SolverEntry* find_solver(const std::string& name) {
  for (const auto& entry : solver_registry()) {
    if (entry.name == name) return &entry;
  }
  return nullptr;
}

SolverOutput run_solver(const SolverEntry& entry,
                        const SolveContext& context,
                        const SolverKnobs& knobs) {
  entry.validate_knobs(knobs);
  const std::unique_ptr<internal::SolverNumerics> numerics = entry.make_numerics(context, knobs);
  return internal::drive_solver(entry.name, context, *numerics);
}

}  // namespace catena
