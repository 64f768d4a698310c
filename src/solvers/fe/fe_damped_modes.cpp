// SPDX-License-Identifier: MIT
// The damped modes of one fe plane: see fe_damped_modes.hpp and docs/explanation/methods/fe.md,
// "Damping".
#include "solvers/fe/fe_damped_modes.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <limits>
#include <string>
#include <vector>

#include "catena/solvers/fe_solver.hpp"
#include "solvers/common/mode_tools.hpp"
#include "solvers/fe/fe_extrapolation.hpp"
#include "solvers/fe/fe_rayleigh_quotient.hpp"
#include "solvers/fe/fe_shapes.hpp"
#include "solvers/fe/fe_summary.hpp"

namespace catena::internal {
namespace {

using Clock = std::chrono::steady_clock;
using Complex = std::complex<double>;
double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The free nodes of a chain of `elements` restricted to those of a chain of `coarse` (a divisor).
Eigen::MatrixXcd restrict_to_nodes(const Eigen::MatrixXcd& vectors,
                                   int elements,
                                   int coarse,
                                   int per_node) {
  const int ratio = elements / coarse;
  Eigen::MatrixXcd out(per_node * (coarse - 1), vectors.cols());
  for (int i = 1; i < coarse; ++i)
    out.middleRows(per_node * (i - 1), per_node) =
        vectors.middleRows(per_node * (i * ratio - 1), per_node);
  return out;
}

// The underdamped roots a level kept and then its spare ones (fe_quadratic_eigen.hpp): the
// candidates of the pairing across levels, column j.
Eigen::MatrixXcd candidate_vectors(const FeDampedEigenSolution& solution) {
  Eigen::MatrixXcd all(solution.vectors.rows(),
                       solution.vectors.cols() + solution.spare_vectors.cols());
  all << solution.vectors, solution.spare_vectors;
  return all;
}
Complex candidate_root(const FeDampedEigenSolution& solution, int j) {
  const auto kept = static_cast<int>(solution.roots.size());
  return j < kept ? solution.roots[j] : solution.spare_roots[j - kept];
}
Eigen::VectorXcd candidate_vector(const FeDampedEigenSolution& solution, int j) {
  const auto kept = static_cast<int>(solution.vectors.cols());
  return j < kept ? Eigen::VectorXcd(solution.vectors.col(j))
                  : Eigen::VectorXcd(solution.spare_vectors.col(j - kept));
}

// Greedy pairing by the complex MAC |a^H b|^2 / (|a|^2 |b|^2), best pair first (as match_modes);
// `macs` receives the MAC of each pair.
std::vector<int> match_complex(const Eigen::MatrixXcd& a,
                               const Eigen::MatrixXcd& b,
                               std::vector<double>& macs) {
  const Eigen::MatrixXcd cross = a.adjoint() * b;
  const auto n = static_cast<int>(a.cols());
  std::vector<int> result(static_cast<std::size_t>(n), -1);
  macs.assign(static_cast<std::size_t>(n), 0.0);
  std::vector<bool> used(static_cast<std::size_t>(b.cols()), false);
  for (int assigned = 0; assigned < n; ++assigned) {
    double best = -1.0;
    int bi = -1, bj = -1;
    for (int i = 0; i < n; ++i) {
      if (result[static_cast<std::size_t>(i)] >= 0) continue;
      for (int j = 0; j < b.cols(); ++j) {
        if (used[static_cast<std::size_t>(j)]) continue;
        const double norms = a.col(i).squaredNorm() * b.col(j).squaredNorm();
        const double mac = norms > 0.0 ? std::norm(cross(i, j)) / norms : 0.0;
        if (mac > best) {
          best = mac;
          bi = i;
          bj = j;
        }
      }
    }
    result[static_cast<std::size_t>(bi)] = bj;
    macs[static_cast<std::size_t>(bi)] = best;
    used[static_cast<std::size_t>(bj)] = true;
  }
  return result;
}

// A pair across levels below this MAC is not the same mode: the reference root is then not
// resolved by the meshes (damped_mode). Paired modes of a resolved spectrum agree to 1 - O(h^2).
constexpr double kMinLevelMac = 0.9;

// The pairing of the finest main mesh's roots with every level's candidates (kept and spare
// roots: a poorly resolved root crosses the cut at `modes` from level to level), and the
// smallest MAC each reference root met on any level.
FeModeMatches match_damped_levels(const FeLevels& levels,
                                  const FePlan& plan,
                                  Plane plane,
                                  int available,
                                  std::vector<double>& worst_mac) {
  const FeLevel& reference = levels[static_cast<std::size_t>(plan.main_fine)][0];
  const int per_node = plane == Plane::InPlane ? 2 : 1;
  const Eigen::MatrixXcd ref = reference.damped.at(plane).vectors.leftCols(available);
  FeModeMatches matches(levels.size(), std::vector<std::vector<int>>(plan.penalties()));
  worst_mac.assign(static_cast<std::size_t>(available), 1.0);
  for (std::size_t m = 0; m < levels.size(); ++m) {
    for (std::size_t k = 0; k < plan.penalties(); ++k) {
      const FeLevel& level = levels[m][k];
      const Eigen::MatrixXcd other = candidate_vectors(level.damped.at(plane));
      const int common = std::min(reference.chain.elements, level.chain.elements);
      std::vector<double> macs;
      matches[m][k] =
          match_complex(restrict_to_nodes(ref, reference.chain.elements, common, per_node),
                        restrict_to_nodes(other, level.chain.elements, common, per_node), macs);
      for (std::size_t i = 0; i < macs.size(); ++i) worst_mac[i] = std::min(worst_mac[i], macs[i]);
    }
  }
  return matches;
}

// omega_d (part 0) or delta (part 1) of reference root i on every level.
std::vector<std::vector<double>> level_parts(
    const FeLevels& levels, const FeModeMatches& matches, Plane plane, int i, int part) {
  std::vector<std::vector<double>> values(levels.size());
  for (std::size_t m = 0; m < levels.size(); ++m) {
    for (std::size_t k = 0; k < levels[m].size(); ++k) {
      const Complex root =
          candidate_root(levels[m][k].damped.at(plane), matches[m][k][static_cast<std::size_t>(i)]);
      values[m].push_back(part == 0 ? root.imag() : -root.real());
    }
  }
  return values;
}

// The rounding of the levels' element-wise quotients for root i (fe_rayleigh_quotient.hpp),
// relative on lambda^2 hence halved, times what the extrapolations amplify it by, as
// rounding_estimate does for an undamped mode; plus the polished pairs' backward error.
double damped_rounding(
    const FePlan& plan, const FeLevels& levels, const FeModeMatches& matches, Plane plane, int i) {
  double largest = 0.0;
  for (std::size_t m = 0; m < levels.size(); ++m) {
    for (std::size_t k = 0; k < levels[m].size(); ++k) {
      const FeLevel& level = levels[m][k];
      const FeDampedEigenSolution& damped = level.damped.at(plane);
      const Vector re = candidate_vector(damped, matches[m][k][static_cast<std::size_t>(i)]).real();
      largest =
          std::max({largest,
                    element_rayleigh_quotient(level.chain, plane, re, level.matrices.at(plane).mass)
                        .relative_rounding,
                    damped.max_backward_error});
    }
  }
  const double mesh_gain = plan.richardson && plan.has_coarse() ? 5.0 / 3.0 : 1.0;
  const double kappa_gain = plan.inextensible ? 3.0 : 1.0;
  return 0.5 * largest * mesh_gain * kappa_gain;
}

// Linear extrapolation to kappa = 0 of two complex modes (a at kappa, b at 2 kappa): 2 a - alpha
// b with alpha the complex least-squares factor aligning b to a; renormalised.
void extrapolate_complex_mode_in_kappa(Mode& a, const Mode& b) {
  auto stack = [](const Mode& mode) {
    Eigen::VectorXcd all(mode.u.size() + mode.w.size() + mode.v.size());
    Eigen::Index at = 0;
    for (const auto& [re, im] : {std::pair{&mode.u, &mode.u_imag}, std::pair{&mode.w, &mode.w_imag},
                                 std::pair{&mode.v, &mode.v_imag}}) {
      for (Eigen::Index j = 0; j < re->size(); ++j) all[at++] = Complex((*re)[j], (*im)[j]);
    }
    return all;
  };
  const Eigen::VectorXcd va = stack(a), vb = stack(b);
  const double denominator = vb.squaredNorm();
  if (denominator == 0.0) return;
  const Complex alpha = vb.dot(va) / denominator;  // vb^H va
  auto combine = [alpha](Vector& re, Vector& im, const Vector& yre, const Vector& yim) {
    if (!re.size() || re.size() != yre.size()) return;
    for (Eigen::Index j = 0; j < re.size(); ++j) {
      const Complex x = 2.0 * Complex(re[j], im[j]) - alpha * Complex(yre[j], yim[j]);
      re[j] = x.real();
      im[j] = x.imag();
    }
  };
  combine(a.u, a.u_imag, b.u, b.u_imag);
  combine(a.w, a.w_imag, b.w, b.w_imag);
  combine(a.v, a.v_imag, b.v, b.v_imag);
  combine(a.tension_n, a.tension_imag_n, b.tension_n, b.tension_imag_n);
  normalise_complex_mode(a, a.normalised_by);
}

struct DampedPlaneInput {
  const SolveContext& context;
  const FePlan& plan;
  const FeLevels& levels;
  Plane plane;
};

// Shapes and tension from the finest main mesh (extrapolated in kappa when penalised).
void attach_damped_shape(const DampedPlaneInput& in,
                         bool overdamped,
                         int first_column,
                         int second_column,
                         Complex lambda,
                         const Vector& stations,
                         Mode& mode) {
  const SolveRequest& request = in.context.request;
  const auto fine = static_cast<std::size_t>(in.plan.main_fine);
  auto level_mode = [&](std::size_t k, int column) {
    const FeLevel& level = in.levels[fine][k];
    const FeDampedEigenSolution& solution = level.damped.at(in.plane);
    const Eigen::VectorXcd vector = overdamped ? Eigen::VectorXcd(solution.real_vectors.col(column))
                                               : candidate_vector(solution, column);
    return damped_mode_on_stations(in.plane, level.chain, vector, lambda, stations,
                                   in.context.statics, request.tension);
  };
  Mode shaped = level_mode(0, first_column);
  if (in.plan.inextensible) extrapolate_complex_mode_in_kappa(shaped, level_mode(1, second_column));
  mode.normalised_by = shaped.normalised_by;
  if (request.tension) mode.max_abs_tension_n = shaped.max_abs_tension_n;
  if (!request.shapes) return;
  mode.s_m = shaped.s_m;
  mode.u = shaped.u;
  mode.w = shaped.w;
  mode.v = shaped.v;
  mode.u_imag = shaped.u_imag;
  mode.w_imag = shaped.w_imag;
  mode.v_imag = shaped.v_imag;
  if (request.tension) {
    mode.tension_n = shaped.tension_n;
    mode.tension_imag_n = shaped.tension_imag_n;
  }
}

// An estimate relative to `value` (-1 without one).
double relative(double error, double value) {
  return error >= 0.0 && value > 0.0 ? error / value : -1.0;
}

// Mode i as the finest main mesh's own root, without an estimate (so a declared miss), when the
// levels do not resolve it: a pairing across levels below kMinLevelMac, or an extrapolation that
// leaves the passive line's half plane (delta < 0: C is positive semi-definite, so every root of
// every level has Re lambda <= 0, and only values outside the asymptotic range extrapolate past
// it). Such a root (a heavily damped one of a seabed dashpot, whose omega_d moves by tens of
// per cent between the meshes) is reported with the reason rather than extrapolated.
Mode unresolved_mode(const DampedPlaneInput& in,
                     int i,
                     const std::string& why,
                     std::vector<std::string>& warnings,
                     Mode mode) {
  const FeDampedEigenSolution& finest =
      in.levels[static_cast<std::size_t>(in.plan.main_fine)][0].damped.at(in.plane);
  const Complex lambda = finest.roots[i];
  set_damped_root(mode, lambda, in.context.groups);
  mode.relative_error_estimate = -1.0;
  mode.decay_rate_error_estimate = -1.0;
  warnings.push_back(fmt::format(
      "{} root near lambda = {:.6g} {:+.6g} i not resolved by the meshes ({}): the finest "
      "mesh's value is returned without an error estimate",
      to_string(in.plane), lambda.real(), lambda.imag(), why));
  return mode;
}

// Underdamped mode i, extrapolated (or unresolved_mode).
Mode damped_mode(const DampedPlaneInput& in,
                 const FeModeMatches& matches,
                 int i,
                 double worst_mac,
                 const Vector& stations,
                 std::vector<std::string>& warnings) {
  const FeExtrapolatedFrequency omega =
      extrapolate_frequency(in.plan, level_parts(in.levels, matches, in.plane, i, 0));
  const FeExtrapolatedFrequency delta =
      extrapolate_frequency(in.plan, level_parts(in.levels, matches, in.plane, i, 1));
  Mode mode;
  mode.index = i + 1;
  const auto fine = static_cast<std::size_t>(in.plan.main_fine);
  const int second = in.plan.inextensible ? matches[fine][1][static_cast<std::size_t>(i)] : 0;
  std::string why;
  if (worst_mac < kMinLevelMac)
    why = fmt::format("its shape pairs across the levels with a MAC of {:.3f} only", worst_mac);
  else if (!(omega.omega_rad_s > 0.0) || !(delta.omega_rad_s >= 0.0))
    why = fmt::format("the extrapolation gives omega_d = {:.6g} rad/s, delta = {:.6g} 1/s",
                      omega.omega_rad_s, delta.omega_rad_s);
  if (!why.empty()) {
    mode = unresolved_mode(in, i, why, warnings, std::move(mode));
    attach_damped_shape(in, false, i, second, Complex(-mode.decay_rate_1_s, mode.omega_rad_s),
                        stations, mode);
    return mode;
  }
  const Complex lambda(-delta.omega_rad_s, omega.omega_rad_s);
  set_damped_root(mode, lambda, in.context.groups);
  const double rounding = damped_rounding(in.plan, in.levels, matches, in.plane, i);
  mode.relative_error_estimate = relative(omega.error_rad_s, omega.omega_rad_s);
  if (mode.relative_error_estimate >= 0.0) mode.relative_error_estimate += rounding;
  // The rounding of lambda is relative to |lambda|: relative to delta it is |lambda| / delta times
  // larger.
  mode.decay_rate_error_estimate = relative(delta.error_rad_s, delta.omega_rad_s);
  if (mode.decay_rate_error_estimate >= 0.0)
    mode.decay_rate_error_estimate += rounding * std::abs(lambda) / delta.omega_rad_s;
  if (in.plan.has_estimate_mesh() && mode.relative_error_estimate >= 0.0 &&
      !in.context.problem.prescribed_forces)
    mode.relative_error_estimate += in.plan.statics_floor(in.context.groups.t0_n);
  attach_damped_shape(in, false, i, second, lambda, stations, mode);
  return mode;
}

// The rounding of overdamped root r relative to delta: a real root is -delta_c +- sqrt(delta_c^2 -
// k/m) of its vector's Rayleigh functional (delta_c = c / 2m), so a relative rounding rho of k
// (the element-wise quotient's, fe_rayleigh_quotient.hpp, or the polished pair's backward error)
// moves it by rho (k/m) / (2 |lambda + delta_c|): relative to |lambda| that is amplified where the
// two roots of the functional are close or the root is the slow one. Times the extrapolations'
// gains, as damped_rounding.
double overdamped_rounding(const DampedPlaneInput& in, Eigen::Index r) {
  double largest = 0.0;
  for (const auto& row : in.levels) {
    for (const FeLevel& level : row) {
      const FeDampedEigenSolution& damped = level.damped.at(in.plane);
      const Eigen::VectorXcd& phi = damped.real_vectors.col(r);
      // The vector of a real root is real up to a phase: the larger of its parts.
      const Vector x =
          phi.real().norm() >= phi.imag().norm() ? Vector(phi.real()) : Vector(phi.imag());
      const SparseMatrix& mass = level.matrices.at(in.plane).mass;
      const double mx = x.dot(mass * x);
      if (!(mx > 0.0)) return std::numeric_limits<double>::infinity();
      const RayleighQuotient k = element_rayleigh_quotient(level.chain, in.plane, x, mass);
      const double delta_c = x.dot(level.damping.at(in.plane).damping * x) / (2.0 * mx);
      const double lambda = damped.real_roots[r];
      const double amplification =
          std::abs(k.value) / (2.0 * std::abs(lambda + delta_c) * std::abs(lambda));
      largest = std::max(largest,
                         std::max(k.relative_rounding, damped.max_backward_error) * amplification);
    }
  }
  const double mesh_gain = in.plan.richardson && in.plan.has_coarse() ? 5.0 / 3.0 : 1.0;
  const double kappa_gain = in.plan.inextensible ? 3.0 : 1.0;
  return largest * mesh_gain * kappa_gain;
}

// The overdamped roots of the finest main mesh that every level found at the same rank, within
// the smallest radius Spectra searched on any level, extrapolated in delta by rank.
void add_overdamped(const DampedPlaneInput& in, const Vector& stations, ModalResult& result) {
  const auto fine = static_cast<std::size_t>(in.plan.main_fine);
  const FeDampedEigenSolution& reference = in.levels[fine][0].damped.at(in.plane);
  double radius = std::numeric_limits<double>::infinity();
  Eigen::Index common = reference.real_roots.size();
  for (const auto& row : in.levels)
    for (const FeLevel& level : row) {
      const FeDampedEigenSolution& solution = level.damped.at(in.plane);
      radius = std::min(radius, solution.radius);
      common = std::min(common, solution.real_roots.size());
    }
  for (Eigen::Index r = 0; r < common; ++r) {
    std::vector<std::vector<double>> delta(in.levels.size());
    bool inside = true;
    for (std::size_t m = 0; m < in.levels.size(); ++m)
      for (const FeLevel& level : in.levels[m]) {
        const double root = level.damped.at(in.plane).real_roots[r];
        inside = inside && std::abs(root) < 0.9 * radius;
        delta[m].push_back(-root);
      }
    if (!inside) break;
    const FeExtrapolatedFrequency value = extrapolate_frequency(in.plan, delta);
    Mode mode;
    mode.index = static_cast<int>(r) + 1;
    set_damped_root(mode, Complex(-value.omega_rad_s, 0.0), in.context.groups);
    mode.decay_rate_error_estimate = relative(value.error_rad_s, value.omega_rad_s);
    if (mode.decay_rate_error_estimate >= 0.0) {
      const double rounding = overdamped_rounding(in, r);
      mode.decay_rate_error_estimate =
          std::isfinite(rounding) ? mode.decay_rate_error_estimate + rounding : -1.0;
    }
    mode.relative_error_estimate = mode.decay_rate_error_estimate;
    attach_damped_shape(in, true, static_cast<int>(r), static_cast<int>(r),
                        Complex(-value.omega_rad_s, 0.0), stations, mode);
    result.overdamped.push_back(std::move(mode));
  }
}

}  // namespace

FePlaneEigenReport solve_level_damped_modes(FeLevels& levels,
                                            Plane plane,
                                            int modes,
                                            const FeSolverOptions& options,
                                            FeTimings& timings,
                                            WorkMeter* meter) {
  FePlaneEigenReport report;
  long solved = 0;
  for (auto& row : levels) {
    for (FeLevel& level : row) {
      const auto start = Clock::now();
      if (!level.matrices.count(plane)) level.matrices[plane] = assemble(plane, level.chain);
      level.damping[plane] = assemble_damping(plane, level.chain);
      timings.assembly_s += seconds_since(start);
      FeDampedEigenSolution eigen = solve_damped_modes(
          level.chain, plane, level.matrices.at(plane), level.damping.at(plane).damping, modes,
          std::max(options.eigen_tolerance, kDampedArnoldiTolerance), options.max_restarts);
      timings.factorization_s += eigen.factorization_time_s;
      timings.eigen_iterations_s += eigen.iteration_time_s;
      report.restarts += eigen.restarts;
      report.operations += eigen.operations;
      const int N = level.chain.elements;
      for (const auto& warning : eigen.warnings)
        report.warnings.push_back(fmt::format("N = {}: {}", N, warning));
      if (eigen.termination != Termination::Converged) {
        if (report.termination != Termination::NumericalFailure)
          report.termination = eigen.termination;
        report.warnings.push_back(fmt::format("N = {}: {}", N, eigen.message));
      } else {
        report.max_backward_error = std::max(report.max_backward_error, eigen.max_backward_error);
        report.max_residual = std::max(report.max_residual, eigen.max_backward_error);
      }
      level.damped[plane] = std::move(eigen);
      if (meter && meter->stop_after(++solved)) return report;
    }
  }
  return report;
}

int damped_modes_on_every_level(const FeLevels& levels, Plane plane, int modes) {
  int available = modes;
  for (const auto& row : levels)
    for (const FeLevel& level : row)
      available = std::min(available, static_cast<int>(level.damped.at(plane).roots.size()));
  return available;
}

void damped_modal_result(const SolveContext& context,
                         const FePlan& plan,
                         const FeLevels& levels,
                         Plane plane,
                         int count,
                         ModalResult& result) {
  const DampedPlaneInput in{context, plan, levels, plane};
  const Vector stations = context.request.stations_m(context.problem.length_m());
  const int available = damped_modes_on_every_level(levels, plane, count);
  SolverSummary& summary = result.summary;
  if (available > 0) {
    std::vector<double> worst_mac;
    const FeModeMatches matches = match_damped_levels(levels, plan, plane, available, worst_mac);
    for (int i = 0; i < available; ++i) {
      Mode mode = damped_mode(in, matches, i, worst_mac[static_cast<std::size_t>(i)], stations,
                              summary.warnings);
      summary.max_error_estimate =
          std::max(summary.max_error_estimate, mode.relative_error_estimate);
      result.modes.push_back(std::move(mode));
    }
    std::stable_sort(result.modes.begin(), result.modes.end(),
                     [](const Mode& a, const Mode& b) { return a.omega_rad_s < b.omega_rad_s; });
    for (std::size_t i = 0; i < result.modes.size(); ++i)
      result.modes[i].index = static_cast<int>(i) + 1;
  }
  add_overdamped(in, stations, result);
  if (available < count && summary.termination == Termination::Converged)
    summary.termination = Termination::NoConvergence;
  const FeDampedEigenSolution& finest =
      levels[static_cast<std::size_t>(plan.main_fine)][0].damped.at(plane);
  bool proved_everywhere = true;
  for (const auto& row : levels)
    for (const FeLevel& level : row) {
      const FeDampedEigenSolution& s = level.damped.at(plane);
      proved_everywhere = proved_everywhere && s.counted == static_cast<int>(s.roots.size());
    }
  const bool proved =
      finest.counted >= 0 && finest.counted == static_cast<int>(finest.roots.size());
  if (proved) result.proved_count_below_top = finest.counted;
  summary.notes.push_back(fmt::format(
      "damped roots of (lambda^2 M + lambda C + K) phi = 0 by Spectra's Arnoldi iteration "
      "(GenEigsSolver) on the linearised operator, polished by inverse iteration; root count by "
      "the argument principle of det Q(lambda) on the finest mesh: {} in {}{}",
      finest.counted, finest.count_region,
      proved_everywhere ? " (and equal to the roots found on every level)"
                        : " (not equal to the roots found on some level)"));
  if (!result.overdamped.empty())
    summary.notes.push_back(fmt::format(
        "{} overdamped (real) roots among the roots of |lambda| below the searched radius, "
        "listed apart",
        result.overdamped.size()));
  const char* name = to_string(plane);
  if (summary.termination == Termination::Converged && proved) {
    summary.message = fmt::format(
        "Converged: {} of {} damped {} modes, normwise backward error {:.1e}, count proved by the "
        "argument principle ({} roots in {}), max relative error estimate {:.1e}",
        available, count, name, summary.max_residual, finest.counted, finest.count_region,
        summary.max_error_estimate);
  } else {
    if (summary.termination == Termination::Converged)
      summary.termination = Termination::NoConvergence;
    summary.message =
        fmt::format("No convergence: {} of {} damped {} modes ({})", available, count, name,
                    summary.warnings.empty() ? finest.message : summary.warnings.back());
  }
}

}  // namespace catena::internal
