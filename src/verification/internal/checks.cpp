// SPDX-License-Identifier: MIT
#include "verification/internal/checks.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "catena/verification/findings.hpp"
#include "catena/verification/independence.hpp"
#include "catena/verification/tolerance_table.hpp"
#include "verification/internal/check_builder.hpp"
#include "verification/internal/damping_checks.hpp"
#include "verification/internal/dynamic_tension_checks.hpp"
#include "verification/internal/estimate_checks.hpp"
#include "verification/internal/mode_mix.hpp"
#include "verification/internal/mode_pairing.hpp"
#include "verification/internal/published_checks.hpp"

namespace catena::internal {
namespace {

// Statics closure |r(L) - (b - a)| relative to the cable size. Newton stops at 1e-14 (or the
// rounding floor near 1e-11); 1e-9 leaves room for ill-conditioned taut cables and still catches
// a wrong equilibrium.
constexpr double kStaticsClosureRel = 1e-9;

const ModalResult* modal(const SolverOutput& output, Plane plane) {
  return modal_of(output, plane);
}

void statics_closure(const SceneResult& result, CheckBuilder& builder) {
  CheckResult check = builder.base("statics-closure", "statics vs supports", "", 0);
  const double L = result.scene.problem.cable.length_m;
  const double chord = result.scene.problem.supports.chord_m().norm();
  check.measured = result.statics->closure_error_m / std::max(L, chord);
  check.tolerance = kStaticsClosureRel;
  check.verdict = check.measured <= check.tolerance ? Verdict::Pass : Verdict::Fail;
  check.detail = fmt::format("closure error {:.3e} m on a cable of {} m ({})",
                             result.statics->closure_error_m, L, result.statics->brief_report());
  builder.add(check);
}

void solver_status(const SolverOutput& output, CheckBuilder& builder) {
  CheckResult check = builder.base("solver-status", output.solver, "", 0);
  check.detail = output.summary.brief_report();
  switch (output.summary.termination) {
    case Termination::Converged:
      check.verdict = Verdict::Pass;
      break;
    case Termination::NotApplicable:
      check.verdict = Verdict::Skipped;
      break;
    case Termination::NoConvergence:
      check.verdict = Verdict::Warn;
      break;
    case Termination::NumericalFailure:
      check.verdict = Verdict::Fail;
      break;
  }
  builder.add(check);
}

void mode_count(const SolverOutput& output, Plane plane, CheckBuilder& builder) {
  const ModalResult* m = modal(output, plane);
  if (!m || m->proved_count_below_top < 0) return;
  CheckResult check = builder.base("mode-count", output.solver, plane_name(plane), 0);
  check.value_a = m->proved_count_below_top;
  check.value_b = static_cast<double>(m->modes.size());
  check.measured = std::abs(check.value_a - check.value_b);
  check.tolerance = 0.0;
  check.verdict = check.measured == 0.0 ? Verdict::Pass : Verdict::Fail;
  check.detail =
      fmt::format("{} eigenvalues proved at or below the top returned frequency, {} returned",
                  m->proved_count_below_top, m->modes.size());
  builder.add(check);
}

// A mode its solver declared beyond its own accuracy target (Mode::meets_target, listed in the
// summary's missed_modes) is still compared, but a disagreement is the WARN the solver announced,
// not a FAIL (docs/reference/verdicts.md, "Declared misses"), as long as it lies within the sum of
// the two estimates; beyond that sum it is a real disagreement or a broken estimate, and stays a
// FAIL (the estimate check also holds the declared estimate to the actual error).
CheckBuilder::Tolerance declared_miss(CheckBuilder::Tolerance tol,
                                      const Mode& x,
                                      const Mode& y,
                                      double measured,
                                      CheckResult& check) {
  if (x.meets_target && y.meets_target) return tol;
  const double ex = x.relative_error_estimate, ey = y.relative_error_estimate;
  if (ex >= 0.0 && ey >= 0.0 && measured > tol.value && measured > ex + ey) {
    check.detail += fmt::format(
        "; declared beyond its solver's accuracy target (missed_modes), but the difference "
        "exceeds the sum of the two estimates {:.1e}",
        ex + ey);
    return tol;
  }
  tol.warn_only = true;
  check.detail += "; declared beyond its solver's accuracy target (missed_modes)";
  return tol;
}

// A damped mode one solver returned and the other has no partner for (mode_pairing.hpp): a WARN
// when it lies within the other's returned omega_d range (a root outside the other's counted
// region, such as a heavily damped one of a seabed dashpot, or one it missed: its summary gives
// the region it counted), a SKIP when it lies beyond the other's top (the other returned fewer
// modes there). Never a FAIL on its own: the paired modes carry the comparison.
void unpaired_modes(const SolverOutput& a,
                    const SolverOutput& b,
                    Plane plane,
                    const ModalResult& ma,
                    const ModalResult& mb,
                    const ModePairs& pairing,
                    CheckBuilder& builder) {
  auto report = [&](const SolverOutput& has, const ModalResult& own, const SolverOutput& lacks,
                    const ModalResult& other, std::size_t i) {
    const Mode& mode = own.modes[i];
    CheckResult check =
        builder.base("unpaired", has.solver + " vs " + lacks.solver, plane_name(plane), mode.index);
    const double top = other.modes.empty() ? 0.0 : other.modes.back().omega_rad_s;
    const bool within = mode.omega_rad_s <= top;
    check.value_a = mode.omega_rad_s;
    check.verdict = within ? Verdict::Warn : Verdict::Skipped;
    check.detail = fmt::format(
        "{}'s mode {} (lambda = {:.9g} {:+.9g} i, damping ratio {:.3g}) has no partner in {}: {}",
        has.solver, mode.index, -mode.decay_rate_1_s, mode.omega_rad_s, mode.damping_ratio,
        lacks.solver,
        within
            ? fmt::format("a root outside {0}'s counted region (its summary) or one {0} "
                          "missed; not compared",
                          lacks.solver)
            : fmt::format("beyond {}'s top omega_d {:.9g} rad/s; not compared", lacks.solver, top));
    builder.add(std::move(check));
  };
  for (std::size_t i : pairing.only_a) report(a, ma, b, mb, i);
  for (std::size_t j : pairing.only_b) report(b, mb, a, ma, j);
}

void frequency_pair(const SceneResult& result,
                    const SolverOutput& a,
                    const SolverOutput& b,
                    Plane plane,
                    CheckBuilder& builder) {
  const ModalResult* ma = modal(a, plane);
  const ModalResult* mb = modal(b, plane);
  if (!ma || !mb) return;
  const std::string quantity =
      plane == Plane::InPlane ? "frequency-in-plane" : "frequency-out-of-plane";
  if (!builder.independent(a.solver, b.solver, quantity, "frequency", plane_name(plane))) return;
  std::optional<CheckBuilder::Tolerance> tol =
      builder.tolerance("frequency", a.solver, b.solver, result.scene.checks.frequency_rel);
  if (!result.scene.checks.frequency_rel) tol = tightened_by_targets(tol, builder, a, b, *ma, *mb);
  const bool damped = result.scene.problem.is_damped();
  const ModePairs pairing = pair_modes(*ma, *mb, damped);
  unpaired_modes(a, b, plane, *ma, *mb, pairing, builder);
  for (const auto& [i, j] : pairing.pairs) {
    const Mode& x = ma->modes[i];
    const Mode& y = mb->modes[j];
    CheckResult check =
        builder.base("frequency", a.solver + " vs " + b.solver, plane_name(plane), x.index);
    if (x.index != y.index) check.detail = fmt::format("{}'s mode {}: ", b.solver, y.index);
    check.value_a = x.omega_rad_s;
    check.value_b = y.omega_rad_s;
    // A damped line's omega_rad_s is the damped frequency omega_d = Im lambda (its decay rate is
    // the decay-rate check's): the detail names it so.
    check.detail +=
        fmt::format("{} {:.12g} vs {:.12g} rad/s (error estimates {:.1e}, {:.1e})",
                    damped ? "omega_d (damped frequency Im lambda)" : "omega", x.omega_rad_s,
                    y.omega_rad_s, x.relative_error_estimate, y.relative_error_estimate);
    if (!tol) continue;
    const double measured = relative_difference(x.omega_rad_s, y.omega_rad_s);
    builder.add_measured(check, measured, declared_miss(*tol, x, y, measured, check), true);
  }
}

// Simpson on equally spaced stations when their number is odd, trapezoid otherwise.
double integrate(const Vector& s, const Vector& f) {
  const Index n = s.size();
  if (n < 3 || n % 2 == 0) {
    double sum = 0.0;
    for (Index i = 1; i < n; ++i) sum += 0.5 * (s[i] - s[i - 1]) * (f[i] + f[i - 1]);
    return sum;
  }
  const double h = (s[n - 1] - s[0]) / static_cast<double>(n - 1);
  double sum = f[0] + f[n - 1];
  for (Index i = 1; i < n - 1; ++i) sum += (i % 2 ? 4.0 : 2.0) * f[i];
  return sum * h / 3.0;
}

void shape_pair(const SceneResult& result,
                const SolverOutput& a,
                const SolverOutput& b,
                Plane plane,
                CheckBuilder& builder) {
  const ModalResult* ma = modal(a, plane);
  const ModalResult* mb = modal(b, plane);
  if (!ma || !mb || !has_stacked_shape(ma->modes[0], plane) ||
      !has_stacked_shape(mb->modes[0], plane))
    return;
  const std::string quantity = plane == Plane::InPlane ? "shape-in-plane" : "shape-out-of-plane";
  if (!builder.independent(a.solver, b.solver, quantity, "shape", plane_name(plane))) return;
  for (const auto& [i, j] : pair_modes(*ma, *mb, result.scene.problem.is_damped()).pairs) {
    const Mode& x = ma->modes[i];
    const Mode& y = mb->modes[j];
    if (!has_stacked_shape(x, plane) || !has_stacked_shape(y, plane) ||
        x.s_m.size() != y.s_m.size())
      continue;
    const Vector p = stacked_shape(x, plane), q = stacked_shape(y, plane);
    const double mac = std::pow(p.dot(q), 2) / (p.squaredNorm() * q.squaredNorm());
    const std::string compare = a.solver + " vs " + b.solver;
    if (auto tol = builder.tolerance("mac", a.solver, b.solver,
                                     result.scene.checks.mac_min
                                         ? std::optional(1.0 - *result.scene.checks.mac_min)
                                         : std::nullopt)) {
      CheckResult check = builder.base("mac", compare, plane_name(plane), x.index);
      check.value_a = mac;
      check.detail = fmt::format("MAC = {:.9f} (measured: 1 - MAC)", mac);
      builder.add_measured(check, 1.0 - mac, *tol, false);
    }
    // Max difference of the normalised shapes, signs aligned.
    const double sign = p.dot(q) < 0.0 ? -1.0 : 1.0;
    const double max_diff =
        (p - sign * q).cwiseAbs().maxCoeff() / std::max(p.cwiseAbs().maxCoeff(), 1e-300);
    if (auto tol =
            builder.tolerance("shape", a.solver, b.solver, result.scene.checks.shape_max_diff)) {
      CheckResult check = builder.base("shape", compare, plane_name(plane), x.index);
      check.detail = "max |shape_a - shape_b| / max |shape_a| over the stations";
      builder.add_measured(check, max_diff, *tol, false);
    }
  }
}

void tension_pair(const SceneResult& result,
                  const SolverOutput& a,
                  const SolverOutput& b,
                  Plane plane,
                  CheckBuilder& builder) {
  const ModalResult* ma = modal(a, plane);
  const ModalResult* mb = modal(b, plane);
  if (!ma || !mb || plane == Plane::OutOfPlane) return;  // out-of-plane modes carry no tension
  if (ma->modes[0].max_abs_tension_n < 0.0 || mb->modes[0].max_abs_tension_n < 0.0) return;
  if (!builder.independent(a.solver, b.solver, "tension", "tension", plane_name(plane))) return;
  for (const auto& [i, j] : pair_modes(*ma, *mb, result.scene.problem.is_damped()).pairs) {
    const Mode& x = ma->modes[i];
    const Mode& y = mb->modes[j];
    if (x.max_abs_tension_n < 0.0 || y.max_abs_tension_n < 0.0) continue;
    if (x.normalised_by != y.normalised_by) continue;
    const auto tol =
        builder.tolerance("tension", a.solver, b.solver, result.scene.checks.tension_rel);
    if (!tol) continue;
    CheckResult check =
        builder.base("tension", a.solver + " vs " + b.solver, plane_name(plane), x.index);
    check.value_a = x.max_abs_tension_n;
    check.value_b = y.max_abs_tension_n;
    check.detail = fmt::format("max |tau| {:.9g} vs {:.9g} N per unit max |{}|",
                               x.max_abs_tension_n, y.max_abs_tension_n, x.normalised_by);
    builder.add_measured(check, relative_difference(x.max_abs_tension_n, y.max_abs_tension_n), *tol,
                         true);
  }
}

// A forcing frequency where at least one solver gave no finite response. Both without one, or a
// decline that is not a resonance (the frequency is beyond that method's resolution, which its
// status reports): SKIP with the reason. One solver at resonance while the other returns a finite
// response: consistent only when the other flags it near_resonance (resonance-amplified, within
// the first solver's accuracy of a natural frequency); a finite response nobody flags contradicts
// the resonance claim, and one of the two answers is wrong: FAIL.
void resonance_claim(const ForcedResponse& x,
                     const ForcedResponse& y,
                     const std::string& solver_x,
                     const std::string& solver_y,
                     CheckResult& check) {
  check.verdict = Verdict::Skipped;
  const bool x_finite = x.diagnostic.empty(), y_finite = y.diagnostic.empty();
  const ForcedResponse& claim = x_finite ? y : x;
  if (!x_finite && !y_finite) {
    check.detail = "not compared: " + x.diagnostic + "; " + y.diagnostic;
    return;
  }
  const ForcedResponse& finite = x_finite ? x : y;
  const std::string& claimant = x_finite ? solver_y : solver_x;
  const std::string& other = x_finite ? solver_x : solver_y;
  if (!claim.at_resonance) {
    check.detail =
        fmt::format("not compared: {} declined this frequency: {}", claimant, claim.diagnostic);
  } else if (finite.near_resonance) {
    check.detail = fmt::format(
        "not compared: {} is at resonance within its accuracy ({}); {} flags its finite "
        "response near a natural frequency (error estimate {:.1e})",
        claimant, claim.diagnostic, other, finite.relative_error_estimate);
  } else {
    check.verdict = Verdict::Fail;
    check.detail = fmt::format(
        "contradiction: {} says resonance ({}) while {} gives a finite response, max |tau| = "
        "{:.9g} N (error estimate {:.1e}), not flagged near a natural frequency",
        claimant, claim.diagnostic, other, finite.max_abs_tension_n,
        finite.relative_error_estimate);
  }
}

// The forced check held to max x kappa(Omega) (CheckBuilder::forced_tolerance); beyond the largest
// conditioned tolerance a WARN "at resonance, not checkable", unless the difference is gross.
void conditioned_forced_check(CheckResult& check,
                              double measured,
                              const CheckBuilder::ForcedTolerance& tol,
                              CheckBuilder& builder) {
  check.detail += "; " + tol.note;
  if (!tol.checkable && measured <= kGrossRelativeDifference) {
    check.measured = measured;
    check.tolerance = tol.tolerance.value;
    check.verdict = Verdict::Warn;
    check.detail =
        fmt::format("at resonance, not checkable: kappa = {:.3g} would allow more than {:g}; ",
                    tol.kappa, kMostConditionedForcedTolerance) +
        check.detail + "; tolerance: " + tol.tolerance.reason;
    builder.add(check);
    return;
  }
  builder.add_measured(check, measured, tol.tolerance, true);
}

void forced_pair(const SolverOutput& a, const SolverOutput& b, bool damped, CheckBuilder& builder) {
  const std::size_t n = std::min(a.forced.size(), b.forced.size());
  if (n == 0 || !builder.independent(a.solver, b.solver, "forced", "forced", "forced")) return;
  for (std::size_t i = 0; i < n; ++i) {
    const ForcedResponse& x = a.forced[i];
    const ForcedResponse& y = b.forced[i];
    CheckResult check =
        builder.base("forced", a.solver + " vs " + b.solver, "forced", static_cast<int>(i + 1));
    check.value_a = x.max_abs_tension_n;
    check.value_b = y.max_abs_tension_n;
    if (!x.diagnostic.empty() || !y.diagnostic.empty()) {
      resonance_claim(x, y, a.solver, b.solver, check);
      builder.add(check);
      continue;
    }
    const auto tol = builder.forced_tolerance(a.solver, b.solver, x.omega_rad_s);
    if (!tol) continue;
    // A damped response is complex: max_abs_tension_n is the largest modulus |tau| on the line.
    check.detail = fmt::format(
        "max |tau|{} at {:.6g} rad/s: {:.9g} vs {:.9g} N (error estimates {:.1e}, {:.1e})",
        damped ? " (complex modulus, damped)" : "", x.omega_rad_s, x.max_abs_tension_n,
        y.max_abs_tension_n, x.relative_error_estimate, y.relative_error_estimate);
    conditioned_forced_check(check, relative_difference(x.max_abs_tension_n, y.max_abs_tension_n),
                             *tol, builder);
  }
}

void orthogonality(const SceneResult& result,
                   const SolverOutput& output,
                   Plane plane,
                   CheckBuilder& builder) {
  const ModalResult* m = modal(output, plane);
  if (!m || m->modes.size() < 2 || !has_stacked_shape(m->modes[0], plane)) return;
  if (result.scene.problem.is_damped()) {
    // Complex modes of a non-proportionally damped line are not orthogonal in the mass inner
    // product (the quadratic eigenproblem's orthogonality involves C and lambda), and the real
    // parts alone are not the shapes: nothing here to hold to 1e-3.
    CheckResult skip = builder.base("orthogonality", output.solver, plane_name(plane), 0);
    skip.verdict = Verdict::Skipped;
    skip.detail = "not checked on a damped line: its complex modes are not mass-orthogonal";
    builder.add(std::move(skip));
    return;
  }
  if (!result.scene.problem.is_uniform()) {
    // The request's equally spaced stations do not fall on a line's joints and points, where the
    // mass density jumps, a point adds its lumped mass and the shapes have kinks: Simpson's rule
    // across them is O(h), not the O(h^4) the tolerance assumes, so the check could not tell.
    CheckResult skip = builder.base("orthogonality", output.solver, plane_name(plane), 0);
    skip.verdict = Verdict::Skipped;
    skip.detail =
        "not checked on a general line: the stations do not resolve its joints and points (the "
        "mass "
        "density jumps and point masses the M-inner product needs)";
    builder.add(std::move(skip));
    return;
  }
  const double mass = result.scene.problem.cable.mass_kg_per_m;
  const double normal_mass = result.scene.problem.cable.normal_mass_kg_per_m();
  auto inner = [&](const Mode& x, const Mode& y) {
    const Vector density =
        plane == Plane::InPlane
            ? Vector(mass * x.u.cwiseProduct(y.u) + normal_mass * x.w.cwiseProduct(y.w))
            : Vector(normal_mass * x.v.cwiseProduct(y.v));
    return integrate(x.s_m, density);
  };
  double worst = 0.0;
  int worst_i = 0, worst_j = 0;
  for (std::size_t i = 0; i < m->modes.size(); ++i) {
    for (std::size_t j = i + 1; j < m->modes.size(); ++j) {
      const Mode& x = m->modes[i];
      const Mode& y = m->modes[j];
      if (!has_stacked_shape(x, plane) || !has_stacked_shape(y, plane)) continue;
      const double value = std::abs(inner(x, y)) / std::sqrt(inner(x, x) * inner(y, y));
      if (!(value <= worst)) {
        worst = value;
        worst_i = x.index;
        worst_j = y.index;
      }
    }
  }
  const auto tol = builder.tolerance("orthogonality", output.solver, output.solver,
                                     result.scene.checks.orthogonality);
  if (!tol) return;
  CheckResult check = builder.base("orthogonality", output.solver, plane_name(plane), 0);
  check.detail =
      fmt::format("max |<phi_i, phi_j>_M| / (|phi_i| |phi_j|) over mode pairs, at modes {} and {}",
                  worst_i, worst_j);
  builder.add_measured(check, worst, *tol, false);
}

// The pair checks of one plane, and each solver's own mode count and orthogonality.
void plane_checks(const SceneResult& result,
                  const std::vector<const SolverOutput*>& usable,
                  Plane plane,
                  CheckBuilder& builder) {
  for (const SolverOutput* output : usable) mode_count(*output, plane, builder);
  for (std::size_t i = 0; i < usable.size(); ++i) {
    for (std::size_t j = i + 1; j < usable.size(); ++j) {
      frequency_pair(result, *usable[i], *usable[j], plane, builder);
      shape_pair(result, *usable[i], *usable[j], plane, builder);
      tension_pair(result, *usable[i], *usable[j], plane, builder);
      if (result.scene.problem.is_damped()) damping_pair(*usable[i], *usable[j], plane, builder);
    }
  }
  for (const SolverOutput* output : usable) orthogonality(result, *output, plane, builder);
}

}  // namespace

std::vector<CheckResult> run_checks(const SceneResult& result,
                                    const ToleranceTable& tolerances,
                                    const FindingsTable& findings,
                                    const std::vector<SolverEntry>& solvers) {
  CheckBuilder builder(result, tolerances, findings, solvers);
  if (!result.statics) return {};
  statics_closure(result, builder);
  for (const auto& output : result.outputs) solver_status(output, builder);
  std::vector<const SolverOutput*> usable;
  for (const auto& output : result.outputs) {
    if (output.summary.is_usable()) usable.push_back(&output);
  }
  for (Plane plane : {Plane::InPlane, Plane::OutOfPlane})
    plane_checks(result, usable, plane, builder);
  const bool damped = result.scene.problem.is_damped();
  for (std::size_t i = 0; i < usable.size(); ++i) {
    for (std::size_t j = i + 1; j < usable.size(); ++j) {
      forced_pair(*usable[i], *usable[j], damped, builder);
      if (damped) declined_forced_pair(*usable[i], *usable[j], builder);
    }
  }
  dynamic_tension_checks(usable, builder);
  estimate_checks(usable, builder);
  published_checks(builder);
  std::vector<CheckResult> checks = builder.checks();
  for (CheckResult& flag : identity_checks(checks)) checks.push_back(std::move(flag));
  return checks;
}

}  // namespace catena::internal
