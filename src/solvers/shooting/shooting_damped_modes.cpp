// SPDX-License-Identifier: MIT
// The damped modes of one plane: see shooting_damped_modes.hpp.
#include "solvers/shooting/shooting_damped_modes.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "solvers/common/mode_tools.hpp"
#include "solvers/shooting/shooting_damped_integrator.hpp"
#include "solvers/shooting/shooting_damped_roots.hpp"
#include "solvers/shooting/shooting_profile.hpp"

namespace catena::internal {

namespace {

using Complex = std::complex<double>;

// Tighter tolerances of the error-estimate refinements, and the loose ones of the count (its
// phase has to be right to well within pi/4 only).
constexpr double kEstimateFactor = 0.01;
constexpr double kCountRelativeTolerance = 1e-5;
// The undamped starting roots' integration tolerance.
constexpr double kStartRelativeTolerance = 1e-6;
// The homotopy's shots (before the root is polished at the solver's tolerances).
constexpr double kStepRelativeTolerance = 1e-6;
// The count's region above the top root: this fraction of omega_top, or half the gap to the next
// root when that is smaller; and its right edge at Re lambda = this fraction of omega_top.
constexpr double kTopMargin = 0.05;
constexpr double kRightEdge = 0.05;
// Samples of D on the negative real axis when the count says real roots are there.
constexpr int kRealSamples = 64;

// A damped root with its error estimates.
struct DampedRoot {
  Complex lambda = 0.0;
  double omega_error = -1.0;
  double delta_error = -1.0;
};

class DampedPlane {
 public:
  DampedPlane(const ShootingCoefficients& k,
              const SolveContext& context,
              Plane plane,
              int count,
              const DampedPlaneSettings& settings)
      : k_(k),
        context_(context),
        plane_(plane),
        count_(count),
        settings_(settings),
        string_only_(plane == Plane::InPlane && is_straight_inextensible(k)),
        integration_plane_(string_only_ ? Plane::OutOfPlane : plane),
        integrator_(integration_plane_, k, settings.integrator),
        f_([this](Complex lambda, double factor) {
          const DampedShot shot = integrator_.shoot(lambda, factor);
          return DampedValue{shot.determinant, shot.log_scale};
        }) {}

  ModalResult run();

 private:
  std::vector<double> undamped_roots(int n);
  bool continue_roots(const std::vector<double>& omegas, std::size_t from);
  DampedRoot estimate(const ContinuedRoot& continued);
  void add_mode(const DampedRoot& root, std::vector<Mode>& modes) const;
  void set_shape(Mode& mode, Complex lambda) const;
  void count_region(double omega_top, double next_omega);
  void finish(ModalResult& result) const;

  const ShootingCoefficients& k_;
  const SolveContext& context_;
  Plane plane_;
  int count_;
  DampedPlaneSettings settings_;
  bool string_only_;
  Plane integration_plane_;
  mutable DampedShootingIntegrator integrator_;
  DampedFunction f_;
  long undamped_shots_ = 0;
  long undamped_steps_ = 0;
  long count_steps_ = 0;  // integration steps of the count's shots
  std::vector<std::string> warnings_;
  std::vector<std::string> lost_;       // reasons of lost continuations
  std::vector<ContinuedRoot> complex_;  // continued roots with Im lambda > 0
  int went_real_ = 0;                   // continuations that ended on the real axis
  std::vector<double> real_;            // real roots found in the region
  RootCount region_count_;
  std::string region_;  // the counted region, for the message
  int complex_in_region_ = 0;
};

// The n lowest undamped roots (multiplicities expanded) of the line without its damping: the
// undamped shot reads no damping coefficient. The bracket is loose: they only start the homotopy.
std::vector<double> DampedPlane::undamped_roots(int n) {
  // Loose tolerances: the roots only start the homotopy, whose last step refines them.
  IntegratorSettings loose = settings_.integrator;
  const double factor = std::max(1.0, kStartRelativeTolerance / loose.relative_tolerance);
  loose.relative_tolerance *= factor;
  loose.absolute_tolerance *= factor;
  ShootingIntegrator integrator(integration_plane_, k_, loose);
  RootFinderSettings rs = settings_.undamped;
  rs.relative_tolerance = loose.relative_tolerance;
  rs.root_tolerance = std::max(rs.root_tolerance, 1e-4);
  rs.error_estimate = false;
  rs.target = 1.0;
  ShootingRootFinder finder([&integrator](double w, double f) { return integrator.shoot(w, f); },
                            rs, settings_.first_guess_rad_s,
                            integration_plane_ == Plane::OutOfPlane);
  const std::vector<Root> roots = finder.find(n, warnings_);
  undamped_shots_ += finder.shots();
  undamped_steps_ += integrator.total_steps();
  std::vector<double> omegas;
  for (const Root& r : roots) {
    for (int j = 0; j < r.multiplicity; ++j) omegas.push_back(r.omega);
  }
  return omegas;
}

// Continues the roots omegas[from..] to t = 1; false when one was lost (reason in lost_).
bool DampedPlane::continue_roots(const std::vector<double>& omegas, std::size_t from) {
  ContinuationSettings cs;
  cs.tolerance = settings_.root_tolerance;
  cs.loose_factor = std::max(1.0, kStepRelativeTolerance / settings_.integrator.relative_tolerance);
  const auto set_scale = [this](double t) { integrator_.set_damping_scale(t); };
  for (std::size_t j = from; j < omegas.size(); ++j) {
    // The roots above the count are polished only if they turn out among the lowest (run()).
    cs.polish = j < std::size_t(count_);
    double gap = omegas[j];
    if (j > 0) gap = std::min(gap, omegas[j] - omegas[j - 1]);
    if (j + 1 < omegas.size()) gap = std::min(gap, omegas[j + 1] - omegas[j]);
    if (!(gap > 1e-6 * omegas[j])) gap = 1e-3 * omegas[j];  // a multiple root: small steps
    const ContinuedRoot c = continue_root(f_, set_scale, Complex(0.0, omegas[j]), gap, cs);
    if (!c.ok) {
      lost_.push_back(c.reason);
      continue;
    }
    // A root that became real is found again on the real axis (count_region).
    if (c.went_real) {
      ++went_real_;
    } else {
      ContinuedRoot upper = c;
      if (c.root.imag() < 0.0) upper.root = std::conj(c.root), upper.slope = std::conj(c.slope);
      complex_.push_back(upper);
    }
  }
  integrator_.set_damping_scale(1.0);
  return lost_.empty();
}

// The error estimates from one shot at 100x tighter tolerances at the root: the Newton step
// -D_tight(lambda) / D'(lambda) (D' from the last Muller parabola) is the root's move, and its
// real and imaginary parts, each relative to its own quantity (with the solver's floor, of |lambda|
// for delta), are the estimates of delta and omega_d. The root is moved by it.
DampedRoot DampedPlane::estimate(const ContinuedRoot& continued) {
  DampedRoot root;
  root.lambda = continued.root;
  if (!settings_.error_estimate || !(std::abs(continued.slope) > 0.0)) return root;
  const double floor = settings_.estimate_floor;
  ContinuedRoot at = continued;
  // As the undamped finder: an estimate of omega_d above the target finds the root again at 10x,
  // then 100x tighter tolerances (each with its own estimate at 100x tighter still).
  for (double factor = 1.0; factor >= 0.01; factor *= 0.1) {
    if (factor < 1.0) {
      const MullerResult again = secant_polish(f_, at.root, at.slope, at.slope_log_scale,
                                               settings_.root_tolerance, factor);
      if (!again.converged) break;
      at.root = again.root, at.slope = again.slope, at.slope_log_scale = again.slope_log_scale;
    }
    const DampedValue tight = f_(at.root, factor * kEstimateFactor);
    const Complex move =
        -tight.determinant * std::exp(tight.log_scale - at.slope_log_scale) / at.slope;
    root.lambda = at.root + move;
    const double omega = std::abs(root.lambda.imag()), delta = -root.lambda.real();
    root.omega_error = omega > 0.0 ? std::max(std::abs(move.imag()) / omega, floor) : -1.0;
    root.delta_error =
        delta > 0.0 ? std::max(std::abs(move.real()) / delta, floor * std::abs(root.lambda) / delta)
                    : -1.0;
    if (root.omega_error <= floor) break;
  }
  return root;
}

// Shape and tension at the root lambda: the null vector c of the complex Phi(L) (smallest right
// singular vector), the profile of Re and Im of the combination at the stations.
void DampedPlane::set_shape(Mode& mode, Complex lambda) const {
  const SolveRequest& request = context_.request;
  const Vector stations = request.stations_m(k_.length_m);
  const std::vector<double> stations_x = scaled_stations(stations, k_.length_m, false);
  const DampedShot shot = integrator_.shoot(lambda, 1.0, &stations_x);
  const int D = integration_plane_ == Plane::InPlane ? 2 : 1;
  const Eigen::JacobiSVD<Eigen::MatrixXcd> svd(shot.y_end.topRows(D), Eigen::ComputeFullV);
  const Eigen::VectorXcd c = svd.matrixV().col(D - 1);
  const ComplexProfile profile =
      evaluate_damped_profile(shot, c, k_, stations, false, integration_plane_);
  Profile re = profile.real, im = profile.imag;
  if (string_only_) re = string_as_inplane(re), im = string_as_inplane(im);
  mode.s_m = stations;
  if (plane_ == Plane::InPlane) {
    mode.u = re.u, mode.u_imag = im.u;
    mode.w = re.w, mode.w_imag = im.w;
    if (request.tension) mode.tension_n = re.tension, mode.tension_imag_n = im.tension;
    const double max_w = (re.w.cwiseAbs2() + im.w.cwiseAbs2()).maxCoeff();
    const double max_u = (re.u.cwiseAbs2() + im.u.cwiseAbs2()).maxCoeff();
    normalise_complex_mode(mode, max_w <= 1e-12 * max_u ? "u" : "w");
  } else {
    mode.v = re.v, mode.v_imag = im.v;
    normalise_complex_mode(mode, "v");
    if (request.tension) {
      // Out-of-plane motion carries no first-order dynamic tension.
      mode.tension_n = Vector::Zero(stations.size());
      mode.tension_imag_n = Vector::Zero(stations.size());
      mode.max_abs_tension_n = 0.0;
    }
  }
  if (!request.shapes) {
    drop_shape_fields(mode);
    mode.u_imag = mode.w_imag = mode.v_imag = mode.tension_imag_n = Vector();
  }
}

void DampedPlane::add_mode(const DampedRoot& root, std::vector<Mode>& modes) const {
  Mode mode;
  mode.index = static_cast<int>(modes.size()) + 1;
  set_damped_root(mode, root.lambda, context_.groups);
  mode.relative_error_estimate = root.omega_error;
  mode.decay_rate_error_estimate = root.delta_error;
  if (context_.request.shapes || context_.request.tension) set_shape(mode, root.lambda);
  modes.push_back(std::move(mode));
}

// The argument-principle count of the region below omega_top (1 + margin), margin at most half
// the gap to the next continued root, and the real roots in it when the count says there are.
void DampedPlane::count_region(double omega_top, double next_omega) {
  double gamma =
      0.0;  // the largest drag per mass: real roots of a line without c_a lie above -gamma
  for (const ShootingPiece& p : k_.all_pieces()) {
    gamma = std::max({gamma, p.damping_tangential / p.m, p.damping_normal / p.M});
  }
  double delta_max = std::max(1.25 * gamma, 0.1 * omega_top);
  for (const ContinuedRoot& c : complex_) delta_max = std::max(delta_max, -1.25 * c.root.real());
  double margin = kTopMargin;
  if (next_omega > omega_top) margin = std::min(margin, 0.5 * (next_omega - omega_top) / omega_top);
  const double top = omega_top * (1.0 + margin), sigma = kRightEdge * omega_top;
  const double factor =
      std::max(1.0, kCountRelativeTolerance / settings_.integrator.relative_tolerance);
  const long steps_before = integrator_.total_steps();
  region_count_ = count_roots(f_, sigma, delta_max, top, factor);
  count_steps_ = integrator_.total_steps() - steps_before;
  complex_in_region_ =
      static_cast<int>(std::count_if(complex_.begin(), complex_.end(), [&](const ContinuedRoot& c) {
        return c.root.imag() <= top && -c.root.real() <= delta_max;
      }));
  if (region_count_.ok && (region_count_.roots > 2 * complex_in_region_ || went_real_ > 0)) {
    real_ = real_roots(f_, delta_max, kRealSamples, settings_.root_tolerance, factor);
  }
  region_ = fmt::format("{:.6g} <= Re lambda <= {:.6g}, |Im lambda| <= {:.10g} 1/s", -delta_max,
                        sigma, top);
}

ModalResult DampedPlane::run() {
  ModalResult result;
  std::vector<double> omegas = undamped_roots(count_ + 1);
  continue_roots(omegas, 0);
  // Roots that became real leave fewer complex ones: continue more undamped roots.
  for (int round = 0; round < 3 && lost_.empty() && complex_.size() < std::size_t(count_ + 1);
       ++round) {
    const std::size_t done = omegas.size();
    omegas = undamped_roots(static_cast<int>(done + count_ + 1 - complex_.size()));
    if (omegas.size() <= done) break;
    continue_roots(omegas, done);
  }
  std::sort(complex_.begin(), complex_.end(), [](const ContinuedRoot& a, const ContinuedRoot& b) {
    return a.root.imag() < b.root.imag();
  });
  for (std::size_t j = 1; j < complex_.size(); ++j) {
    const Complex root = complex_[j].root;
    if (std::abs(root - complex_[j - 1].root) <= 1e-6 * std::abs(root)) {
      lost_.push_back(fmt::format("two continuations reached the same root {:.10g}{:+.10g}i 1/s",
                                  root.real(), root.imag()));
    }
  }
  if (!lost_.empty()) {
    result.summary.termination = Termination::NoConvergence;
    result.summary.message = fmt::format("No convergence ({} damped modes): {}", to_string(plane_),
                                         fmt::join(lost_, "; "));
    return result;
  }
  std::vector<DampedRoot> roots;
  for (std::size_t j = 0; j < complex_.size() && j < std::size_t(count_); ++j) {
    ContinuedRoot& c = complex_[j];
    if (!c.polished) {
      const MullerResult polished =
          secant_polish(f_, c.root, c.slope, c.slope_log_scale, settings_.root_tolerance, 1.0);
      if (!polished.converged) {
        result.summary.termination = Termination::NoConvergence;
        result.summary.message = fmt::format(
            "No convergence ({} damped modes): the root near {:.10g}{:+.10g}i 1/s did not "
            "converge at the solver's tolerances",
            to_string(plane_), c.root.real(), c.root.imag());
        return result;
      }
      c.root = polished.root, c.slope = polished.slope;
      c.slope_log_scale = polished.slope_log_scale, c.polished = true;
    }
    roots.push_back(estimate(c));
  }
  std::sort(roots.begin(), roots.end(), [](const DampedRoot& a, const DampedRoot& b) {
    return a.lambda.imag() < b.lambda.imag();
  });
  for (const DampedRoot& root : roots) add_mode(root, result.modes);
  const double top = result.modes.empty() ? 0.0 : result.modes.back().omega_rad_s;
  if (top > 0.0) {
    count_region(top, complex_.size() > roots.size() ? complex_[roots.size()].root.imag() : 0.0);
  }
  for (double r : real_) {
    // The slope of D on the real axis by a forward difference (Brent gives none).
    ContinuedRoot real;
    real.root = r;
    const double h = 1e-6 * std::abs(r);
    const DampedValue at = f_(r, 1.0), beside = f_(r + h, 1.0);
    real.slope_log_scale = at.log_scale;
    real.slope =
        (beside.determinant * std::exp(beside.log_scale - at.log_scale) - at.determinant) / h;
    DampedRoot root = estimate(real);
    root.lambda = Complex(root.lambda.real(), 0.0);
    root.omega_error = -1.0;
    add_mode(root, result.overdamped);
  }
  finish(result);
  return result;
}

void DampedPlane::finish(ModalResult& result) const {
  SolverSummary& summary = result.summary;
  const int found = static_cast<int>(result.modes.size());
  const int reals = static_cast<int>(real_.size());
  const bool proved =
      region_count_.ok && complex_in_region_ == found && region_count_.roots == 2 * found + reals;
  result.proved_count_below_top = proved ? found : -1;
  summary.termination =
      found == count_ && proved ? Termination::Converged : Termination::NoConvergence;
  double max_omega_error = -1.0, max_delta_error = -1.0;
  for (const Mode& mode : result.modes) {
    max_omega_error = std::max(max_omega_error, mode.relative_error_estimate);
    max_delta_error = std::max(max_delta_error, mode.decay_rate_error_estimate);
  }
  summary.max_error_estimate = std::max(max_omega_error, max_delta_error);
  std::string count_text;
  if (!region_count_.ok) {
    count_text = fmt::format(
        "the argument-principle count failed ({}): the number of roots is "
        "not proved",
        region_count_.reason);
  } else {
    count_text = fmt::format(
        "the argument principle counts {} roots in {} ({} complex pairs and {} real roots "
        "found){}",
        region_count_.roots, region_, complex_in_region_, reals,
        proved ? ": all returned"
               : ": the count does not match, a root not continued from the undamped modes may "
                 "lie in the region");
  }
  summary.message = fmt::format(
      "{}: {} of {} {} damped modes (omega_d = Im lambda), {} overdamped roots; {}; max relative "
      "error estimate {:.2e} (omega_d), {:.2e} (delta)",
      summary.termination == Termination::Converged ? "Converged" : "No convergence", found, count_,
      to_string(plane_), reals, count_text, max_omega_error, max_delta_error);
  summary.iterations = integrator_.total_shots() + undamped_shots_;
  summary.operations = integrator_.total_rhs_evaluations();
  summary.notes.push_back(fmt::format(
      "damped: {} undamped shots ({} steps) for the starting roots; {} damped shots ({} steps), "
      "of which {} ({} steps) for the count; roots continued from the undamped ones along the "
      "damping scale (Muller)",
      undamped_shots_, undamped_steps_, integrator_.total_shots(), integrator_.total_steps(),
      region_count_.evaluations, count_steps_));
  if (went_real_ > 0) {
    summary.notes.push_back(fmt::format("{} continued roots became real (overdamped)", went_real_));
  }
  for (const std::string& w : warnings_) summary.warnings.push_back(w);
}

}  // namespace

ModalResult damped_plane_modes(const ShootingCoefficients& k,
                               const SolveContext& context,
                               Plane plane,
                               int count,
                               const DampedPlaneSettings& settings) {
  DampedPlane solver(k, context, plane, count, settings);
  return solver.run();
}

}  // namespace catena::internal
