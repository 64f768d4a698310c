// SPDX-License-Identifier: MIT
// The one solver skeleton: see solver_driver.hpp for the steps and the combination rule.
#include "solvers/common/solver_driver.hpp"

#include <fmt/format.h>

#include <chrono>
#include <exception>

#include "catena/core/error.hpp"
#include "catena/statics/statics_match.hpp"
#include "solvers/common/dynamic_tension.hpp"
#include "solvers/common/result_validation.hpp"
#include "solvers/common/work_meter.hpp"

namespace catena::internal {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The driver's check between parts (catena/solvers/run_limits.hpp): once a part has run and the
// run's deadline has passed, the parts not started yet are skipped and reported with nothing done.
std::optional<SolverSummary> skipped_for_time(const SolveContext& context,
                                              const SolverOutput& output,
                                              const std::string& units,
                                              long total) {
  const bool after_a_part = output.inplane || output.outofplane;
  if (!after_a_part || !context.limits || !context.limits->expired()) return std::nullopt;
  SolverSummary summary;
  summary.solver = output.solver;
  summary.termination = Termination::NoConvergence;
  summary.message = "No convergence: " + time_limit_message(*context.limits, 0, total, units);
  summary.wall_time_s = 0.0;
  return summary;
}

// The forced plane follows the forcing direction: out of plane only when the end moves normal to
// the plane of the supports.
void run_parts(const SolveContext& context,
               SolverNumerics& numerics,
               SolverOutput& output,
               std::optional<ForcedOutcome>& forced,
               std::optional<SolverSummary>& dynamic) {
  const SolveRequest& request = context.request;
  const std::pair<Plane, int> planes[] = {{Plane::InPlane, request.inplane_modes},
                                          {Plane::OutOfPlane, request.outofplane_modes}};
  for (const auto& [plane, count] : planes) {
    if (count <= 0) continue;
    if (auto skipped =
            skipped_for_time(context, output, std::string(to_string(plane)) + " modes", count)) {
      ModalResult& result =
          (plane == Plane::InPlane ? output.inplane : output.outofplane).emplace();
      result.plane = plane;
      result.summary = *skipped;
      continue;
    }
    const auto start = Clock::now();
    ModalResult result = numerics.modes(plane, count);
    result.plane = plane;
    validate_modal_result(result, count);
    apply_accuracy_target(result);
    result.summary.solver = output.solver;
    result.summary.wall_time_s = seconds_since(start);
    (plane == Plane::InPlane ? output.inplane : output.outofplane) = std::move(result);
  }
  if (request.forced) {
    const long frequencies = static_cast<long>(request.forced->omegas_rad_s.size());
    if (auto skipped = skipped_for_time(context, output, "forced frequencies", frequencies)) {
      forced = ForcedOutcome{{}, *skipped};
      return;
    }
    const auto start = Clock::now();
    if (context.problem.is_damped() && !numerics.handles_damped_forced()) {
      forced = ForcedOutcome{};
      forced->summary.termination = Termination::NotApplicable;
      forced->summary.message =
          fmt::format("damped forced response not computed ({} frequencies asked)", frequencies);
      forced->summary.warnings.push_back(
          "the line is damped and this method's forced response is undamped only: not computed");
      forced->summary.solver = output.solver;
      return;
    }
    // The model is linear in the amplitude: solved for its mantissa, scaled exactly by a power of
    // two here, so that no amplitude overflows a solve (result_validation.hpp).
    ForcedRequest unit = *request.forced;
    unit.amplitude_m = amplitude_mantissa(request.forced->amplitude_m);
    forced = numerics.forced(unit);
    scale_forced_outcome(*forced, request.forced->amplitude_m);
    validate_forced_outcome(*forced);
    forced->summary.solver = output.solver;
    forced->summary.wall_time_s = seconds_since(start);
    output.forced = std::move(forced->responses);
  }
  if (request.motion) {
    const auto start = Clock::now();
    dynamic = solve_dynamic_tension(context, numerics, output.dynamic_tension);
    dynamic->solver = output.solver;
    dynamic->wall_time_s = seconds_since(start);
  }
}

}  // namespace

ForcedOutcome SolverNumerics::forced_with_drag(const ForcedRequest& request,
                                               const DragProfile& drag) {
  (void)drag;
  ForcedOutcome outcome;
  outcome.summary.termination = Termination::NotApplicable;
  outcome.summary.message = fmt::format("dynamic tension not computed ({} frequencies asked)",
                                        request.omegas_rad_s.size());
  return outcome;
}

ForcedOutcome SolverNumerics::forced(const ForcedRequest& request) {
  ForcedOutcome outcome;
  outcome.summary.termination = Termination::NotApplicable;
  outcome.summary.message = fmt::format("forced response not computed ({} frequencies asked)",
                                        request.omegas_rad_s.size());
  outcome.summary.warnings.push_back("forced response is not part of this method: not computed");
  return outcome;
}

SolverOutput drive_solver(const std::string& solver,
                          const SolveContext& context,
                          SolverNumerics& numerics) {
  context.request.validate();
  context.problem.validate();
  // Statics of another problem would give "converged" numbers for the wrong cable (issue 32).
  check_statics_match(context.problem, context.statics);
  const auto start = Clock::now();
  SolverOutput output;
  output.solver = solver;
  SolverSummary& summary = output.summary;
  summary.solver = solver;
  std::optional<ForcedOutcome> forced;
  std::optional<SolverSummary> dynamic;
  try {
    std::optional<std::string> reason = numerics.not_applicable();
    if (!reason && context.problem.is_damped() && !numerics.handles_damping())
      reason = "the line is damped and this method computes undamped modes only";
    if (!reason && context.problem.has_tangential_added_mass() &&
        !numerics.handles_tangential_added_mass())
      reason =
          "the line has a tangential added mass (added_mass_tangential), which this method's "
          "model does not carry";
    if (reason) {
      summary.termination = Termination::NotApplicable;
      summary.message = *reason;
      summary.wall_time_s = seconds_since(start);
      return output;
    }
    if (auto outcome = numerics.prepare()) {
      numerics.describe(summary);
      summary.termination = outcome->termination;
      summary.message = outcome->message;
      summary.wall_time_s = seconds_since(start);
      return output;
    }
    run_parts(context, numerics, output, forced, dynamic);
    numerics.describe(summary);
  } catch (const InvalidInput&) {
    throw;
  } catch (const std::exception& error) {
    // Numerical trouble belongs in the summary; what still escapes is reported, not thrown.
    output = SolverOutput{};
    output.solver = solver;
    output.summary.solver = solver;
    output.summary.termination = Termination::NumericalFailure;
    output.summary.message = std::string("Numerical failure: ") + error.what();
    output.summary.wall_time_s = seconds_since(start);
    return output;
  }
  std::vector<std::pair<std::string, const SolverSummary*>> parts;
  if (output.inplane) parts.emplace_back("in-plane", &output.inplane->summary);
  if (output.outofplane) parts.emplace_back("out-of-plane", &output.outofplane->summary);
  if (forced) parts.emplace_back("forced", &forced->summary);
  if (dynamic) parts.emplace_back("dynamic tension", &*dynamic);
  combine_summaries(parts, summary);
  summary.wall_time_s = seconds_since(start);
  return output;
}

void apply_accuracy_target(ModalResult& result) {
  SolverSummary& summary = result.summary;
  const double target = summary.accuracy_target;
  if (!(target > 0.0)) return;
  for (Mode& mode : result.modes) {
    const double estimate = mode.relative_error_estimate;
    mode.meets_target = estimate >= 0.0 && estimate <= target;
    if (mode.meets_target) continue;
    summary.missed_modes.push_back(
        estimate < 0.0
            ? fmt::format("mode {}: no error estimate (target {:.2g})", mode.index, target)
            : fmt::format("mode {}: estimate {:.2g} > target {:.2g}", mode.index, estimate,
                          target));
  }
  if (summary.missed_modes.empty()) return;
  const std::string missed =
      fmt::format("{} of {} {} modes miss the accuracy target {:.2g}", summary.missed_modes.size(),
                  result.modes.size(), to_string(result.plane), target);
  if (summary.termination == Termination::Converged) {
    summary.termination = Termination::NoConvergence;
    summary.message = "No convergence: " + missed + " (" + summary.message + ")";
  } else {
    summary.message += "; " + missed;
  }
}

void combine_summaries(const std::vector<std::pair<std::string, const SolverSummary*>>& parts,
                       SolverSummary& overall) {
  bool all_converged = true, any_usable = false;
  long iterations = -1, operations = -1;
  double max_error = -1.0, max_residual = -1.0;
  std::string message;
  for (const auto& [name, part] : parts) {
    const bool counts = part->termination != Termination::NotApplicable;
    all_converged = all_converged && (!counts || part->termination == Termination::Converged);
    any_usable = any_usable || part->is_usable();
    if (part->iterations >= 0) iterations = std::max(iterations, 0L) + part->iterations;
    if (part->operations >= 0) operations = std::max(operations, 0L) + part->operations;
    max_error = std::max(max_error, part->max_error_estimate);
    max_residual = std::max(max_residual, part->max_residual);
    message += (message.empty() ? "" : "; ") + part->message;
    for (const auto& warning : part->warnings) overall.warnings.push_back(name + ": " + warning);
    for (const auto& missed : part->missed_modes)
      overall.missed_modes.push_back(name + " " + missed);
    overall.accuracy_target = std::max(overall.accuracy_target, part->accuracy_target);
    if (name == "forced" || name == "dynamic tension") {
      // A plane's notes stay in its own summary; the forced part has no other place for them.
      for (const auto& note : part->notes) overall.notes.push_back(name + ": " + note);
    }
  }
  if (parts.empty()) {
    overall.termination = Termination::Converged;
    overall.message = "Converged: nothing was requested";
    return;
  }
  overall.termination = all_converged ? Termination::Converged
                        : any_usable  ? Termination::NoConvergence
                                      : Termination::NumericalFailure;
  if (!any_usable && all_converged) overall.termination = Termination::NotApplicable;
  overall.message = message;
  overall.iterations = iterations;
  overall.operations = operations;
  overall.max_error_estimate = max_error;
  overall.max_residual = max_residual;
}

}  // namespace catena::internal
