// SPDX-License-Identifier: MIT
// The checks of a damped scene on hand-made results (docs/reference/verdicts.md, "Damped scenes"):
// two solvers whose damped modes agree in omega_d but not in delta pass the frequency check and
// fail the decay-rate check, also at a damping ratio of 1e-4 where |lambda| moves far less than
// the tolerance; overdamped roots are paired; a declined solver is a SKIP, never a FAIL; an
// undamped scene gets none of these checks. Tolerances are those of verification/tolerances.toml.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "catena/io/findings_reader.hpp"
#include "catena/io/tolerance_reader.hpp"
#include "catena/statics/problem_builders.hpp"
#include "catena/verification/forced_conditioning.hpp"
#include "verification/internal/checks.hpp"

namespace catena {
namespace {

// Gale's B-3 cable (h/b = 0.5, sag 0.8), damped when `drag` > 0 (c_t = c_n = drag).
SceneResult gale_result(double drag) {
  SceneResult result;
  result.scene.name = "damped-test-scene";
  result.scene.problem = make_gale_sag_problem(0.5, 0.8);
  result.scene.problem.cable.damping.tangential_n_s_per_m2 = drag;
  result.scene.problem.cable.damping.normal_n_s_per_m2 = drag;
  result.statics = solve_statics(result.scene.problem);
  result.groups = compute_dimensionless_groups(result.scene.problem, *result.statics);
  return result;
}

Mode damped_mode(int index, double omega_d, double delta) {
  Mode mode;
  mode.index = index;
  mode.omega_rad_s = omega_d;
  mode.decay_rate_1_s = delta;
  mode.damping_ratio = delta / std::hypot(delta, omega_d);
  mode.relative_error_estimate = 1e-10;
  return mode;
}

// A converged solver output with in-plane modes (omega_d, delta).
SolverOutput output_with(const std::string& solver,
                         const std::vector<std::pair<double, double>>& roots) {
  SolverOutput out;
  out.solver = solver;
  out.summary.solver = solver;
  out.summary.termination = Termination::Converged;
  ModalResult modal;
  modal.summary.termination = Termination::Converged;
  for (std::size_t i = 0; i < roots.size(); ++i)
    modal.modes.push_back(damped_mode(static_cast<int>(i + 1), roots[i].first, roots[i].second));
  out.inplane = modal;
  return out;
}

std::vector<CheckResult> run_checks(const SceneResult& result) {
  static const ToleranceTable tolerances = builtin_tolerance_table();
  static const FindingsTable findings = builtin_findings_table();
  return internal::run_checks(result, tolerances, findings);
}

const CheckResult* find(const std::vector<CheckResult>& checks, const std::string& kind, int mode) {
  for (const auto& c : checks) {
    if (c.check == kind && c.mode == mode) return &c;
  }
  return nullptr;
}

std::optional<Verdict> verdict_of(const std::vector<CheckResult>& checks,
                                  const std::string& kind,
                                  int mode) {
  const CheckResult* check = find(checks, kind, mode);
  return check ? std::optional(check->verdict) : std::nullopt;
}

int count_of(const std::vector<CheckResult>& checks, const std::string& kind) {
  int n = 0;
  for (const auto& c : checks) n += c.check == kind;
  return n;
}

TEST(DampingChecks, AgreeingDampedModesPassFrequencyAndDecayRate) {
  SceneResult r = gale_result(0.1);
  r.outputs = {output_with("frobenius", {{1.8597624309, 0.05}, {3.1617163183, 0.05}}),
               output_with("shooting", {{1.8597624309 * (1 + 2e-10), 0.05 * (1 + 3e-10)},
                                        {3.1617163183, 0.05}})};
  const auto checks = run_checks(r);
  EXPECT_EQ(verdict_of(checks, "frequency", 1), Verdict::Pass);
  ASSERT_EQ(verdict_of(checks, "decay-rate", 1), Verdict::Pass);
  EXPECT_EQ(verdict_of(checks, "decay-rate", 2), Verdict::Pass);
  const CheckResult* c = find(checks, "decay-rate", 1);
  EXPECT_NEAR(c->measured, 3e-10, 1e-12);  // relative to delta, not to |lambda|
  EXPECT_EQ(c->tolerance, 1e-9);           // the exact pair's rule
  EXPECT_NE(c->detail.find("on its own"), std::string::npos) << c->detail;
  // The frequency check names the damped frequency.
  EXPECT_NE(find(checks, "frequency", 1)->detail.find("omega_d"), std::string::npos);
}

TEST(DampingChecks, ADelta1e3OffFailsTheDecayRateCheckWhileOmegaPasses) {
  SceneResult r = gale_result(0.1);
  r.outputs = {output_with("frobenius", {{1.8597624309, 0.05}}),
               output_with("shooting", {{1.8597624309, 0.05 * (1 + 1e-3)}})};
  const auto checks = run_checks(r);
  EXPECT_EQ(verdict_of(checks, "frequency", 1), Verdict::Pass);
  const CheckResult* c = find(checks, "decay-rate", 1);
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(c->verdict, Verdict::Fail);
  EXPECT_EQ(c->compare, "frobenius vs shooting");
  EXPECT_NEAR(c->measured, 1e-3 / (1 + 1e-3), 1e-12);
}

// zeta = 1e-4: delta 1e-3 off moves |lambda| by 1e-7 only, within fe's 1e-6; delta on its own
// sees it.
TEST(DampingChecks, LightDampingDeltaIsCheckedOnItsOwnNotThroughLambda) {
  SceneResult r = gale_result(4e-4);
  const double omega = 1.86, delta = 1.86e-4;
  r.outputs = {output_with("fe", {{omega, delta}}),
               output_with("shooting", {{omega, delta * (1 + 1e-3)}})};
  const double lambda_change =
      std::abs(std::hypot(omega, delta * (1 + 1e-3)) / std::hypot(omega, delta) - 1.0);
  ASSERT_LT(lambda_change, 1e-6);
  const auto checks = run_checks(r);
  EXPECT_EQ(verdict_of(checks, "frequency", 1), Verdict::Pass);
  const CheckResult* c = find(checks, "decay-rate", 1);
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(c->verdict, Verdict::Fail);
  EXPECT_EQ(c->tolerance, 1e-6);  // fe's rule
  EXPECT_GT(c->measured, 9e-4);
}

// A plane the damping does not reach (delta 0 exactly in one solver, rounding in the other):
// below the solvers' resolution of lambda (their declared accuracies here, 1e-12 and 1e-10) delta
// is compared relative to |lambda|, and passes.
TEST(DampingChecks, AnUndampedModeOfADampedLineComparesDeltaRelativeToLambda) {
  SceneResult r = gale_result(0.1);
  r.outputs = {output_with("frobenius", {{2.0, 0.0}}), output_with("shooting", {{2.0, 1e-15}})};
  const auto checks = run_checks(r);
  const CheckResult* c = find(checks, "decay-rate", 1);
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(c->verdict, Verdict::Pass);
  EXPECT_NE(c->detail.find("relative to |lambda|"), std::string::npos) << c->detail;
}

// A model's tolerance is wide (1e-4 + eps^2, 8.1 here at Gale's eps = 2.85, as a WARN limit): the
// threshold below which delta is compared relative to |lambda| is the solvers' resolution of
// lambda, not that tolerance, so a model's delta 5% off at zeta = 1e-4 is still measured on its
// own.
TEST(DampingChecks, AModelsDeltaIsMeasuredOnItsOwnAtLightDamping) {
  SceneResult r = gale_result(4e-4);
  r.outputs = {output_with("shooting", {{1.86, 1.86e-4}}),
               output_with("asymptotic", {{1.86, 1.86e-4 * 1.05}})};
  const std::vector<CheckResult> c_checks = run_checks(r);
  const CheckResult* c = find(c_checks, "decay-rate", 1);
  ASSERT_NE(c, nullptr);
  EXPECT_NEAR(c->measured, 0.05 / 1.05, 1e-9);
  EXPECT_NE(c->detail.find("on its own"), std::string::npos) << c->detail;
}

TEST(DampingChecks, ADeltaItsSolverDoesNotClaimIsADeclaredMissWarn) {
  SceneResult r = gale_result(0.1);
  r.outputs = {output_with("frobenius", {{1.86, 0.05}}),
               output_with("shooting", {{1.86, 0.05 * (1 + 1e-5)}})};
  r.outputs[1].inplane->summary.accuracy_target = 1.1e-9;
  r.outputs[1].inplane->modes[0].decay_rate_error_estimate = 1e-4;  // above its target
  EXPECT_EQ(verdict_of(run_checks(r), "decay-rate", 1), Verdict::Warn);
}

TEST(DampingChecks, ADecayRateEstimateBelowTheActualErrorFails) {
  SceneResult r = gale_result(0.1);
  r.outputs = {output_with("frobenius", {{1.86, 0.05}}),
               output_with("shooting", {{1.86, 0.05 * (1 + 1e-6)}})};
  r.outputs[0].inplane->modes[0].decay_rate_error_estimate = 1e-12;
  r.outputs[1].inplane->modes[0].decay_rate_error_estimate = 1e-9;  // claims 1e-9, is 1e-6 off
  const auto checks = run_checks(r);
  bool failed = false;
  for (const auto& c : checks) {
    if (c.check == "decay-estimate" && c.compare == "shooting vs frobenius")
      failed = c.verdict == Verdict::Fail;
  }
  EXPECT_TRUE(failed);
}

TEST(DampingChecks, OverdampedRootsBothListAreCompared) {
  SceneResult r = gale_result(4.0);
  r.outputs = {output_with("frobenius", {{2.4492754188, 2.0}}),
               output_with("shooting", {{2.4492754188, 2.0}})};
  for (auto& output : r.outputs) {
    for (double delta : {1.2659811306, 2.7340188694}) {
      Mode root = damped_mode(static_cast<int>(output.inplane->overdamped.size() + 1), 0.0, delta);
      root.damping_ratio = 1.0;
      output.inplane->overdamped.push_back(root);
    }
  }
  EXPECT_EQ(verdict_of(run_checks(r), "overdamped", 2), Verdict::Pass);
  r.outputs[1].inplane->overdamped[1].decay_rate_1_s *= 1 + 1e-6;
  const auto checks = run_checks(r);
  EXPECT_EQ(verdict_of(checks, "overdamped", 1), Verdict::Pass);
  EXPECT_EQ(verdict_of(checks, "overdamped", 2), Verdict::Fail);
}

TEST(DampingChecks, ASolverThatDeclinesTheDampedSceneIsASkipNeverAFail) {
  SceneResult r = gale_result(0.1);
  SolverOutput declined;
  declined.solver = "airy";
  declined.summary.solver = "airy";
  declined.summary.termination = Termination::NotApplicable;
  declined.summary.message = "the line is damped and this method computes undamped modes only";
  r.outputs = {output_with("frobenius", {{1.86, 0.05}}), declined};
  const auto checks = run_checks(r);
  for (const auto& c : checks) {
    EXPECT_NE(c.verdict, Verdict::Fail) << c.check << " " << c.compare << ": " << c.detail;
    if (c.check == "solver-status" && c.compare == "airy") {
      EXPECT_EQ(c.verdict, Verdict::Skipped);
      EXPECT_NE(c.detail.find("damped"), std::string::npos) << c.detail;
    }
  }
  EXPECT_EQ(count_of(checks, "decay-rate"), 0);
}

TEST(DampingChecks, ADeclinedDampedForcedResponseIsASkipWithTheReason) {
  SceneResult r = gale_result(0.1);
  r.request.forced = ForcedRequest{};
  r.request.forced->omegas_rad_s = {1.0};
  r.outputs = {output_with("frobenius", {{1.86, 0.05}}), output_with("shooting", {{1.86, 0.05}})};
  ForcedResponse response;
  response.omega_rad_s = 1.0;
  response.max_abs_tension_n = 0.1;
  r.outputs[0].forced = {response};
  r.outputs[1].summary.message = "damped forced response not computed (1 frequencies asked)";
  const auto checks = run_checks(r);
  const CheckResult* c = find(checks, "forced", 0);
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(c->verdict, Verdict::Skipped);
  EXPECT_NE(c->detail.find("shooting returned no damped forced response"), std::string::npos)
      << c->detail;
}

TEST(DampingChecks, AnUndampedSceneHasNoDampingChecksAndItsOwnFrequencyDetail) {
  SceneResult r = gale_result(0.0);
  r.outputs = {output_with("frobenius", {{1.86, 0.0}}), output_with("shooting", {{1.86, 0.0}})};
  const auto checks = run_checks(r);
  EXPECT_EQ(count_of(checks, "decay-rate"), 0);
  EXPECT_EQ(count_of(checks, "overdamped"), 0);
  EXPECT_EQ(count_of(checks, "decay-estimate"), 0);
  const CheckResult* c = find(checks, "frequency", 1);
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(c->detail.rfind("omega 1.86 vs", 0), 0u) << c->detail;
}

// A heavily damped root one solver returns (a seabed dashpot's, zeta 0.98, outside the other's
// counted region) and a mode beyond the other's top: paired by lambda, the common modes are
// compared with each other (not shifted by one), the extra root is an `unpaired` WARN, the mode
// beyond the top a SKIP, and nothing FAILs (docs/reference/verdicts.md, "Damped scenes").
TEST(DampingChecks, ARootOneSolverDoesNotReachIsUnpairedAndShiftsNoPair) {
  SceneResult r = gale_result(0.1);
  const double p = 1.0 + 1e-11;
  r.outputs = {output_with("fe", {{0.834, 0.0099}, {1.357, 0.0156}, {1.993, 8.90}, {2.404, 0.028}}),
               output_with("shooting", {{0.834 * p, 0.0099 * p},
                                        {1.357 * p, 0.0156 * p},
                                        {2.404 * p, 0.028 * p},
                                        {2.929, 0.035}})};
  const auto checks = run_checks(r);
  EXPECT_EQ(count_of(checks, "frequency"), 3);
  EXPECT_EQ(count_of(checks, "decay-rate"), 3);
  for (int mode : {1, 2, 4}) {
    EXPECT_EQ(verdict_of(checks, "frequency", mode), Verdict::Pass) << mode;
    EXPECT_EQ(verdict_of(checks, "decay-rate", mode), Verdict::Pass) << mode;
  }
  // fe's mode 4 is shooting's mode 3, and the detail says so.
  EXPECT_NE(find(checks, "frequency", 4)->detail.find("shooting's mode 3"), std::string::npos);
  EXPECT_EQ(verdict_of(checks, "frequency", 3), std::nullopt);
  int unpaired = 0;
  for (const auto& c : checks) {
    EXPECT_NE(c.verdict, Verdict::Fail) << c.check << " " << c.compare << " " << c.detail;
    if (c.check != "unpaired") continue;
    ++unpaired;
    if (c.compare == "fe vs shooting") {
      EXPECT_EQ(c.mode, 3);
      EXPECT_EQ(c.verdict, Verdict::Warn) << c.detail;  // within shooting's omega_d range
    } else {
      EXPECT_EQ(c.compare, "shooting vs fe");
      EXPECT_EQ(c.mode, 4);
      EXPECT_EQ(c.verdict, Verdict::Skipped) << c.detail;  // beyond fe's top
    }
  }
  EXPECT_EQ(unpaired, 2);
  // The estimate check holds fe's mode 4 against shooting's mode 3, and has no reference for
  // the unpaired root.
  const CheckResult* estimate = nullptr;
  for (const auto& c : checks)
    if (c.check == "estimate" && c.compare == "fe vs shooting" && c.mode == 4) estimate = &c;
  ASSERT_NE(estimate, nullptr);
  EXPECT_EQ(estimate->verdict, Verdict::Pass) << estimate->detail;
  for (const auto& c : checks)
    EXPECT_FALSE(c.check == "estimate" && c.compare == "fe vs shooting" && c.mode == 3);
}

// Undamped, the pairing stays by index (the counted spectra make mode i the same mode): a mode
// one solver has in the middle of the other's spectrum shifts the pairs and FAILs, as before.
TEST(DampingChecks, UndampedModesArePairedByIndexStill) {
  SceneResult r = gale_result(0.0);
  r.outputs = {output_with("frobenius", {{1.86, 0.0}, {2.5, 0.0}, {3.16, 0.0}}),
               output_with("shooting", {{1.86, 0.0}, {3.16, 0.0}})};
  const auto checks = run_checks(r);
  EXPECT_EQ(verdict_of(checks, "frequency", 1), Verdict::Pass);
  EXPECT_EQ(verdict_of(checks, "frequency", 2), Verdict::Fail);
  EXPECT_EQ(count_of(checks, "frequency"), 2);
  EXPECT_EQ(count_of(checks, "unpaired"), 0);
}

// kappa of a damped response: finite at resonance, 2 |lambda|^2 / (2 delta Omega) there; the same
// as the undamped formula with every delta 0.
TEST(DampingChecks, TheForcedConditionNumberOfADampedLineIsFiniteAtResonance) {
  ForcedConditioning damped;
  damped.omegas_rad_s = {1.0, 3.0};
  damped.decay_rates_1_s = {0.01, 0.01};
  const double at = damped.condition(1.0);
  EXPECT_NEAR(at, 2.0 * 1.0001 / std::hypot(1e-4, 0.02), 1e-9 * at);
  ForcedConditioning undamped = damped;
  undamped.decay_rates_1_s.clear();
  EXPECT_TRUE(std::isinf(undamped.condition(1.0)));
  ForcedConditioning zero = damped;
  zero.decay_rates_1_s = {0.0, 0.0};
  EXPECT_EQ(zero.condition(1.7), undamped.condition(1.7));
}

}  // namespace
}  // namespace catena
