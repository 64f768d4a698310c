// SPDX-License-Identifier: MIT
// The one solver skeleton: the driver's steps and the rule that combines the parts of a run.
#include "solvers/common/solver_driver.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>

#include "catena/core/error.hpp"
#include "catena/statics/problem_builders.hpp"
#include "solvers/common/solver_test_support.hpp"

namespace catena::internal {
namespace {

SolverSummary part(Termination termination,
                   const std::string& message,
                   long iterations = -1,
                   double error = -1.0) {
  SolverSummary summary;
  summary.termination = termination;
  summary.message = message;
  summary.iterations = iterations;
  summary.max_error_estimate = error;
  return summary;
}

Termination combined(std::initializer_list<Termination> terminations) {
  std::vector<SolverSummary> summaries;
  for (Termination t : terminations) summaries.push_back(part(t, "x"));
  std::vector<std::pair<std::string, const SolverSummary*>> parts;
  for (const auto& s : summaries) parts.emplace_back("p", &s);
  SolverSummary overall;
  combine_summaries(parts, overall);
  return overall.termination;
}

ModalResult plane_with_estimates(std::initializer_list<double> estimates, double target) {
  ModalResult result;
  result.plane = Plane::OutOfPlane;
  int index = 0;
  for (double estimate : estimates) {
    Mode mode;
    mode.index = ++index;
    mode.omega_rad_s = index;
    mode.relative_error_estimate = estimate;
    result.modes.push_back(mode);
  }
  result.summary = part(Termination::Converged, "Converged: 3 modes");
  result.summary.accuracy_target = target;
  return result;
}

TEST(AccuracyTarget, ModesBeyondTheTargetAreNamedAndThePlaneIsNotConverged) {
  ModalResult result = plane_with_estimates({1e-11, 2.4e-7, -1.0}, 1.1e-9);
  apply_accuracy_target(result);
  EXPECT_TRUE(result.modes[0].meets_target);
  EXPECT_FALSE(result.modes[1].meets_target);
  EXPECT_FALSE(result.modes[2].meets_target);  // no estimate: the target is not claimed
  ASSERT_EQ(result.summary.missed_modes.size(), 2u);
  EXPECT_EQ(result.summary.missed_modes[0], "mode 2: estimate 2.4e-07 > target 1.1e-09");
  EXPECT_EQ(result.summary.missed_modes[1], "mode 3: no error estimate (target 1.1e-09)");
  EXPECT_EQ(result.summary.termination, Termination::NoConvergence);
  EXPECT_EQ(result.summary.message,
            "No convergence: 2 of 3 out-of-plane modes miss the accuracy target 1.1e-09 "
            "(Converged: 3 modes)");
}

TEST(AccuracyTarget, NoTargetOrEveryModeWithinItChangesNothing) {
  for (double target : {-1.0, 1e-6}) {
    ModalResult result = plane_with_estimates({1e-11, 2.4e-7}, target);
    apply_accuracy_target(result);
    EXPECT_TRUE(result.modes[0].meets_target && result.modes[1].meets_target) << target;
    EXPECT_TRUE(result.summary.missed_modes.empty());
    EXPECT_EQ(result.summary.termination, Termination::Converged);
  }
}

TEST(AccuracyTarget, TheOverallSummaryListsEveryPlanesMissesAndTheLargestTarget) {
  SolverSummary a = part(Termination::NoConvergence, "in");
  a.accuracy_target = 1e-9;
  a.missed_modes = {"mode 1: estimate 1e-08 > target 1e-09"};
  SolverSummary b = part(Termination::Converged, "out");
  b.accuracy_target = 2e-9;
  SolverSummary overall;
  combine_summaries({{"in-plane", &a}, {"out-of-plane", &b}}, overall);
  EXPECT_DOUBLE_EQ(overall.accuracy_target, 2e-9);
  ASSERT_EQ(overall.missed_modes.size(), 1u);
  EXPECT_EQ(overall.missed_modes[0], "in-plane mode 1: estimate 1e-08 > target 1e-09");
  EXPECT_EQ(overall.termination, Termination::NoConvergence);
}

TEST(CombineSummaries, TerminationFollowsTheDocumentedRule) {
  using T = Termination;
  EXPECT_EQ(combined({T::Converged, T::Converged}), T::Converged);
  EXPECT_EQ(combined({T::Converged, T::NoConvergence}), T::NoConvergence);
  EXPECT_EQ(combined({T::Converged, T::NumericalFailure}), T::NoConvergence);
  EXPECT_EQ(combined({T::NumericalFailure, T::NumericalFailure}), T::NumericalFailure);
  EXPECT_EQ(combined({T::Converged, T::NotApplicable}), T::Converged);
  EXPECT_EQ(combined({T::NumericalFailure, T::NotApplicable}), T::NumericalFailure);
  EXPECT_EQ(combined({T::NotApplicable}), T::NotApplicable);
  EXPECT_EQ(combined({}), T::Converged);
}

TEST(CombineSummaries, SumsCountsTakesLargestEstimatesAndPrefixesWarnings) {
  SolverSummary a = part(Termination::Converged, "in ok", 3, 1e-9);
  SolverSummary b = part(Termination::Converged, "out ok", -1, 1e-7);
  b.warnings.push_back("close modes");
  SolverSummary overall;
  overall.warnings.push_back("from describe");
  combine_summaries({{"in-plane", &a}, {"out-of-plane", &b}}, overall);
  EXPECT_EQ(overall.message, "in ok; out ok");
  EXPECT_EQ(overall.iterations, 3);
  EXPECT_EQ(overall.operations, -1);
  EXPECT_DOUBLE_EQ(overall.max_error_estimate, 1e-7);
  ASSERT_EQ(overall.warnings.size(), 2u);
  EXPECT_EQ(overall.warnings[0], "from describe");
  EXPECT_EQ(overall.warnings[1], "out-of-plane: close modes");
}

// A scripted numerics: what each step does is set by the test.
class ScriptedNumerics final : public SolverNumerics {
 public:
  std::optional<std::string> reason;
  std::optional<Outcome> prepared;
  bool throw_numerical = false, throw_input = false;
  std::vector<Plane> asked;
  // Applied to each plane's (valid) result before it is returned.
  std::function<void(ModalResult&)> corrupt;
  // The forced response per metre of amplitude at every frequency: max |tau| = this, w = 1 m/m.
  std::optional<double> unit_tension_n;
  double amplitude_seen_m = 0.0;

  bool damped_modes = false, damped_forced = false;

  std::optional<std::string> not_applicable() const override { return reason; }
  bool handles_damping() const override { return damped_modes; }
  bool handles_damped_forced() const override { return damped_forced; }
  std::optional<Outcome> prepare() override { return prepared; }
  ModalResult modes(Plane plane, int count) override {
    asked.push_back(plane);
    if (throw_numerical) throw std::runtime_error("singular pivot");
    if (throw_input) throw InvalidInput("[solvers.x].k = 0: must be > 0");
    ModalResult result;
    for (int i = 1; i <= count; ++i) {
      Mode mode;
      mode.index = i;
      mode.omega_rad_s = i;
      result.modes.push_back(mode);
    }
    result.summary = part(Termination::Converged, "ok");
    if (corrupt) corrupt(result);
    return result;
  }
  ForcedOutcome forced(const ForcedRequest& request) override {
    if (!unit_tension_n) return SolverNumerics::forced(request);
    amplitude_seen_m = request.amplitude_m;
    ForcedOutcome outcome;
    for (double omega : request.omegas_rad_s) {
      ForcedResponse response;
      response.omega_rad_s = omega;
      response.s_m = Vector::LinSpaced(3, 0.0, 1.0);
      response.w = Vector::Constant(3, request.amplitude_m);
      response.tension_n = Vector::Constant(3, *unit_tension_n * request.amplitude_m);
      response.max_abs_tension_n = *unit_tension_n * request.amplitude_m;
      outcome.responses.push_back(response);
    }
    outcome.summary = part(Termination::Converged, "forced ok");
    return outcome;
  }
};

class DriveSolver : public ::testing::Test {
 protected:
  testing::SolvedProblem solved =
      testing::prepare(make_taut_inclined_problem(0.1, 20.0, 10.0, 1.0));
  SolveRequest request = testing::modes_request(3, 2);
  SolverOutput drive(ScriptedNumerics& numerics) {
    const SolveContext context{solved.problem, solved.statics, solved.groups, request};
    return drive_solver("scripted", context, numerics);
  }
};

TEST_F(DriveSolver, RunsEachRequestedPlaneInPlaneFirstAndNamesAndTimesThem) {
  ScriptedNumerics numerics;
  const SolverOutput output = drive(numerics);
  ASSERT_EQ(numerics.asked, (std::vector<Plane>{Plane::InPlane, Plane::OutOfPlane}));
  ASSERT_TRUE(output.inplane && output.outofplane);
  EXPECT_EQ(output.inplane->modes.size(), 3u);
  EXPECT_EQ(output.outofplane->plane, Plane::OutOfPlane);
  EXPECT_EQ(output.outofplane->summary.solver, "scripted");
  EXPECT_GE(output.inplane->summary.wall_time_s, 0.0);
  EXPECT_EQ(output.solver, "scripted");
  EXPECT_EQ(output.summary.termination, Termination::Converged);
  EXPECT_GE(output.summary.wall_time_s, 0.0);
}

TEST_F(DriveSolver, SkipsPlanesNotAsked) {
  request = testing::modes_request(0, 2);
  ScriptedNumerics numerics;
  const SolverOutput output = drive(numerics);
  EXPECT_EQ(numerics.asked, (std::vector<Plane>{Plane::OutOfPlane}));
  EXPECT_FALSE(output.inplane.has_value());
}

TEST_F(DriveSolver, NotApplicableStopsBeforeAnyWork) {
  ScriptedNumerics numerics;
  numerics.reason = "vertical chord";
  const SolverOutput output = drive(numerics);
  EXPECT_TRUE(numerics.asked.empty());
  EXPECT_EQ(output.summary.termination, Termination::NotApplicable);
  EXPECT_EQ(output.summary.message, "vertical chord");
}

// A damped line is never answered with undamped numbers: numerics that do not handle damping are
// declined before any work, and a forced response they cannot damp is not computed.
TEST_F(DriveSolver, DampedLinesAreDeclinedByNumericsThatDoNotHandleDamping) {
  solved.problem.cable.damping.normal_n_s_per_m2 = 0.01;
  solved.statics = solve_statics(solved.problem);  // given statics must hold the damping too
  ScriptedNumerics undamped_only;
  const SolverOutput declined = drive(undamped_only);
  EXPECT_TRUE(undamped_only.asked.empty());
  EXPECT_EQ(declined.summary.termination, Termination::NotApplicable);
  EXPECT_NE(declined.summary.message.find("damped"), std::string::npos);

  request.forced = ForcedRequest{};
  request.forced->omegas_rad_s = {0.5, 1.5};
  ScriptedNumerics modes_only;
  modes_only.damped_modes = true;
  modes_only.unit_tension_n = 2.0;
  const SolverOutput partial = drive(modes_only);
  EXPECT_EQ(modes_only.asked.size(), 2u);
  EXPECT_TRUE(partial.forced.empty());
  EXPECT_EQ(modes_only.amplitude_seen_m, 0.0);
  EXPECT_NE(partial.summary.message.find("damped forced response not computed"), std::string::npos);

  ScriptedNumerics both;
  both.damped_modes = both.damped_forced = true;
  both.unit_tension_n = 2.0;
  EXPECT_EQ(drive(both).forced.size(), 2u);
}

TEST_F(DriveSolver, APreparedOutcomeEndsTheRunWithThatStatus) {
  ScriptedNumerics numerics;
  numerics.prepared = Outcome{Termination::NoConvergence, "No convergence: too stiff"};
  const SolverOutput output = drive(numerics);
  EXPECT_TRUE(numerics.asked.empty());
  EXPECT_EQ(output.summary.termination, Termination::NoConvergence);
  EXPECT_EQ(output.summary.message, "No convergence: too stiff");
}

TEST_F(DriveSolver, NumericalExceptionsBecomeAStatusAndBadInputPropagates) {
  ScriptedNumerics failing;
  failing.throw_numerical = true;
  const SolverOutput output = drive(failing);
  EXPECT_EQ(output.summary.termination, Termination::NumericalFailure);
  EXPECT_NE(output.summary.message.find("singular pivot"), std::string::npos);
  EXPECT_EQ(output.summary.solver, "scripted");
  ScriptedNumerics bad;
  bad.throw_input = true;
  EXPECT_THROW(drive(bad), InvalidInput);
}

TEST_F(DriveSolver, ValidatesTheRequestBeforeAnything) {
  request.points = 1;
  ScriptedNumerics numerics;
  EXPECT_THROW(drive(numerics), InvalidInput);
  EXPECT_TRUE(numerics.asked.empty());
}

TEST_F(DriveSolver, AForcedRequestWithoutAForcedMethodIsReportedNotComputed) {
  ForcedRequest forced;
  forced.omegas_rad_s = {0.5, 1.0};
  request.forced = forced;
  ScriptedNumerics numerics;
  const SolverOutput output = drive(numerics);
  EXPECT_TRUE(output.forced.empty());
  EXPECT_EQ(output.summary.termination, Termination::Converged);
  ASSERT_FALSE(output.summary.warnings.empty());
  EXPECT_NE(output.summary.warnings.back().find("forced: "), std::string::npos);
}

// A wrong answer never leaves the skeleton as "converged": the driver validates every plane.
TEST_F(DriveSolver, ANegativeFrequencyIsNeverReportedConverged) {
  ScriptedNumerics numerics;
  numerics.corrupt = [](ModalResult& result) {
    if (result.modes.size() == 3) result.modes[2].omega_rad_s = -0.525;
  };
  const SolverOutput output = drive(numerics);
  EXPECT_EQ(output.inplane->summary.termination, Termination::NoConvergence);
  EXPECT_EQ(output.inplane->modes.size(), 2u);
  EXPECT_NE(output.inplane->summary.message.find("mode 3"), std::string::npos)
      << output.inplane->summary.message;
  EXPECT_EQ(output.outofplane->summary.termination, Termination::Converged);
  EXPECT_EQ(output.summary.termination, Termination::NoConvergence);
  EXPECT_NE(output.summary.message.find("not a finite positive frequency"), std::string::npos);
}

// Sorting a negative frequency first leaves no valid prefix: nothing usable in that plane.
TEST_F(DriveSolver, AnInvalidFirstModeFailsThePlane) {
  ScriptedNumerics numerics;
  numerics.corrupt = [](ModalResult& result) { result.modes[0].omega_rad_s = std::nan(""); };
  const SolverOutput output = drive(numerics);
  EXPECT_EQ(output.inplane->summary.termination, Termination::NumericalFailure);
  EXPECT_TRUE(output.inplane->modes.empty());
  EXPECT_EQ(output.outofplane->summary.termination, Termination::NumericalFailure);
  EXPECT_EQ(output.summary.termination, Termination::NumericalFailure);
}

TEST_F(DriveSolver, ForcedResponseIsSolvedForTheAmplitudesMantissaAndScaled) {
  ForcedRequest forced;
  forced.amplitude_m = 0.02;
  forced.omegas_rad_s = {0.5, 1.0};
  request.forced = forced;
  ScriptedNumerics numerics;
  numerics.unit_tension_n = 3.0;
  const SolverOutput output = drive(numerics);
  EXPECT_EQ(numerics.amplitude_seen_m,
            0.64);  // 0.02 = 0.64 / 32: the mantissa, then scaled by 2^-5
  ASSERT_EQ(output.forced.size(), 2u);
  EXPECT_DOUBLE_EQ(output.forced[0].max_abs_tension_n, 0.06);
  EXPECT_DOUBLE_EQ(output.forced[0].w[1], 0.02);
  EXPECT_DOUBLE_EQ(output.forced[0].s_m[2], 1.0);  // stations are not scaled
  EXPECT_EQ(output.summary.termination, Termination::Converged);
}

TEST_F(DriveSolver, AnOverflowingOrSilentNonFiniteForcedResponseGetsADiagnostic) {
  ForcedRequest forced;
  forced.amplitude_m = 1e308;
  forced.omegas_rad_s = {0.5};
  request.forced = forced;
  ScriptedNumerics overflowing;
  overflowing.unit_tension_n = 10.0;
  SolverOutput output = drive(overflowing);
  ASSERT_EQ(output.forced.size(), 1u);
  EXPECT_NE(output.forced[0].diagnostic.find("overflows double precision"), std::string::npos);
  EXPECT_EQ(output.forced[0].max_abs_tension_n, 0.0);
  EXPECT_EQ(output.summary.termination, Termination::NoConvergence);
  ScriptedNumerics silent;
  silent.unit_tension_n = std::numeric_limits<double>::infinity();
  request.forced->amplitude_m = 0.01;
  output = drive(silent);
  EXPECT_NE(output.forced[0].diagnostic.find("without a diagnostic"), std::string::npos);
  EXPECT_TRUE(output.forced[0].tension_n.size() == 0);
  EXPECT_EQ(output.summary.termination, Termination::NoConvergence);
}

}  // namespace
}  // namespace catena::internal
