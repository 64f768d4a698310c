#include "catena/solvers/solver_registry.hpp"

#include "solvers/internal/solver_driver.hpp"
#include "solvers/internal/solver_entries.hpp"

namespace catena {
namespace {

using Computations = std::map<std::string, std::string>;

// One id per code path, per quantity the harness compares (docs/verdicts.md, "Independence").
// Written side by side so that a shared path is visible at a glance: asymptotic and airy both
// take their out-of-plane modes from internal::wkb_outofplane_modes (taut_cable_theory.hpp).
Computations own_paths(const std::string& solver) {
  return {{"frequency-in-plane", solver + "-in-plane"}, {"frequency-out-of-plane", solver + "-out-of-plane"},
          {"shape-in-plane", solver + "-in-plane"},     {"shape-out-of-plane", solver + "-out-of-plane"},
          {"tension", solver + "-in-plane"},            {"forced", solver + "-forced"}};
}

Computations declared_computations(const std::string& solver) {
  Computations paths = own_paths(solver);
  if (solver == "asymptotic" || solver == "airy") {
    // WKB string frequencies and shapes. airy's still come from the shared WKB code; its own
    // Bessel-function solution replaces them (then its id becomes "airy-bessel-out-of-plane").
    paths["frequency-out-of-plane"] = "wkb-out-of-plane";
    paths["shape-out-of-plane"] = "wkb-out-of-plane";
    paths.erase("forced");  // neither computes a forced response
  }
  return paths;
}

SolverEntry with_computations(SolverEntry entry) {
  entry.computations = declared_computations(entry.name);
  return entry;
}

}  // namespace

const std::vector<std::string>& compared_quantities() {
  static const std::vector<std::string> quantities = {"frequency-in-plane", "frequency-out-of-plane",
                                                      "shape-in-plane",     "shape-out-of-plane",
                                                      "tension",            "forced"};
  return quantities;
}

const std::vector<SolverEntry>& solver_registry() {
  static const std::vector<SolverEntry> entries = {
      with_computations(internal::make_fe_entry()),         with_computations(internal::make_shooting_entry()),
      with_computations(internal::make_frobenius_entry()),  with_computations(internal::make_asymptotic_entry()),
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

SolverOutput run_solver(const SolverEntry& entry, const SolveContext& context, const SolverKnobs& knobs) {
  entry.validate_knobs(knobs);
  const std::unique_ptr<internal::SolverNumerics> numerics = entry.make_numerics(context, knobs);
  return internal::drive_solver(entry.name, context, *numerics);
}

}  // namespace catena
