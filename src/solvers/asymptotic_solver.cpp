// Placeholder registry entry for the `asymptotic` solver: it declines every problem until the solver
// lands (see the project's issues).
#include "solvers/internal/knob_reader.hpp"
#include "solvers/internal/solver_entries.hpp"

namespace catena::internal {

SolverEntry make_asymptotic_entry() {
  SolverEntry entry;
  entry.name = "asymptotic";
  entry.description = "not implemented yet";
  entry.not_applicable_reason = [](const SolveContext&) -> std::optional<std::string> {
    return std::string("the asymptotic solver is not implemented yet");
  };
  entry.validate_knobs = [](const SolverKnobs& knobs) { KnobReader("asymptotic", knobs).reject_unknown(); };
  entry.run = [](const SolveContext&, const SolverKnobs&) { return SolverOutput{}; };
  return entry;
}

}  // namespace catena::internal
