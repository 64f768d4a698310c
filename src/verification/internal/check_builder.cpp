// SPDX-License-Identifier: MIT
#include "verification/internal/check_builder.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "catena/verification/independence.hpp"

namespace catena::internal {
namespace {

// Whatever a tolerance says, a relative difference above this is a gross disagreement
// (docs/reference/verdicts.md).
constexpr double kGrossRelative = kGrossRelativeDifference;

}  // namespace

const char* plane_name(Plane plane) {
  return plane == Plane::InPlane ? "in-plane" : "out-of-plane";
}

double relative_difference(double a, double b) {
  const double scale = std::max(std::abs(a), std::abs(b));
  return scale == 0.0 ? 0.0 : std::abs(a - b) / scale;
}

const ModalResult* modal_of(const SolverOutput& output, Plane plane) {
  const auto& m = plane == Plane::InPlane ? output.inplane : output.outofplane;
  return m && !m->modes.empty() ? &*m : nullptr;
}

ModelParameters model_parameters(const SceneResult& result) {
  ModelParameters parameters;
  if (!result.groups) return parameters;
  parameters.eps = result.groups->eps;
  const double ea = result.scene.problem.cable.axial_stiffness_n;
  parameters.strain = std::isfinite(ea) && ea > 0.0 ? result.groups->t0_n / ea : 0.0;
  return parameters;
}

CheckBuilder::CheckBuilder(const SceneResult& result,
                           const ToleranceTable& tolerances,
                           const FindingsTable& findings,
                           const std::vector<SolverEntry>& solvers)
    : result_(result),
      tolerances_(tolerances),
      findings_(findings),
      solvers_(solvers),
      parameters_(model_parameters(result)) {}

std::optional<CheckBuilder::Tolerance> CheckBuilder::tolerance(
    const std::string& check,
    const std::string& a,
    const std::string& b,
    std::optional<double> scene_override) const {
  if (scene_override) return Tolerance{*scene_override, "scene [checks] override"};
  const ToleranceRule* rule = tolerances_.find(check, a, b, result_.scene.name, result_.scene.tags);
  if (!rule) return std::nullopt;
  return Tolerance{rule->tolerance(parameters_), rule->reason, rule->warn_only};
}

std::optional<CheckBuilder::ForcedTolerance> CheckBuilder::forced_tolerance(const std::string& a,
                                                                            const std::string& b,
                                                                            double omega) const {
  const auto rule = tolerance("forced", a, b, result_.scene.checks.tension_rel);
  if (!rule) return std::nullopt;
  const ForcedConditioning& conditioning = result_.forced_conditioning;
  ForcedTolerance out;
  out.max = rule->value;
  out.kappa = conditioning.condition(omega);
  out.tolerance = *rule;
  out.tolerance.value = out.max * out.kappa;
  out.checkable = out.tolerance.value <= kMostConditionedForcedTolerance;
  const std::string source =
      conditioning.covers(omega)
          ? fmt::format("from {}'s natural frequencies", conditioning.solver)
          : fmt::format("conditioning unknown, the strictest: {}", conditioning.note);
  out.note = fmt::format("tolerance {:.1e} x kappa {:.3g} ({}) = {:.2e}", out.max, out.kappa,
                         source, out.tolerance.value);
  return out;
}

const SolverEntry* CheckBuilder::entry(const std::string& name) const {
  for (const auto& e : solvers_) {
    if (e.name == name) return &e;
  }
  return nullptr;
}

std::optional<std::string> CheckBuilder::shared(const std::string& a,
                                                const std::string& b,
                                                const std::string& quantity) const {
  const SolverEntry* x = entry(a);
  const SolverEntry* y = entry(b);
  return x && y ? shared_computation(*x, *y, quantity) : std::nullopt;
}

bool CheckBuilder::independent(const std::string& a,
                               const std::string& b,
                               const std::string& quantity,
                               const std::string& check,
                               const std::string& plane) {
  const auto id = shared(a, b, quantity);
  if (!id) return true;
  CheckResult skip = base(check, a + " vs " + b, plane, 0);
  skip.verdict = Verdict::Skipped;
  skip.detail = fmt::format("{}{} (both solvers compute {} by it: one witness, not two)",
                            kSharedComputationDetail, *id, quantity);
  add(std::move(skip));
  return false;
}

CheckResult CheckBuilder::base(const std::string& check,
                               const std::string& compare,
                               const std::string& plane,
                               int mode) const {
  CheckResult c;
  c.scene = result_.scene.name;
  c.check = check;
  c.compare = compare;
  c.plane = plane;
  c.mode = mode;
  c.value_a = c.value_b = std::nan("");
  return c;
}

void CheckBuilder::add(CheckResult check) { checks_.push_back(std::move(check)); }

void CheckBuilder::add_measured(CheckResult check,
                                double measured,
                                const Tolerance& tol,
                                bool relative) {
  check.measured = measured;
  check.tolerance = tol.value;
  if (!std::isfinite(measured)) {
    check.verdict = Verdict::Fail;
    check.detail = "non-finite value; " + check.detail;
  } else if (relative && measured > kGrossRelative && !tol.warn_only) {
    check.verdict = Verdict::Fail;
    check.detail = "gross disagreement; " + check.detail;
  } else if (measured <= tol.value) {
    check.verdict = Verdict::Pass;
  } else {
    // A rule marked beyond = "warn" describes a model's documented limit, not a defect.
    check.verdict = tol.warn_only ? Verdict::Warn : Verdict::Fail;
  }
  check.tolerance_reason = tol.reason;
  add(std::move(check));
}

// Two exact solvers that were both asked for an accuracy (their planes' accuracy_target, set by
// the scene's knobs, never by an estimate) are held to the sum of those targets where it is below
// the table's rule: a scene that asks shooting for 1e-12 sees a 1e-10 change of frobenius. The
// rule stays the ceiling, so no tolerance ever widens (docs/reference/verdicts.md, "Tolerances").
std::optional<CheckBuilder::Tolerance> tightened_by_targets(
    std::optional<CheckBuilder::Tolerance> tol,
    const CheckBuilder& builder,
    const SolverOutput& a,
    const SolverOutput& b,
    const ModalResult& ma,
    const ModalResult& mb) {
  const SolverAccuracy* da = builder.tolerances().solver(a.solver);
  const SolverAccuracy* db = builder.tolerances().solver(b.solver);
  const double ta = ma.summary.accuracy_target, tb = mb.summary.accuracy_target;
  if (!tol || !da || !db || !da->exact || !db->exact || !(ta > 0.0) || !(tb > 0.0)) return tol;
  if (!(ta + tb < tol->value)) return tol;
  tol->value = ta + tb;
  tol->reason = fmt::format(
      "the sum of the accuracy targets the scene asked ({} {:.2g} + {} {:.2g}), below the rule: {}",
      a.solver, ta, b.solver, tb, tol->reason);
  return tol;
}

}  // namespace catena::internal
