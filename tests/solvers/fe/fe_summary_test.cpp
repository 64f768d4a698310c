// SPDX-License-Identifier: MIT
// fe summary text (src/solvers/fe/fe_summary.cpp): the resolution names every mesh and
// penalty, the inextensible warning states the penalties, and the forced message counts.
#include "solvers/fe/fe_summary.hpp"

#include <gtest/gtest.h>

#include <string>

namespace catena {
namespace {

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(FeSummary, SecondsInMicrosecondsOrMilliseconds) {
  EXPECT_EQ(internal::format_seconds(12.34e-6), "12.3 us");
  EXPECT_EQ(internal::format_seconds(0.0045678), "4.568 ms");
}

TEST(FeSummary, ResolutionNamesMeshesAndPenalties) {
  internal::FePlan plan;
  plan.meshes = {400, 800};
  plan.richardson = true;
  plan.axial_stiffness_n = {1e6};
  EXPECT_EQ(internal::fe_resolution(plan), "N = 400, 800 elements, Richardson (order 2 -> 4)");
  SolverSummary extensible;
  internal::describe_fe_run(plan, extensible);
  EXPECT_EQ(extensible.resolution, internal::fe_resolution(plan));
  EXPECT_TRUE(extensible.warnings.empty());

  plan.richardson = false;
  plan.inextensible = true;
  plan.kappas = {1e-6, 2e-6};
  plan.axial_stiffness_n = {5e6, 2.5e6};
  EXPECT_TRUE(contains(internal::fe_resolution(plan),
                       "no Richardson; penalty kappa = 1.0e-06 and 2.0e-06"));
  SolverSummary inextensible;
  internal::describe_fe_run(plan, inextensible);
  ASSERT_EQ(inextensible.warnings.size(), 1u);
  EXPECT_TRUE(contains(inextensible.warnings[0], "EA = H/kappa = 5.0000e+06 N and 2.5000e+06 N"));
}

TEST(FeSummary, RoundingFloorDeclineStatesTheNumbers) {
  internal::FePlan plan;
  plan.meshes = {4000, 8000};
  plan.main_fine = 1;
  plan.axial_stiffness_n = {1e8};
  const std::string text = internal::fe_rounding_floor_decline(plan, 1.0, 1e-2);
  EXPECT_TRUE(contains(text, "EA/T0 = 1.00e+08")) << text;
  EXPECT_TRUE(contains(text, "N = 8000 elements")) << text;
  EXPECT_TRUE(contains(text, "(> 1e-02)")) << text;
}

TEST(FeSummary, ForcedMessageCountsResponsesAndResonances) {
  internal::ForcedOutcome outcome;
  outcome.responses.resize(3);
  outcome.responses[1].diagnostic = "resonance";
  outcome.responses[1].at_resonance = true;
  internal::FeTimings timings;
  timings.forced_s = 2e-3;
  internal::ForcedOutcome declined = outcome;
  internal::describe_forced(outcome, timings);
  EXPECT_EQ(outcome.summary.termination, Termination::Converged);
  EXPECT_EQ(outcome.summary.message,
            "Converged: 2 of 3 forced frequencies (1 at resonance: no finite response)");
  ASSERT_EQ(outcome.summary.notes.size(), 1u);
  EXPECT_EQ(outcome.summary.notes[0], "time: forced response 2.000 ms");
  // A frequency beyond what the mesh resolves has no answer: the forced part did not converge.
  declined.responses[2].diagnostic = "beyond the mesh";
  internal::describe_forced(declined, timings);
  EXPECT_EQ(declined.summary.termination, Termination::NoConvergence);
  EXPECT_EQ(declined.summary.message,
            "No convergence: 1 of 3 forced frequencies (1 at resonance: no finite response); 1 "
            "declined, e.g. beyond the mesh");
}

}  // namespace
}  // namespace catena
