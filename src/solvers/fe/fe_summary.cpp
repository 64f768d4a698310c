// SPDX-License-Identifier: MIT
// The fe solver's summary text: see fe_summary.hpp.
#include "solvers/fe/fe_summary.hpp"

#include <fmt/format.h>

namespace catena::internal {
namespace {

std::string inertia_note(const FePlaneFacts& facts) {
  const FeEigenSolution& finest = *facts.finest;
  return fmt::format(
      "mode count proved by Sylvester inertia: LDLT(K - sigma M) at sigma = {:.9e} rad^2/s^2 "
      "(just above the top eigenvalue, N = {}) has {} negative pivots for {} modes{}",
      finest.inertia_shift, facts.finest_chain->elements, finest.inertia_count,
      finest.eigenvalues.size(),
      facts.inertia_proved_everywhere ? "; same on every mesh" : "; NOT on every mesh");
}

std::string quality_note(const FePlaneEigenReport& eigen) {
  return fmt::format(
      "max mass-orthogonality error {:.2e} (M-normalised); max normwise backward error {:.2e} "
      "(the relative residual ||K phi - w^2 M phi|| / ||K phi|| has a rounding floor of about "
      "eps ||K|| / ||K phi||, large for a stiff chain)",
      eigen.max_orthogonality_error, eigen.max_backward_error);
}

std::string observed_order_note(const FePlan& plan, const std::vector<double>& orders) {
  std::string list;
  for (double p : orders) list += fmt::format("{}{:.3f}", list.empty() ? "" : ", ", p);
  const std::size_t last = plan.meshes.size() - 1;
  return fmt::format("observed order of the unextrapolated frequencies from N = {}, {}, {}: {}",
                     plan.meshes[last - 2], plan.meshes[last - 1], plan.meshes[last], list);
}

}  // namespace

std::string low_order_note(const FePlan& plan,
                           const std::vector<Mode>& modes,
                           const std::vector<std::pair<double, double>>& low_orders) {
  std::string list;
  for (const auto& [omega, order] : low_orders) {
    int index = 0;
    for (const Mode& mode : modes)
      if (mode.omega_rad_s == omega) index = mode.index;
    list += fmt::format("{}mode {} ({})", list.empty() ? "" : ", ", index,
                        order > 0.0 ? fmt::format("p = {:.2f}", order) : "not monotone");
  }
  const auto half = static_cast<std::size_t>(plan.estimate_coarse);
  return fmt::format(
      "observed order of the unextrapolated frequencies on N = {}, {}, {} below the 2 Richardson "
      "assumes: {}; their error estimates are taken at the observed order",
      plan.meshes[half], plan.meshes[static_cast<std::size_t>(plan.main_coarse)],
      plan.meshes[static_cast<std::size_t>(plan.main_fine)], list);
}

namespace {

std::string statics_note(const FeChain& chain, bool prescribed_forces) {
  return fmt::format(
      "discrete statics (N = {}): H = {:.12g} N, V_A = {:.12g} N, {} Newton iterations, closure "
      "{:.2e} m ({})",
      chain.elements, chain.horizontal_force_n, chain.vertical_force_a_n, chain.newton_iterations,
      chain.closure_error_m,
      prescribed_forces ? "prescribed end forces kept" : "Newton on the chain's closure");
}

std::string time_note(const FeTimings& timings) {
  return fmt::format(
      "time so far: statics {}, assembly {}, factorization {}, eigen iterations {}, shapes {}",
      format_seconds(timings.statics_s), format_seconds(timings.assembly_s),
      format_seconds(timings.factorization_s), format_seconds(timings.eigen_iterations_s),
      format_seconds(timings.postprocessing_s));
}

}  // namespace

std::string fe_statics_note(const FeChain& chain, bool prescribed_forces) {
  return statics_note(chain, prescribed_forces);
}

std::string fe_time_note(const FeTimings& timings) { return time_note(timings); }

std::string format_seconds(double seconds) {
  return seconds < 1e-3 ? fmt::format("{:.1f} us", seconds * 1e6)
                        : fmt::format("{:.3f} ms", seconds * 1e3);
}

std::string fe_resolution(const FePlan& plan) {
  std::string meshes;
  for (int N : plan.meshes) meshes += fmt::format("{}{}", meshes.empty() ? "" : ", ", N);
  std::string resolution =
      fmt::format("N = {} elements{}", meshes,
                  plan.richardson ? ", Richardson (order 2 -> 4)" : ", no Richardson");
  if (plan.inextensible) {
    resolution += fmt::format("; penalty kappa = {:.1e} and {:.1e}, extrapolated to 0",
                              plan.kappas[0], plan.kappas[1]);
    if (plan.kappas.size() > 2)
      resolution += fmt::format(" ({:.1e} for the estimate)", plan.kappas[2]);
  }
  return resolution;
}

void describe_fe_run(const FePlan& plan, SolverSummary& summary) {
  summary.resolution = fe_resolution(plan);
  if (!plan.inextensible) return;
  summary.warnings.push_back(fmt::format(
      "inextensible cable: penalty EA = H/kappa = {:.4e} N and {:.4e} N (kappa = {:.1e}, {:.1e}), "
      "results extrapolated linearly to kappa = 0",
      plan.axial_stiffness_n[0], plan.axial_stiffness_n[1], plan.kappas[0], plan.kappas[1]));
}

std::string fe_rounding_floor_decline(const FePlan& plan, double t0_n, double max_floor) {
  return fmt::format(
      "No convergence: the in-plane chain is too stiff for double precision: EA/T0 = {:.2e} with "
      "N = {} elements gives a rounding floor of {:.1e} relative on mode 1 (> {:.0e}); use fewer "
      "elements, or the shooting solver (exact in EA, no discretisation)",
      plan.axial_stiffness_n[0] / std::max(t0_n, 1e-300), plan.finest_elements(),
      plan.rounding_floor(t0_n, 1), max_floor);
}

void describe_fe_plane(const FePlaneFacts& facts, ModalResult& result) {
  SolverSummary& summary = result.summary;
  const char* plane = to_string(facts.plane);
  if (!facts.has_coarse && !result.modes.empty()) {
    summary.warnings.push_back(fmt::format(
        "no error estimate: without Richardson the estimate needs N/2 = {} elements, too few for "
        "{} {} modes (relative_error_estimate = -1)",
        facts.estimate_elements, facts.modes_asked, plane));
  }
  summary.notes.push_back(inertia_note(facts));
  summary.notes.push_back(quality_note(*facts.eigen));
  if (!facts.observed_orders.empty())
    summary.notes.push_back(observed_order_note(*facts.plan, facts.observed_orders));
  summary.notes.push_back(statics_note(*facts.finest_chain, facts.prescribed_forces));
  summary.notes.push_back(time_note(*facts.timings));
  if (summary.termination == Termination::Converged) {
    summary.message = fmt::format(
        "Converged: {} of {} {} modes, max relative residual {:.1e} (normwise backward error "
        "{:.1e}), mode count proved by inertia ({}), max relative error estimate {:.1e}",
        facts.modes_available, facts.modes_asked, plane, summary.max_residual,
        facts.eigen->max_backward_error, facts.finest->inertia_count, summary.max_error_estimate);
  } else {
    summary.message = fmt::format(
        "No convergence: {} of {} {} modes ({})", facts.modes_available, facts.modes_asked, plane,
        summary.warnings.empty() ? std::string("see warnings") : summary.warnings.back());
  }
}

std::string fe_eigen_failure_message(Plane plane, const FePlaneEigenReport& eigen) {
  return fmt::format("Numerical failure: {} eigenproblem: {}", to_string(plane),
                     eigen.warnings.empty() ? std::string("?") : eigen.warnings.back());
}

void describe_forced(ForcedOutcome& outcome, const FeTimings& timings) {
  const std::size_t asked = outcome.responses.size();
  std::size_t resonant = 0, declined = 0;
  const ForcedResponse* first_declined = nullptr;
  for (const ForcedResponse& response : outcome.responses) {
    resonant += response.at_resonance ? 1 : 0;
    if (!response.diagnostic.empty() && !response.at_resonance && !declined++)
      first_declined = &response;
  }
  SolverSummary& summary = outcome.summary;
  // A resonance diagnostic is the discrete model's answer at that frequency, not a failure; a
  // declined frequency (beyond the mesh, or an estimate above 1) has no answer.
  summary.termination = declined ? Termination::NoConvergence : Termination::Converged;
  summary.message = fmt::format(
      "{}: {} of {} forced frequencies{}{}", declined ? "No convergence" : "Converged",
      asked - resonant - declined, asked,
      resonant ? fmt::format(" ({} at resonance: no finite response)", resonant) : std::string(),
      declined ? fmt::format("; {} declined, e.g. {}", declined, first_declined->diagnostic)
               : std::string());
  summary.notes.push_back(
      fmt::format("time: forced response {}", format_seconds(timings.forced_s)));
}

}  // namespace catena::internal
