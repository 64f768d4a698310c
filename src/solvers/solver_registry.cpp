#include "catena/solvers/solver_registry.hpp"

#include <chrono>

#include "catena/core/error.hpp"
#include "solvers/internal/solver_driver.hpp"
#include "solvers/internal/solver_entries.hpp"

namespace catena {

const std::vector<SolverEntry>& solver_registry() {
  static const std::vector<SolverEntry> entries = {
      internal::make_fe_entry(),         internal::make_shooting_entry(),
      internal::make_frobenius_entry(),  internal::make_asymptotic_entry(),
      internal::make_airy_entry(),
  };
  return entries;
}

const SolverEntry* find_solver(const std::string& name) {
  for (const auto& entry : solver_registry()) {
    if (entry.name == name) return &entry;
  }
  return nullptr;
}

namespace {

// Transitional: the old whole-run path, for solvers not yet on the driver.
SolverOutput run_legacy(const SolverEntry& entry, const SolveContext& context, const SolverKnobs& knobs) {
  SolverOutput output;
  output.solver = entry.name;
  output.summary.solver = entry.name;
  if (entry.not_applicable_reason) {
    if (auto reason = entry.not_applicable_reason(context)) {
      output.summary.termination = Termination::NotApplicable;
      output.summary.message = *reason;
      output.summary.wall_time_s = 0.0;
      return output;
    }
  }
  const auto start = std::chrono::steady_clock::now();
  try {
    output = entry.run(context, knobs);
  } catch (const InvalidInput&) {
    throw;
  } catch (const std::exception& error) {
    output = SolverOutput{};
    output.summary.termination = Termination::NumericalFailure;
    output.summary.message = std::string("Numerical failure: ") + error.what();
  }
  output.solver = entry.name;
  output.summary.solver = entry.name;
  output.summary.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return output;
}

}  // namespace

SolverOutput run_solver(const SolverEntry& entry, const SolveContext& context, const SolverKnobs& knobs) {
  entry.validate_knobs(knobs);
  if (!entry.make_numerics) return run_legacy(entry, context, knobs);
  const std::unique_ptr<internal::SolverNumerics> numerics = entry.make_numerics(context, knobs);
  return internal::drive_solver(entry.name, context, *numerics);
}

}  // namespace catena
