// SPDX-License-Identifier: MIT
// The verification checks on hand-made results: each verdict (PASS, FAIL, SOURCE, SKIP) is reached
// by the case that should reach it, and a check's record names scene, solvers, values and
// tolerance. Expected outcomes follow from the rules in verification/tolerances.toml.
#include "verification/internal/checks.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "catena/io/findings_reader.hpp"
#include "catena/io/tolerance_reader.hpp"
#include "catena/statics/problem_builders.hpp"
#include "catena/verification/independence.hpp"

namespace catena {
namespace {

SceneResult gale_result() {
  SceneResult result;
  result.scene.name = "test-scene";
  result.scene.problem = make_gale_sag_problem(0.0, 0.9);
  result.statics = solve_statics(result.scene.problem);
  result.groups = compute_dimensionless_groups(result.scene.problem, *result.statics);
  return result;
}

SolverOutput output_with(const std::string& solver,
                         std::vector<double> omegas,
                         double estimate,
                         bool with_shapes = false) {
  SolverOutput out;
  out.solver = solver;
  out.summary.solver = solver;
  out.summary.termination = Termination::Converged;
  ModalResult modal;
  modal.summary.termination = Termination::Converged;
  const Vector s = Vector::LinSpaced(101, 0.0, 1.0);
  for (std::size_t i = 0; i < omegas.size(); ++i) {
    Mode mode;
    mode.index = static_cast<int>(i + 1);
    mode.omega_rad_s = omegas[i];
    mode.relative_error_estimate = estimate;
    if (with_shapes) {
      mode.s_m = s;
      mode.w = (s.array() * kPi * double(i + 1)).sin();
      mode.u = Vector::Zero(s.size());
    }
    modal.modes.push_back(mode);
  }
  modal.proved_count_below_top = static_cast<int>(omegas.size());
  out.inplane = modal;
  return out;
}

// The checks of `result` against the reviewed tables built into the library.
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

// The verdict of the check, or nullopt when it was not made: comparing with an expected verdict
// therefore also asserts that the check exists.
std::optional<Verdict> verdict_of(const std::vector<CheckResult>& checks,
                                  const std::string& kind,
                                  int mode) {
  const CheckResult* check = find(checks, kind, mode);
  return check ? std::optional(check->verdict) : std::nullopt;
}

TEST(Checks, FrequencyAgreementWithinEstimatesPasses) {
  SceneResult r = gale_result();
  r.outputs = {output_with("fe", {1.0, 2.0}, 1e-9),
               output_with("shooting", {1.0 + 1e-9, 2.0}, 1e-10)};
  const auto checks = run_checks(r);
  ASSERT_NE(find(checks, "frequency", 1), nullptr);
  EXPECT_EQ(verdict_of(checks, "frequency", 1), Verdict::Pass);
  EXPECT_EQ(verdict_of(checks, "statics-closure", 0), Verdict::Pass);
  EXPECT_EQ(verdict_of(checks, "mode-count", 0), Verdict::Pass);
}

TEST(Checks, APerturbedFrequencyFailsNamingEverything) {
  SceneResult r = gale_result();
  r.outputs = {output_with("fe", {1.0, 2.0 * (1 + 1e-3)}, 1e-9),
               output_with("shooting", {1.0, 2.0}, 1e-10)};
  const auto checks = run_checks(r);
  const CheckResult* c = find(checks, "frequency", 2);
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(c->verdict, Verdict::Fail);
  EXPECT_EQ(c->scene, "test-scene");
  EXPECT_EQ(c->compare, "fe vs shooting");
  EXPECT_NEAR(c->measured, 1e-3 / (1 + 1e-3), 1e-12);
  EXPECT_EQ(c->tolerance, 1e-6);  // fe's row of verification/tolerances.toml
  EXPECT_NE(c->detail.find("2.002"), std::string::npos) << c->detail;
}

TEST(Checks, NonFiniteFrequencyFailsWhateverTheTolerance) {
  SceneResult r = gale_result();
  r.outputs = {output_with("fe", {std::nan("")}, 1e-9), output_with("shooting", {1.0}, 1e-10)};
  EXPECT_EQ(verdict_of(run_checks(r), "frequency", 1), Verdict::Fail);
}

TEST(Checks, MissingModeShowsAsModeCountFailure) {
  SceneResult r = gale_result();
  r.outputs = {output_with("fe", {1.0, 2.0}, 1e-9)};
  r.outputs[0].inplane->proved_count_below_top = 3;
  EXPECT_EQ(verdict_of(run_checks(r), "mode-count", 0), Verdict::Fail);
}

TEST(Checks, PublishedValueWithinPrintedRoundingPasses) {
  SceneResult r = gale_result();
  PublishedValues p;
  p.source = "table";
  p.unit = FrequencyUnit::GaleRatio;
  p.modes = {1};
  p.values = {1.91};
  p.decimals = 2;
  r.scene.published = {p};
  r.outputs = {output_with("shooting", {1.9149}, 1e-10)};
  EXPECT_EQ(verdict_of(run_checks(r), "published", 1), Verdict::Pass);
  r.outputs = {output_with("shooting", {1.9151}, 1e-10)};
  EXPECT_EQ(verdict_of(run_checks(r), "published", 1), Verdict::Fail);
}

TEST(Checks, PublishedValueContradictedByTwoAgreeingSolversIsASourceDiscrepancy) {
  SceneResult r = gale_result();
  PublishedValues p;
  p.source = "table";
  p.unit = FrequencyUnit::GaleRatio;
  p.modes = {1};
  p.values = {2.00};
  p.decimals = 2;
  r.scene.published = {p};
  r.outputs = {output_with("frobenius", {1.9149}, 1e-12),
               output_with("shooting", {1.9149 + 1e-10}, 1e-10)};
  const auto checks = run_checks(r);
  // Both solvers are designated (no `solvers` list): one published check each, each confirmed by
  // the other.
  int published = 0;
  for (const auto& c : checks) {
    if (c.check != "published") continue;
    ++published;
    EXPECT_EQ(c.verdict, Verdict::SourceDiscrepancy) << c.compare << ": " << c.detail;
    EXPECT_NE(c.detail.find("confirmed by"), std::string::npos) << c.detail;
  }
  EXPECT_EQ(published, 2);
}

TEST(Checks, IdenticalShapesPassMacAndOrthogonalModesPassOrthogonality) {
  SceneResult r = gale_result();
  r.outputs = {output_with("fe", {1.0, 2.0, 3.0}, 1e-9, true),
               output_with("shooting", {1.0, 2.0, 3.0}, 1e-10, true)};
  const auto checks = run_checks(r);
  EXPECT_EQ(verdict_of(checks, "mac", 3), Verdict::Pass);
  EXPECT_EQ(verdict_of(checks, "shape", 3), Verdict::Pass);
  EXPECT_EQ(verdict_of(checks, "orthogonality", 0), Verdict::Pass);
  // A swapped pair of shapes fails the MAC.
  std::swap(r.outputs[0].inplane->modes[0].w, r.outputs[0].inplane->modes[1].w);
  EXPECT_EQ(verdict_of(run_checks(r), "mac", 1), Verdict::Fail);
}

// On a general line the stations do not resolve the joints and points the M-inner product needs:
// orthogonality is SKIP with that reason, never a PASS or FAIL it cannot back.
TEST(Checks, OrthogonalityOnAGeneralLineIsSkippedWithTheReason) {
  SceneResult r = gale_result();
  r.scene.problem.line = r.scene.problem.as_line();
  r.scene.problem.line.segments.push_back(r.scene.problem.line.segments.front());
  ASSERT_FALSE(r.scene.problem.is_uniform());
  r.outputs = {output_with("fe", {1.0, 2.0, 3.0}, 1e-9, true)};
  const auto checks = run_checks(r);
  const CheckResult* check = find(checks, "orthogonality", 0);
  ASSERT_NE(check, nullptr);
  EXPECT_EQ(check->verdict, Verdict::Skipped);
  EXPECT_NE(check->detail.find("general line"), std::string::npos) << check->detail;
}

// A solver output with one forced response: finite max |tau| (with its estimate), or none with a
// diagnostic.
SolverOutput forced_output(const std::string& solver, double max_tension, double estimate) {
  SolverOutput out;
  out.solver = solver;
  out.summary.solver = solver;
  out.summary.termination = Termination::Converged;
  ForcedResponse r;
  r.omega_rad_s = 100.0;
  r.max_abs_tension_n = max_tension;
  r.relative_error_estimate = estimate;
  out.forced.push_back(r);
  return out;
}

SolverOutput forced_diagnostic(const std::string& solver, bool at_resonance) {
  SolverOutput out = forced_output(solver, 0.0, -1.0);
  out.forced[0].diagnostic =
      at_resonance ? "at a natural frequency: resonance" : "beyond the series; declined";
  out.forced[0].at_resonance = at_resonance;
  return out;
}

std::vector<Verdict> forced_verdicts(const std::vector<CheckResult>& checks) {
  std::vector<Verdict> out;
  for (const auto& c : checks)
    if (c.check == "forced") out.push_back(c.verdict);
  return out;
}

TEST(Checks, AResonanceClaimAgainstUnflaggedFiniteResponsesFails) {
  // Regression: frobenius called Omega = 100 a resonance while fe and shooting agreed on 224.4 N
  // with no sign of a nearby natural frequency; the pair checks were skipped and the run passed.
  SceneResult r = gale_result();
  r.outputs = {forced_output("fe", 224.38, 2e-3), forced_output("shooting", 224.385, 1e-8),
               forced_diagnostic("frobenius", true)};
  const auto checks = run_checks(r);
  const std::vector<Verdict> verdicts = forced_verdicts(checks);
  ASSERT_EQ(verdicts.size(), 3u);  // fe-shooting, fe-frobenius, shooting-frobenius
  EXPECT_EQ(verdicts[0], Verdict::Pass);
  EXPECT_EQ(verdicts[1], Verdict::Fail);
  EXPECT_EQ(verdicts[2], Verdict::Fail);
  for (const auto& c : checks) {
    if (c.check == "forced" && c.verdict == Verdict::Fail) {
      EXPECT_NE(c.detail.find("frobenius says resonance"), std::string::npos) << c.detail;
    }
  }
}

TEST(Checks, AResonanceClaimAgainstAFlaggedNearResonanceResponseIsSkippedWithTheReason) {
  SceneResult r = gale_result();
  SolverOutput near = forced_output("shooting", 2.4e5, 8e-3);
  near.forced[0].near_resonance = true;
  r.outputs = {forced_diagnostic("fe", true), near};
  const auto checks = run_checks(r);
  ASSERT_EQ(forced_verdicts(checks), std::vector<Verdict>{Verdict::Skipped});
  EXPECT_NE(
      find(checks, "forced", 1)->detail.find("flags its finite response near a natural frequency"),
      std::string::npos);
}

TEST(Checks, ADeclinedForcingFrequencyIsSkippedNotFailed) {
  // A decline (beyond a method's resolution) is not a claim about the physics: the solver's
  // status reports it.
  SceneResult r = gale_result();
  r.outputs = {forced_output("shooting", 224.385, 1e-8), forced_diagnostic("frobenius", false)};
  const auto checks = run_checks(r);
  ASSERT_EQ(forced_verdicts(checks), std::vector<Verdict>{Verdict::Skipped});
  EXPECT_NE(find(checks, "forced", 1)->detail.find("declined"), std::string::npos);
}

// fe and shooting 1e-3 apart at Omega = 100 rad/s, with the natural frequencies of the most
// accurate exact solver set by hand: `nearest` is the natural frequency closest to 100.
SceneResult conditioned_pair(double nearest, double fe_estimate) {
  SceneResult r = gale_result();
  r.outputs = {forced_output("fe", 224.16, fe_estimate), forced_output("shooting", 224.385, 1e-8)};
  r.forced_conditioning.solver = "shooting";
  r.forced_conditioning.omegas_rad_s = {10.0, nearest, 300.0};
  return r;
}

TEST(Checks, TheForcedToleranceGrowsWithTheConditionNumberNotWithEstimates) {
  // Far from resonance (modes 10, 200, 300: kappa = 2 x 200^2 / (200^2 - 100^2) = 2.67):
  // 1e-3 > 1e-4 x 2.67, FAIL.
  SceneResult far = conditioned_pair(200.0, 1e-6);
  const std::vector<CheckResult> far_checks = run_checks(far);  // kept: `check` points into it
  const CheckResult* check = find(far_checks, "forced", 1);
  ASSERT_NE(check, nullptr);
  EXPECT_EQ(check->verdict, Verdict::Fail) << check->detail;
  EXPECT_NEAR(check->tolerance, 1e-4 * 2.0 * 4e4 / 3e4, 1e-12);
  EXPECT_NE(check->detail.find("x kappa 2.67 (from shooting's natural frequencies)"),
            std::string::npos)
      << check->detail;
  // A large estimate does not widen it.
  const std::vector<CheckResult> wide_estimate = run_checks(conditioned_pair(200.0, 0.5));
  EXPECT_EQ(find(wide_estimate, "forced", 1)->tolerance, check->tolerance);
  // Near resonance (omega_2 = 100.5: kappa = 2 x 100.5^2 / 100.25 = 201.5) the same values pass.
  const std::vector<CheckResult> near_checks = run_checks(conditioned_pair(100.5, 1e-6));
  const CheckResult* near = find(near_checks, "forced", 1);
  EXPECT_EQ(near->verdict, Verdict::Pass) << near->detail;
  EXPECT_NEAR(near->tolerance, 1e-4 * 2.0 * 100.5 * 100.5 / (100.5 * 100.5 - 1e4), 1e-12);
}

TEST(Checks, AtResonanceTheForcedCheckWarnsThatItCannotCheck) {
  // omega_2 = 100.001: kappa = 1e5, max x kappa = 10 > 0.1: not checkable, a WARN that says so.
  const std::vector<CheckResult> checks = run_checks(conditioned_pair(100.001, 1e-6));
  const CheckResult* check = find(checks, "forced", 1);
  EXPECT_EQ(check->verdict, Verdict::Warn) << check->detail;
  EXPECT_NE(check->detail.find("at resonance, not checkable"), std::string::npos) << check->detail;
  // Unless the two disagree grossly.
  SceneResult gross = conditioned_pair(100.001, 1e-6);
  gross.outputs[0].forced[0].max_abs_tension_n = 80.0;
  EXPECT_EQ(find(run_checks(gross), "forced", 1)->verdict, Verdict::Fail);
}

TEST(Checks, WithoutNaturalFrequenciesAboveTheForcingTheForcedToleranceIsTheStrictest) {
  SceneResult r = conditioned_pair(100.5, 1e-6);
  r.forced_conditioning.omegas_rad_s = {10.0, 50.0};  // nothing known above 100 rad/s
  r.forced_conditioning.note = "2 modes only";
  const std::vector<CheckResult> checks = run_checks(r);
  const CheckResult* check = find(checks, "forced", 1);
  EXPECT_EQ(check->verdict, Verdict::Fail) << check->detail;
  EXPECT_DOUBLE_EQ(check->tolerance, 1e-4);
  EXPECT_NE(check->detail.find("conditioning unknown, the strictest: 2 modes only"),
            std::string::npos);
}

const CheckResult* find_compare(const std::vector<CheckResult>& checks,
                                const std::string& kind,
                                const std::string& compare,
                                int mode) {
  for (const auto& c : checks) {
    if (c.check == kind && c.compare == compare && c.mode == mode) return &c;
  }
  return nullptr;
}

TEST(Checks, AFrequencyToleranceIsTheSameWhateverTheEstimates) {
  // The old rule max(floor, factor * (est_a + est_b)) let a solver widen its own checks.
  SceneResult r = gale_result();
  r.outputs = {output_with("fe", {1.0, 2.0}, 1e-9),
               output_with("shooting", {1.0, 2.0 * (1 + 1e-4)}, 1e-10)};
  const CheckResult honest = *find(run_checks(r), "frequency", 2);
  r.outputs[0].inplane->modes[1].relative_error_estimate = 1e-2;
  r.outputs[1].inplane->modes[1].relative_error_estimate = 1e-2;
  const CheckResult boastful = *find(run_checks(r), "frequency", 2);
  EXPECT_EQ(honest.tolerance, boastful.tolerance);
  EXPECT_EQ(honest.tolerance, 1e-6);
  EXPECT_EQ(boastful.verdict, Verdict::Fail);
}

TEST(Checks, TwoExactSolversAskedForMoreAreHeldToTheSumOfTheirTargetsNeverMore) {
  // frobenius and shooting 1e-10 apart: inside the rule (1e-9) at the defaults ...
  SceneResult r = gale_result();
  r.outputs = {output_with("shooting", {1.0, 2.0}, 1e-11),
               output_with("frobenius", {1.0, 2.0 * (1 + 1e-10)}, 1e-12)};
  EXPECT_EQ(find(run_checks(r), "frequency", 2)->verdict, Verdict::Pass);
  // ... but a scene that asked shooting for 1.1e-11 and frobenius for 1e-11 holds them to 2.1e-11.
  r.outputs[0].inplane->summary.accuracy_target = 1.1e-11;
  r.outputs[1].inplane->summary.accuracy_target = 1e-11;
  const CheckResult tight = *find(run_checks(r), "frequency", 2);
  EXPECT_DOUBLE_EQ(tight.tolerance, 2.1e-11);
  EXPECT_EQ(tight.verdict, Verdict::Fail);
  // Targets looser than the rule never widen it.
  r.outputs[0].inplane->summary.accuracy_target = 1e-3;
  EXPECT_EQ(find(run_checks(r), "frequency", 2)->tolerance, 1e-9);
}

TEST(Checks, AForcedToleranceIsTheSameWhateverTheEstimates) {
  SceneResult r = gale_result();
  r.outputs = {forced_output("fe", 224.0, 1e-6), forced_output("shooting", 224.385, 1e-8)};
  const CheckResult honest = *find(run_checks(r), "forced", 1);
  r.outputs[0].forced[0].relative_error_estimate = 0.5;
  const CheckResult boastful = *find(run_checks(r), "forced", 1);
  EXPECT_EQ(honest.tolerance, boastful.tolerance);
  EXPECT_EQ(boastful.verdict, Verdict::Fail);
}

// MoorDyn's MHK_RM1_Floating deck (issue 31): fe's estimate 3.1e-5 above the 1e-6 the frequency
// check holds it to. Declared (meets_target false, as fe marks a mode beyond its default target
// 1e-6), a difference beyond the tolerance but within the two estimates is the WARN fe announced;
// beyond the sum of the estimates it is a real disagreement (or a broken estimate) and FAILs.
TEST(Checks, ADeclaredMissWarnsWithinTheSumOfTheEstimatesAndFailsBeyondIt) {
  SceneResult r = gale_result();
  r.outputs = {output_with("fe", {1.0 * (1 + 1.9e-6), 2.0 * (1 + 2e-4)}, 3.1e-5),
               output_with("shooting", {1.0, 2.0}, 1.1e-9)};
  r.outputs[0].inplane->summary.accuracy_target = 1e-6;
  for (Mode& mode : r.outputs[0].inplane->modes) mode.meets_target = false;
  const auto checks = run_checks(r);
  const CheckResult* within = find_compare(checks, "frequency", "fe vs shooting", 1);
  ASSERT_NE(within, nullptr);
  EXPECT_EQ(within->tolerance, 1e-6);  // the rule: the estimate never widens it
  EXPECT_GT(within->measured, within->tolerance);
  EXPECT_EQ(within->verdict, Verdict::Warn);
  EXPECT_NE(within->detail.find("declared beyond its solver's accuracy target"), std::string::npos)
      << within->detail;
  const CheckResult* beyond = find_compare(checks, "frequency", "fe vs shooting", 2);
  ASSERT_NE(beyond, nullptr);
  EXPECT_EQ(beyond->verdict, Verdict::Fail);
  EXPECT_NE(beyond->detail.find("exceeds the sum of the two estimates"), std::string::npos)
      << beyond->detail;
  // Undeclared, the same estimate above the tolerance is a claim fe did not keep: FAIL.
  for (Mode& mode : r.outputs[0].inplane->modes) mode.meets_target = true;
  EXPECT_EQ(find_compare(run_checks(r), "frequency", "fe vs shooting", 1)->verdict, Verdict::Fail);
}

TEST(Checks, AnEstimateBelowTheActualErrorFails) {
  SceneResult r = gale_result();
  // fe claims 1e-9 but is 1e-7 away from shooting, which claims 1e-11.
  r.outputs = {output_with("fe", {1.0 * (1 + 1e-7)}, 1e-9), output_with("shooting", {1.0}, 1e-11)};
  const auto checks = run_checks(r);
  const CheckResult* c = find_compare(checks, "estimate", "fe vs shooting", 1);
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(c->verdict, Verdict::Fail);
  EXPECT_NEAR(c->measured, 1e-7, 1e-13);
  EXPECT_DOUBLE_EQ(c->tolerance, 1e-9 + 1e-11);
  EXPECT_NE(c->detail.find("estimate not an upper bound"), std::string::npos) << c->detail;
  // The same miss within fe's estimate plus the reference's passes.
  r.outputs[0].inplane->modes[0].relative_error_estimate = 2e-7;
  EXPECT_EQ(find_compare(run_checks(r), "estimate", "fe vs shooting", 1)->verdict, Verdict::Pass);
}

TEST(Checks, AnEstimateTenThousandTimesTheActualErrorWarns) {
  SceneResult r = gale_result();
  r.outputs = {output_with("fe", {1.0 * (1 + 1e-9)}, 1e-5), output_with("shooting", {1.0}, 1e-11)};
  const auto checks = run_checks(r);
  const CheckResult* c = find_compare(checks, "estimate", "fe vs shooting", 1);
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(c->verdict, Verdict::Warn);
  EXPECT_NE(c->detail.find("estimate uninformative"), std::string::npos) << c->detail;
  // At or below the accuracy the solver was asked for, a generous estimate is no fault.
  r.outputs[0].inplane->modes[0].relative_error_estimate = 1e-6;  // fe's accuracy in the table
  r.outputs[0].inplane->modes[0].omega_rad_s = 1.0 * (1 + 1e-10);
  EXPECT_EQ(find_compare(run_checks(r), "estimate", "fe vs shooting", 1)->verdict, Verdict::Pass);
}

TEST(Checks, AnEstimateAtTheAccuracyTargetTheSolverReportsIsNotUninformative) {
  // shooting floors its estimate at its target 10 rtol + root_tolerance (1.1e-9): against a more
  // accurate reference that is 1e4 x its actual error, but it is what the solver promised.
  SceneResult r = gale_result();
  r.outputs = {output_with("shooting", {1.0 * (1 + 1e-13)}, 1.1e-9),
               output_with("fe", {1.0}, 1e-13)};
  EXPECT_EQ(find_compare(run_checks(r), "estimate", "shooting vs fe", 1)->verdict,
            Verdict::Warn);  // rtol 1e-10
  r.outputs[0].inplane->summary.accuracy_target = 1.1e-9;
  EXPECT_EQ(find_compare(run_checks(r), "estimate", "shooting vs fe", 1)->verdict, Verdict::Pass);
  // Above the reported target it still warns.
  r.outputs[0].inplane->modes[0].relative_error_estimate = 1e-8;
  EXPECT_EQ(find_compare(run_checks(r), "estimate", "shooting vs fe", 1)->verdict, Verdict::Warn);
}

TEST(Checks, TheReferenceIsTheOtherExactSolverWithTheSmallestEstimate) {
  SceneResult r = gale_result();
  r.outputs = {output_with("fe", {1.0 + 1e-8}, 1e-7), output_with("shooting", {1.0 + 1e-10}, 1e-10),
               output_with("frobenius", {1.0}, 1e-13),
               output_with("asymptotic", {1.0 + 1e-4}, 1e-3)};
  const auto checks = run_checks(r);
  EXPECT_NE(find_compare(checks, "estimate", "fe vs frobenius", 1), nullptr);
  EXPECT_NE(find_compare(checks, "estimate", "frobenius vs shooting", 1), nullptr);  // not itself
  EXPECT_NE(find_compare(checks, "estimate", "asymptotic vs frobenius", 1), nullptr);
  EXPECT_EQ(find_compare(checks, "estimate", "fe vs asymptotic", 1),
            nullptr);  // a model is no reference
  // A reference that did not converge is not one.
  r.outputs[2].summary.termination = Termination::NoConvergence;
  EXPECT_NE(find_compare(run_checks(r), "estimate", "fe vs shooting", 1), nullptr);
}

TEST(Checks, SolversSharingAComputationAreNotComparedOnIt) {
  // A registry in which fe and shooting declare the same in-plane frequency path.
  std::vector<SolverEntry> solvers(2);
  solvers[0].name = "fe";
  solvers[1].name = "shooting";
  solvers[0].computations = {{"frequency-in-plane", "shared-path"}, {"forced", "fe-forced"}};
  solvers[1].computations = {{"frequency-in-plane", "shared-path"}, {"forced", "shooting-forced"}};
  SceneResult r = gale_result();
  r.outputs = {output_with("fe", {1.0, 2.0}, 1e-9), output_with("shooting", {1.0, 2.0}, 1e-10)};
  const auto checks = internal::run_checks(r, builtin_tolerance_table(), FindingsTable{}, solvers);
  int skips = 0;
  for (const auto& c : checks) {
    EXPECT_FALSE(c.check == "frequency" && c.verdict != Verdict::Skipped)
        << c.compare << " mode " << c.mode;
    EXPECT_NE(c.check, "estimate") << "a solver sharing the path is no reference";
    if (c.check == "frequency" && c.verdict == Verdict::Skipped) {
      ++skips;
      EXPECT_EQ(c.detail.rfind(kSharedComputationDetail, 0), 0u) << c.detail;
      EXPECT_NE(c.detail.find("shared-path"), std::string::npos) << c.detail;
    }
  }
  EXPECT_EQ(skips, 1);  // once per scene, pair and quantity, not per mode
  EXPECT_EQ(tally_independence({r}).shared_not_compared, 0);  // r.checks was not filled
  SceneResult with_checks = r;
  with_checks.checks = checks;
  EXPECT_EQ(tally_independence({with_checks}).shared_not_compared, 1);
}

TEST(Checks, BitIdenticalValuesOverAModeListAreFlaggedAsAnIdentityCheck) {
  SceneResult r = gale_result();
  // Not whole multiples of the lowest (the string limit's harmonics are left alone).
  r.outputs = {output_with("fe", {1.25, 2.6, 3.75}, 1e-9),
               output_with("shooting", {1.25, 2.6, 3.75}, 1e-10)};
  const auto checks = run_checks(r);
  const CheckResult* flag = find(checks, kIdentityCheck, 0);
  ASSERT_NE(flag, nullptr);
  EXPECT_EQ(flag->verdict, Verdict::Fail);
  EXPECT_EQ(flag->compare, "fe vs shooting");
  EXPECT_EQ(flag->measured, 3.0);
  // One value differing in its last bit makes them two witnesses again.
  r.outputs[1].inplane->modes[2].omega_rad_s = std::nextafter(3.75, 4.0);
  EXPECT_EQ(find(run_checks(r), kIdentityCheck, 0), nullptr);
}

}  // namespace
}  // namespace catena
