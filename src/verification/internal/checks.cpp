#include "verification/internal/checks.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace catena::internal {
namespace {

// Statics closure |r(L) - (b - a)| relative to the cable size. Newton stops at 1e-14 (or the
// rounding floor near 1e-11); 1e-9 leaves room for ill-conditioned taut cables and still catches
// a wrong equilibrium.
constexpr double kStaticsClosureRel = 1e-9;

CheckResult statics_closure(const SceneResult& result) {
  CheckResult check;
  check.scene = result.scene.name;
  check.check = "statics-closure";
  check.compare = "statics vs supports";
  const double L = result.scene.problem.cable.length_m;
  const double chord = result.scene.problem.supports.chord_m().norm();
  check.measured = result.statics->closure_error_m / std::max(L, chord);
  check.tolerance = kStaticsClosureRel;
  check.verdict = check.measured <= check.tolerance ? Verdict::Pass : Verdict::Fail;
  check.detail = fmt::format("closure error {:.3e} m on a cable of {} m ({})",
                             result.statics->closure_error_m, L, result.statics->brief_report());
  return check;
}

// A solver that applies must produce a usable result; one that declines says why (SKIP).
CheckResult solver_status(const SceneResult& result, const SolverOutput& output) {
  CheckResult check;
  check.scene = result.scene.name;
  check.check = "solver-status";
  check.compare = output.solver;
  check.detail = output.summary.brief_report();
  switch (output.summary.termination) {
    case Termination::Converged: check.verdict = Verdict::Pass; break;
    case Termination::NotApplicable: check.verdict = Verdict::Skipped; break;
    case Termination::NoConvergence: check.verdict = Verdict::Warn; break;
    case Termination::NumericalFailure: check.verdict = Verdict::Fail; break;
  }
  return check;
}

}  // namespace

std::vector<CheckResult> run_checks(const SceneResult& result) {
  std::vector<CheckResult> checks;
  if (!result.statics) return checks;
  checks.push_back(statics_closure(result));
  for (const auto& output : result.outputs) checks.push_back(solver_status(result, output));
  return checks;
}

}  // namespace catena::internal
