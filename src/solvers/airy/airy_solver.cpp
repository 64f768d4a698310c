// SPDX-License-Identifier: MIT
// Triantafyllou's Airy-function solution (Grinfogel 1984, eqs. 7-16;
// docs/explanation/methods/airy.md): the solver's knobs, applicability and numerics. The model, its
// boundary determinant, the root scan and the mode shapes are in src/solvers/airy/airy_*; the
// out-of-plane string of linear tension in src/solvers/airy/airy_tension_string.hpp.
#include "catena/solvers/airy_solver.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include "catena/core/error.hpp"
#include "solvers/airy/airy_boundary_system.hpp"
#include "solvers/airy/airy_mode_shape.hpp"
#include "solvers/airy/airy_model.hpp"
#include "solvers/airy/airy_root_scan.hpp"
#include "solvers/airy/airy_tension_string.hpp"
#include "solvers/common/knob_table.hpp"
#include "solvers/common/line_applicability.hpp"
#include "solvers/common/modal_damping.hpp"
#include "solvers/common/mode_tools.hpp"
#include "solvers/common/solver_driver.hpp"
#include "solvers/common/solver_entries.hpp"
#include "solvers/common/taut_cable_theory.hpp"
#include "solvers/common/work_meter.hpp"

namespace catena {

std::string to_string(AiryCurvatureFit fit) {
  switch (fit) {
    case AiryCurvatureFit::Tangent:
      return "tangent";
    case AiryCurvatureFit::Secant:
      return "secant";
    case AiryCurvatureFit::Paper:
      return "paper";
  }
  return "?";
}

std::optional<AiryCurvatureFit> parse_airy_curvature_fit(const std::string& text) {
  if (text == "tangent") return AiryCurvatureFit::Tangent;
  if (text == "secant") return AiryCurvatureFit::Secant;
  if (text == "paper") return AiryCurvatureFit::Paper;
  return std::nullopt;
}

namespace internal {

const KnobTable<AirySolverOptions>& airy_knobs() {
  using O = AirySolverOptions;
  static const KnobTable<O> table("airy", [] {
    std::vector<KnobBinding<O>> knobs{
        choice_knob("curvature_fit", &O::curvature_fit,
                    {{"tangent", AiryCurvatureFit::Tangent},
                     {"secant", AiryCurvatureFit::Secant},
                     {"paper", AiryCurvatureFit::Paper}},
                    "linearisation of Q(s): tangent at s_a, secant through the ends, or the "
                    "paper's eqs. (17)-(18)"),
        real_knob("scan_step", &O::scan_step_k_l_over_pi, Range::closed(1e-4, 0.5),
                  "scan step in kL/pi"),
        real_knob("cutoff_fraction", &O::cutoff_fraction, Range{0.0, 1.0, true, true},
                  "spurious-root cutoff as a fraction of the string bound"),
        real_knob("max_k_l_over_pi", &O::max_k_l_over_pi, Range::at_least(0.0),
                  "scan limit in kL/pi (0: 2 modes + 20)"),
        integer_knob("tolerance_bits", &O::tolerance_bits, Range::closed(20, 53),
                     "root tolerance in bits")};
    for (auto& knob : taut_theory_knobs<O>("the travel time")) knobs.push_back(std::move(knob));
    return knobs;
  }());
  return table;
}

}  // namespace internal

void AirySolverOptions::validate() const {
  internal::airy_knobs().validate(*this);
  internal::require_warning_below_max_eps("airy", eps_warning_threshold, max_eps);
}

std::optional<std::string> airy_not_applicable_reason(const Problem& problem,
                                                      const StaticSolution& statics,
                                                      const DimensionlessGroups& groups,
                                                      const AirySolverOptions& options) {
  // Like eq. (21), the Airy model linearises about a slightly stretched string.
  const double strain = internal::static_strain(problem, groups);
  if (strain > internal::kMaxStaticStrain) {
    return fmt::format(
        "static strain T0/EA = {:.3g} > {:.1g}: the small-strain Airy model does not apply", strain,
        internal::kMaxStaticStrain);
  }
  if (!(statics.horizontal_force_n() > 0.0) || std::abs(std::cos(groups.chord_angle_rad)) < 1e-9) {
    return fmt::format(
        "vertical chord (H = {:.3g} N): the static curvature vanishes and the Airy solution "
        "degenerates",
        statics.horizontal_force_n());
  }
  if (std::abs(std::sin(groups.chord_angle_rad)) < 1e-6) {
    return fmt::format(
        "horizontal chord (phi_a = {:.3g} deg): Q0 = 0 and the Airy solution degenerates into "
        "Irvine's, which the asymptotic solver gives exactly",
        groups.chord_angle_rad * 180.0 / kPi);
  }
  if (groups.eps > options.max_eps) {
    return fmt::format(
        "eps = W0 L / T0 = {:.4g} > max_eps = {:.4g}: the Airy model is asymptotic "
        "in eps (linearised Q, WKB fast solution)",
        groups.eps, options.max_eps);
  }
  return std::nullopt;
}

double airy_frequency_determinant(const Problem& problem,
                                  const StaticSolution& statics,
                                  const DimensionlessGroups& groups,
                                  double k_l,
                                  const AirySolverOptions& options) {
  options.validate();
  const internal::AiryModel model = internal::build_airy_model(
      problem, statics, groups, options.curvature_fit, options.quadrature_panels);
  return internal::airy_determinant_at(model, groups, k_l);
}

namespace internal {
namespace {

// In plane, the Airy arguments grow as 1 / (eps cos phi_a) as the sag vanishes, and the boundary
// determinant is a difference of their phases: rounding reaches the roots as about u / (eps cos
// phi_a), far above the model error eps^2 and the root tolerance. Measured against eq. (21)
// (asymptotic, exact to O(eps^2) + rounding there: taut_inclined eps 1e-12 to 1e-6, phi_a 10 to
// 89 deg, lambda^2 1e-4 to 100, issue 32): at most 1.4 u / (eps cos phi_a) wherever that is below
// 1e-7, but errors of 35 % to 100 % at 1.1e-6 (lambda^2 = 1e-4) and above. The estimate is at least
// kInplaneRoundingFactor u / (eps cos phi_a); the plane declines above kMaxInplaneRounding of the
// bare term.
constexpr double kInplaneRoundingFactor = 4.0;
constexpr double kMaxInplaneRounding = 4e-7;  // kInplaneRoundingFactor x the measured 1e-7

double inplane_rounding_floor(const DimensionlessGroups& groups) {
  const double turn = groups.eps * std::cos(groups.chord_angle_rad);
  if (!(turn > 0.0)) return 0.0;  // declined elsewhere (horizontal and vertical chords)
  return kInplaneRoundingFactor * 0.5 * std::numeric_limits<double>::epsilon() / turn;
}

// The numerics of the airy solver for one problem: the Airy determinant's roots in plane, the
// Bessel modes of the linear-tension string out of plane (airy_tension_string.hpp).
class AiryNumerics final : public SolverNumerics {
 public:
  AiryNumerics(const SolveContext& context, const AirySolverOptions& options)
      : context_(context),
        options_(options),
        // O(eps^2) from the model, plus half the static strain T0/EA it neglects in k (as
        // asymptotic); the roots themselves are solved to 2^(1 - tolerance_bits).
        inplane_model_error_(context.groups.eps * context.groups.eps +
                             0.5 * static_strain(context.problem, context.groups)),
        root_error_(std::ldexp(1.0, 1 - options.tolerance_bits)),
        inplane_rounding_(inplane_rounding_floor(context.groups)),
        inplane_error_estimate_(std::max({inplane_model_error_, root_error_, inplane_rounding_})) {}

  std::optional<std::string> not_applicable() const override {
    if (auto reason = uniform_cable_only(context_.problem, "the Airy boundary-layer solution"))
      return reason;
    if (auto reason = no_seabed_contact(context_.statics, "the Airy boundary-layer solution"))
      return reason;
    return airy_not_applicable_reason(context_.problem, context_.statics, context_.groups,
                                      options_);
  }

  // Light damping by first-order perturbation of the model's own modes (modal_damping.hpp).
  bool handles_damping() const override { return true; }

  void describe(SolverSummary& summary) const override;

  ModalResult modes(Plane plane, int count) override {
    return plane == Plane::InPlane ? inplane_modes(count) : outofplane_modes();
  }

 private:
  std::string resolution() const;
  ModalResult inplane_modes(int count) const;
  ModalResult outofplane_modes() const;  // as many as the request asks
  Mode outofplane_mode(int n,
                       double omega,
                       const TensionString& string,
                       const Vector& stations,
                       double estimate) const;
  Mode inplane_mode(int index,
                    double kl,
                    const AiryModel& model,
                    const Vector& stations,
                    const Vector& travel_times,
                    double& max_residual) const;
  double inplane_mode_decay_rate(const AiryModel& model, double omega) const;
  double outofplane_mode_decay_rate(const TensionString& string, double omega) const;
  void add_scan_notes(const AiryRootScan& scan, SolverSummary& summary) const;
  void set_inplane_outcome(int found,
                           int count,
                           const AiryRootScan& scan,
                           double max_residual,
                           SolverSummary& summary) const;

  const SolveContext& context_;
  AirySolverOptions options_;
  double inplane_model_error_;
  double root_error_;
  double inplane_rounding_;
  double inplane_error_estimate_;
};

std::string AiryNumerics::resolution() const {
  return fmt::format(
      "scan step kL/pi = {:.3g}, TOMS 748 to {} bits, Q fit '{}', {} x 20-point Gauss-Legendre",
      options_.scan_step_k_l_over_pi, options_.tolerance_bits, to_string(options_.curvature_fit),
      options_.quadrature_panels);
}

void AiryNumerics::describe(SolverSummary& summary) const {
  const double eps = context_.groups.eps;
  summary.resolution = resolution();
  summary.notes.push_back(fmt::format(
      "Triantafyllou's Airy model is asymptotic in eps (linearised Q, WKB fast solution): in-plane "
      "model error O(eps^2) + T0/(2 EA) = {:.3g} reported as relative_error_estimate; out of "
      "plane the bound of the linear-tension string (its notes); roots are solved to {:.1e}",
      inplane_model_error_, root_error_));
  if (eps > options_.eps_warning_threshold) {
    summary.warnings.push_back(fmt::format(
        "eps = {:.4g} > {:.3g}: the Airy model's linearisation of Q and WKB fast solution lose "
        "accuracy; expect errors of order eps^2 = {:.2g} or worse",
        eps, options_.eps_warning_threshold, inplane_model_error_));
  }
}

// One in-plane mode at root kL; with the shape (and tension) on the stations when asked,
// normalised like every solver's. `max_residual` gains the boundary system's sigma ratio.
Mode AiryNumerics::inplane_mode(int index,
                                double kl,
                                const AiryModel& model,
                                const Vector& stations,
                                const Vector& travel_times,
                                double& max_residual) const {
  const SolveRequest& request = context_.request;
  const CableProperties& cable = context_.problem.cable;
  Mode mode;
  mode.index = index;
  const double omega = context_.groups.omega_from_k_l_over_pi(kl / kPi);
  set_mode_frequency(mode, omega, context_.groups);
  mode.relative_error_estimate = inplane_error_estimate_;
  if (!request.shapes && !request.tension) return mode;
  AiryModeShape shape =
      airy_mode_shape(model, context_.statics, omega, stations, travel_times * omega);
  max_residual = std::max(max_residual, shape.residual);
  mode.s_m = stations;
  mode.w = std::move(shape.w);
  mode.u = std::move(shape.u);
  if (request.tension) mode.tension_n = std::move(shape.tension_n);
  normalise_inplane_mode(mode);
  mode.modal_mass_kg = inplane_modal_mass(mode, cable.mass_kg_per_m, cable.normal_mass_kg_per_m());
  if (!request.shapes) drop_shape_fields(mode);
  return mode;
}

// delta of the in-plane mode at omega: its shape and tension on nodes fine for the quadrature of
// modal_damping.hpp (the fast phase omega x travel time sets their spacing), whatever the
// request's stations.
double AiryNumerics::inplane_mode_decay_rate(const AiryModel& model, double omega) const {
  const SolveContext& c = context_;
  const DampingQuadrature quadrature =
      damping_quadrature(c.problem.cable.length_m, omega * model.travel_time);
  const Vector travel_times =
      transverse_travel_times(c.statics, c.problem.cable.normal_mass_kg_per_m(), quadrature.s_m);
  AiryModeShape shape =
      airy_mode_shape(model, c.statics, omega, quadrature.s_m, travel_times * omega);
  InplaneModeSamples samples;
  samples.u = std::move(shape.u);
  samples.w = std::move(shape.w);
  samples.tension_n = std::move(shape.tension_n);
  return inplane_decay_rate(quadrature, samples, DampedSection::of(c.problem));
}

// delta of the linear-tension string's mode at omega (its Bessel shape on the nodes).
double AiryNumerics::outofplane_mode_decay_rate(const TensionString& string, double omega) const {
  const DampingQuadrature quadrature =
      damping_quadrature(string.length, omega * string_travel_time(string, string.length));
  return outofplane_decay_rate(quadrature, string_mode_shape(string, omega, quadrature.s_m),
                               DampedSection::of(context_.problem));
}

// How the scan went, and the warning it calls for: a first root close to the spurious-root cutoff.
// (The count is not cross-checked with another solver's equation: airy stays independent.)
void AiryNumerics::add_scan_notes(const AiryRootScan& scan, SolverSummary& summary) const {
  const DimensionlessGroups& groups = context_.groups;
  const int found = static_cast<int>(scan.roots.size());
  summary.notes.push_back(fmt::format(
      "scan kL/pi in [{:.4g}, {:.4g}] ({} determinants): {} sign changes, {} close pairs found "
      "at |det| minima; roots below kL/pi = {:.4g} (spurious, WKB invalid) skipped; no proof of "
      "count",
      scan.cutoff_kl / kPi, (scan.roots.empty() ? scan.limit_kl : scan.roots.back()) / kPi,
      scan.evaluations, scan.sign_changes, scan.pairs_from_minima, scan.cutoff_kl / kPi));
  if (found == 0) return;
  if (scan.roots.front() < 1.1 * scan.cutoff_kl) {
    summary.warnings.push_back(fmt::format(
        "the first root kL/pi = {:.4g} lies within 10% of the spurious-root cutoff {:.4g}: it may "
        "be the model's spurious low root (eps = {:.3g} is large)",
        scan.roots.front() / kPi, scan.cutoff_kl / kPi, groups.eps));
  }
}

void AiryNumerics::set_inplane_outcome(int found,
                                       int count,
                                       const AiryRootScan& scan,
                                       double max_residual,
                                       SolverSummary& summary) const {
  const bool need_shape = context_.request.shapes || context_.request.tension;
  if (found < count) {
    summary.termination = Termination::NoConvergence;
    summary.message = fmt::format("No convergence: {} of {} in-plane roots below kL/pi = {:.4g}",
                                  found, count, scan.limit_kl / kPi);
    return;
  }
  summary.termination = Termination::Converged;
  summary.message =
      fmt::format("Converged: {} of {} in-plane roots of the Airy determinant to {} bits{}", found,
                  count, options_.tolerance_bits,
                  need_shape ? fmt::format(", max sigma_min/sigma_max {:.1e}", max_residual) : "");
}

ModalResult AiryNumerics::inplane_modes(int count) const {
  const SolveContext& c = context_;
  if (inplane_rounding_ > kMaxInplaneRounding) {
    ModalResult declined;
    declined.summary.termination = Termination::NotApplicable;
    declined.summary.message = fmt::format(
        "Not applicable: in plane, eps cos(phi_a) = {:.3g}: the Airy arguments grow as its inverse "
        "and their phases cancel, leaving the roots known to about {:.2g} relative (> {:.0e}; "
        "errors of 35 % to 100 % measured at eps cos(phi_a) <= 1e-10)",
        c.groups.eps * std::cos(c.groups.chord_angle_rad), inplane_rounding_, kMaxInplaneRounding);
    return declined;
  }
  const AiryModel model = build_airy_model(c.problem, c.statics, c.groups, options_.curvature_fit,
                                           options_.quadrature_panels);
  WorkMeter meter(c, "airy", "in-plane modes", count);
  const AiryRootScan scan = scan_airy_roots(model, c.groups, c.statics, count, options_, &meter);
  const bool need_shape = c.request.shapes || c.request.tension;
  const Vector stations = c.request.stations_m(c.problem.cable.length_m);
  const Vector travel_times =
      need_shape
          ? transverse_travel_times(c.statics, c.problem.cable.normal_mass_kg_per_m(), stations)
          : Vector();
  ModalResult result;
  double max_residual = 0.0;
  for (std::size_t i = 0; i < scan.roots.size(); ++i) {
    result.modes.push_back(inplane_mode(static_cast<int>(i) + 1, scan.roots[i], model, stations,
                                        travel_times, max_residual));
  }
  SolverSummary& summary = result.summary;
  summary.resolution = resolution();
  summary.operations = scan.evaluations;
  summary.max_error_estimate = inplane_error_estimate_;
  summary.max_residual = need_shape ? max_residual : -1.0;
  add_scan_notes(scan, summary);
  set_inplane_outcome(static_cast<int>(result.modes.size()), count, scan, max_residual, summary);
  mark_time_limit(meter, summary);
  if (c.problem.is_damped()) {
    std::vector<double> rates;
    for (const Mode& mode : result.modes)
      rates.push_back(inplane_mode_decay_rate(model, mode.omega_rad_s));
    apply_perturbed_damping(Plane::InPlane, result, rates, DampedSection::of(c.problem), c.groups);
  }
  return result;
}

ModalResult AiryNumerics::outofplane_modes() const {
  const SolveContext& c = context_;
  const FittedTensionString fitted = fit_tension_string(c.statics);
  const TensionString& string = fitted.string;
  const double deviation = fitted.deviation;
  const double estimate = linear_tension_error_bound(deviation) + root_error_;
  const int count = c.request.outofplane_modes;
  const Vector stations = c.request.stations_m(c.problem.cable.length_m);
  ModalResult result;
  for (int n = 1; n <= count; ++n) {
    result.modes.push_back(outofplane_mode(n, string_frequency(string, n, options_.tolerance_bits),
                                           string, stations, estimate));
  }
  result.proved_count_below_top = count;
  SolverSummary& summary = result.summary;
  summary.resolution = fmt::format("Bessel J0, Y0 in modulus-phase form, TOMS 748 to {} bits",
                                   options_.tolerance_bits);
  summary.termination = Termination::Converged;
  summary.max_error_estimate = estimate;
  summary.message = fmt::format(
      "Converged: {} out-of-plane modes of the linear-tension string (Bessel J0, Y0); the n-th "
      "root of the monotone Bessel phase is the n-th mode",
      count);
  summary.notes.push_back(fmt::format(
      "P = T/(1+e) made linear (ends {:.6g} N, {:.6g} N: the secant scaled to balance the "
      "deviation) deviates from the statics by at most {:.3g} relative: by the min-max principle "
      "the frequencies are within "
      "1/sqrt(1 - {:.3g}) - 1 = {:.3g}, reported as relative_error_estimate (+ root tolerance)",
      string.stiffness_a, string.stiffness_b, deviation, deviation, estimate - root_error_));
  if (c.problem.is_damped()) {
    std::vector<double> rates;
    for (const Mode& mode : result.modes)
      rates.push_back(outofplane_mode_decay_rate(string, mode.omega_rad_s));
    apply_perturbed_damping(Plane::OutOfPlane, result, rates, DampedSection::of(c.problem),
                            c.groups);
  }
  return result;
}

// The n-th out-of-plane mode at omega; with the Bessel shape when asked, normalised like every
// solver's, and no first-order tension (out-of-plane motion stretches the cable to second order).
Mode AiryNumerics::outofplane_mode(int n,
                                   double omega,
                                   const TensionString& string,
                                   const Vector& stations,
                                   double estimate) const {
  const SolveRequest& request = context_.request;
  Mode mode;
  mode.index = n;
  set_mode_frequency(mode, omega, context_.groups);
  mode.relative_error_estimate = estimate;
  if (!request.shapes && !request.tension) return mode;
  mode.s_m = stations;
  mode.v = string_mode_shape(string, omega, stations);
  normalise_outofplane_mode(mode);
  mode.modal_mass_kg = outofplane_modal_mass(mode, string.normal_mass);
  if (request.tension) {
    mode.tension_n = Vector::Zero(stations.size());
    mode.max_abs_tension_n = 0.0;
  }
  if (!request.shapes) drop_shape_fields(mode);
  return mode;
}

}  // namespace

SolverEntry make_airy_entry() {
  SolverEntry entry = make_solver_entry(
      "Triantafyllou's Airy-function solution (Grinfogel 1984, eqs. 12-16): roots of the 4x4 "
      "boundary determinant with exponentially scaled Ai, Bi; the paper's 'exact' reference. Out "
      "of plane: the string of linear tension, exactly in Bessel J0, Y0",
      airy_knobs(), [](const SolveContext& context, const AirySolverOptions& options) {
        return std::make_unique<AiryNumerics>(context, options);
      });
  entry.kind = SolverKind::Model;  // its error is the model's: each mode's estimate states it
  return entry;
}

}  // namespace internal

SolverOutput solve_airy(const Problem& problem,
                        const StaticSolution& statics,
                        const DimensionlessGroups& groups,
                        const SolveRequest& request,
                        const AirySolverOptions& options) {
  return internal::solve_with<internal::AiryNumerics>("airy", {problem, statics, groups, request},
                                                      options);
}

}  // namespace catena
