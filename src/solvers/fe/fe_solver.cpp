// SPDX-License-Identifier: MIT
// The `fe` solver: its knobs, and its numerics on the solver skeleton. The method is documented in
// fe_solver.hpp and docs/explanation/methods/fe.md; its stages are in internal/fe_*: discrete
// statics (fe_chain_statics), operators (fe_operators), eigenpairs of one level (fe_eigen), the
// plan and its levels (fe_levels), stations (fe_shapes), extrapolation (fe_extrapolation), forced
// response (fe_forced) and summary text (fe_summary).
#include "catena/solvers/fe_solver.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <map>

#include "catena/core/error.hpp"
#include "solvers/common/knob_table.hpp"
#include "solvers/common/line_applicability.hpp"
#include "solvers/common/line_modal_mass.hpp"
#include "solvers/common/mode_tools.hpp"
#include "solvers/common/solver_driver.hpp"
#include "solvers/common/solver_entries.hpp"
#include "solvers/common/work_meter.hpp"
#include "solvers/fe/fe_damped_forced.hpp"
#include "solvers/fe/fe_damped_modes.hpp"
#include "solvers/fe/fe_drag_forced.hpp"
#include "solvers/fe/fe_extrapolation.hpp"
#include "solvers/fe/fe_forced.hpp"
#include "solvers/fe/fe_levels.hpp"
#include "solvers/fe/fe_refinement.hpp"
#include "solvers/fe/fe_seabed_contact.hpp"
#include "solvers/fe/fe_shapes.hpp"
#include "solvers/fe/fe_summary.hpp"

namespace catena {
namespace internal {

const KnobTable<FeSolverOptions>& fe_knobs() {
  using O = FeSolverOptions;
  static const KnobTable<O> table(
      "fe",
      {integer_knob("elements", &O::elements, Range::closed(2, 5e7),
                    "number of bar elements N (the coarse mesh with Richardson); resolves up to "
                    "N/2 modes per plane"),
       flag_knob("richardson", &O::richardson,
                 "solve N and 2N and extrapolate (order 2 -> 4); N/2 too, for the error estimate"),
       real_knob(
           "kappa", &O::kappa, Range::open_closed(0.0, 1e-2),
           "inextensible cables: penalty H/EA (and 2 kappa, extrapolated to 0; 4 kappa for the "
           "error estimate)"),
       flag_knob("observed_order", &O::observed_order,
                 "also solve 4N and report the observed convergence order"),
       real_knob("tolerance", &O::tolerance, Range::closed(0.0, 1.0),
                 "accuracy target of each frequency [-] (default 1e-6, fe's declared accuracy): "
                 "while a mode's error estimate exceeds it, fe solves again on a finer mesh (up "
                 "to max_elements); a mode that still exceeds it is named and the plane not "
                 "converged (0: none)"),
       integer_knob(
           "max_elements", &O::max_elements, Range::closed(2, 5e7),
           "the largest N a tolerance may refine to (at or below elements: no refinement)")});
  return table;
}

}  // namespace internal

// eigen_tolerance and max_restarts are options of the typed API only (no scene knob).
void FeSolverOptions::validate() const {
  internal::fe_knobs().validate(*this);
  if (!(eigen_tolerance > 0.0) || !(eigen_tolerance <= 1e-4))
    throw InvalidInput(fmt::format("FeSolverOptions::eigen_tolerance = {}: must be in (0, 1e-4]",
                                   eigen_tolerance));
  if (max_restarts < 1)
    throw InvalidInput(
        fmt::format("FeSolverOptions::max_restarts = {}: must be >= 1", max_restarts));
}

namespace internal {
namespace {

using Clock = std::chrono::steady_clock;

// Above this rounding floor of mode 1 (relative) the in-plane answer would be noise: declined.
constexpr double kMaxRoundingFloor = 1e-2;

// The numerics of the fe solver for one problem: the plan's levels in prepare(), each plane's
// eigenpairs extrapolated in modes(), the forced response on the finest main mesh.
class FeNumerics final : public SolverNumerics {
 public:
  FeNumerics(const SolveContext& context, const FeSolverOptions& options)
      : context_(context),
        options_(sized_for_request(options, context.request)),
        plan_(make_fe_plan(context.problem,
                           context.statics,
                           options_,
                           context.request.inplane_modes,
                           context.request.outofplane_modes)) {}

  std::optional<std::string> not_applicable() const override {
    if (auto slack = slack_line_declined(context_.statics)) return slack;
    return fe_penalty_not_applicable(plan_);
  }
  void describe(SolverSummary& summary) const override {
    describe_fe_run(plan_, summary);
    if (auto note =
            seabed_model_note(context_.statics,
                              "lumped on the grounded nodes like the mass; every contact "
                              "boundary is a node, the layer sqrt(T/k) on its grounded side a "
                              "piece of its own"))
      summary.notes.push_back(*note);
  }
  // Damped lines: the quadratic eigenproblem (fe_damped_modes.hpp).
  bool handles_damping() const override { return true; }
  bool handles_damped_forced() const override { return true; }
  std::optional<Outcome> prepare() override;
  ModalResult modes(Plane plane, int count) override;
  ForcedOutcome forced(const ForcedRequest& request) override {
    const Plane plane = forced_plane(request);
    if (auto singular = seabed_plane_singular(plane, context_.statics)) {
      ForcedOutcome declined;
      declined.summary.termination = Termination::NotApplicable;
      declined.summary.message = *singular;
      return declined;
    }
    std::string note;
    if (naturals_[plane].empty()) note = compute_naturals_for(plane, request);
    ForcedOutcome outcome =
        context_.problem.is_damped()
            ? fe_damped_forced_response(request, context_, plan_, levels_, naturals_[plane],
                                        timings_)
            : fe_forced_response(request, context_, plan_, levels_, naturals_[plane], timings_);
    if (!note.empty()) outcome.summary.notes.push_back(note);
    return outcome;
  }
  // The tangential inertia m + ma_t is in the chain's lumped mass (fe_operators.hpp).
  bool handles_tangential_added_mass() const override { return true; }
  bool handles_drag() const override { return true; }
  ForcedOutcome forced_with_drag(const ForcedRequest& request, const DragProfile& drag) override;

 private:
  static FeSolverOptions sized_for_request(FeSolverOptions options, const SolveRequest& request);
  void require_modes_fit() const;
  ModalResult modes_on_plan(Plane plane, int count);
  void damped_modes_on_plan(Plane plane, int count, ModalResult& result);
  std::string refine_plan(Plane plane, int elements);
  // What a refinement replaces, kept to go back to when the finer mesh does worse.
  struct FeRun {
    FeSolverOptions options;
    FePlan plan;
    FeLevels levels;
    std::vector<FeNaturalFrequency> naturals;
  };
  void restore(Plane plane, FeRun run) {
    options_ = run.options;
    plan_ = std::move(run.plan);
    levels_ = std::move(run.levels);
    naturals_[plane] = std::move(run.naturals);
  }
  std::string compute_naturals_for(Plane plane, const ForcedRequest& request);
  void extrapolate_modes(Plane plane,
                         int available,
                         ModalResult& result,
                         std::vector<double>& orders);
  Mode extrapolated_mode(Plane plane,
                         int i,
                         const FeModeMatches& matches,
                         const FeExtrapolatedFrequency& frequency,
                         const Vector& stations) const;
  void attach_shape(
      Plane plane, int i, const FeModeMatches& matches, const Vector& stations, Mode& mode) const;

  const SolveContext& context_;
  FeSolverOptions options_;
  FePlan plan_;
  FeLevels levels_;
  FeTimings timings_;
  // The natural frequencies computed per plane, for the forced response's resonance check.
  std::map<Plane, std::vector<FeNaturalFrequency>> naturals_;
  // How the dynamic tension's natural frequencies were found (compute_naturals_for), when fe
  // computed them itself.
  std::string drag_naturals_note_;
};

// The default mesh (FeSolverOptions::elements = 400) resolves 200 modes per plane; a request up
// to the 1000-mode limit (docs/reference/scene-format.md) gets the mesh it needs, 2 x modes
// elements rounded up to a multiple of 4 (at most 2000: a few MB, its shift-invert Lanczos
// minutes at 1000 modes, bounded by the time limit), instead of refusing the scene. Any other
// `elements` is the user's choice and stays as given (too few: InvalidInput below).
FeSolverOptions FeNumerics::sized_for_request(FeSolverOptions options,
                                              const SolveRequest& request) {
  const int modes = std::max(request.inplane_modes, request.outofplane_modes);
  if (options.elements == FeSolverOptions{}.elements &&
      fe_resolvable_modes(options.elements) < modes) {
    options.elements = 4 * ((2 * modes + 3) / 4);
    options.max_elements = std::max(options.max_elements, options.elements);
  }
  return options;
}

// Bad input: every requested mode must be resolved by the coarsest mesh that feeds the result
// (fe_resolvable_modes: at least 4 elements per wavelength).
void FeNumerics::require_modes_fit() const {
  const SolveRequest& request = context_.request;
  const int N = options_.elements;
  const int coarsest = plan_.meshes.front();
  for (const auto& [plane, modes] : {std::pair{Plane::InPlane, request.inplane_modes},
                                     std::pair{Plane::OutOfPlane, request.outofplane_modes}}) {
    if (modes > 0 && fe_resolvable_modes(coarsest) < modes) {
      throw InvalidInput(fmt::format(
          "[solvers.fe].elements = {}: too few for {} {} modes (the coarsest mesh, {} elements, "
          "resolves at most "
          "{} modes per plane: at least 4 elements per wavelength, see "
          "docs/explanation/methods/fe.md). Violated "
          "constraint: modes <= elements / 2, i.e. elements >= {}.",
          N, modes, to_string(plane), coarsest, fe_resolvable_modes(coarsest), 2 * modes));
    }
  }
}

std::optional<Outcome> FeNumerics::prepare() {
  require_modes_fit();
  const SolveRequest& request = context_.request;
  const bool inplane_asked =
      request.inplane_modes > 0 ||
      (request.forced && forced_plane(*request.forced) == Plane::InPlane) ||
      (request.motion && request.motion->direction != ForcingDirection::OutOfPlane);
  const double t0_n = context_.groups.t0_n;
  if (inplane_asked && plan_.rounding_floor(t0_n, 1) > kMaxRoundingFloor)
    return Outcome{Termination::NoConvergence,
                   fe_rounding_floor_decline(plan_, t0_n, kMaxRoundingFloor)};
  std::string failure;
  levels_ = solve_level_statics(context_.problem, context_.statics, plan_, timings_, failure);
  if (!failure.empty())
    return Outcome{Termination::NumericalFailure, "Numerical failure: " + failure};
  return std::nullopt;
}

// The resonance check of the forced response needs the natural frequencies of the forced plane
// with their error estimates (fe_forced.hpp). When that plane's modes were not asked, fe computes
// them itself: every mode up to 5% above the highest forcing frequency and one more (counted by
// the inertia of K - omega^2 M on the finest mesh), at most a quarter of the coarse mesh's
// unknowns (the higher modes are not resolved). Returns the note for the summary.
std::string FeNumerics::compute_naturals_for(Plane plane, const ForcedRequest& request) {
  if (request.omegas_rad_s.empty()) return {};
  const double top =
      1.05 * *std::max_element(request.omegas_rad_s.begin(), request.omegas_rad_s.end());
  const auto fine = static_cast<std::size_t>(plan_.main_fine);
  assemble_missing(levels_, plane, {fine});
  const int below = count_eigenvalues_below(levels_[fine][0].matrices.at(plane), top * top);
  const int cap = fe_unknowns(plane, std::max(2, options_.elements / 2)) / 4;
  if (below < 0 || below + 1 > cap)
    return fmt::format(
        "resonance check of the forced response by the pivots of K - omega^2 M only: {} {} modes "
        "lie below the forcing frequencies, more than the {} the meshes resolve",
        below, to_string(plane), cap);
  // On the plan as it is: the accuracy target refines for the modes a request asks, not for
  // these (a refinement here would move every drag iterate to the finer mesh).
  const ModalResult own = modes_on_plan(plane, below + 1);
  return fmt::format(
      "resonance check of the forced response against the {} lowest {} natural frequencies, "
      "computed for it (relative error estimates up to {:.1e})",
      own.modes.size(), to_string(plane), own.summary.max_error_estimate);
}

// The damped forced response with the drag profile added (fe_drag_forced.hpp). The levels, their
// operators and the natural frequencies of the forced plane are computed on the first iterate and
// reused by the next ones: an iterate costs the damping assembly and the complex banded solves.
ForcedOutcome FeNumerics::forced_with_drag(const ForcedRequest& request, const DragProfile& drag) {
  const Plane plane = forced_plane(request);
  if (auto singular = seabed_plane_singular(plane, context_.statics)) {
    ForcedOutcome declined;
    declined.summary.termination = Termination::NotApplicable;
    declined.summary.message = *singular;
    return declined;
  }
  if (naturals_[plane].empty()) drag_naturals_note_ = compute_naturals_for(plane, request);
  ForcedOutcome outcome =
      fe_drag_forced_response(request, drag, context_, plan_, levels_, naturals_[plane], timings_);
  if (!drag_naturals_note_.empty()) outcome.summary.notes.push_back(drag_naturals_note_);
  return outcome;
}

// Shapes and tension from the finest main mesh (extrapolated in kappa when penalised).
void FeNumerics::attach_shape(
    Plane plane, int i, const FeModeMatches& matches, const Vector& stations, Mode& mode) const {
  const SolveRequest& request = context_.request;
  const auto fine = static_cast<std::size_t>(plan_.main_fine);
  const bool with_tension = request.tension;
  auto level_mode = [&](std::size_t k, int column) {
    const FeLevel& level = levels_[fine][k];
    return mode_on_stations(plane, level.chain, level.eigen.at(plane).eigenvectors.col(column),
                            stations, context_.statics, with_tension);
  };
  Mode shaped = level_mode(0, i);
  if (plan_.inextensible)
    extrapolate_mode_in_kappa(shaped, level_mode(1, matches[fine][1][static_cast<std::size_t>(i)]));
  mode.normalised_by = shaped.normalised_by;
  if (with_tension) mode.max_abs_tension_n = shaped.max_abs_tension_n;
  if (!request.shapes) return;
  mode.s_m = shaped.s_m;
  mode.u = shaped.u;
  mode.w = shaped.w;
  mode.v = shaped.v;
  if (with_tension) mode.tension_n = shaped.tension_n;
  const Problem& problem = context_.problem;
  if (!problem.is_uniform()) {
    mode.modal_mass_kg = line_modal_mass(plane, mode, problem.line, context_.statics);
    return;
  }
  const CableProperties& cable = problem.cable;
  mode.modal_mass_kg =
      plane == Plane::InPlane
          ? inplane_modal_mass(mode, cable.tangential_mass_kg_per_m(), cable.normal_mass_kg_per_m())
          : outofplane_modal_mass(mode, cable.normal_mass_kg_per_m());
}

// Mode i: the extrapolated frequency, its relative error estimate (plus the rounding of the
// levels' Rayleigh quotients, and the statics' rounding floor where the estimate mesh makes the
// estimate tight), and its shape.
Mode FeNumerics::extrapolated_mode(Plane plane,
                                   int i,
                                   const FeModeMatches& matches,
                                   const FeExtrapolatedFrequency& frequency,
                                   const Vector& stations) const {
  const double omega = frequency.omega_rad_s, error = frequency.error_rad_s;
  Mode mode;
  mode.index = i + 1;
  set_mode_frequency(mode, omega, context_.groups);
  mode.relative_error_estimate = (error >= 0.0 && omega > 0.0) ? error / omega : -1.0;
  if (mode.relative_error_estimate >= 0.0)
    mode.relative_error_estimate += rounding_estimate(plan_, levels_, matches, plane, i);
  // Prescribed end forces are kept exactly (no Newton on the closure): no statics rounding floor.
  if (plan_.has_estimate_mesh() && mode.relative_error_estimate >= 0.0 &&
      !context_.problem.prescribed_forces)
    mode.relative_error_estimate += plan_.statics_floor(context_.groups.t0_n);
  attach_shape(plane, i, matches, stations, mode);
  return mode;
}

// The lowest `available` modes of `plane`, extrapolated, lowest first; the observed orders when
// asked.
void FeNumerics::extrapolate_modes(Plane plane,
                                   int available,
                                   ModalResult& result,
                                   std::vector<double>& orders) {
  const auto start = Clock::now();
  const Vector stations = context_.request.stations_m(context_.problem.length_m());
  const FeModeMatches matches = match_level_modes(levels_, plan_, plane, available);
  const std::size_t last = plan_.meshes.size() - 1;
  std::vector<std::pair<double, double>> low_orders;  // (omega, observed order)
  for (int i = 0; i < available; ++i) {
    const std::vector<std::vector<double>> omega = level_omegas(levels_, matches, plane, i);
    if (options_.observed_order && plan_.meshes.size() >= 3)
      orders.push_back(observed_order(omega[last - 2][0], omega[last - 1][0], omega[last][0]));
    const FeExtrapolatedFrequency frequency = extrapolate_frequency(plan_, omega);
    Mode mode = extrapolated_mode(plane, i, matches, frequency, stations);
    if (frequency.below_assumed_order)
      low_orders.emplace_back(mode.omega_rad_s, frequency.observed_order);
    result.summary.max_error_estimate =
        std::max(result.summary.max_error_estimate, mode.relative_error_estimate);
    result.modes.push_back(std::move(mode));
  }
  // Extrapolation may reorder two modes closer than their discretisation errors: report them
  // lowest first.
  std::stable_sort(result.modes.begin(), result.modes.end(),
                   [](const Mode& a, const Mode& b) { return a.omega_rad_s < b.omega_rad_s; });
  for (std::size_t i = 0; i < result.modes.size(); ++i)
    result.modes[i].index = static_cast<int>(i) + 1;
  if (!low_orders.empty())
    result.summary.notes.push_back(low_order_note(plan_, result.modes, low_orders));
  timings_.postprocessing_s += std::chrono::duration<double>(Clock::now() - start).count();
}

// Replaces the plan and its levels by those of a mesh of `elements`. Returns why not (and
// changes nothing) when that chain would be declined (in-plane rounding floor), could not meet
// the target (statics floor) or its statics fail; empty on success.
std::string FeNumerics::refine_plan(Plane plane, int elements) {
  FeSolverOptions finer = options_;
  finer.elements = elements;
  const SolveRequest& request = context_.request;
  FePlan plan = make_fe_plan(context_.problem, context_.statics, finer, request.inplane_modes,
                             request.outofplane_modes);
  const double t0_n = context_.groups.t0_n;
  if (plane == Plane::InPlane && plan.rounding_floor(t0_n, 1) > kMaxRoundingFloor)
    return fmt::format(
        "at N = {} the chain's normwise rounding floor would be {:.1e}, where fe declines the "
        "plane",
        elements, plan.rounding_floor(t0_n, 1));
  // The statics' rounding floor grows with N (FePlan::statics_floor): a mesh whose floor alone
  // exceeds the target cannot meet it.
  if (plan.has_estimate_mesh() && !context_.problem.prescribed_forces &&
      plan.statics_floor(t0_n) >= options_.tolerance)
    return fmt::format("at N = {} the statics' rounding floor alone would be {:.1e}", elements,
                       plan.statics_floor(t0_n));
  std::string failure;
  FeLevels levels =
      solve_level_statics(context_.problem, context_.statics, plan, timings_, failure);
  if (!failure.empty())
    return fmt::format("the discrete statics at N = {} failed: {}", elements, failure);
  options_ = finer;
  plan_ = std::move(plan);
  levels_ = std::move(levels);
  return {};
}

std::vector<double> error_estimates(const ModalResult& result) {
  std::vector<double> estimates;
  for (const Mode& mode : result.modes) estimates.push_back(mode.relative_error_estimate);
  return estimates;
}

// The modes of one plane, on finer meshes while the accuracy target asks for one and a refinement
// pays (fe_refinement.hpp). A refinement replaces the plan for the rest of the run: the other
// plane and the forced response use the finer mesh too. A finer solve that does not complete
// (time limit, failure) leaves the last complete result.
ModalResult FeNumerics::modes(Plane plane, int count) {
  ModalResult result = modes_on_plan(plane, count);
  const int first_elements = options_.elements;
  double first_worst = 0.0, previous_worst = 0.0;
  std::string stop_reason;
  while (result.summary.termination == Termination::Converged) {
    const std::vector<double> estimates = error_estimates(result);
    const FeRefinementStep step =
        fe_refined_elements({options_.elements, options_.max_elements, options_.tolerance,
                             options_.richardson, estimates, previous_worst});
    stop_reason = step.stop_reason;
    if (step.elements == 0) break;
    FeRun kept{options_, plan_, std::move(levels_), naturals_[plane]};
    stop_reason = refine_plan(plane, step.elements);
    if (!stop_reason.empty()) {
      levels_ = std::move(kept.levels);
      break;
    }
    previous_worst = fe_worst_miss(estimates, options_.tolerance);
    if (first_worst == 0.0) first_worst = previous_worst;
    ModalResult finer = modes_on_plan(plane, count);
    const double finer_worst = fe_worst_miss(error_estimates(finer), options_.tolerance);
    if (finer.modes.size() < result.modes.size() || finer_worst > previous_worst) {
      stop_reason = finer.modes.size() < result.modes.size()
                        ? fmt::format("the solve at N = {} did not complete", options_.elements)
                        : fmt::format("at N = {} the largest estimate grew to {:.1e}; N = {} kept",
                                      options_.elements, finer_worst, kept.options.elements);
      restore(plane, std::move(kept));
      break;
    }
    result = std::move(finer);
  }
  std::string note;
  if (options_.elements != first_elements)
    note = fmt::format(
        "mesh refined for the accuracy target {:.1e}: from N = {} (largest estimate {:.1e}) to N = "
        "{} "
        "elements",
        options_.tolerance, first_elements, first_worst, options_.elements);
  if (!stop_reason.empty())
    note += (note.empty() ? "mesh not refined: " : "; not refined further: ") + stop_reason;
  if (!note.empty()) result.summary.notes.push_back(note);
  return result;
}

ModalResult FeNumerics::modes_on_plan(Plane plane, int count) {
  naturals_[plane].clear();
  ModalResult result;
  SolverSummary& summary = result.summary;
  summary.resolution = fe_resolution(plan_);
  if (options_.tolerance > 0.0) summary.accuracy_target = options_.tolerance;
  if (auto singular = seabed_plane_singular(plane, context_.statics)) {
    summary.termination = Termination::NotApplicable;
    summary.message = *singular;
    return result;
  }
  if (context_.problem.is_damped()) {
    damped_modes_on_plan(plane, count, result);
    return result;
  }
  WorkMeter meter(context_, "fe", std::string(to_string(plane)) + " eigen solves (mesh levels)",
                  level_count(levels_));
  const FePlaneEigenReport eigen =
      solve_level_modes(levels_, plane, count, options_, timings_, &meter);
  summary.termination = eigen.termination;
  summary.iterations = eigen.restarts;
  summary.operations = eigen.operations;
  summary.max_residual = eigen.max_residual;
  summary.warnings = eigen.warnings;
  if (eigen.termination == Termination::NumericalFailure) {
    summary.message = fe_eigen_failure_message(plane, eigen);
    return result;
  }
  if (meter.stopped()) {
    // The modes are extrapolated from every level: none is available before all are solved.
    summary.message = fmt::format("0 of {} {} modes", count, to_string(plane));
    mark_time_limit(meter, summary);
    return result;
  }
  const int available = modes_on_every_level(levels_, plane, count);
  std::vector<double> orders;
  extrapolate_modes(plane, available, result, orders);
  for (const Mode& mode : result.modes)
    naturals_[plane].push_back({mode.index, mode.omega_rad_s, mode.relative_error_estimate});
  if (available < count && summary.termination == Termination::Converged)
    summary.termination = Termination::NoConvergence;
  const FeLevel& finest = levels_[static_cast<std::size_t>(plan_.main_fine)][0];
  result.proved_count_below_top = finest.eigen.at(plane).inertia_count;
  FePlaneFacts facts;
  facts.plane = plane;
  facts.modes_asked = count;
  facts.modes_available = available;
  facts.estimate_elements = options_.elements / 2;
  facts.has_coarse = plan_.has_coarse();
  facts.finest = &finest.eigen.at(plane);
  facts.finest_chain = &finest.chain;
  facts.prescribed_forces = context_.problem.prescribed_forces.has_value();
  facts.inertia_proved_everywhere = inertia_proved_on_every_level(levels_, plane);
  facts.eigen = &eigen;
  facts.observed_orders = std::move(orders);
  facts.plan = &plan_;
  facts.timings = &timings_;
  describe_fe_plane(facts, result);
  return result;
}

// The damped counterpart of modes_on_plan's eigen part: the damped roots on every level, then
// the plane's result (fe_damped_modes.hpp).
void FeNumerics::damped_modes_on_plan(Plane plane, int count, ModalResult& result) {
  SolverSummary& summary = result.summary;
  WorkMeter meter(context_, "fe",
                  std::string(to_string(plane)) + " damped eigen solves (mesh levels)",
                  level_count(levels_));
  const FePlaneEigenReport eigen =
      solve_level_damped_modes(levels_, plane, count, options_, timings_, &meter);
  summary.termination = eigen.termination;
  summary.iterations = eigen.restarts;
  summary.operations = eigen.operations;
  summary.max_residual = eigen.max_residual;
  summary.warnings = eigen.warnings;
  if (eigen.termination == Termination::NumericalFailure) {
    summary.message = fe_eigen_failure_message(plane, eigen);
    return;
  }
  if (meter.stopped()) {
    summary.message = fmt::format("0 of {} {} modes", count, to_string(plane));
    mark_time_limit(meter, summary);
    return;
  }
  const auto start = Clock::now();
  damped_modal_result(context_, plan_, levels_, plane, count, result);
  for (const Mode& mode : result.modes)
    naturals_[plane].push_back({mode.index, mode.omega_rad_s, mode.relative_error_estimate,
                                mode.decay_rate_1_s, mode.decay_rate_error_estimate});
  timings_.postprocessing_s += std::chrono::duration<double>(Clock::now() - start).count();
  const FeLevel& finest = levels_[static_cast<std::size_t>(plan_.main_fine)][0];
  summary.notes.push_back(
      fe_statics_note(finest.chain, context_.problem.prescribed_forces.has_value()));
  summary.notes.push_back(fe_time_note(timings_));
}

}  // namespace

SolverEntry make_fe_entry() {
  SolverEntry entry = make_solver_entry(
      "lumped-mass chain of N bar elements about its own exact statics; banded shift-invert "
      "Lanczos (Spectra, implicit restarts), Sylvester-inertia mode count, Richardson N/2N "
      "extrapolation",
      fe_knobs(), [](const SolveContext& context, const FeSolverOptions& options) {
        return std::make_unique<FeNumerics>(context, options);
      });
  entry.kind = SolverKind::Exact;
  entry.certifies_references = true;  // any sag, inclination and EA
  entry.all_modes_at_once = true;     // one shift-invert Lanczos per mesh level
  // Its `tolerance` (the plane summaries' accuracy_target; default 1e-6, verification/
  // tolerances.toml, [[solver]] fe: the penalty floor of inextensible cables is a few 1e-7), and
  // 1e-6 where a scene switched the target off (tolerance = 0).
  set_accuracy_target(entry, fe_knobs(), [](const FeSolverOptions& options) {
    return options.tolerance > 0.0 ? options.tolerance : 1e-6;
  });
  return entry;
}

}  // namespace internal

SolverOutput solve_fe(const Problem& problem,
                      const StaticSolution& statics,
                      const DimensionlessGroups& groups,
                      const SolveRequest& request,
                      const FeSolverOptions& options) {
  return internal::solve_with<internal::FeNumerics>("fe", {problem, statics, groups, request},
                                                    options);
}

}  // namespace catena
