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
constexpr double kCountRelativeTolerance = 1e-6;
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
  DampedRoot estimate(Complex lambda);
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
  std::vector<std::string> warnings_;
  std::vector<std::string> lost_;      // reasons of lost continuations
  std::vector<Complex> complex_;       // continued roots with Im lambda > 0
  int went_real_ = 0;                  // continuations that ended on the real axis
  std::vector<double> real_;           // real roots found in the region
  RootCount region_count_;
  std::string region_;                 // the counted region, for the message
  int complex_in_region_ = 0;
};

// The n lowest undamped roots (multiplicities expanded) of the line without its damping: the
// undamped shot reads no damping coefficient. The bracket is loose: they only start the homotopy.
std::vector<double> DampedPlane::undamped_roots(int n) {
  ShootingIntegrator integrator(integration_plane_, k_, settings_.integrator);
  RootFinderSettings rs = settings_.undamped;
  rs.root_tolerance = std::max(rs.root_tolerance, 1e-7);
  rs.error_estimate = false;
  rs.target = 1.0;
  ShootingRootFinder finder([&integrator](double w, double f) { return integrator.shoot(w, f); },
                            rs, settings_.first_guess_rad_s,
                            integration_plane_ == Plane::OutOfPlane);
  const std::vector<Root> roots = finder.find(n, warnings_);
  undamped_shots_ += finder.shots();
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
  const auto set_scale = [this](double t) { integrator_.set_damping_scale(t); };
  for (std::size_t j = from; j < omegas.size(); ++j) {
    double gap = omegas[j];
    if (j > 0) gap = std::min(gap, omegas[j] - omegas[j - 1]);
    if (j + 1 < omegas.size()) gap = std::min(gap, omegas[j + 1] - omegas[j]);
    if (!(gap > 1e-6 * omegas[j])) gap = 1e-3 * omegas[j];  // a multiple root: small steps
    const ContinuedRoot c = continue_root(f_, set_scale, Complex(0.0, omegas[j]), gap, cs);
    if (!c.ok) {
      lost_.push_back(c.reason);
      continue;
    }
    if (std::abs(c.root.imag()) <= 1e-8 * std::abs(c.root)) {
      ++went_real_;
    } else {
      complex_.push_back(Complex(c.root.real(), std::abs(c.root.imag())));
    }
  }
  integrator_.set_damping_scale(1.0);
  return lost_.empty();
}

// The root found again at 100x tighter tolerances: the estimates are the changes of omega_d and
// of delta, each relative to itself, with the solver's floor (of |lambda| for delta).
DampedRoot DampedPlane::estimate(Complex lambda) {
  DampedRoot root;
  root.lambda = lambda;
  if (!settings_.error_estimate) return root;
  const double radius = 1e-3 * std::abs(lambda);
  const MullerResult tight = muller_root(f_, lambda, 1e-6 * std::abs(lambda),
                                         settings_.root_tolerance, kEstimateFactor, radius);
  if (!tight.converged) {
    warnings_.push_back(fmt::format(
        "root {:.10g}{:+.10g}i 1/s: no estimate (the refinement at tighter tolerances did not "
        "converge)",
        lambda.real(), lambda.imag()));
    return root;
  }
  root.lambda = tight.root;
  const double floor = settings_.estimate_floor;
  const double omega = std::abs(tight.root.imag()), delta = -tight.root.real();
  if (omega > 0.0) {
    root.omega_error = std::max(std::abs(tight.root.imag() - lambda.imag()) / omega, floor);
  }
  if (delta > 0.0) {
    root.delta_error = std::max(std::abs(tight.root.real() - lambda.real()) / delta,
                                floor * std::abs(tight.root) / delta);
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
  // The real and imaginary parts as one-column shots for evaluate_profile (linear in y).
  Shot parts[2];
  for (std::size_t j = 0; j < shot.station_y.size(); ++j) {
    const Eigen::VectorXcd y = combine_damped_at_station(shot, j, c);
    parts[0].station_y.emplace_back(y.real());
    parts[1].station_y.emplace_back(y.imag());
    parts[0].station_segment.push_back(0);
    parts[1].station_segment.push_back(0);
  }
  const Eigen::VectorXd one = Eigen::VectorXd::Ones(1);
  Profile re = evaluate_profile(parts[0], one, k_, stations, false, integration_plane_);
  Profile im = evaluate_profile(parts[1], one, k_, stations, false, integration_plane_);
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
  double gamma = 0.0;  // the largest drag per mass: real roots of a line without c_a lie above -gamma
  for (const ShootingPiece& p : k_.all_pieces()) {
    gamma = std::max({gamma, p.damping_tangential / p.m, p.damping_normal / p.M});
  }
  double delta_max = std::max(1.25 * gamma, 0.1 * omega_top);
  for (const Complex& root : complex_) delta_max = std::max(delta_max, -1.25 * root.real());
  double margin = kTopMargin;
  if (next_omega > omega_top) margin = std::min(margin, 0.5 * (next_omega - omega_top) / omega_top);
  const double top = omega_top * (1.0 + margin), sigma = kRightEdge * omega_top;
  const double factor =
      std::max(1.0, kCountRelativeTolerance / settings_.integrator.relative_tolerance);
  region_count_ = count_roots(f_, sigma, delta_max, top, factor);
  complex_in_region_ = static_cast<int>(std::count_if(
      complex_.begin(), complex_.end(),
      [&](const Complex& r) { return r.imag() <= top && -r.real() <= delta_max; }));
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
  std::sort(complex_.begin(), complex_.end(),
            [](const Complex& a, const Complex& b) { return a.imag() < b.imag(); });
  for (std::size_t j = 1; j < complex_.size(); ++j) {
    if (std::abs(complex_[j] - complex_[j - 1]) <= 1e-6 * std::abs(complex_[j])) {
      lost_.push_back(fmt::format("two continuations reached the same root {:.10g}{:+.10g}i 1/s",
                                  complex_[j].real(), complex_[j].imag()));
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
    roots.push_back(estimate(complex_[j]));
  }
  std::sort(roots.begin(), roots.end(), [](const DampedRoot& a, const DampedRoot& b) {
    return a.lambda.imag() < b.lambda.imag();
  });
  for (const DampedRoot& root : roots) add_mode(root, result.modes);
  const double top = result.modes.empty() ? 0.0 : result.modes.back().omega_rad_s;
  if (top > 0.0) {
    count_region(top, complex_.size() > roots.size() ? complex_[roots.size()].imag() : 0.0);
  }
  for (double r : real_) {
    DampedRoot root = estimate(Complex(r, 0.0));
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
  const bool proved = region_count_.ok && complex_in_region_ == found &&
                      region_count_.roots == 2 * found + reals;
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
    count_text = fmt::format("the argument-principle count failed ({}): the number of roots is "
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
      summary.termination == Termination::Converged ? "Converged" : "No convergence", found,
      count_, to_string(plane_), reals, count_text, max_omega_error, max_delta_error);
  summary.iterations = integrator_.total_shots() + undamped_shots_;
  summary.operations = integrator_.total_rhs_evaluations();
  summary.notes.push_back(fmt::format(
      "damped: {} undamped shots (starting roots), {} damped shots ({} for the count), {} "
      "integration steps; roots continued from the undamped ones along the damping scale (Muller)",
      undamped_shots_, integrator_.total_shots(), region_count_.evaluations,
      integrator_.total_steps()));
  if (went_real_ > 0) {
    summary.notes.push_back(
        fmt::format("{} continued roots became real (overdamped)", went_real_));
  }
  for (const std::string& w : warnings_) summary.warnings.push_back(w);
}

}  // namespace

ModalResult damped_plane_modes(const ShootingCoefficients& k,
                               const SolveContext& context,
                               Plane plane,
                               int count,
                               const DampedPlaneSettings& settings,
                               WorkMeter* meter) {
  (void)meter;
  DampedPlane solver(k, context, plane, count, settings);
  return solver.run();
}

}  // namespace catena::internal
