#include "catena/solvers/solver_registry.hpp"

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

SolverOutput run_solver(const SolverEntry& entry, const SolveContext& context, const SolverKnobs& knobs) {
  entry.validate_knobs(knobs);
  const std::unique_ptr<internal::SolverNumerics> numerics = entry.make_numerics(context, knobs);
  return internal::drive_solver(entry.name, context, *numerics);
}

}  // namespace catena
