// SPDX-License-Identifier: MIT
// One part of a run measured against the run's budget: when it stops, what it reports, and the
// message a stopped part carries.
#include "solvers/common/work_meter.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <string>
#include <tuple>
#include <vector>

namespace catena {
namespace {

RunLimits expired_limits() {
  RunLimits limits;
  limits.deadline = RunLimits::Clock::now() - std::chrono::seconds(1);
  limits.time_limit_s = 0.5;
  return limits;
}

TEST(WorkMeter, NeverStopsWithoutLimitsOrWhenThePartIsDone) {
  internal::WorkMeter unlimited(nullptr, "x", "things", 3);
  EXPECT_FALSE(unlimited.stop_after(1));
  const RunLimits limits = expired_limits();
  internal::WorkMeter last(&limits, "x", "things", 3);
  EXPECT_FALSE(last.stop_after(3));  // nothing left to skip
  EXPECT_TRUE(last.message().empty());
  internal::WorkMeter early(&limits, "x", "things", 3);
  EXPECT_TRUE(early.stop_after(1));
  EXPECT_EQ(early.message(), "time limit of 0.5 s reached after 1 of 3 things");
  SolverSummary summary;
  summary.termination = Termination::Converged;
  summary.message = "Converged: 1 of 1 things";
  internal::mark_time_limit(early, summary);
  EXPECT_EQ(summary.termination, Termination::NoConvergence);
  EXPECT_EQ(summary.message,
            "No convergence: time limit of 0.5 s reached after 1 of 3 things; 1 of 1 things");
}

TEST(WorkMeter, ReportsEachUnitToTheProgressCallback) {
  std::vector<std::tuple<std::string, std::string, long, long>> calls;
  RunLimits limits;
  limits.progress = [&](const std::string& solver, const std::string& part, long done, long total) {
    calls.emplace_back(solver, part, done, total);
  };
  internal::WorkMeter meter(&limits, "shooting", "in-plane modes", 2);
  EXPECT_FALSE(meter.stop_after(1));
  EXPECT_FALSE(meter.stop_after(2));
  ASSERT_GE(calls.size(), 2u);
  EXPECT_EQ(std::get<0>(calls.back()), "shooting");
  EXPECT_EQ(std::get<1>(calls.back()), "in-plane modes");
  EXPECT_EQ(std::get<2>(calls.back()), 2);
  EXPECT_EQ(std::get<3>(calls.back()), 2);
  EXPECT_EQ(meter.done(), 2);
  EXPECT_FALSE(meter.stopped());
}

TEST(WorkMeter, AStoppedMeterStaysStoppedAndAnUnstoppedOneLeavesTheSummaryAlone) {
  const RunLimits limits = expired_limits();
  internal::WorkMeter meter(&limits, "fe", "levels", 4);
  EXPECT_TRUE(meter.stop_after(1));
  EXPECT_TRUE(meter.stop_after(2));
  EXPECT_TRUE(meter.stopped());
  internal::WorkMeter unlimited(nullptr, "fe", "levels", 4);
  SolverSummary summary;
  summary.termination = Termination::Converged;
  summary.message = "Converged";
  internal::mark_time_limit(unlimited, summary);
  EXPECT_EQ(summary.termination, Termination::Converged);
  EXPECT_EQ(summary.message, "Converged");
}

}  // namespace
}  // namespace catena
