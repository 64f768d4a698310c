// SPDX-License-Identifier: MIT
// The dynamic-tension checks: see dynamic_tension_checks.hpp and docs/reference/verdicts.md,
// "Dynamic tension".
#include "verification/internal/dynamic_tension_checks.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace catena::internal {
namespace {

// The harness recomputes the linearised drag from a solver's final motion in double precision: a
// division by the section's factor and a square root of a sum of two squares per station, a few
// rounding errors of the largest velocity. 1e-12 leaves room for them and is far below any
// fixed-point tolerance a request may ask (>= 1e-14 relative is allowed, but then the residual is
// at rounding level too and this floor is what the check resolves).
constexpr double kConsistencyRounding = 1e-12;
// Two forcing frequencies are the same when they differ by less than this (relative): a scene
// writes 2 pi / T as a decimal literal, which reads back within an ulp or two of the motion's
// omega; the response moves by kappa x 1e-12 between them, far below any anchor tolerance.
constexpr double kSameFrequency = 1e-12;

bool has_values(const DynamicTension& t) {
  const Vector& v = dynamic_station_values(t);
  return t.s_m.size() > 0 && v.size() == t.s_m.size() && v.allFinite();
}

std::string excitation(const DynamicTension& t) {
  return t.irregular ? std::string("irregular motion") : fmt::format("period {:g} s", t.period_s);
}

const char* quantity_name(const DynamicTension& t) { return t.irregular ? "sigma_T" : "|T_dyn|"; }

// max_j |a_j - b_j| / max_j max(|a_j|, |b_j|): the tension along the line compared in the
// max-norm, relative to its largest value (a station-by-station relative difference means nothing
// where the amplitude passes near zero, e.g. on the grounded part of a line).
double max_norm_difference(const Vector& a, const Vector& b) {
  const double scale = std::max(a.cwiseAbs().maxCoeff(), b.cwiseAbs().maxCoeff());
  return scale > 0.0 ? (a - b).cwiseAbs().maxCoeff() / scale : 0.0;
}

bool same_excitation(const DynamicTension& x, const DynamicTension& y) {
  if (x.irregular != y.irregular) return false;
  return x.irregular || relative_difference(x.period_s, y.period_s) <= kSameFrequency;
}

// A fixed point its solver did not reach is compared, but a disagreement is the WARN the solver
// announced (converged = false with a diagnostic), not a FAIL, as a declared miss
// (docs/reference/verdicts.md, "Declared misses"); the fixed-point check reports it.
CheckBuilder::Tolerance declared(CheckBuilder::Tolerance tol,
                                 const DynamicTension& x,
                                 const DynamicTension& y,
                                 std::string& detail) {
  if (x.converged && y.converged) return tol;
  tol.warn_only = true;
  detail += "; a fixed point not reached (declared by its solver: converged = false)";
  return tol;
}

void compare_pair(const SolverOutput& a,
                  const SolverOutput& b,
                  std::size_t k,
                  const CheckBuilder::Tolerance& rule,
                  CheckBuilder& builder) {
  const DynamicTension& x = a.dynamic_tension[k];
  const DynamicTension& y = b.dynamic_tension[k];
  const std::string compare = a.solver + " vs " + b.solver;
  const int index = static_cast<int>(k + 1);
  if (!same_excitation(x, y) || !has_values(x) || !has_values(y)) {
    CheckResult skip = builder.base("dynamic-tension", compare, kFairleadPlace, index);
    skip.verdict = Verdict::Skipped;
    skip.detail = !same_excitation(x, y)
                      ? fmt::format("not compared: different excitations ({} and {})",
                                    excitation(x), excitation(y))
                      : fmt::format("not compared ({}): {}; {}", excitation(x),
                                    has_values(x) ? "values" : x.diagnostic,
                                    has_values(y) ? "values" : y.diagnostic);
    builder.add(std::move(skip));
    return;
  }
  const std::string estimates =
      fmt::format("(estimates {:.1e}, {:.1e}; fixed-point residuals {:.1e}, {:.1e})",
                  x.relative_error_estimate, y.relative_error_estimate, x.residual, y.residual);
  for (const bool fairlead : {true, false}) {
    const DynamicTensionEnd& ex = fairlead ? x.fairlead : x.anchor;
    const DynamicTensionEnd& ey = fairlead ? y.fairlead : y.anchor;
    CheckResult check =
        builder.base("dynamic-tension", compare, fairlead ? kFairleadPlace : kAnchorPlace, index);
    check.value_a = dynamic_end_value(x, ex);
    check.value_b = dynamic_end_value(y, ey);
    check.detail = fmt::format("{}: {} at s = {:g} m {:.9g} vs {:.9g} N {}", excitation(x),
                               quantity_name(x), ex.s_m, check.value_a, check.value_b, estimates);
    const auto tol = declared(rule, x, y, check.detail);
    builder.add_measured(check, relative_difference(check.value_a, check.value_b), tol, true);
  }
  const Vector& vx = dynamic_station_values(x);
  const Vector& vy = dynamic_station_values(y);
  if (vx.size() != vy.size()) return;
  CheckResult check = builder.base("dynamic-tension", compare, kStationsPlace, index);
  check.value_a = vx.cwiseAbs().maxCoeff();
  check.value_b = vy.cwiseAbs().maxCoeff();
  check.detail = fmt::format(
      "{}: max_s |{a} - {a}'| / max_s {a} over {n} stations (largest {va:.9g} vs {vb:.9g} N) {e}",
      excitation(x), fmt::arg("a", quantity_name(x)), fmt::arg("n", vx.size()),
      fmt::arg("va", check.value_a), fmt::arg("vb", check.value_b), fmt::arg("e", estimates));
  const auto tol = declared(rule, x, y, check.detail);
  builder.add_measured(check, max_norm_difference(vx, vy), tol, true);
  // The motion along the line: what an out-of-plane motion drives (its tension is of second order,
  // zero in the linear model), and what the drag is linearised about.
  if (x.motion_m.size() != vx.size() || y.motion_m.size() != vx.size()) return;
  CheckResult motion = builder.base("dynamic-tension", compare, kMotionPlace, index);
  // The values shown are at the middle station: the largest motion is often end b's, which the
  // boundary condition prescribes (equal in both solvers by construction, not by computation).
  const Eigen::Index middle = x.motion_m.size() / 2;
  motion.value_a = x.motion_m[middle];
  motion.value_b = y.motion_m[middle];
  motion.detail = fmt::format(
      "{}: motion {} |x(s)| along the line, max-norm over {} stations (middle {:.9g} vs {:.9g} m) "
      "{}",
      excitation(x), x.irregular ? "standard deviation of" : "amplitude", vx.size(), motion.value_a,
      motion.value_b, estimates);
  const auto motion_tol = declared(rule, x, y, motion.detail);
  builder.add_measured(motion, max_norm_difference(x.motion_m, y.motion_m), motion_tol, true);
}

void dynamic_tension_pair(const SolverOutput& a, const SolverOutput& b, CheckBuilder& builder) {
  const std::size_t n = std::min(a.dynamic_tension.size(), b.dynamic_tension.size());
  if (n == 0) return;
  if (!builder.independent(a.solver, b.solver, "dynamic-tension", "dynamic-tension",
                           kFairleadPlace))
    return;
  const auto rule = builder.tolerance("dynamic-tension", a.solver, b.solver, std::nullopt);
  if (!rule) return;
  for (std::size_t k = 0; k < n; ++k) compare_pair(a, b, k, *rule, builder);
}

// converged with residual <= tolerance: PASS; converged beyond it (or without a finite residual):
// FAIL, a claim the solver cannot stand behind; not converged: WARN with the residual and the
// solver's reason (the solver said so: no-convergence, as the solver-status check).
void fixed_point(const SolverOutput& output,
                 std::size_t k,
                 double tolerance,
                 CheckBuilder& builder) {
  const DynamicTension& t = output.dynamic_tension[k];
  CheckResult check =
      builder.base("fixed-point", output.solver, kDynamicPlace, static_cast<int>(k + 1));
  check.measured = t.residual;
  check.tolerance = tolerance;
  const bool within = std::isfinite(t.residual) && t.residual >= 0.0 && t.residual <= tolerance;
  const std::string what = fmt::format("{}: residual {:.3e} after {} iterations (tolerance {:.1e})",
                                       excitation(t), t.residual, t.iterations, tolerance);
  if (t.converged) {
    check.verdict = within ? Verdict::Pass : Verdict::Fail;
    check.detail = within ? what : "claimed converged beyond the tolerance; " + what;
  } else {
    check.verdict = Verdict::Warn;
    check.detail = fmt::format("not converged (declared): {}; {}", what,
                               t.diagnostic.empty() ? "no diagnostic given" : t.diagnostic);
  }
  check.tolerance_reason =
      "the request's fixed-point tolerance ([request.motion].tolerance): max_s |V(x) - V| / "
      "max_s |V(x)| of the velocity scales";
  builder.add(std::move(check));
}

// The drag factors a 1/2 rho Cd d (normal) and a 1/2 rho CdAx pi d (tangential) of each segment
// [kg/m^2], a = 8 / (3 pi) (harmonic linearisation), and the segments' starts [m]: the model's
// definition (issue 30; MorisonDrag in include/catena/models/line.hpp), recomputed here from the
// problem, not taken from the solvers' shared code.
struct DragFactors {
  std::vector<double> start, normal, tangential;
  // The segment of station s: the one that contains it, on a joint the one that begins there.
  std::size_t segment_of(double s) const {
    const auto after = std::upper_bound(start.begin(), start.end(), s);
    return after == start.begin() ? 0 : std::size_t(after - start.begin()) - 1;
  }
};

DragFactors harmonic_drag_factors(const Problem& problem) {
  DragFactors f;
  const double a = 8.0 / (3.0 * std::numbers::pi);
  const double half_rho = 0.5 * problem.environment.water_density_kg_per_m3;
  double s = 0.0;
  for (const LineSegment& segment : problem.as_line().segments) {
    f.start.push_back(s);
    f.normal.push_back(a * half_rho * segment.drag.normal * segment.drag.diameter_m);
    f.tangential.push_back(a * half_rho * segment.drag.tangential * std::numbers::pi *
                           segment.drag.diameter_m);
    s += segment.length_m;
  }
  return f;
}

// Regular motion with drag: the velocity amplitude the reported c_n, c_t stand for,
// sqrt((c_n / f_n)^2 + (c_t / f_t)^2), against omega |x(s)| from the reported motion amplitude.
// The two differ by at most sqrt(2) x the fixed point's residual (|V - G(V)| <= residual x
// max |G(V)| in each of V_n, V_t); stations whose section lacks either coefficient in plane (one
// component of the velocity cannot be recovered) are left out.
void drag_consistency(const SolverOutput& output,
                      std::size_t k,
                      const DragFactors& factors,
                      bool out_of_plane,
                      CheckBuilder& builder) {
  const DynamicTension& t = output.dynamic_tension[k];
  const Eigen::Index n = t.s_m.size();
  if (t.irregular || !has_values(t) || t.motion_m.size() != n ||
      t.normal_damping_n_s_per_m2.size() != n || t.tangential_damping_n_s_per_m2.size() != n ||
      !(t.residual >= 0.0))
    return;
  double worst = 0.0, largest = 0.0;
  int used = 0;
  for (Eigen::Index j = 0; j < n; ++j) {
    const std::size_t seg = factors.segment_of(t.s_m[j]);
    const double fn = factors.normal[seg], ft = factors.tangential[seg];
    const double reference = t.omega_rad_s * t.motion_m[j];
    largest = std::max(largest, std::abs(reference));
    if (!(fn > 0.0) || (!out_of_plane && !(ft > 0.0))) continue;
    const double vn = t.normal_damping_n_s_per_m2[j] / fn;
    const double vt = ft > 0.0 ? t.tangential_damping_n_s_per_m2[j] / ft : 0.0;
    worst = std::max(worst, std::abs(std::hypot(vn, vt) - reference));
    ++used;
  }
  if (used == 0) return;
  CheckResult check =
      builder.base("drag-consistency", output.solver, kDynamicPlace, static_cast<int>(k + 1));
  check.detail = fmt::format(
      "{}: max_s |V(c(s)) - omega |x(s)|| / max_s omega |x(s)| over {} stations, V recomputed from "
      "the reported c_n, c_t (8/(3 pi) 1/2 rho Cd d V_n, 8/(3 pi) 1/2 rho CdAx pi d V_t), held to "
      "sqrt(2) x the reported residual {:.3e}",
      excitation(t), used, t.residual);
  const CheckBuilder::Tolerance tol{
      std::sqrt(2.0) * t.residual + kConsistencyRounding,
      "the fixed point's own residual: |V - G(V)| <= residual max |G(V)| in V_n and in V_t, so "
      "sqrt(2) x residual for their Euclidean sum, plus 1e-12 for rounding"};
  builder.add_measured(check, largest > 0.0 ? worst / largest : worst, tol, false);
}

// The forced response of `request` at omega, when the forced request drives the same end in the
// same direction as the motion; nullptr otherwise.
const ForcedResponse* forced_twin(const SolverOutput& output,
                                  const SolveRequest& request,
                                  double omega) {
  const auto& forced = request.forced;
  const auto& motion = request.motion;
  if (!forced || !motion || forced->end != CableEnd::B || forced->direction != motion->direction)
    return nullptr;
  if (motion->direction == ForcingDirection::GivenVector &&
      (forced->unit_vector() - motion->unit_vector()).cwiseAbs().maxCoeff() > kSameFrequency)
    return nullptr;
  for (std::size_t i = 0; i < output.forced.size() && i < forced->omegas_rad_s.size(); ++i) {
    if (relative_difference(forced->omegas_rad_s[i], omega) <= kSameFrequency &&
        output.forced[i].diagnostic.empty())
      return &output.forced[i];
  }
  return nullptr;
}

// A scene without drag: the fixed point is one linear solve, the damped forced response of the
// same line at the same frequency. Its tension amplitude per metre of motion against the same
// solver's forced |tau| per metre of forcing, in the max-norm over the stations. A consistency
// anchor of the solver's two paths (they may share code), not a second witness.
void drag_anchor(const SolverOutput& output, std::size_t k, CheckBuilder& builder) {
  const DynamicTension& t = output.dynamic_tension[k];
  const SolveRequest& request = builder.result().request;
  if (t.irregular || !has_values(t)) return;
  const ForcedResponse* twin = forced_twin(output, request, t.omega_rad_s);
  if (!twin || twin->tension_n.size() != t.s_m.size()) return;
  const auto tol = builder.tolerance("drag-anchor", output.solver, output.solver, std::nullopt);
  if (!tol) return;
  Vector forced = twin->tension_n.cwiseAbs();
  if (twin->tension_imag_n.size() == forced.size())
    forced = (twin->tension_n.cwiseAbs2() + twin->tension_imag_n.cwiseAbs2()).cwiseSqrt();
  forced /= request.forced->amplitude_m;
  const Vector dynamic = t.amplitude_n / request.motion->amplitude_m;
  CheckResult check =
      builder.base("drag-anchor", output.solver, kDynamicPlace, static_cast<int>(k + 1));
  check.value_a = dynamic.maxCoeff();
  check.value_b = forced.maxCoeff();
  check.detail = fmt::format(
      "{} (no drag): |T_dyn(s)| / A against the forced response |tau(s)| / A at {:.9g} rad/s, "
      "max-norm over {} stations (largest {:.9g} vs {:.9g} N/m)",
      excitation(t), twin->omega_rad_s, t.s_m.size(), check.value_a, check.value_b);
  builder.add_measured(check, max_norm_difference(dynamic, forced), *tol, true);
}

// Each output's own checks, for every excitation it returned.
void own_checks(const SolverOutput& output, CheckBuilder& builder) {
  const SceneResult& result = builder.result();
  const Problem& problem = result.scene.problem;
  const auto& motion = result.request.motion;
  const bool drag = problem.has_drag();
  const DragFactors factors = drag ? harmonic_drag_factors(problem) : DragFactors{};
  const bool out_of_plane = motion->direction == ForcingDirection::OutOfPlane;
  for (std::size_t k = 0; k < output.dynamic_tension.size(); ++k) {
    fixed_point(output, k, motion->tolerance, builder);
    if (!output.summary.is_usable()) continue;
    if (drag) drag_consistency(output, k, factors, out_of_plane, builder);
    if (!drag) drag_anchor(output, k, builder);
  }
}

}  // namespace

double dynamic_end_value(const DynamicTension& t, const DynamicTensionEnd& end) {
  return t.irregular ? end.std_n : end.amplitude_n;
}

const Vector& dynamic_station_values(const DynamicTension& t) {
  return t.irregular ? t.std_n : t.amplitude_n;
}

void dynamic_tension_checks(const std::vector<const SolverOutput*>& usable, CheckBuilder& builder) {
  if (!builder.result().request.motion) return;
  for (const SolverOutput& output : builder.result().outputs) own_checks(output, builder);
  for (std::size_t i = 0; i < usable.size(); ++i) {
    for (std::size_t j = i + 1; j < usable.size(); ++j)
      dynamic_tension_pair(*usable[i], *usable[j], builder);
  }
}

}  // namespace catena::internal
