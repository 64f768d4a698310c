// SPDX-License-Identifier: MIT
#include "verification/internal/damping_checks.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "verification/internal/mode_pairing.hpp"

namespace catena::internal {
namespace {

double modulus(const Mode& mode) { return std::hypot(mode.decay_rate_1_s, mode.omega_rad_s); }

// A decay rate its solver does not claim to its plane's accuracy target (its own estimate of the
// relative error of delta is above the target, or the mode is a declared miss) is still compared,
// but a disagreement is the WARN the solver announced, as for a frequency (docs/reference/
// verdicts.md, "Declared misses"); the decay-estimate check holds that estimate to the actual
// error. The estimate never widens the tolerance.
bool declared_decay_miss(const Mode& mode, double target) {
  if (!mode.meets_target) return true;
  return target > 0.0 && mode.decay_rate_error_estimate > target;
}

// The decay-rate tolerance of the pair: the table's `decay-rate` rule, tightened to the sum of
// the accuracy targets the scene asked of two exact solvers, as the frequency check is.
std::optional<CheckBuilder::Tolerance> decay_tolerance(const SolverOutput& a,
                                                       const SolverOutput& b,
                                                       const ModalResult& ma,
                                                       const ModalResult& mb,
                                                       const CheckBuilder& builder) {
  return tightened_by_targets(builder.tolerance("decay-rate", a.solver, b.solver, std::nullopt),
                              builder, a, b, ma, mb);
}

// The resolution of lambda a solver promises, relative to |lambda|: its plane's accuracy target,
// else the accuracy its [[solver]] declaration states (a model's is rounding: its delta is a
// formula on its own modes), else 0.
double resolution(const SolverOutput& output, double target, const CheckBuilder& builder) {
  if (target > 0.0) return target;
  const SolverAccuracy* declared = builder.tolerances().solver(output.solver);
  return declared ? declared->accuracy : 0.0;
}

// delta of x against delta of y, relative to delta itself: the point of a decay-rate check (a
// damping ratio of 1e-4 whose delta is 10% off moves |lambda| by 1e-5 only). Where both damping
// ratios are at or below the coarser of the two solvers' resolutions of lambda (`resolved`, their
// targets relative to |lambda|), delta cannot be held on its own: it is compared relative to
// |lambda| then, and the detail says so (an undamped plane of a damped line, delta 0 against
// rounding). Two exact zeros agree.
void compare_decay(const std::string& check_kind,
                   const std::string& compare,
                   Plane plane,
                   const Mode& x,
                   const Mode& y,
                   double target_x,
                   double target_y,
                   double resolved,
                   CheckBuilder::Tolerance tol,
                   CheckBuilder& builder) {
  CheckResult check = builder.base(check_kind, compare, plane_name(plane), x.index);
  check.value_a = x.decay_rate_1_s;
  check.value_b = y.decay_rate_1_s;
  check.detail = fmt::format(
      "delta {:.12g} vs {:.12g} 1/s, damping ratio {:.3g} vs {:.3g} (delta error estimates "
      "{:.1e}, {:.1e})",
      x.decay_rate_1_s, y.decay_rate_1_s, x.damping_ratio, y.damping_ratio,
      x.decay_rate_error_estimate, y.decay_rate_error_estimate);
  double measured = relative_difference(x.decay_rate_1_s, y.decay_rate_1_s);
  if (std::max(x.damping_ratio, y.damping_ratio) <= resolved) {
    const double scale = std::max(modulus(x), modulus(y));
    measured = scale > 0.0 ? std::abs(x.decay_rate_1_s - y.decay_rate_1_s) / scale : 0.0;
    check.detail += fmt::format(
        "; damping ratio below the solvers' resolution of lambda {:.1e}: delta compared relative "
        "to |lambda|",
        resolved);
  } else {
    check.detail += "; relative error of delta on its own";
  }
  if (declared_decay_miss(x, target_x) || declared_decay_miss(y, target_y)) {
    tol.warn_only = true;
    check.detail += "; declared beyond its solver's accuracy target (decay-rate estimate)";
  }
  builder.add_measured(check, measured, tol, true);
}

void decay_rate_pair(const SolverOutput& a,
                     const SolverOutput& b,
                     Plane plane,
                     const ModalResult& ma,
                     const ModalResult& mb,
                     CheckBuilder& builder) {
  const auto tol = decay_tolerance(a, b, ma, mb, builder);
  if (!tol) return;
  const double resolved = std::max(resolution(a, ma.summary.accuracy_target, builder),
                                   resolution(b, mb.summary.accuracy_target, builder));
  // Paired by lambda (mode_pairing.hpp), as the frequency check pairs them.
  for (const auto& [i, j] : pair_modes(ma, mb, true).pairs) {
    compare_decay("decay-rate", a.solver + " vs " + b.solver, plane, ma.modes[i], mb.modes[j],
                  ma.summary.accuracy_target, mb.summary.accuracy_target, resolved, *tol, builder);
  }
}

// The real roots both solvers list, in their order (ascending delta). Each solver lists those it
// found among its roots of smallest |lambda|; a root one of them did not reach is not paired.
void overdamped_pair(const SolverOutput& a,
                     const SolverOutput& b,
                     Plane plane,
                     const ModalResult& ma,
                     const ModalResult& mb,
                     CheckBuilder& builder) {
  const std::size_t n = std::min(ma.overdamped.size(), mb.overdamped.size());
  if (n == 0) return;
  const auto tol = decay_tolerance(a, b, ma, mb, builder);
  if (!tol) return;
  // An overdamped root's damping ratio is 1: its delta is always held on its own.
  for (std::size_t i = 0; i < n; ++i) {
    compare_decay("overdamped", a.solver + " vs " + b.solver, plane, ma.overdamped[i],
                  mb.overdamped[i], ma.summary.accuracy_target, mb.summary.accuracy_target, 0.0,
                  *tol, builder);
  }
}

}  // namespace

void damping_pair(const SolverOutput& a,
                  const SolverOutput& b,
                  Plane plane,
                  CheckBuilder& builder) {
  const auto& ma = plane == Plane::InPlane ? a.inplane : a.outofplane;
  const auto& mb = plane == Plane::InPlane ? b.inplane : b.outofplane;
  if (!ma || !mb || (ma->modes.empty() && ma->overdamped.empty()) ||
      (mb->modes.empty() && mb->overdamped.empty()))
    return;
  // delta comes out of the same eigenvalue as omega_d: the frequency computation's id decides.
  const std::string quantity =
      plane == Plane::InPlane ? "frequency-in-plane" : "frequency-out-of-plane";
  if (!builder.independent(a.solver, b.solver, quantity, "decay-rate", plane_name(plane))) return;
  decay_rate_pair(a, b, plane, *ma, *mb, builder);
  overdamped_pair(a, b, plane, *ma, *mb, builder);
}

void declined_forced_pair(const SolverOutput& a, const SolverOutput& b, CheckBuilder& builder) {
  const auto& request = builder.result().request.forced;
  if (!request || request->omegas_rad_s.empty()) return;
  if (a.forced.empty() == b.forced.empty()) return;
  const SolverOutput& declined = a.forced.empty() ? a : b;
  const SolverOutput& other = a.forced.empty() ? b : a;
  CheckResult check = builder.base("forced", a.solver + " vs " + b.solver, "forced", 0);
  check.verdict = Verdict::Skipped;
  check.detail = fmt::format(
      "not compared: {} returned no damped forced response ({}); {} returned {}", declined.solver,
      declined.summary.brief_report(), other.solver, other.forced.size());
  builder.add(std::move(check));
}

}  // namespace catena::internal
