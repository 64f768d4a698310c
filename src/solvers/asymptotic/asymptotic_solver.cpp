// SPDX-License-Identifier: MIT
// Grinfogel's (1984) asymptotic solution for the taut inclined cable: eq. (21) frequencies, WKB
// out-of-plane frequencies, eqs. (34)/(28)/(37) shapes and eq. (38) tension. The notation and
// the bracketing argument that makes the root count exact are in asymptotic_solver.hpp.
#include "catena/solvers/asymptotic_solver.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/tools/roots.hpp>
#include <cmath>

#include "catena/core/error.hpp"
#include "solvers/asymptotic/asymptotic_formulas.hpp"
#include "solvers/asymptotic/asymptotic_wkb_string.hpp"
#include "solvers/common/knob_table.hpp"
#include "solvers/common/line_applicability.hpp"
#include "solvers/common/modal_damping.hpp"
#include "solvers/common/mode_tools.hpp"
#include "solvers/common/solver_driver.hpp"
#include "solvers/common/solver_entries.hpp"
#include "solvers/common/taut_cable_theory.hpp"

namespace catena {
namespace {

// 49/64 = (7/8)^2: the square of the near-cross-over slow amplitude 7/4 e1 over 2 (eq. 29).
constexpr double kCrossOverCoefficient = 49.0 / 64.0;

struct TanRoots {
  double minus;  // t_-(x) <= 0
  double plus;   // t_+(x) >= 0
};

// The two roots of (1 + c) t^2 + p t - c = 0, the form eq. (21) takes in t = tan x. The root of
// larger magnitude is formed without cancellation and the other from the product -c/(1+c), so
// that for c = 0 the small root is exactly 0 and the large one exactly -p (Irvine, bit for bit).
TanRoots tan_roots(double x, double c, double inv_lambda2) {
  const double p = 4.0 * x * x * x * inv_lambda2 - x;
  if (c == 0.0) return p > 0.0 ? TanRoots{-p, 0.0} : TanRoots{0.0, -p};
  // hypot: p^2 overflows for lambda^2 -> 0 (p ~ x^3 / lambda^2).
  const double root = std::hypot(p, 2.0 * std::sqrt(c * (1.0 + c)));
  if (p > 0.0) {
    const double minus = -(p + root) / (2.0 * (1.0 + c));
    return {minus, -c / ((1.0 + c) * minus)};
  }
  const double plus = (root - p) / (2.0 * (1.0 + c));
  return {-c / ((1.0 + c) * plus), plus};
}

// Root of sin x - t(x) cos x on [a, b], which is cos x (tan x - t(x)): strictly monotone there.
// When the end values do not bracket (t = 0 at x = n pi, where sin(n pi) rounds to +-1e-16), the
// root is that end point.
template <class TanFamily>
double family_root(double a, double b, TanFamily family, long& iterations) {
  auto g = [&](double x) { return std::sin(x) - family(x) * std::cos(x); };
  const double ga = g(a);
  const double gb = g(b);
  if (ga == 0.0) return a;
  if (gb == 0.0 || (ga > 0.0) == (gb > 0.0)) return std::abs(ga) < std::abs(gb) ? a : b;
  boost::uintmax_t max_iterations = 200;
  const auto bracket = boost::math::tools::toms748_solve(
      g, a, b, ga, gb, boost::math::tools::eps_tolerance<double>(53), max_iterations);
  iterations += static_cast<long>(max_iterations);
  return 0.5 * (bracket.first + bracket.second);
}

std::vector<double> eq21_roots_counted(
    int count, double eps, double phi_rad, double lambda2, long& iterations) {
  const double e1 = eps * std::sin(phi_rad);
  const double c = kCrossOverCoefficient * e1 * e1;
  const double inv_lambda2 = std::isinf(lambda2) ? 0.0 : 1.0 / lambda2;
  std::vector<double> roots;
  roots.reserve(static_cast<std::size_t>(std::max(count, 0)));
  // Branch n of tan, x in ((n - 1/2) pi, (n + 1/2) pi), holds the '-' root below n pi and the
  // '+' root above it; branch 0 holds only the spurious '+' root, skipped.
  for (int n = 1; static_cast<int>(roots.size()) < count; ++n) {
    const double low = (n - 0.5) * kPi;
    const double mid = n * kPi;
    const double high = (n + 0.5) * kPi;
    const double x_minus = family_root(
        low, mid, [&](double x) { return tan_roots(x, c, inv_lambda2).minus; }, iterations);
    roots.push_back(2.0 * x_minus);
    if (static_cast<int>(roots.size()) == count) break;
    const double x_plus = family_root(
        mid, high, [&](double x) { return tan_roots(x, c, inv_lambda2).plus; }, iterations);
    roots.push_back(2.0 * x_plus);
  }
  return roots;
}

void require(bool ok, const std::string& message) {
  if (!ok) throw InvalidInput(message);
}

}  // namespace

std::string to_string(AsymptoticShapeFormula formula) {
  return formula == AsymptoticShapeFormula::Eq28 ? "28" : "34";
}

std::optional<AsymptoticShapeFormula> parse_asymptotic_shape_formula(const std::string& text) {
  if (text == "34") return AsymptoticShapeFormula::Eq34;
  if (text == "28") return AsymptoticShapeFormula::Eq28;
  return std::nullopt;
}

namespace internal {

const KnobTable<AsymptoticSolverOptions>& asymptotic_knobs() {
  using O = AsymptoticSolverOptions;
  static const KnobTable<O> table("asymptotic", [] {
    std::vector<KnobBinding<O>> knobs{choice_knob(
        "shape_formula", &O::shape_formula,
        {{"34", AsymptoticShapeFormula::Eq34}, {"28", AsymptoticShapeFormula::Eq28}},
        "transverse shape formula: eq. (34) uniformly valid, or eq. (28) zeroth order")};
    for (auto& knob : taut_theory_knobs<O>("the WKB integral")) knobs.push_back(std::move(knob));
    return knobs;
  }());
  return table;
}

}  // namespace internal

void AsymptoticSolverOptions::validate() const {
  internal::asymptotic_knobs().validate(*this);
  internal::require_warning_below_max_eps("asymptotic", eps_warning_threshold, max_eps);
}

double grinfogel_eq21(double kl, double eps, double phi_rad, double lambda2) {
  const double x = 0.5 * kl;
  const double e1 = eps * std::sin(phi_rad);
  const double inv_lambda2 = std::isinf(lambda2) ? 0.0 : 1.0 / lambda2;
  const double main = std::sin(x) * (std::cos(x) * x * (kl * kl * inv_lambda2 - 1.0) + std::sin(x));
  return main - kCrossOverCoefficient * e1 * e1 * std::cos(kl);
}

std::vector<double> grinfogel_eq21_roots(int count, double eps, double phi_rad, double lambda2) {
  require(count >= 0, fmt::format("grinfogel_eq21_roots: count = {} must be >= 0", count));
  require(std::isfinite(eps) && eps >= 0.0,
          fmt::format("grinfogel_eq21_roots: eps = {} must be finite and >= 0", eps));
  require(std::isfinite(phi_rad), "grinfogel_eq21_roots: phi must be finite");
  require(lambda2 > 0.0, fmt::format("grinfogel_eq21_roots: lambda2 = {} must be > 0", lambda2));
  long iterations = 0;
  return eq21_roots_counted(count, eps, phi_rad, lambda2, iterations);
}

double first_axial_k_l(double eps, double phi_rad, double lambda2, double mass_ratio) {
  if (std::isinf(lambda2)) return kInfinity;
  return kPi * std::sqrt(lambda2 / mass_ratio) / (eps * std::cos(phi_rad));
}

std::vector<double> wkb_outofplane_omegas(const StaticSolution& statics,
                                          int count,
                                          int quadrature_panels) {
  require(
      quadrature_panels >= 1,
      fmt::format("wkb_outofplane_omegas: quadrature_panels = {} must be >= 1", quadrature_panels));
  const CableProperties& cable = statics.cable();
  const double M = cable.normal_mass_kg_per_m();
  // Slowness of transverse waves in the unstretched coordinate: sqrt(M / (T/(1+e))).
  auto slowness = [&](double s) {
    return std::sqrt(M * (1.0 + statics.strain(s)) / statics.tension_n(s));
  };
  const double L = cable.length_m;
  const double panel = L / quadrature_panels;
  double travel_time = 0.0;
  for (int i = 0; i < quadrature_panels; ++i) {
    travel_time +=
        boost::math::quadrature::gauss<double, 20>::integrate(slowness, i * panel, (i + 1) * panel);
  }
  std::vector<double> omegas;
  for (int n = 1; n <= count; ++n) omegas.push_back(n * kPi / travel_time);
  return omegas;
}

std::optional<std::string> asymptotic_not_applicable_reason(
    const Problem& problem,
    const StaticSolution& statics,
    const DimensionlessGroups& groups,
    const AsymptoticSolverOptions& options) {
  const double cos_phi = std::cos(groups.chord_angle_rad);
  // The theory linearises about a slightly stretched string: at a static strain T0/EA of order
  // one (lambda^2 << eps^2) its frequencies are off by the strain itself.
  const double strain = internal::static_strain(problem, groups);
  if (strain > internal::kMaxStaticStrain) {
    return fmt::format(
        "static strain T0/EA = {:.3g} > {:.1g}: the small-strain theory of eq. (21) does not apply "
        "(lambda^2 = {:.3g} is far below eps^2 = {:.3g})",
        strain, internal::kMaxStaticStrain, groups.lambda2, groups.eps * groups.eps);
  }
  if (!(statics.horizontal_force_n() > 0.0) || std::abs(cos_phi) < 1e-9) {
    return fmt::format(
        "vertical chord (H = {:.3g} N, phi_a = {:.6g} deg): lambda^2 = 0 and Grinfogel's eq. (21) "
        "degenerates; the theory covers inclined cables with |phi_a| < 90 deg",
        statics.horizontal_force_n(), groups.chord_angle_rad * 180.0 / kPi);
  }
  if (groups.eps > options.max_eps) {
    return fmt::format(
        "eps = W0 L / T0 = {:.4g} > max_eps = {:.4g}: the expansion in powers of eps is not "
        "meaningful for such a slack cable (its error is O(eps^2))",
        groups.eps, options.max_eps);
  }
  return std::nullopt;
}

namespace internal {
namespace {

// The numerics of the asymptotic solver for one problem: eq. (21) in plane, WKB out of plane.
class AsymptoticNumerics final : public SolverNumerics {
 public:
  AsymptoticNumerics(const SolveContext& context, const AsymptoticSolverOptions& options)
      : context_(context),
        options_(options),
        // Model error: O(eps^2) from the expansion, plus the static strain e0 = T0/EA that eq. (21)
        // leaves out of k = omega / sqrt(T0/M) (a pre-strained string is slower by 1/sqrt(1 + e0)).
        static_strain_(static_strain(context.problem, context.groups)),
        error_estimate_(context.groups.eps * context.groups.eps + 0.5 * static_strain_) {}

  std::optional<std::string> not_applicable() const override {
    if (auto reason = uniform_cable_only(context_.problem, "the taut-cable asymptotic expansion"))
      return reason;
    if (auto reason = no_seabed_contact(context_.statics, "the taut-cable asymptotic expansion"))
      return reason;
    return asymptotic_not_applicable_reason(context_.problem, context_.statics, context_.groups,
                                            options_);
  }

  // Light damping by first-order perturbation of the model's own modes (modal_damping.hpp).
  bool handles_damping() const override { return true; }

  void describe(SolverSummary& summary) const override;
  ModalResult modes(Plane plane, int count) override {
    return plane == Plane::InPlane ? inplane_modes(count) : outofplane_modes(count);
  }

 private:
  ModalResult inplane_modes(int count) const;
  ModalResult outofplane_modes(int count) const;
  Mode inplane_mode(int index, double kl, const Vector& stations) const;
  double eq38_tension(const AsymptoticModeShape& shape, double omega) const;
  double inplane_mode_decay_rate(double kl, double omega) const;
  double outofplane_mode_decay_rate(int n, double omega) const;
  void add_character_notes(const std::vector<double>& roots, SolverSummary& summary) const;

  const SolveContext& context_;
  AsymptoticSolverOptions options_;
  double static_strain_;
  double error_estimate_;
};

void AsymptoticNumerics::describe(SolverSummary& summary) const {
  const DimensionlessGroups& groups = context_.groups;
  summary.resolution = "closed form: eq. (21) roots to double precision (TOMS 748), WKB with " +
                       fmt::format("{} x 20-point Gauss-Legendre", options_.quadrature_panels);
  summary.notes.push_back(fmt::format(
      "model error O(eps^2): eps = {:.4g}, phi_a = {:.4g} deg, lambda^2 = {:.6g}, h = {:.4g}; "
      "every "
      "frequency carries relative_error_estimate = eps^2 + e0/2 = {:.3g} (e0 = T0/EA = {:.3g}, the "
      "static strain the theory neglects)",
      groups.eps, groups.chord_angle_rad * 180.0 / kPi, groups.lambda2, groups.mass_ratio,
      error_estimate_, static_strain_));
  if (groups.eps > options_.eps_warning_threshold) {
    summary.warnings.push_back(fmt::format(
        "eps = {:.4g} > {:.3g}: outside the region where the O(eps^2) expansion is meaningful; "
        "expect errors of order eps^2 = {:.2g} or worse (in the paper's eps = 0.49 table 'approx' "
        "and 'exact' differ by up to 0.029 in kL/pi)",
        groups.eps, options_.eps_warning_threshold, error_estimate_));
  }
  if (context_.problem.cable.is_inextensible()) {
    summary.notes.push_back(
        "inextensible cable: eq. (21) taken in the limit 1/lambda^2 = 0 (Irvine's inextensible "
        "shallow cable, symmetric modes tan x = x)");
  }
}

// Eq. (38): tau = -M omega^2 w_slow / alpha with w_slow = -(S2 + 7/4 e1) in the units of the
// shape functions and alpha = eps cos(phi_a) / L.
double AsymptoticNumerics::eq38_tension(const AsymptoticModeShape& shape, double omega) const {
  const CableProperties& cable = context_.problem.cable;
  return cable.normal_mass_kg_per_m() * omega * omega * shape.slow_amplitude * cable.length_m /
         (context_.groups.eps * std::cos(context_.groups.chord_angle_rad));
}

// delta of the in-plane mode of root kL: its shapes (34)/(28), (37) and tension (38) on nodes
// fine for the quadrature of modal_damping.hpp, whatever the request's stations.
double AsymptoticNumerics::inplane_mode_decay_rate(double kl, double omega) const {
  const CableProperties& cable = context_.problem.cable;
  const DimensionlessGroups& groups = context_.groups;
  const DampingQuadrature quadrature = damping_quadrature(cable.length_m, kl);
  AsymptoticModeShape shape =
      asymptotic_mode_shape(quadrature.s_m, cable.length_m, kl, groups.eps, groups.chord_angle_rad,
                            groups.lambda2, options_.shape_formula);
  InplaneModeSamples samples;
  samples.tension_n = Vector::Constant(quadrature.s_m.size(), eq38_tension(shape, omega));
  samples.u = std::move(shape.u);
  samples.w = std::move(shape.w);
  return inplane_decay_rate(quadrature, samples, DampedSection::of(context_.problem));
}

// delta of the n-th out-of-plane WKB mode (its phase runs through n pi along the cable).
double AsymptoticNumerics::outofplane_mode_decay_rate(int n, double omega) const {
  const DampingQuadrature quadrature = damping_quadrature(context_.problem.cable.length_m, n * kPi);
  return outofplane_decay_rate(quadrature,
                               wkb_outofplane_shape(context_.statics, quadrature.s_m, omega),
                               DampedSection::of(context_.problem));
}

// One in-plane mode of root kL: frequency, and on request the shapes (34)/(28)/(37) and the
// tension (38), normalised like every solver's.
Mode AsymptoticNumerics::inplane_mode(int index, double kl, const Vector& stations) const {
  const CableProperties& cable = context_.problem.cable;
  const DimensionlessGroups& groups = context_.groups;
  const SolveRequest& request = context_.request;
  Mode mode;
  mode.index = index;
  set_mode_frequency(mode, groups.omega_from_k_l_over_pi(kl / kPi), groups);
  mode.relative_error_estimate = error_estimate_;
  if (!request.shapes && !request.tension) return mode;
  const double eps = groups.eps, phi = groups.chord_angle_rad;
  const AsymptoticModeShape shape = asymptotic_mode_shape(stations, cable.length_m, kl, eps, phi,
                                                          groups.lambda2, options_.shape_formula);
  mode.s_m = stations;
  mode.w = shape.w;
  mode.u = shape.u;
  const double M = cable.normal_mass_kg_per_m();
  if (request.tension) {
    mode.tension_n = Vector::Constant(stations.size(), eq38_tension(shape, mode.omega_rad_s));
  }
  normalise_inplane_mode(mode);
  mode.modal_mass_kg = inplane_modal_mass(mode, cable.mass_kg_per_m, M);
  if (!request.shapes) drop_shape_fields(mode);
  return mode;
}

// Notes on each mode's character (symmetric-like, antisymmetric-like, hybrid near cross-over).
void AsymptoticNumerics::add_character_notes(const std::vector<double>& roots,
                                             SolverSummary& summary) const {
  const double eps = context_.groups.eps, phi = context_.groups.chord_angle_rad;
  const double lambda2 = context_.groups.lambda2;
  std::string character, hybrid;
  for (std::size_t i = 0; i < roots.size(); ++i) {
    const double kl = roots[i];
    // Roots alternate between the '-' family (even i) and the '+' family; the family that
    // carries Irvine's symmetric root is '-' above cross-over (kL > lambda) and '+' below.
    const bool above_cross_over = !std::isinf(lambda2) && kl * kl > lambda2;
    const bool symmetric_like = (i % 2 == 0) == above_cross_over;
    const double detuning = std::isinf(lambda2) ? -1.0 : kl * kl / lambda2 - 1.0;
    const bool in_hybrid_region = std::abs(detuning) < 2.0 * eps * std::abs(std::sin(phi));
    if (in_hybrid_region) hybrid += fmt::format("{}{}", hybrid.empty() ? "" : ", ", i + 1);
    character += fmt::format("{}{} {}", i ? ", " : "", i + 1,
                             in_hybrid_region ? "H" : (symmetric_like ? "S" : "A"));
  }
  summary.notes.push_back(
      "mode character (S symmetric-like, A antisymmetric-like, H hybrid: |k^2L^2/lambda^2 - 1| "
      "< 2 eps sin(phi_a)): " +
      character);
  if (!hybrid.empty()) {
    summary.notes.push_back(fmt::format(
        "modes in the hybrid (near-cross-over) region |k^2L^2/lambda^2 - 1| < 2 eps sin(phi_a): "
        "{} (there the eps^2 term of eq. (21) is leading order)",
        hybrid));
  }
}

ModalResult AsymptoticNumerics::inplane_modes(int count) const {
  const DimensionlessGroups& groups = context_.groups;
  ModalResult result;
  long iterations = 0;
  std::vector<double> roots =
      eq21_roots_counted(count, groups.eps, groups.chord_angle_rad, groups.lambda2, iterations);
  const double axial_kl =
      first_axial_k_l(groups.eps, groups.chord_angle_rad, groups.lambda2, groups.mass_ratio);
  // Eq. (21) assumes quasi-static stretching and has no axial modes, while the exact spectrum has
  // its first axial mode near axial_kl: every root above it is compared with the wrong index and
  // is off by the spacing of the modes (issue 32: mode 4 at kL/pi = 4, 8 % off, and mode 5 29 %
  // off, at lambda^2 = 0.1, strain 0.098, where the axial mode is at kL/pi = 3.69). Measured
  // against fe (taut_inclined phi 30 deg, lambda^2 0.1, 1, 10, strain 1e-3 to 0.098, 14 modes):
  // every root up to 0.97 of axial_kl is within the estimate, the first above it (1.04) is not. The
  // roots from kMaxAxialFraction of axial_kl on are not returned.
  constexpr double kMaxAxialFraction = 0.9;
  const auto first_beyond = std::find_if(
      roots.begin(), roots.end(), [&](double kl) { return kl >= kMaxAxialFraction * axial_kl; });
  const std::size_t declined = static_cast<std::size_t>(roots.end() - first_beyond);
  roots.erase(first_beyond, roots.end());
  const Vector stations = context_.request.stations_m(context_.problem.cable.length_m);
  for (std::size_t i = 0; i < roots.size(); ++i) {
    result.modes.push_back(inplane_mode(static_cast<int>(i) + 1, roots[i], stations));
  }
  result.proved_count_below_top = static_cast<int>(result.modes.size());
  SolverSummary& summary = result.summary;
  summary.termination = Termination::Converged;
  summary.message = fmt::format(
      "Converged: {} of {} in-plane roots of eq. (21), count proved by the one-root-per-tan-"
      "branch bracketing; top kL/pi = {:.6g}",
      result.modes.size(), count, roots.empty() ? 0.0 : roots.back() / kPi);
  summary.iterations = iterations;
  summary.max_error_estimate = error_estimate_;
  add_character_notes(roots, summary);
  if (declined > 0) {
    summary.termination = roots.empty() ? Termination::NotApplicable : Termination::NoConvergence;
    summary.message = fmt::format(
        "{}: {} of {} in-plane modes; the next root of eq. (21) lies at or above {} of the first "
        "axial mode kL/pi = {:.4g}, which eq. (21) lacks (quasi-static stretching): beyond it the "
        "exact spectrum holds the axial modes too, so its modes are not computed here",
        roots.empty() ? "Not applicable" : "No convergence", roots.size(), count, kMaxAxialFraction,
        axial_kl / kPi);
  }
  if (!roots.empty() && roots.back() > 0.25 * axial_kl) {
    summary.warnings.push_back(fmt::format(
        "top kL/pi = {:.4g} exceeds a quarter of the first axial mode kL/pi = {:.4g}: eq. (21) "
        "assumes quasi-static stretching and has no axial modes",
        roots.back() / kPi, axial_kl / kPi));
  }
  if (context_.problem.is_damped()) {
    std::vector<double> rates;
    for (std::size_t i = 0; i < roots.size(); ++i)
      rates.push_back(inplane_mode_decay_rate(roots[i], result.modes[i].omega_rad_s));
    apply_perturbed_damping(Plane::InPlane, result, rates, DampedSection::of(context_.problem),
                            groups);
  }
  return result;
}

ModalResult AsymptoticNumerics::outofplane_modes(int count) const {
  const double M = context_.problem.cable.normal_mass_kg_per_m();
  ModalResult result =
      wkb_outofplane_modes(context_.statics, context_.groups, context_.request, M, error_estimate_,
                           options_.quadrature_panels, "asymptotic");
  result.summary.message = fmt::format(
      "Converged: {} of {} out-of-plane WKB string modes omega_n = n pi / int sqrt(M(1+e)/T) ds",
      result.modes.size(), count);
  result.summary.max_error_estimate = error_estimate_;
  if (context_.problem.is_damped()) {
    std::vector<double> rates;
    for (const Mode& mode : result.modes)
      rates.push_back(outofplane_mode_decay_rate(mode.index, mode.omega_rad_s));
    apply_perturbed_damping(Plane::OutOfPlane, result, rates, DampedSection::of(context_.problem),
                            context_.groups);
  }
  return result;
}

}  // namespace

SolverEntry make_asymptotic_entry() {
  SolverEntry entry = make_solver_entry(
      "Grinfogel (1984) perturbation solution for taut inclined cables: eq. (21) frequencies "
      "(exact root count), WKB out-of-plane, shapes eq. (34)/(28)/(37), tension eq. (38); error "
      "O(eps^2)",
      asymptotic_knobs(), [](const SolveContext& context, const AsymptoticSolverOptions& options) {
        return std::make_unique<AsymptoticNumerics>(context, options);
      });
  entry.kind = SolverKind::Model;  // its error is the model's: each mode's estimate states it
  return entry;
}

}  // namespace internal

SolverOutput solve_asymptotic(const Problem& problem,
                              const StaticSolution& statics,
                              const DimensionlessGroups& groups,
                              const SolveRequest& request,
                              const AsymptoticSolverOptions& options) {
  return internal::solve_with<internal::AsymptoticNumerics>(
      "asymptotic", {problem, statics, groups, request}, options);
}

}  // namespace catena
