// SPDX-License-Identifier: MIT
// The `shooting` solver: frequencies by conjugate-point counting and root refinement on the
// principal solutions, shapes from the null vector, forced response by superposition
// (see include/catena/solvers/shooting_solver.hpp for the method). This file holds the options,
// the knob table and ShootingNumerics, which runs one plane as: integrator
// (internal/shooting_integrator), root finder (internal/shooting_root_finder), modes
// (internal/shooting_modes); the forced response is internal/shooting_forced.
#include "catena/solvers/shooting_solver.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>
#include <memory>
#include <optional>

#include "catena/core/error.hpp"
#include "solvers/common/knob_table.hpp"
#include "solvers/common/line_applicability.hpp"
#include "solvers/common/solver_driver.hpp"
#include "solvers/common/solver_entries.hpp"
#include "solvers/common/work_meter.hpp"
#include "solvers/shooting/shooting_coefficients.hpp"
#include "solvers/shooting/shooting_damped_forced.hpp"
#include "solvers/shooting/shooting_damped_integrator.hpp"
#include "solvers/shooting/shooting_damped_modes.hpp"
#include "solvers/shooting/shooting_forced.hpp"
#include "solvers/shooting/shooting_grounded.hpp"
#include "solvers/shooting/shooting_integrator.hpp"
#include "solvers/shooting/shooting_modes.hpp"
#include "solvers/shooting/shooting_root_finder.hpp"
#include "solvers/shooting/shooting_shot_setup.hpp"

namespace catena {

std::string to_string(ShootingMethod method) {
  switch (method) {
    case ShootingMethod::RungeKutta:
      return "rk";
    case ShootingMethod::Adams:
      return "adams";
    case ShootingMethod::Bdf:
      return "bdf";
  }
  return "?";
}

double ShootingSolverOptions::effective_absolute_tolerance() const {
  return absolute_tolerance > 0.0 ? absolute_tolerance : relative_tolerance / 100.0;
}

double ShootingSolverOptions::effective_root_tolerance() const {
  return root_tolerance > 0.0 ? root_tolerance : relative_tolerance;
}

namespace internal {

const KnobTable<ShootingSolverOptions>& shooting_knobs() {
  using O = ShootingSolverOptions;
  static const KnobTable<O> table(
      "shooting",
      {real_knob("rtol", &O::relative_tolerance, Range::closed(1e-14, 1e-2),
                 "relative tolerance of the integration"),
       real_knob("atol", &O::absolute_tolerance, Range::closed(0.0, 1e-2),
                 "absolute tolerance of the integration on the scaled state (0: rtol/100)"),
       real_knob("root_tolerance", &O::root_tolerance, Range::closed(0.0, 1e-2),
                 "relative width of the final frequency bracket (0: rtol)"),
       choice_knob("method", &O::method,
                   {{"rk", ShootingMethod::RungeKutta},
                    {"adams", ShootingMethod::Adams},
                    {"bdf", ShootingMethod::Bdf}},
                   "SUNDIALS ARKODE's ERKStep with Verner's 6(5) pair, or CVODE's Adams or BDF"),
       choice_knob("nonlinear_solver", &O::fixed_point_iteration,
                   {{"newton", false}, {"fixed_point", true}},
                   "CVODE's Newton (dense LU, analytic Jacobian) or fixed-point iteration"),
       integer_knob("max_steps", &O::max_steps, Range::at_least(100),
                    "maximum integration steps per shot"),
       real_knob("max_condition", &O::max_condition, Range::closed(2.0, 1e8),
                 "re-orthonormalise the principal pair when cond(Gram) exceeds this"),
       flag_knob("error_estimate", &O::error_estimate,
                 "one extra shot per mode at 100x tighter tolerances"),
       choice_knob(
           "root_finder", &O::newton, {{"newton", true}, {"brent", false}},
           "refine each root by Newton with the shot's frequency derivative, or by Brent")});
  return table;
}

}  // namespace internal

void ShootingSolverOptions::validate() const { internal::shooting_knobs().validate(*this); }

namespace internal {
namespace {

IntegratorSettings integrator_settings(const ShootingSolverOptions& options) {
  IntegratorSettings settings;
  settings.relative_tolerance = options.relative_tolerance;
  settings.absolute_tolerance = options.effective_absolute_tolerance();
  settings.method = options.method;
  settings.fixed_point = options.fixed_point_iteration;
  settings.max_steps = options.max_steps;
  settings.max_condition = options.max_condition;
  return settings;
}

// The accuracy each frequency is asked for: the integration's 10 rtol (what a shot at rtol
// typically moves a root by; the error estimate measures it) plus the final bracket's width.
double accuracy_target(const ShootingSolverOptions& options) {
  return 10.0 * options.relative_tolerance + options.effective_root_tolerance();
}

RootFinderSettings root_finder_settings(const ShootingSolverOptions& options) {
  RootFinderSettings settings;
  settings.relative_tolerance = options.relative_tolerance;
  settings.root_tolerance = options.effective_root_tolerance();
  settings.error_estimate = options.error_estimate;
  settings.target = accuracy_target(options);
  settings.estimate_floor = settings.target;
  return settings;
}

// The SUNDIALS integrator and method of the shots, e.g. "ARKODE ERKStep, Verner 8-stage 6(5)
// table" (the knob `method`; "Integrators" in docs/explanation/methods/shooting.md).
std::string integrator_name(const ShootingSolverOptions& options) {
  if (options.method == ShootingMethod::RungeKutta) {
    return "ARKODE ERKStep, Verner 8-stage 6(5) table";
  }
  return fmt::format(
      "CVODE {}, {}", options.method == ShootingMethod::Adams ? "Adams" : "BDF",
      options.fixed_point_iteration ? "fixed-point iteration" : "Newton with dense LU");
}

std::string resolution(const ShootingSolverOptions& options) {
  return fmt::format("{}, rtol {:.1e} atol {:.1e}, root bracket {:.1e}", integrator_name(options),
                     options.relative_tolerance, options.effective_absolute_tolerance(),
                     options.effective_root_tolerance());
}

// What a failure on a grounded stretch away from A likely means: the general shot crosses it
// (the grounded run takes only the pieces from A), and its steps grow with the e-folds
// L_g sqrt(k / T) of the foundation's growing solution (docs/explanation/methods/shooting.md,
// "The grounded run"). Empty when no such stretch has many e-folds.
std::string grounded_middle_hint(const ShootingCoefficients& k) {
  std::size_t leading = 0;
  while (leading < k.pieces.size() && k.pieces[leading].grounded) ++leading;
  double efolds = 0.0, s_begin = 0.0, s_end = 0.0;
  for (std::size_t j = leading; j < k.pieces.size(); ++j) {
    const ShootingPiece& p = k.pieces[j];
    if (!p.grounded || !(p.min_tension(k.H) > 0.0)) continue;
    const double stiffness = std::max(p.foundation_normal, p.foundation_tangential);
    const double e = (p.s_end - p.s_begin) * std::sqrt(stiffness / p.min_tension(k.H));
    if (e > efolds) efolds = e, s_begin = p.s_begin, s_end = p.s_end;
  }
  if (!(efolds > 100.0)) return "";
  return fmt::format(
      "; the general shot crosses the grounded stretch s in [{:.6g}, {:.6g}] m away from A, where "
      "the foundation's solution grows by {:.0f} e-folds (L_g sqrt(k / T)): the grounded run, "
      "whose cost does not grow with k, takes only the stretch from A",
      s_begin, s_end, efolds);
}

// A plane whose frequencies could not be found: the integrator failed (the reason says where).
void mark_failed(Plane plane,
                 const ShootingFailure& failure,
                 const ShootingCoefficients& k,
                 SolverSummary& summary) {
  summary.termination = Termination::NumericalFailure;
  summary.message = fmt::format("Numerical failure ({}): {}{}", to_string(plane), failure.what(),
                                grounded_middle_hint(k));
}

// A grounded stretch without static tension (friction that takes it all on the stretch from an
// anchor on the seabed, or a slack line, H = 0, whose grounded part carries none and whose hanging
// part leaves the seabed with T = 0) has no transverse stiffness but the foundation's: the shot's
// coefficient 1/T is infinite there, in both planes, and the count of conjugate points is not
// defined. Declined, wherever along the line the stretch lies.
std::optional<std::string> slack_on_seabed(const StaticSolution& statics) {
  if (!statics.has_contact()) return std::nullopt;
  const double H = statics.horizontal_force_n();
  double slack = 0.0;
  for (const StaticPiece& piece : statics.pieces()) {
    if (!piece.grounded) continue;
    const double middle = piece.s_begin_m + 0.5 * piece.section.length_m;
    if (!(statics.tension_n(middle) > 0.0)) slack += piece.section.length_m;
  }
  if (!(slack > 0.0)) return std::nullopt;
  if (!(H > 0.0)) {
    return fmt::format(
        "a slack line (H = 0): {:.6g} m rest on the seabed without static tension and the hanging "
        "part leaves it with T = 0; the transverse equations divide by T, so the shot is singular "
        "there in both planes (fe solves a plane whose seabed stiffness holds the grounded part)",
        slack);
  }
  return fmt::format(
      "the seabed friction (seabed.friction = {:.6g}) brings the static tension on {:.6g} m of the "
      "grounded part to zero (H = {:.6g} N < C_B w L_g): that stretch has no transverse stiffness "
      "but the foundation's and the transverse equations of both planes are singular there; lower "
      "seabed.friction below H / (w L_g) or shorten the grounded length",
      statics.seabed().friction, slack, H);
}

// The numerics of the shooting solver for one problem.
class ShootingNumerics final : public SolverNumerics {
 public:
  ShootingNumerics(const SolveContext& context, const ShootingSolverOptions& options)
      : context_(context), options_(options) {}

  std::optional<std::string> not_applicable() const override;
  // Damped modes (shooting_damped_modes.hpp) and forced response (shooting_damped_forced.hpp),
  // on the seabed too (the damped grounded run, shooting_damped_grounded.hpp).
  bool handles_damping() const override { return true; }
  bool handles_damped_forced() const override { return true; }
  // The dynamic tension: the damped forced response with the linearised drag added
  // (forced_with_drag), and the tangential added mass in ShootingPiece::m.
  bool handles_drag() const override { return true; }
  bool handles_tangential_added_mass() const override { return true; }
  ForcedOutcome forced_with_drag(const ForcedRequest& request, const DragProfile& drag) override;
  std::optional<Outcome> prepare() override {
    k_ = ShootingCoefficients::from_statics(context_.statics);
    return std::nullopt;
  }
  void describe(SolverSummary& summary) const override;
  ModalResult modes(Plane plane, int count) override;
  ForcedOutcome forced(const ForcedRequest& request) override {
    WorkMeter meter(context_, "shooting", "forced frequencies",
                    static_cast<long>(request.omegas_rad_s.size()));
    const Vector stations = context_.request.stations_m(k_.length_m);
    ForcedOutcome outcome = context_.problem.is_damped()
                                ? shooting_damped_forced_responses(
                                      k_, request, stations, integrator_settings(options_), &meter)
                                : shooting_forced_responses(k_, request, stations,
                                                            integrator_settings(options_), &meter);
    mark_time_limit(meter, outcome.summary);
    return outcome;
  }

 private:
  ModalResult damped_modes(Plane plane, int count);
  void add_modes(ShootingIntegrator& integrator,
                 const std::vector<Root>& roots,
                 Plane plane,
                 int count,
                 ModalResult& result) const;
  void finish_summary(const ShootingRootFinder& finder,
                      const ShootingIntegrator& integrator,
                      Plane plane,
                      int count,
                      ModalResult& result) const;

  const SolveContext& context_;
  ShootingSolverOptions options_;
  ShootingCoefficients k_;
  // The integrator of forced_with_drag, kept across the fixed point's iterates (its SUNDIALS
  // objects are made once), and the plane it was made for.
  std::unique_ptr<DampedShootingIntegrator> drag_integrator_;
  Plane drag_plane_ = Plane::InPlane;
};

// One iterate of the drag linearisation's fixed point (solver_driver.hpp): the damped forced
// response with the profile's damping added to the pieces' (damping_at, shooting_system.hpp).
// The error estimate (a re-solve at 100x tighter tolerances, 2-3x the cost of the response) is
// computed only where it is read: for a profile without drag (the driver's only call) and at the
// driver's final call (DragProfile::is_final); the intermediate iterates return
// relative_error_estimate = -1 (none), which the driver never reports.
ForcedOutcome ShootingNumerics::forced_with_drag(const ForcedRequest& request,
                                                 const DragProfile& drag) {
  WorkMeter meter(context_, "shooting", "dynamic tension frequencies",
                  static_cast<long>(request.omegas_rad_s.size()));
  const IntegratorSettings settings = integrator_settings(options_);
  const Plane plane = damped_forced_plane(k_, request);
  try {
    if (!drag_integrator_ || drag_plane_ != plane) {
      drag_integrator_ = std::make_unique<DampedShootingIntegrator>(plane, k_, settings);
      drag_plane_ = plane;
    }
  } catch (const ShootingFailure& failure) {
    ForcedOutcome outcome;
    outcome.summary.termination = Termination::NumericalFailure;
    outcome.summary.message = failure.what();
    return outcome;
  }
  drag_integrator_->set_drag(&drag);
  ForcedOutcome outcome =
      shooting_damped_forced_responses(*drag_integrator_, k_, request, drag.stations(), settings,
                                       drag.is_final() || !drag.has_drag(), &meter);
  drag_integrator_->set_drag(nullptr);
  mark_time_limit(meter, outcome.summary);
  return outcome;
}

// The equations divide by the static tension: where it vanishes inside the cable (a slack
// vertical cable), the principal solutions are not defined.
// Why the seabed foundation is too stiff for the shot, or nothing.
std::optional<std::string> foundation_too_stiff(const StaticSolution& statics) {
  if (!statics.has_contact()) return std::nullopt;
  const ShootingCoefficients k = ShootingCoefficients::from_statics(statics);
  for (const ShootingPiece& p : k.pieces) {
    if (!p.grounded || !(p.min_tension(k.H) > 0.0)) continue;
    const double stiffness = std::max(p.foundation_normal, p.foundation_tangential);
    const double efolds = (p.s_end - p.s_begin) * std::sqrt(stiffness / p.min_tension(k.H));
    if (efolds > kMaxGroundedEfolds) {
      return fmt::format(
          "[seabed] stiffness {:.3g} N/m per m: on the grounded stretch s in [{:.6g}, {:.6g}] m "
          "the foundation's solution grows by {:.3g} e-folds (L_g sqrt(k / T)), more than the "
          "{:.0e} "
          "a shot carries (its scale factors are kept per e^600)",
          stiffness, p.s_begin, p.s_end, efolds, kMaxGroundedEfolds);
    }
  }
  return std::nullopt;
}

std::optional<std::string> ShootingNumerics::not_applicable() const {
  const StaticSolution& statics = context_.statics;
  if (auto reason = slack_on_seabed(statics)) return reason;
  if (auto reason = foundation_too_stiff(statics)) return reason;
  const double L = statics.cable().length_m;
  const double V_A = statics.vertical_force_a_n();
  const double V_B = statics.vertical_force_n(L);
  if (statics.horizontal_force_n() <= 0.0 && V_A * V_B <= 0.0) {
    return std::string("the static tension vanishes inside the cable (H = 0 and V changes sign)");
  }
  return std::nullopt;
}

void ShootingNumerics::describe(SolverSummary& summary) const {
  summary.resolution = resolution(options_);
  summary.notes.push_back(
      "exact linearisation about the closed-form static catenary; A^{-1} used, so EA = inf is "
      "exact (no penalty); counting by the conjugate points of the principal solution (phase of "
      "det(Phi + iF), Morse index / Sturm)");
  const char* how = "integrated piece by piece, continuous across every contact boundary";
  if (auto note = seabed_model_note(context_.statics, how)) summary.notes.push_back(*note);
}

// In plane, the modes of a nearly straight cable depend on the stretching its curvature causes:
// the axial displacement, a difference of the shot's components of relative size ~ the angle the
// tangent turns through (the axial frame, shooting_integrator.hpp, stretches it by at most
// kMaxAxialStretch = 1e8). Rounding of those components reaches the stretching as about
// u / turn, and the frequencies in proportion to how much the stretching moves them, about
// min(1, lambda^2 / pi^2) with Irvine's lambda^2 = turn^2 EA / T (Irvine's symmetric modes); the
// error estimate (a re-shot at tighter tolerances) sees none of it. Measured against eq. (21)
// (taut_inclined eps 1e-12 to 1e-6, phi_a 10 to 89 deg, lambda^2 1e-4 to 100, issue 32): the error
// is at most 0.33 of this floor, and 36 times it (a 23 % error) at a turn of 1.7e-14 rad. The
// estimate is therefore at least kInplaneRoundingFactor times the floor, and the plane declines
// where the bare u / turn exceeds kMaxInplaneRoundingFloor. A straight line (turn 0) decouples
// exactly.
constexpr double kInplaneRoundingFactor = 1.0;  // 3x the largest measured 0.33
constexpr double kMaxInplaneRoundingFloor = 1e-3;

// u / turn, and the floor: that times min(1, lambda^2 / pi^2) (with the stiffest section's EA,
// the larger lambda^2) and kInplaneRoundingFactor.
struct RoundingFloor {
  double per_turn = 0.0;
  double floor = 0.0;
};

RoundingFloor inplane_rounding_floor(const ShootingCoefficients& k) {
  const double turn = tangent_turn_rad(k);
  if (turn == 0.0) return {};
  double min_compliance = kInfinity;
  for (const ShootingPiece& p : k.all_pieces())
    min_compliance = std::min(min_compliance, p.compliance);
  const double lambda2 =
      min_compliance > 0.0 ? turn * turn / (k.t_ref * min_compliance) : kInfinity;
  RoundingFloor r;
  r.per_turn = 0.5 * std::numeric_limits<double>::epsilon() / turn;
  r.floor = kInplaneRoundingFactor * r.per_turn * std::min(1.0, lambda2 / (kPi * kPi));
  return r;
}

void apply_rounding_floor(double floor, double turn, ModalResult& result) {
  if (floor <= 0.0) return;
  bool raised = false;
  for (Mode& mode : result.modes) {
    if (mode.relative_error_estimate < 0.0 || mode.relative_error_estimate >= floor) continue;
    mode.relative_error_estimate = floor;
    raised = true;
  }
  if (!raised) return;
  result.summary.max_error_estimate = std::max(result.summary.max_error_estimate, floor);
  result.summary.notes.push_back(fmt::format(
      "in-plane error estimates raised to the rounding floor {:.2g} ({} u / (tangent turn {:.3g} "
      "rad) x min(1, lambda^2 / pi^2)): the stretching of a nearly straight cable is known only "
      "to that",
      floor, kInplaneRoundingFactor, turn));
}

// Frequencies (and shapes, tension) of one plane. A straight (vertical, H = 0) inextensible
// cable: the axial direction is rigid, det Phi(L) vanishes identically, and the in-plane problem
// is the transverse string alone, which is the out-of-plane equation for the normal displacement.
ModalResult ShootingNumerics::modes(Plane plane, int count) {
  if (context_.problem.is_damped()) return damped_modes(plane, count);
  ModalResult result;
  SolverSummary& summary = result.summary;
  summary.resolution = resolution(options_);
  summary.accuracy_target = accuracy_target(options_);
  const bool string_only = plane == Plane::InPlane && is_straight_inextensible(k_);
  if (string_only) {
    summary.notes.push_back(
        "straight inextensible cable: in-plane modes are the transverse string modes (normal "
        "displacement w, u = 0); the axial direction is rigid and its constant dynamic tension is "
        "statically indeterminate (reported as 0)");
  }
  const RoundingFloor rounding =
      plane == Plane::InPlane && !string_only ? inplane_rounding_floor(k_) : RoundingFloor{};
  if (rounding.per_turn > kMaxInplaneRoundingFloor) {
    summary.termination = Termination::NotApplicable;
    summary.message = fmt::format(
        "Not applicable: in plane, the static tangent turns by only {:.3g} rad along the line, so "
        "the stretching that sets the in-plane modes is a difference of the shot's components "
        "known to about {:.2g} relative (rounding / turn), above the {:.0e} this solver reports",
        tangent_turn_rad(k_), rounding.per_turn, kMaxInplaneRoundingFloor);
    return result;
  }
  const Plane integration_plane = string_only ? Plane::OutOfPlane : plane;
  std::optional<ShootingIntegrator> integrator;
  try {
    integrator.emplace(integration_plane, k_, integrator_settings(options_));
  } catch (const ShootingFailure& failure) {
    mark_failed(plane, failure, k_, summary);
    return result;
  }
  // String estimate of the (n+1)-th frequency, nudged off the exact string values.
  const double guess = (count + 1.37) * kPi / transverse_travel_time(k_);
  ShootingRootFinder finder(
      [&integrator](double omega, double factor) { return integrator->shoot(omega, factor); },
      root_finder_settings(options_), guess, integration_plane == Plane::OutOfPlane);
  // A line with point attachments keeps Brent: near a mode localised at a heavy point the count
  // steps steeply, Newton's safeguard shoots slopes it does not use, and its fewer shots cost
  // more time (docs/explanation/methods/shooting.md, "Newton refinement"). Segments alone do not:
  // three identical segments cost 1.9x the one-segment cable out of plane with Brent.
  if (options_.newton && k_.points.empty()) {
    finder.set_slope_shots([&integrator](double omega, double factor) {
      return integrator->shoot(omega, factor, nullptr, false, true);
    });
  }
  WorkMeter meter(context_, "shooting", std::string(to_string(plane)) + " modes", count);
  try {
    const std::vector<Root> roots = finder.find(count, summary.warnings, &meter);
    add_modes(*integrator, roots, plane, count, result);
    apply_rounding_floor(rounding.floor, tangent_turn_rad(k_), result);
  } catch (const ShootingFailure& failure) {
    mark_failed(plane, failure, k_, summary);
    summary.iterations = finder.shots();
    summary.operations = integrator->total_rhs_evaluations();
    return result;
  }
  finish_summary(finder, *integrator, plane, count, result);
  mark_time_limit(meter, summary);
  return result;
}

// The damped modes of one plane (shooting_damped_modes.hpp); an integration failure makes the
// plane a NumericalFailure with its reason.
ModalResult ShootingNumerics::damped_modes(Plane plane, int count) {
  DampedPlaneSettings settings;
  settings.integrator = integrator_settings(options_);
  settings.undamped = root_finder_settings(options_);
  settings.root_tolerance = options_.effective_root_tolerance();
  settings.error_estimate = options_.error_estimate;
  settings.estimate_floor = accuracy_target(options_);
  settings.first_guess_rad_s = (count + 2.37) * kPi / transverse_travel_time(k_);
  ModalResult result;
  try {
    result = damped_plane_modes(k_, context_, plane, count, settings);
  } catch (const ShootingFailure& failure) {
    result = ModalResult();
    mark_failed(plane, failure, k_, result.summary);
  }
  result.summary.resolution = resolution(options_);
  result.summary.accuracy_target = accuracy_target(options_);
  return result;
}

// Modes of the roots, clustered: roots closer than the integration can resolve form one
// (numerically) multiple root whose null space is spanned by the smallest singular vectors of
// Phi(L) together. A failing shape shot keeps the modes built so far, with a warning.
void ShootingNumerics::add_modes(ShootingIntegrator& integrator,
                                 const std::vector<Root>& roots,
                                 Plane plane,
                                 int count,
                                 ModalResult& result) const {
  SolverSummary& summary = result.summary;
  const double merge =
      1000.0 * std::max(options_.relative_tolerance, options_.effective_root_tolerance());
  const std::vector<std::vector<Root>> clusters = cluster_roots(roots, merge);
  if (clusters.size() < roots.size()) {
    summary.notes.push_back(fmt::format(
        "{} groups of frequencies closer than {:.1e} (relative): shapes from the joint null space, "
        "mass-orthogonalised",
        roots.size() - clusters.size(), merge));
  }
  const bool string_only = plane == Plane::InPlane && is_straight_inextensible(k_);
  ShootingModeBuilder builder(integrator, k_, context_, plane, string_only);
  try {
    for (const std::vector<Root>& cluster : clusters)
      builder.add_cluster(cluster, count, result.modes);
  } catch (const ShootingFailure& failure) {
    summary.warnings.push_back(fmt::format("shapes: {}", failure.what()));
  }
  summary.max_error_estimate = builder.max_error();
  summary.max_residual = builder.max_residual();
}

void ShootingNumerics::finish_summary(const ShootingRootFinder& finder,
                                      const ShootingIntegrator& integrator,
                                      Plane plane,
                                      int count,
                                      ModalResult& result) const {
  SolverSummary& summary = result.summary;
  result.proved_count_below_top = finder.proved_count();
  summary.iterations = finder.shots();
  summary.operations = integrator.total_rhs_evaluations();
  const int found = static_cast<int>(result.modes.size());
  summary.termination = found == count ? Termination::Converged : Termination::NoConvergence;
  summary.message = fmt::format(
      "{}: {} of {} {} modes; conjugate-point count proves {} eigenvalues <= {:.10g} rad/s; max "
      "relative error estimate {:.2e}",
      found == count ? "Converged" : "No convergence", found, count, to_string(plane),
      result.proved_count_below_top, result.modes.empty() ? 0.0 : result.modes.back().omega_rad_s,
      summary.max_error_estimate);
  const ShotTally& tally = finder.tally();
  summary.notes.push_back(fmt::format(
      "{} shots ({} bracketing by counts, {} refining, {} error estimates, {} tightening), {} "
      "integration steps, {} RHS evaluations; principal pair re-orthonormalised {} times "
      "(max log volume growth {:.3g}); max phase defect {:.2e} rad ({} re-shots for phase); {} "
      "refinements at tighter tolerances for estimates above the target {:.2g}",
      finder.shots(), tally.bracketing, tally.refining, tally.estimate, tally.tightening,
      integrator.total_steps(), integrator.total_rhs_evaluations(),
      integrator.total_reorthonormalisations(), integrator.max_log_growth(),
      finder.max_phase_defect(), finder.phase_retries(), finder.tightened(),
      summary.accuracy_target));
}

}  // namespace

SolverEntry make_shooting_entry() {
  SolverEntry entry = make_solver_entry(
      "exact linear boundary-value solution: principal solutions integrated by SUNDIALS ARKODE "
      "(ERKStep, Verner's 6(5) pair), "
      "modes counted by conjugate points (Morse index) and refined by safeguarded Newton steps "
      "with the frequency derivative of the shot (Brent's method as fallback) on a count-aware "
      "phase function; any sag, inclination, EA (inf exact), added mass; damped lines (on the "
      "seabed too) by complex roots continued from the undamped ones, counted by the argument "
      "principle",
      shooting_knobs(), [](const SolveContext& context, const ShootingSolverOptions& options) {
        return std::make_unique<ShootingNumerics>(context, options);
      });
  entry.kind = SolverKind::Exact;
  entry.certifies_references = true;  // any sag, inclination and EA
  set_accuracy_target(entry, shooting_knobs(), accuracy_target);
  return entry;
}

}  // namespace internal

SolverOutput solve_shooting(const Problem& problem,
                            const StaticSolution& statics,
                            const DimensionlessGroups& groups,
                            const SolveRequest& request,
                            const ShootingSolverOptions& options) {
  return internal::solve_with<internal::ShootingNumerics>(
      "shooting", {problem, statics, groups, request}, options);
}

}  // namespace catena
