// SPDX-License-Identifier: MIT
#include "verification/internal/estimate_checks.hpp"

#include <fmt/format.h>

#include <cmath>
#include <functional>
#include <optional>

#include "verification/internal/dynamic_tension_checks.hpp"
#include "verification/internal/mode_pairing.hpp"

namespace catena::internal {
namespace {

// A value a solver returned with its own relative error estimate, and the accuracy target the
// solver reported for it (0: none reported).
struct Claim {
  double value = 0.0;
  double estimate = 0.0;
  double target = 0.0;
};

// Where a claim sits: the quantity (for the independence rule), the plane and the mode.
struct Place {
  std::string quantity;
  std::string plane;
  int mode = 0;
  /// The check's kind: "estimate", or "decay-estimate" for a decay rate's estimate.
  std::string check = "estimate";
};

using ClaimOf = std::function<std::optional<Claim>(const SolverOutput&, bool as_reference)>;

// The accuracy the scene asked of the solver: the target the solver reported for the value (what
// it promises: shooting's 10 rtol + root_tolerance, fe's tolerance), else its accuracy knob when
// the scene sets it, else the table's default.
double requested_accuracy(const SceneResult& result,
                          const SolverAccuracy& accuracy,
                          const Claim& claim) {
  if (claim.target > 0.0) return claim.target;
  const auto solver = result.scene.solvers.find(accuracy.name);
  if (!accuracy.accuracy_knob.empty() && solver != result.scene.solvers.end()) {
    const auto knob = solver->second.find(accuracy.accuracy_knob);
    if (knob != solver->second.end() && std::holds_alternative<double>(knob->second)) {
      return std::get<double>(knob->second);
    }
  }
  return accuracy.accuracy;
}

std::optional<Claim> usable_claim(double value, double estimate, double target = 0.0) {
  if (!(estimate >= 0.0) || !std::isfinite(estimate)) return std::nullopt;
  return Claim{value, estimate, target};
}

// The reference for `claimant`'s value at `place`: among the other solvers declared exact in the
// table, Converged, not sharing the computation, with a finite value and an estimate, the one whose
// estimate is smallest (the first on a tie).
const SolverOutput* reference_for(const SolverOutput& claimant,
                                  const std::vector<const SolverOutput*>& usable,
                                  const Place& place,
                                  const ClaimOf& claim_of,
                                  const CheckBuilder& builder,
                                  Claim& reference_claim) {
  const SolverOutput* best = nullptr;
  for (const SolverOutput* other : usable) {
    if (other == &claimant || other->summary.termination != Termination::Converged) continue;
    const SolverAccuracy* accuracy = builder.tolerances().solver(other->solver);
    if (!accuracy || !accuracy->exact ||
        builder.shared(claimant.solver, other->solver, place.quantity))
      continue;
    const auto claim = claim_of(*other, true);
    if (!claim || !std::isfinite(claim->value)) continue;
    if (!best || claim->estimate < reference_claim.estimate) {
      best = other;
      reference_claim = *claim;
    }
  }
  return best;
}

// (a) actual > estimate + the reference's estimate: FAIL; (b) estimate > 1000 x the resolvable
// error (the actual error, but not below what the reference can resolve) and above the requested
// accuracy: WARN; PASS otherwise.
void judge(CheckResult& check, const Claim& claim, const Claim& reference, double requested) {
  const double actual = relative_difference(claim.value, reference.value);
  const double resolvable = std::max(actual, reference.estimate);
  check.value_a = claim.value;
  check.value_b = reference.value;
  check.measured = actual;
  check.tolerance = claim.estimate + reference.estimate;
  if (!std::isfinite(claim.value) || !(actual <= check.tolerance)) {
    check.verdict = Verdict::Fail;
    check.detail = "estimate not an upper bound; " + check.detail;
    if (reference.estimate > claim.estimate)
      check.detail += " (the reference's estimate is the larger: the miss may be the reference's)";
  } else if (claim.estimate > kUninformativeRatio * resolvable && claim.estimate > requested) {
    check.verdict = Verdict::Warn;
    check.detail = fmt::format(
        "estimate uninformative: {:.1e} x the resolvable error, above the requested accuracy "
        "{:.1e}; {}",
        claim.estimate / resolvable, requested, check.detail);
  } else {
    check.verdict = Verdict::Pass;
  }
}

void check_claim(const SolverOutput& claimant,
                 const std::vector<const SolverOutput*>& usable,
                 const Place& place,
                 const ClaimOf& claim_of,
                 CheckBuilder& builder) {
  const SolverAccuracy* accuracy = builder.tolerances().solver(claimant.solver);
  const auto claim = claim_of(claimant, false);
  if (!accuracy || !claim) return;
  Claim reference;
  const SolverOutput* ref = reference_for(claimant, usable, place, claim_of, builder, reference);
  if (!ref) return;
  CheckResult check =
      builder.base(place.check, claimant.solver + " vs " + ref->solver, place.plane, place.mode);
  check.detail = fmt::format(
      "{} {:.12g} with estimate {:.2e} against the reference {} {:.12g} (estimate {:.2e}): "
      "actual relative error {:.2e}",
      claimant.solver, claim->value, claim->estimate, ref->solver, reference.value,
      reference.estimate, relative_difference(claim->value, reference.value));
  judge(check, *claim, reference, requested_accuracy(builder.result(), *accuracy, *claim));
  builder.add(std::move(check));
}

// The mode of `output` that stands for the claimant's mode `index` in `plane`: the claimant's own
// mode, or, for a reference, its mode of the same index (undamped: the counted spectra make it
// the same mode) or its partner by lambda (damped: mode_pairing.hpp; none when unpaired). A
// reference's plane must itself have converged.
const Mode* claimed_mode(const SolverOutput& output,
                         bool as_reference,
                         const ModalResult& claimant,
                         Plane plane,
                         int index,
                         bool damped) {
  const auto& modal = plane == Plane::InPlane ? output.inplane : output.outofplane;
  if (!modal || (as_reference && modal->summary.termination != Termination::Converged))
    return nullptr;
  if (!as_reference || !damped) {
    for (const Mode& mode : modal->modes)
      if (mode.index == index) return &mode;
    return nullptr;
  }
  for (const auto& [i, j] : pair_modes(claimant, *modal, true).pairs)
    if (claimant.modes[i].index == index) return &modal->modes[j];
  return nullptr;
}

// The frequency of mode `index` in `plane`.
ClaimOf frequency_claim(const ModalResult& claimant, Plane plane, int index, bool damped) {
  return [&claimant, plane, index, damped](const SolverOutput& output,
                                           bool as_reference) -> std::optional<Claim> {
    const Mode* mode = claimed_mode(output, as_reference, claimant, plane, index, damped);
    if (!mode) return std::nullopt;
    const auto& modal = plane == Plane::InPlane ? output.inplane : output.outofplane;
    return usable_claim(mode->omega_rad_s, mode->relative_error_estimate,
                        modal->summary.accuracy_target);
  };
}

// The decay rate delta of mode `index` in `plane` with its estimate of the relative error of
// delta on its own (Mode::decay_rate_error_estimate: -1, no claim, on an undamped line), held to
// the plane's accuracy target as the frequency is.
ClaimOf decay_claim(const ModalResult& claimant, Plane plane, int index) {
  return [&claimant, plane, index](const SolverOutput& output,
                                   bool as_reference) -> std::optional<Claim> {
    const Mode* mode = claimed_mode(output, as_reference, claimant, plane, index, true);
    if (!mode) return std::nullopt;
    const auto& modal = plane == Plane::InPlane ? output.inplane : output.outofplane;
    return usable_claim(mode->decay_rate_1_s, mode->decay_rate_error_estimate,
                        modal->summary.accuracy_target);
  };
}

// max |tau| of forcing frequency `i`, when the solver gave a finite response.
ClaimOf forced_claim(std::size_t i) {
  return [i](const SolverOutput& output, bool) -> std::optional<Claim> {
    if (i >= output.forced.size() || !output.forced[i].diagnostic.empty()) return std::nullopt;
    return usable_claim(output.forced[i].max_abs_tension_n,
                        output.forced[i].relative_error_estimate);
  };
}

// The dynamic tension of excitation `k` at the fairlead or the anchor (amplitude, or standard
// deviation when irregular) with its estimate (the linear solves' plus the fixed point's
// residual); a reference must have reached its fixed point.
ClaimOf dynamic_claim(std::size_t k, bool fairlead) {
  return [k, fairlead](const SolverOutput& output, bool as_reference) -> std::optional<Claim> {
    if (k >= output.dynamic_tension.size()) return std::nullopt;
    const DynamicTension& t = output.dynamic_tension[k];
    const double value = dynamic_end_value(t, fairlead ? t.fairlead : t.anchor);
    // An exact zero (the first-order tension of an out-of-plane motion) has no relative error.
    if (t.s_m.size() == 0 || !(value > 0.0) || (as_reference && !t.converged)) return std::nullopt;
    return usable_claim(value, t.relative_error_estimate);
  };
}

}  // namespace

void estimate_checks(const std::vector<const SolverOutput*>& usable, CheckBuilder& builder) {
  for (const SolverOutput* output : usable) {
    for (Plane plane : {Plane::InPlane, Plane::OutOfPlane}) {
      const auto& modal = plane == Plane::InPlane ? output->inplane : output->outofplane;
      if (!modal) continue;
      const std::string quantity =
          plane == Plane::InPlane ? "frequency-in-plane" : "frequency-out-of-plane";
      const bool damped = builder.result().scene.problem.is_damped();
      for (const Mode& mode : modal->modes) {
        check_claim(*output, usable, {quantity, plane_name(plane), mode.index},
                    frequency_claim(*modal, plane, mode.index, damped), builder);
        if (mode.decay_rate_error_estimate >= 0.0)
          check_claim(*output, usable, {quantity, plane_name(plane), mode.index, "decay-estimate"},
                      decay_claim(*modal, plane, mode.index), builder);
      }
    }
    for (std::size_t i = 0; i < output->forced.size(); ++i) {
      check_claim(*output, usable, {"forced", "forced", static_cast<int>(i + 1)}, forced_claim(i),
                  builder);
    }
    for (std::size_t k = 0; k < output->dynamic_tension.size(); ++k) {
      for (const bool fairlead : {true, false})
        check_claim(
            *output, usable,
            {"dynamic-tension", fairlead ? kFairleadPlace : kAnchorPlace, static_cast<int>(k + 1)},
            dynamic_claim(k, fairlead), builder);
    }
  }
}

}  // namespace catena::internal
