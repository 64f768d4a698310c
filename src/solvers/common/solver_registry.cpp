// SPDX-License-Identifier: MIT
#include "catena/solvers/solver_registry.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "catena/core/error.hpp"
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
// Its own code path for every compared quantity: the default of an entry that declares none.
Computations own_computations(const std::string& solver) {
  return {{"frequency-in-plane", solver + "-in-plane"},
          {"frequency-out-of-plane", solver + "-out-of-plane"},
          {"shape-in-plane", solver + "-in-plane"},
          {"shape-out-of-plane", solver + "-out-of-plane"},
          {"tension", solver + "-in-plane"},
          {"forced", solver + "-forced"}};
}

Computations declared_computations(const std::string& solver) {
  Computations paths = own_computations(solver);
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

namespace {

// The five, then whatever register_solver() added.
std::vector<SolverEntry>& registry() {
  static std::vector<SolverEntry> entries = {
      with_computations(internal::make_fe_entry()),
      with_computations(internal::make_shooting_entry()),
      with_computations(internal::make_frobenius_entry()),
      with_computations(internal::make_asymptotic_entry()),
      with_computations(internal::make_airy_entry()),
  };
  return entries;
}

}  // namespace

const std::vector<SolverEntry>& solver_registry() { return registry(); }

const SolverEntry* find_solver(const std::string& name) {
  for (const auto& entry : solver_registry()) {
    if (entry.name == name) return &entry;
  }
  return nullptr;
}

void register_solver(SolverEntry entry) {
  if (entry.name.empty()) throw InvalidInput("register_solver: the entry has no name");
  if (find_solver(entry.name))
    throw InvalidInput(
        fmt::format("register_solver: a solver named '{}' is already registered", entry.name));
  if (!entry.validate_knobs || !entry.make_numerics)
    throw InvalidInput(fmt::format(
        "register_solver: '{}' lacks validate_knobs or make_numerics (see make_solver_entry in "
        "src/solvers/common/knob_table.hpp)",
        entry.name));
  if (entry.computations.empty()) entry.computations = own_computations(entry.name);
  registry().push_back(std::move(entry));
}

std::vector<std::string> solver_names(SolverKind kind) {
  std::vector<std::string> names;
  for (const auto& entry : solver_registry()) {
    if (entry.kind == kind) names.push_back(entry.name);
  }
  return names;
}

bool is_exact_solver(const std::string& name) {
  const SolverEntry* entry = find_solver(name);
  return entry && entry->kind == SolverKind::Exact;
}

std::vector<std::string> exact_solvers_by_accuracy() {
  std::vector<std::pair<double, std::string>> ranked;
  for (const auto& entry : solver_registry()) {
    if (entry.kind != SolverKind::Exact) continue;
    // An exact solver that states no accuracy goes last.
    const double target = entry.accuracy_target ? entry.accuracy_target({}) : INFINITY;
    ranked.emplace_back(target, entry.name);
  }
  std::stable_sort(ranked.begin(), ranked.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::string> names;
  for (const auto& [target, name] : ranked) names.push_back(name);
  return names;
}

std::vector<std::string> reference_solvers() {
  std::vector<std::string> names;
  for (const auto& name : exact_solvers_by_accuracy()) {
    if (find_solver(name)->certifies_references) names.push_back(name);
  }
  return names;
}

SolverOutput run_solver(const SolverEntry& entry,
                        const SolveContext& context,
                        const SolverKnobs& knobs) {
  entry.validate_knobs(knobs);
  const std::unique_ptr<internal::SolverNumerics> numerics = entry.make_numerics(context, knobs);
  return internal::drive_solver(entry.name, context, *numerics);
}

}  // namespace catena
