// SPDX-License-Identifier: MIT
#include "catena/solvers/solver_summary.hpp"

#include <fmt/format.h>

namespace catena {

std::string to_string(Termination termination) {
  switch (termination) {
    case Termination::Converged:
      return "converged";
    case Termination::NoConvergence:
      return "no-convergence";
    case Termination::NumericalFailure:
      return "numerical-failure";
    case Termination::NotApplicable:
      return "not-applicable";
  }
  return "?";
}

bool SolverSummary::is_usable() const {
  return termination == Termination::Converged || termination == Termination::NoConvergence;
}

std::string SolverSummary::brief_report() const {
  std::string line = fmt::format("{}: {}: {}", solver, to_string(termination), message);
  if (!resolution.empty()) line += fmt::format(" ({})", resolution);
  if (wall_time_s >= 0.0) line += fmt::format(" [{:.3g} ms]", wall_time_s * 1e3);
  return line;
}

std::string SolverSummary::full_report() const {
  std::string text = brief_report() + "\n";
  if (iterations >= 0) text += fmt::format("  iterations: {}\n", iterations);
  if (operations >= 0) text += fmt::format("  operations: {}\n", operations);
  if (max_error_estimate >= 0.0)
    text += fmt::format("  max relative error estimate: {:.3e}\n", max_error_estimate);
  if (max_residual >= 0.0) text += fmt::format("  max residual: {:.3e}\n", max_residual);
  for (const auto& note : notes) text += "  note: " + note + "\n";
  for (const auto& warning : warnings) text += "  warning: " + warning + "\n";
  return text;
}

}  // namespace catena
