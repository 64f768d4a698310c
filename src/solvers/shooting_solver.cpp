// The `shooting` solver: frequencies by conjugate-point counting and root refinement on the
// principal solutions, shapes from the null vector, forced response by superposition
// (see include/catena/solvers/shooting_solver.hpp for the method).
#include "catena/solvers/shooting_solver.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <optional>

#include "catena/core/error.hpp"
#include "solvers/internal/knob_reader.hpp"
#include "solvers/internal/mode_tools.hpp"
#include "solvers/internal/shooting_integrator.hpp"
#include "solvers/internal/solver_entries.hpp"

namespace catena {

std::string to_string(ShootingMethod method) {
  return method == ShootingMethod::Adams ? "adams" : "bdf";
}

double ShootingSolverOptions::effective_absolute_tolerance() const {
  return absolute_tolerance > 0.0 ? absolute_tolerance : relative_tolerance / 100.0;
}

double ShootingSolverOptions::effective_root_tolerance() const {
  return root_tolerance > 0.0 ? root_tolerance : relative_tolerance;
}

void ShootingSolverOptions::validate() const {
  auto fail = [](const std::string& field, double value, const std::string& constraint) {
    throw InvalidInput(
        fmt::format("Invalid ShootingSolverOptions::{} = {}. Violated constraint: {}.", field,
                    value, constraint));
  };
  if (!(relative_tolerance >= 1e-14 && relative_tolerance <= 1e-2))
    fail("relative_tolerance", relative_tolerance, "1e-14 <= relative_tolerance <= 1e-2");
  if (!(absolute_tolerance >= 0.0 && absolute_tolerance <= 1e-2))
    fail("absolute_tolerance", absolute_tolerance, "0 <= absolute_tolerance <= 1e-2");
  if (!(root_tolerance >= 0.0 && root_tolerance <= 1e-2))
    fail("root_tolerance", root_tolerance, "0 <= root_tolerance <= 1e-2");
  if (max_steps < 100) fail("max_steps", static_cast<double>(max_steps), "max_steps >= 100");
  if (!(max_condition >= 2.0 && max_condition <= 1e8))
    fail("max_condition", max_condition, "2 <= max_condition <= 1e8");
}

namespace {

using internal::ShootingCoefficients;
using internal::ShootingFailure;
using internal::ShootingIntegrator;
using internal::Shot;

// One evaluation of the end function: the count of eigenvalues below omega, the end eigen-angles
// (for the count-aware root function) and the smooth end determinant.
struct Sample {
  int count = 0;
  double angle_min = 0.0;
  double angle_max = 0.0;
  double determinant = 0.0;
};

// internal::count_function on a stored sample.
double count_function(const Sample& sample, int n) {
  const double angle = sample.count < n ? sample.angle_max : sample.angle_min;
  return (sample.count - n) + (angle - kPi) / (2.0 * kPi);
}

// Brent's zero finder (Brent 1973, "zeroin"): inverse quadratic / secant steps safeguarded by
// bisection, one evaluation per iteration, and every step at least the tolerance long so that
// the bracket closes. Needs f(a) f(b) < 0; returns the final bracket (ascending), of width
// <= ~relative_tolerance * omega.
template <class Function>
std::pair<double, double> brent_zero(
    Function f, double a, double b, double fa, double fb, double relative_tolerance) {
  double c = a, fc = fa;
  double d = b - a, e = d;
  for (int iteration = 0; iteration < 300; ++iteration) {
    if ((fb > 0.0 && fc > 0.0) || (fb < 0.0 && fc < 0.0)) {
      c = a;
      fc = fa;
      d = e = b - a;
    }
    if (std::abs(fc) < std::abs(fb)) {
      a = b;
      b = c;
      c = a;
      fa = fb;
      fb = fc;
      fc = fa;
    }
    const double tol1 = 2.0 * std::numeric_limits<double>::epsilon() * std::abs(b) +
                        0.25 * relative_tolerance * std::abs(b);
    const double xm = 0.5 * (c - b);
    if (std::abs(xm) <= tol1 || fb == 0.0) break;
    if (std::abs(e) >= tol1 && std::abs(fa) > std::abs(fb)) {
      double p, q;
      const double s = fb / fa;
      if (a == c) {
        p = 2.0 * xm * s;
        q = 1.0 - s;
      } else {
        const double qa = fa / fc, r = fb / fc;
        p = s * (2.0 * xm * qa * (qa - r) - (b - a) * (r - 1.0));
        q = (qa - 1.0) * (r - 1.0) * (s - 1.0);
      }
      if (p > 0.0) q = -q;
      p = std::abs(p);
      if (2.0 * p < std::min(3.0 * xm * q - std::abs(tol1 * q), std::abs(e * q))) {
        e = d;
        d = p / q;
      } else {
        d = xm;
        e = d;
      }
    } else {
      d = xm;
      e = d;
    }
    a = b;
    fa = fb;
    b += std::abs(d) > tol1 ? d : std::copysign(tol1, xm);
    fb = f(b);
  }
  return {std::min(b, c), std::max(b, c)};
}

// A frequency found (a cluster of `multiplicity` equal frequencies for a double root).
struct Root {
  double omega = 0.0;
  int multiplicity = 1;
  double relative_error = 0.0;
  double residual = 0.0;  // smaller |determinant| at the final bracket ends
};

// Brackets and refines the lowest `num_modes` eigenfrequencies of one plane. Mode n is the root of
// the count-aware function h_n (shooting_integrator.hpp), bracketed by any two samples with
// counts < n and >= n: the sign of h_n certifies the count, so no mode can be skipped.
class ModeFinder {
 public:
  static constexpr long kMaxShots = 20000;
  static constexpr double kMaxPhaseDefect = 0.5;  // [rad]

  /// `scalar`: a one-component problem (out of plane, or a straight inextensible cable), whose
  /// continuous count is smooth across the eigenvalues.
  ModeFinder(ShootingIntegrator& integrator,
             const ShootingSolverOptions& options,
             double first_guess_rad_s,
             bool scalar)
      : integrator_(integrator),
        options_(options),
        first_guess_(first_guess_rad_s),
        scalar_(scalar) {}

  std::vector<Root> find(int num_modes, std::vector<std::string>& warnings) {
    std::vector<Root> roots;
    const Sample& zero = evaluate(0.0);
    if (zero.count != 0) {
      warnings.push_back(fmt::format("count at omega = 0 is {} (expected 0)", zero.count));
    }
    // An upper bound: the string estimate, enlarged until the count reaches num_modes.
    double top = first_guess_;
    for (int attempt = 0; evaluate(top).count < num_modes; ++attempt) {
      if (attempt > 200) throw ShootingFailure("no upper bound found for the requested modes");
      top *= 1.5;
    }
    const double tol = options_.effective_root_tolerance();
    int n = 1;
    while (n <= num_modes && scalar_) {
      // Out of plane the continuous count c = N + (abar - pi)/(2 pi) (Pruefer's angle) is smooth
      // and monotone in omega, and c = n exactly at the n-th eigenvalue: any two samples with
      // counts < n and >= n bracket it, and Brent converges on the nearly linear c - n at once.
      const auto [lo, hi] = bracket(n);
      roots.push_back(refine_scalar(n, lo, hi));
      ++n;
    }
    while (n <= num_modes) {
      const auto [lo, hi] = bracket(n);
      const Sample& a = samples_.at(lo);
      const Sample& b = samples_.at(hi);
      if (a.count == n - 1 && b.count == n && a.determinant * b.determinant < 0.0) {
        roots.push_back(refine(n, lo, hi));
        ++n;
      } else if (hi - lo <= tol * hi) {
        // Several eigenvalues inside a bracket narrower than the tolerance: a multiple root
        // (e.g. Irvine's cross-over), returned as that many modes.
        Root root;
        root.omega = 0.5 * (lo + hi);
        root.multiplicity = std::max(1, b.count - std::max(a.count, n - 1));
        if (a.count != n - 1) {
          warnings.push_back(fmt::format("mode {}: count {} just below the root (expected {})", n,
                                         a.count, n - 1));
        }
        if (b.count - a.count == 1) {
          warnings.push_back(fmt::format(
              "mode {}: the end determinant does not change sign across the count bracket "
              "[{:.17g}, {:.17g}] rad/s; located by bisection on the count",
              n, lo, hi));
        }
        root.relative_error = 0.5 * (hi - lo) / root.omega + 10.0 * options_.relative_tolerance;
        root.residual = std::min(std::abs(a.determinant), std::abs(b.determinant));
        roots.push_back(root);
        n += root.multiplicity;
      } else {
        evaluate(trial_point(n, lo, hi));
      }
    }
    const auto above = samples_.upper_bound(roots.back().omega);
    proved_count_ = above == samples_.end() ? -1 : above->second.count;
    return roots;
  }

  long shots() const { return shots_; }
  int proved_count() const { return proved_count_; }
  double max_phase_defect() const { return max_phase_defect_; }

 private:
  const Sample& evaluate(double omega) {
    auto it = samples_.find(omega);
    if (it != samples_.end()) return it->second;
    if (shots_ >= kMaxShots) throw ShootingFailure(fmt::format("more than {} shots", kMaxShots));
    Shot shot = integrator_.shoot(omega);
    ++shots_;
    if (shot.phase_defect > kMaxPhaseDefect) {
      // The integrated phase fixes the winding, so it must be right to well within pi: re-shoot
      // at 100x tighter tolerances (never seen in the tests; a safety net).
      shot = integrator_.shoot(omega, 0.01);
      ++shots_;
      ++phase_retries_;
    }
    max_phase_defect_ = std::max(max_phase_defect_, shot.phase_defect);
    const Sample sample{shot.count, shot.angle_min, shot.angle_max, shot.determinant};
    return samples_.emplace(omega, sample).first->second;
  }

  // Largest sampled omega with count < n, and the smallest sample above it with count >= n.
  std::pair<double, double> bracket(int n) const {
    double lo = 0.0;
    for (const auto& [omega, sample] : samples_) {
      if (sample.count < n) lo = std::max(lo, omega);
    }
    double hi = samples_.rbegin()->first;
    for (auto it = samples_.upper_bound(lo); it != samples_.end(); ++it) {
      if (it->second.count >= n) {
        hi = it->first;
        break;
      }
    }
    return {lo, hi};
  }

  // Next trial inside a count bracket: where the leading eigen-angle of the lower end is predicted
  // to reach its crossing (linear in omega through the origin of h_n, which is nearly linear for
  // string-like modes), kept within the middle 80% of the bracket; bisection otherwise.
  double trial_point(int n, double lo, double hi) const {
    const Sample& a = samples_.at(lo);
    const double mid = 0.5 * (lo + hi);
    if (a.count != n - 1 || lo <= 0.0) return mid;
    const double h_lo = count_function(a, n);  // in (-1, 0]
    auto below = samples_.find(lo);
    if (below == samples_.begin()) return mid;
    --below;
    if (below->second.count != n - 1) return mid;
    const double h_below = count_function(below->second, n);
    if (!(h_lo > h_below)) return mid;
    // Aim a little beyond the predicted crossing, so that the new point is likely the upper end.
    const double predicted = lo - h_lo * (lo - below->first) / (h_lo - h_below);
    const double aim = predicted + 0.02 * (predicted - lo) + 1e-9 * predicted;
    return std::clamp(aim, lo + 0.1 * (hi - lo), hi - 0.1 * (hi - lo));
  }

  Root refine_scalar(int n, double lo, double hi) {
    auto g = [this, n](double omega) { return count_function(evaluate(omega), n); };
    const auto [a, b] =
        brent_zero(g, lo, hi, count_function(samples_.at(lo), n),
                   count_function(samples_.at(hi), n), options_.effective_root_tolerance());
    const Sample& sa = evaluate(a);
    const Sample& sb = evaluate(b);
    Root root;
    root.omega = 0.5 * (a + b);
    root.residual = std::min(std::abs(sa.determinant), std::abs(sb.determinant));
    const double ga = count_function(sa, n), gb = count_function(sb, n);
    const double slope = (b > a) ? (gb - ga) / (b - a) : 0.0;
    double integration_error = 10.0 * options_.relative_tolerance * root.omega;
    if (options_.error_estimate && slope > 0.0) {
      const Shot tight = integrator_.shoot(root.omega, 0.1);
      ++shots_;
      const Sample st{tight.count, tight.angle_min, tight.angle_max, tight.determinant};
      const double here = ga + slope * (root.omega - a);
      integration_error = std::abs((count_function(st, n) - here) / slope);
    }
    root.relative_error = (0.5 * (b - a) + integration_error) / root.omega;
    return root;
  }

  Root refine(int n, double lo, double hi) {
    auto f = [this](double omega) { return evaluate(omega).determinant; };
    const auto [a, b] =
        brent_zero(f, lo, hi, samples_.at(lo).determinant, samples_.at(hi).determinant,
                   options_.effective_root_tolerance());
    const Sample& sa = evaluate(a);
    const Sample& sb = evaluate(b);
    Root root;
    root.omega = 0.5 * (a + b);
    root.residual = std::min(std::abs(sa.determinant), std::abs(sb.determinant));
    (void)n;
    const double slope = (b > a) ? (sb.determinant - sa.determinant) / (b - a) : 0.0;
    double integration_error = 10.0 * options_.relative_tolerance * root.omega;
    if (options_.error_estimate && slope != 0.0) {
      // The root of the end determinant at 10x tighter tolerances, one secant step from here.
      const Shot tight = integrator_.shoot(root.omega, 0.1);
      ++shots_;
      const double here = sa.determinant + slope * (root.omega - a);
      integration_error = std::abs((tight.determinant - here) / slope);
    }
    root.relative_error = (0.5 * (b - a) + integration_error) / root.omega;
    return root;
  }

  ShootingIntegrator& integrator_;
  const ShootingSolverOptions& options_;
  double first_guess_;
  bool scalar_;
  std::map<double, Sample> samples_;
  long shots_ = 0;
  int proved_count_ = -1;
  double max_phase_defect_ = 0.0;

 public:
  long phase_retries_ = 0;
};

// Transverse travel time int sqrt(M (1+e)/T) ds [s] (Simpson), for the first frequency guess.
double travel_time(const ShootingCoefficients& k) {
  constexpr int kIntervals = 64;
  const double h = k.length_m / kIntervals;
  double sum = 0.0;
  for (int i = 0; i <= kIntervals; ++i) {
    const double s = i * h;
    const double T = k.tension(s);
    const double value = std::sqrt(k.M * (1.0 + T * k.compliance) / T);
    const double weight = (i == 0 || i == kIntervals) ? 1.0 : (i % 2 ? 4.0 : 2.0);
    sum += weight * value;
  }
  return sum * h / 3.0;
}

internal::IntegratorSettings integrator_settings(const ShootingSolverOptions& options) {
  internal::IntegratorSettings settings;
  settings.relative_tolerance = options.relative_tolerance;
  settings.absolute_tolerance = options.effective_absolute_tolerance();
  settings.use_bdf = options.method == ShootingMethod::Bdf;
  settings.fixed_point = options.fixed_point_iteration;
  settings.max_steps = options.max_steps;
  settings.max_condition = options.max_condition;
  return settings;
}

// Displacement (and force) along the cable for the combination c of a shot's final basis.
struct Profile {
  Vector u, w, v, tension;
};

Profile evaluate_profile(const Shot& shot,
                         const Eigen::VectorXd& c,
                         const ShootingCoefficients& k,
                         const Vector& stations_m,
                         bool reversed,
                         Plane plane) {
  const Index n = stations_m.size();
  Profile p;
  if (plane == Plane::InPlane) {
    p.u.resize(n);
    p.w.resize(n);
    p.tension.resize(n);
  } else {
    p.v.resize(n);
  }
  for (Index j = 0; j < n; ++j) {
    // Shots from b record stations in reverse order.
    const std::size_t recorded = static_cast<std::size_t>(reversed ? n - 1 - j : j);
    const Eigen::VectorXd y = internal::combine_at_station(shot, recorded, c);
    const double s = stations_m[j];
    if (plane == Plane::InPlane) {
      const Vec2 phi = k.length_m * y.head<2>();
      const Vec2 force = k.t_ref * y.tail<2>();
      const Vec2 t = k.tangent(s);
      p.u[j] = phi.dot(t);
      p.w[j] = phi.dot(k.normal(s));
      p.tension[j] = force.dot(t);
    } else {
      p.v[j] = k.length_m * y[0];
    }
  }
  return p;
}

bool is_straight_inextensible(const ShootingCoefficients& k) {
  return k.H == 0.0 && k.compliance == 0.0;
}

// Out-of-plane profile of the transverse string re-labelled as the in-plane normal motion.
Profile string_as_inplane(const Profile& string) {
  Profile p;
  p.w = string.v;
  p.u = Vector::Zero(string.v.size());
  p.tension = Vector::Zero(string.v.size());
  return p;
}

std::vector<double> scaled_stations(const Vector& stations_m, double length_m, bool reversed) {
  std::vector<double> x(static_cast<std::size_t>(stations_m.size()));
  const Index n = stations_m.size();
  for (Index j = 0; j < n; ++j) {
    const double s = stations_m[reversed ? n - 1 - j : j];
    x[static_cast<std::size_t>(j)] = reversed ? 1.0 - s / length_m : s / length_m;
  }
  return x;
}

// Frequencies (and shapes, tension) of one plane.
ModalResult solve_plane(Plane plane,
                        int num_modes,
                        const ShootingCoefficients& k,
                        const DimensionlessGroups& groups,
                        const SolveRequest& request,
                        const ShootingSolverOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  ModalResult result;
  result.plane = plane;
  SolverSummary& summary = result.summary;
  summary.solver = "shooting";
  const char* plane_name = plane == Plane::InPlane ? "in-plane" : "out-of-plane";
  summary.resolution =
      fmt::format("CVODE {} rtol {:.1e} atol {:.1e}, root bracket {:.1e}",
                  to_string(options.method), options.relative_tolerance,
                  options.effective_absolute_tolerance(), options.effective_root_tolerance());
  // A straight (vertical, H = 0) inextensible cable: the axial direction is rigid, det Phi(L)
  // vanishes identically, and the in-plane problem is the transverse string alone, which is the
  // out-of-plane equation for the normal displacement.
  const bool string_only = plane == Plane::InPlane && is_straight_inextensible(k);
  if (string_only) {
    summary.notes.push_back(
        "straight inextensible cable: in-plane modes are the transverse string modes (normal "
        "displacement w, u = 0); the axial direction is rigid and its constant dynamic tension is "
        "statically indeterminate (reported as 0)");
  }
  const Plane integration_plane = string_only ? Plane::OutOfPlane : plane;
  ShootingIntegrator integrator(integration_plane, k, integrator_settings(options));
  // String estimate of the (n+1)-th frequency, nudged off the exact string values.
  const double guess = (num_modes + 1.37) * kPi / travel_time(k);
  ModeFinder finder(integrator, options, guess, integration_plane == Plane::OutOfPlane);
  std::vector<Root> roots;
  try {
    roots = finder.find(num_modes, summary.warnings);
  } catch (const ShootingFailure& failure) {
    summary.termination = Termination::NumericalFailure;
    summary.message = fmt::format("Numerical failure ({}): {}", plane_name, failure.what());
    summary.iterations = finder.shots();
    summary.operations = integrator.total_rhs_evaluations();
    return result;
  }

  // Roots closer than the integration can resolve form one (numerically) multiple root: its
  // null space is spanned by the smallest singular vectors of Phi(L) together.
  const double merge =
      1000.0 * std::max(options.relative_tolerance, options.effective_root_tolerance());
  std::vector<std::vector<Root>> clusters;
  for (const Root& root : roots) {
    if (!clusters.empty() && root.omega - clusters.back().back().omega <= merge * root.omega) {
      clusters.back().push_back(root);
    } else {
      clusters.push_back({root});
    }
  }
  if (clusters.size() < roots.size()) {
    summary.notes.push_back(fmt::format(
        "{} groups of frequencies closer than {:.1e} (relative): shapes from the joint null space, "
        "mass-orthogonalised",
        roots.size() - clusters.size(), merge));
  }

  const bool want_profile = request.shapes || request.tension;
  const Vector stations = request.stations_m(k.length_m);
  const std::vector<double> x = scaled_stations(stations, k.length_m, false);
  double max_error = 0.0, max_residual = 0.0;
  int index = 1;
  try {
    for (const std::vector<Root>& cluster : clusters) {
      int cluster_size = 0;
      double cluster_omega = 0.0;
      for (const Root& r : cluster) {
        cluster_size += r.multiplicity;
        cluster_omega += r.omega * r.multiplicity;
      }
      cluster_omega /= cluster_size;
      std::vector<Eigen::VectorXd> null_vectors;
      Shot shot;
      if (want_profile) {
        shot = integrator.shoot(cluster_omega, 1.0, &x);
        const int D = integration_plane == Plane::InPlane ? 2 : 1;
        const Eigen::MatrixXd phi_end = shot.y_end.topRows(D);
        const Eigen::JacobiSVD<Eigen::MatrixXd> svd(phi_end, Eigen::ComputeFullV);
        for (int j = 0; j < cluster_size && j < D; ++j) {
          null_vectors.push_back(svd.matrixV().col(D - 1 - j));
        }
        if (null_vectors.size() == 2) {
          // A double root has a two-dimensional null space: return a mass-orthogonal pair
          // (Gram-Schmidt in int (m u u' + M w w') ds on the stations).
          const Profile p1 = evaluate_profile(shot, null_vectors[0], k, stations, false, plane);
          const Profile p2 = evaluate_profile(shot, null_vectors[1], k, stations, false, plane);
          auto mass_product = [&](const Profile& a, const Profile& b) {
            const Vector density = k.m * a.u.cwiseProduct(b.u) + k.M * a.w.cwiseProduct(b.w);
            return internal::integrate_on_stations(stations, density);
          };
          const double m11 = mass_product(p1, p1);
          if (m11 > 0.0) null_vectors[1] -= (mass_product(p1, p2) / m11) * null_vectors[0];
        }
      }
      int member = 0;
      for (const Root& root : cluster) {
        for (int j = 0; j < root.multiplicity && index <= num_modes; ++j, ++index) {
          Mode mode;
          mode.index = index;
          internal::set_mode_frequency(mode, root.omega, groups);
          mode.relative_error_estimate = root.relative_error;
          if (want_profile && member < static_cast<int>(null_vectors.size())) {
            Profile p = evaluate_profile(shot, null_vectors[static_cast<std::size_t>(member++)], k,
                                         stations, false, integration_plane);
            if (string_only) p = string_as_inplane(p);
            mode.s_m = stations;
            if (plane == Plane::InPlane) {
              mode.u = p.u;
              mode.w = p.w;
              if (request.tension) mode.tension_n = p.tension;
              internal::normalise_inplane_mode(mode);
              mode.modal_mass_kg = internal::inplane_modal_mass(mode, k.m, k.M);
            } else {
              mode.v = p.v;
              internal::normalise_outofplane_mode(mode);
              mode.modal_mass_kg = internal::outofplane_modal_mass(mode, k.M);
              if (request.tension) {
                // Out-of-plane motion carries no first-order dynamic tension.
                mode.tension_n = Vector::Zero(stations.size());
                mode.max_abs_tension_n = 0.0;
              }
            }
            if (!request.shapes) {
              mode.s_m.resize(0);
              mode.u.resize(0);
              mode.w.resize(0);
              mode.v.resize(0);
              mode.tension_n.resize(0);
              mode.modal_mass_kg = -1.0;
            }
          }
          max_error = std::max(max_error, root.relative_error);
          max_residual = std::max(max_residual, root.residual);
          result.modes.push_back(std::move(mode));
        }
      }
    }
  } catch (const ShootingFailure& failure) {
    summary.warnings.push_back(fmt::format("shapes: {}", failure.what()));
  }

  result.proved_count_below_top = finder.proved_count();
  summary.iterations = finder.shots();
  summary.operations = integrator.total_rhs_evaluations();
  summary.max_error_estimate = max_error;
  summary.max_residual = max_residual;
  const int found = static_cast<int>(result.modes.size());
  summary.termination = found == num_modes ? Termination::Converged : Termination::NoConvergence;
  summary.message = fmt::format(
      "{}: {} of {} {} modes; conjugate-point count proves {} eigenvalues <= {:.10g} rad/s; max "
      "relative error estimate {:.2e}",
      found == num_modes ? "Converged" : "No convergence", found, num_modes, plane_name,
      result.proved_count_below_top, result.modes.empty() ? 0.0 : result.modes.back().omega_rad_s,
      max_error);
  summary.notes.push_back(fmt::format(
      "{} shots, {} CVODE steps, {} RHS evaluations; principal pair re-orthonormalised {} times "
      "(max log volume growth {:.3g}); max phase defect {:.2e} rad ({} re-shots for phase)",
      finder.shots(), integrator.total_steps(), integrator.total_rhs_evaluations(),
      integrator.total_reorthonormalisations(), integrator.max_log_growth(),
      finder.max_phase_defect(), finder.phase_retries_));
  summary.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

ForcedResponse forced_response(ShootingIntegrator& integrator,
                               const ShootingCoefficients& k,
                               const ForcedRequest& forced,
                               double omega,
                               const Vector& stations,
                               const ShootingSolverOptions& options,
                               bool& near_resonance) {
  ForcedResponse response;
  response.omega_rad_s = omega;
  Plane plane =
      forced.direction == ForcingDirection::OutOfPlane ? Plane::OutOfPlane : Plane::InPlane;
  const bool from_b = forced.end == CableEnd::A;  // start at the fixed end
  const double s_driven = forced.end == CableEnd::B ? k.length_m : 0.0;
  Eigen::VectorXd d(plane == Plane::InPlane ? 2 : 1);
  bool string_only = false;
  if (plane == Plane::OutOfPlane) {
    d[0] = forced.amplitude_m;
  } else {
    Vec2 direction;
    switch (forced.direction) {
      case ForcingDirection::Tangential:
        direction = k.tangent(s_driven);
        break;
      case ForcingDirection::Normal:
        direction = k.normal(s_driven);
        break;
      default:
        direction = forced.vector.normalized();
        break;
    }
    d = forced.amplitude_m * direction;
    if (is_straight_inextensible(k)) {
      // Only the normal part can move a straight inextensible cable; see solve_plane.
      const double axial = direction.dot(k.tangent(s_driven));
      if (std::abs(axial) > 1e-12) {
        response.diagnostic = fmt::format(
            "a straight inextensible cable cannot be displaced along its axis (axial part {:.3g} "
            "of the drive): no finite response",
            axial);
        return response;
      }
      string_only = true;
      plane = Plane::OutOfPlane;
      d = Eigen::VectorXd::Constant(1, forced.amplitude_m * direction.dot(k.normal(s_driven)));
    }
  }
  const int D = plane == Plane::InPlane ? 2 : 1;
  const std::vector<double> x = scaled_stations(stations, k.length_m, from_b);
  const Shot shot = integrator.shoot(omega, 1.0, &x, from_b);
  // Resonance: the end determinant is at the level of the integration error.
  const double resonance_level = 1e3 * options.relative_tolerance;
  if (std::abs(shot.determinant) <= resonance_level) {
    response.diagnostic = fmt::format(
        "forcing at a natural frequency (resonance): |det Phi(L)| / sqrt(det G) = {:.2e} <= "
        "{:.1e}, no finite response",
        std::abs(shot.determinant), resonance_level);
    return response;
  }
  near_resonance = std::abs(shot.determinant) < 1e-3;
  const Eigen::MatrixXd phi_end = shot.y_end.topRows(D);
  const Eigen::VectorXd c = phi_end.partialPivLu().solve(d / k.length_m);
  Profile p = evaluate_profile(shot, c, k, stations, from_b, plane);
  if (string_only) p = string_as_inplane(p);
  response.s_m = stations;
  if (plane == Plane::InPlane || string_only) {
    response.u = p.u;
    response.w = p.w;
    response.tension_n = p.tension;
  } else {
    response.v = p.v;
    response.tension_n = Vector::Zero(stations.size());
  }
  response.max_abs_tension_n = response.tension_n.cwiseAbs().maxCoeff();
  // The principal solutions carry a relative error ~rtol; the 2x2 solve for the combination
  // amplifies it by the condition of Phi(L), ~1 / |normalised det| (large near resonance).
  response.relative_error_estimate = options.relative_tolerance / std::abs(shot.determinant);
  return response;
}

}  // namespace

SolverOutput solve_shooting(const Problem& problem,
                            const StaticSolution& statics,
                            const DimensionlessGroups& groups,
                            const SolveRequest& request,
                            const ShootingSolverOptions& options) {
  options.validate();
  request.validate();
  const auto start = std::chrono::steady_clock::now();
  SolverOutput output;
  output.solver = "shooting";
  SolverSummary& summary = output.summary;
  summary.solver = "shooting";
  const ShootingCoefficients k = ShootingCoefficients::from_statics(statics);
  (void)problem;
  summary.resolution =
      fmt::format("CVODE {} rtol {:.1e} atol {:.1e}, root bracket {:.1e}",
                  to_string(options.method), options.relative_tolerance,
                  options.effective_absolute_tolerance(), options.effective_root_tolerance());
  summary.notes.push_back(
      "exact linearisation about the closed-form static catenary; A^{-1} used, so EA = inf is "
      "exact (no penalty); counting by the conjugate points of the principal solution (phase of "
      "det(Phi + iF), Morse index / Sturm)");

  bool all_converged = true;
  bool any_usable = false;
  long iterations = 0, operations = 0;
  double max_error = -1.0, max_residual = -1.0;
  auto absorb = [&](const ModalResult& plane) {
    all_converged = all_converged && plane.summary.termination == Termination::Converged;
    any_usable = any_usable || plane.summary.is_usable();
    iterations += std::max(0L, plane.summary.iterations);
    operations += std::max(0L, plane.summary.operations);
    max_error = std::max(max_error, plane.summary.max_error_estimate);
    max_residual = std::max(max_residual, plane.summary.max_residual);
    for (const auto& w : plane.summary.warnings) summary.warnings.push_back(w);
  };
  if (request.inplane_modes > 0) {
    output.inplane =
        solve_plane(Plane::InPlane, request.inplane_modes, k, groups, request, options);
    absorb(*output.inplane);
  }
  if (request.outofplane_modes > 0) {
    output.outofplane =
        solve_plane(Plane::OutOfPlane, request.outofplane_modes, k, groups, request, options);
    absorb(*output.outofplane);
  }
  if (request.forced) {
    const ForcedRequest& forced = *request.forced;
    const Plane plane =
        forced.direction == ForcingDirection::OutOfPlane ? Plane::OutOfPlane : Plane::InPlane;
    const Vector stations = request.stations_m(k.length_m);
    try {
      const Plane integration_plane = is_straight_inextensible(k) ? Plane::OutOfPlane : plane;
      ShootingIntegrator integrator(integration_plane, k, integrator_settings(options));
      for (double omega : forced.omegas_rad_s) {
        bool near_resonance = false;
        output.forced.push_back(
            forced_response(integrator, k, forced, omega, stations, options, near_resonance));
        if (!output.forced.back().diagnostic.empty()) {
          summary.warnings.push_back(fmt::format("forced response at {:.10g} rad/s: {}", omega,
                                                 output.forced.back().diagnostic));
        } else if (near_resonance) {
          summary.warnings.push_back(fmt::format(
              "forced response at {:.10g} rad/s is near a natural frequency (|det Phi(L)| / "
              "sqrt(det G) < 1e-3): the response is resonance-amplified and sensitive to omega",
              omega));
        }
      }
      iterations += static_cast<long>(forced.omegas_rad_s.size());
      operations += integrator.total_rhs_evaluations();
      any_usable = true;
    } catch (const ShootingFailure& failure) {
      all_converged = false;
      summary.warnings.push_back(fmt::format("forced response: {}", failure.what()));
    }
  }

  summary.iterations = iterations;
  summary.operations = operations;
  summary.max_error_estimate = max_error;
  summary.max_residual = max_residual;
  std::string parts;
  if (output.inplane) parts += output.inplane->summary.message;
  if (output.outofplane) parts += (parts.empty() ? "" : "; ") + output.outofplane->summary.message;
  if (request.forced) {
    parts += (parts.empty() ? "" : "; ") + fmt::format("{} of {} forced frequencies",
                                                       output.forced.size(),
                                                       request.forced->omegas_rad_s.size());
  }
  if (all_converged) {
    summary.termination = Termination::Converged;
    summary.message = parts.empty() ? "Converged: nothing was requested" : parts;
  } else {
    summary.termination = any_usable ? Termination::NoConvergence : Termination::NumericalFailure;
    summary.message = parts.empty() ? "Numerical failure" : parts;
  }
  summary.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return output;
}

namespace internal {

namespace {

ShootingSolverOptions read_knobs(const SolverKnobs& knobs) {
  KnobReader reader("shooting", knobs);
  ShootingSolverOptions options;
  options.relative_tolerance = reader.get_double("rtol", options.relative_tolerance);
  options.absolute_tolerance = reader.get_double("atol", options.absolute_tolerance);
  options.root_tolerance = reader.get_double("root_tolerance", options.root_tolerance);
  const std::string method = reader.get_string("method", to_string(options.method));
  if (method == "adams") {
    options.method = ShootingMethod::Adams;
  } else if (method == "bdf") {
    options.method = ShootingMethod::Bdf;
  } else {
    throw InvalidInput(
        fmt::format("{} = \"{}\": must be \"adams\" or \"bdf\"", reader.key("method"), method));
  }
  const std::string nonlinear = reader.get_string(
      "nonlinear_solver", options.fixed_point_iteration ? "fixed_point" : "newton");
  if (nonlinear == "newton") {
    options.fixed_point_iteration = false;
  } else if (nonlinear == "fixed_point") {
    options.fixed_point_iteration = true;
  } else {
    throw InvalidInput(fmt::format("{} = \"{}\": must be \"newton\" or \"fixed_point\"",
                                   reader.key("nonlinear_solver"), nonlinear));
  }
  options.max_steps = reader.get_integer("max_steps", options.max_steps);
  options.max_condition = reader.get_double("max_condition", options.max_condition);
  options.error_estimate = reader.get_bool("error_estimate", options.error_estimate);
  reader.reject_unknown();
  try {
    options.validate();
  } catch (const InvalidInput& error) {
    throw InvalidInput(fmt::format("[solvers.shooting]: {}", error.what()));
  }
  return options;
}

}  // namespace

SolverEntry make_shooting_entry() {
  SolverEntry entry;
  entry.name = "shooting";
  entry.description =
      "exact linear boundary-value solution: principal solutions integrated with SUNDIALS CVODE, "
      "modes counted by conjugate points (Morse index) and refined by Brent's method on a "
      "count-aware phase function; any sag, "
      "inclination, EA (inf exact), added mass";
  entry.knobs = {
      {"rtol", "CVODE relative tolerance, in [1e-14, 1e-2], default 1e-10"},
      {"atol", "CVODE absolute tolerance on the scaled state, in [0, 1e-2], default rtol/100"},
      {"root_tolerance", "relative width of the final frequency bracket, default rtol"},
      {"method", "\"adams\" (default) or \"bdf\""},
      {"nonlinear_solver", "\"newton\" (dense LU, analytic Jacobian; default) or \"fixed_point\""},
      {"max_steps", "maximum CVODE steps per shot, >= 100, default 500000"},
      {"max_condition", "re-orthonormalise when cond(Gram) exceeds this, in [2, 1e8], default 100"},
      {"error_estimate", "one extra shot per mode at 10x tighter tolerances, default true"},
  };
  entry.not_applicable_reason = [](const SolveContext& context) -> std::optional<std::string> {
    const StaticSolution& statics = context.statics;
    const double L = statics.cable().length_m;
    const double V_A = statics.vertical_force_a_n();
    const double V_B = statics.vertical_force_n(L);
    if (statics.horizontal_force_n() <= 0.0 && V_A * V_B <= 0.0) {
      return std::string("the static tension vanishes inside the cable (H = 0 and V changes sign)");
    }
    return std::nullopt;
  };
  entry.validate_knobs = [](const SolverKnobs& knobs) { read_knobs(knobs); };
  entry.run = [](const SolveContext& context, const SolverKnobs& knobs) {
    return solve_shooting(context.problem, context.statics, context.groups, context.request,
                          read_knobs(knobs));
  };
  return entry;
}

}  // namespace internal
}  // namespace catena
