// Placeholder registry entry for the `fe` solver: it declines every problem until the solver
// lands (see the project's issues).
#include "solvers/internal/knob_reader.hpp"
#include "solvers/internal/solver_entries.hpp"

namespace catena::internal {

SolverEntry make_fe_entry() {
  SolverEntry entry;
  entry.name = "fe";
  entry.description = "not implemented yet";
  entry.not_applicable_reason = [](const SolveContext&) -> std::optional<std::string> {
    return std::string("the fe solver is not implemented yet");
  };
  entry.validate_knobs = [](const SolverKnobs& knobs) { KnobReader("fe", knobs).reject_unknown(); };
  entry.run = [](const SolveContext&, const SolverKnobs&) { return SolverOutput{}; };
  return entry;
}

}  // namespace catena::internal
