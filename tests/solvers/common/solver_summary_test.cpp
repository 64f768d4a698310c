// SPDX-License-Identifier: MIT
// SolverSummary: the termination names written to report.json, which terminations carry results,
// and the one-line and several-line reports (fields shown only when they were counted or measured).
#include "catena/solvers/solver_summary.hpp"

#include <gtest/gtest.h>

#include <string>

namespace catena {
namespace {

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

SolverSummary converged_summary() {
  SolverSummary summary;
  summary.termination = Termination::Converged;
  summary.message = "6 of 6 modes";
  summary.solver = "fe";
  return summary;
}

TEST(SolverSummary, TerminationNamesAreTheDocumentedOnes) {
  EXPECT_EQ(to_string(Termination::Converged), "converged");
  EXPECT_EQ(to_string(Termination::NoConvergence), "no-convergence");
  EXPECT_EQ(to_string(Termination::NumericalFailure), "numerical-failure");
  EXPECT_EQ(to_string(Termination::NotApplicable), "not-applicable");
}

TEST(SolverSummary, DefaultMeansNeverRanAndIsNotUsable) {
  const SolverSummary summary;
  EXPECT_EQ(summary.termination, Termination::NumericalFailure);
  EXPECT_EQ(summary.message, "solve() was not called.");
  EXPECT_FALSE(summary.is_usable());
  EXPECT_EQ(summary.iterations, -1);
  EXPECT_EQ(summary.operations, -1);
  EXPECT_EQ(summary.max_error_estimate, -1.0);
  EXPECT_EQ(summary.max_residual, -1.0);
  EXPECT_EQ(summary.wall_time_s, -1.0);
}

TEST(SolverSummary, UsableOnlyWithResults) {
  SolverSummary summary;
  summary.termination = Termination::Converged;
  EXPECT_TRUE(summary.is_usable());
  summary.termination = Termination::NoConvergence;  // partial results are still results
  EXPECT_TRUE(summary.is_usable());
  summary.termination = Termination::NumericalFailure;
  EXPECT_FALSE(summary.is_usable());
  summary.termination = Termination::NotApplicable;
  EXPECT_FALSE(summary.is_usable());
}

TEST(SolverSummary, BriefReportWithoutResolutionOrTimeIsSolverTerminationMessage) {
  EXPECT_EQ(converged_summary().brief_report(), "fe: converged: 6 of 6 modes");
  SolverSummary declined;
  declined.termination = Termination::NotApplicable;
  declined.solver = "frobenius";
  declined.message = "EA is finite";
  EXPECT_EQ(declined.brief_report(), "frobenius: not-applicable: EA is finite");
}

TEST(SolverSummary, BriefReportAddsResolutionAndTimeInMilliseconds) {
  SolverSummary summary = converged_summary();
  summary.resolution = "N = 800 and 1600 elements";
  summary.wall_time_s = 0.0123;
  EXPECT_EQ(summary.brief_report(),
            "fe: converged: 6 of 6 modes (N = 800 and 1600 elements) [12.3 ms]");
  // A time of exactly zero was measured (>= 0): it is shown.
  summary.resolution.clear();
  summary.wall_time_s = 0.0;
  EXPECT_EQ(summary.brief_report(), "fe: converged: 6 of 6 modes [0 ms]");
}

TEST(SolverSummary, FullReportOfAnUncountedRunIsTheBriefLine) {
  const SolverSummary summary = converged_summary();
  EXPECT_EQ(summary.full_report(), summary.brief_report() + "\n");
}

TEST(SolverSummary, FullReportListsCountsEstimatesNotesThenWarnings) {
  SolverSummary summary = converged_summary();
  summary.iterations = 7;
  summary.operations = 0;
  summary.max_error_estimate = 3.1e-12;
  summary.max_residual = 0.0;
  summary.notes = {"mode count proved by Sylvester inertia: 6"};
  summary.warnings = {"kappa penalty used"};
  EXPECT_EQ(summary.full_report(),
            "fe: converged: 6 of 6 modes\n"
            "  iterations: 7\n"
            "  operations: 0\n"
            "  max relative error estimate: 3.100e-12\n"
            "  max residual: 0.000e+00\n"
            "  note: mode count proved by Sylvester inertia: 6\n"
            "  warning: kappa penalty used\n");
}

TEST(SolverSummary, FullReportLeavesOutWhatWasNotCounted) {
  SolverSummary summary = converged_summary();
  summary.operations = 42;
  const std::string text = summary.full_report();
  EXPECT_TRUE(contains(text, "  operations: 42\n")) << text;
  EXPECT_FALSE(contains(text, "iterations")) << text;
  EXPECT_FALSE(contains(text, "error estimate")) << text;
  EXPECT_FALSE(contains(text, "residual")) << text;
  EXPECT_FALSE(contains(text, "note:")) << text;
  EXPECT_FALSE(contains(text, "warning:")) << text;
}

}  // namespace
}  // namespace catena
