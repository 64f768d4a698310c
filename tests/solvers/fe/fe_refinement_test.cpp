// SPDX-License-Identifier: MIT
// fe's mesh refinement toward an accuracy target (src/solvers/fe/fe_refinement.hpp): the
// predicted mesh, its bounds, and when it stops.
#include "solvers/fe/fe_refinement.hpp"

#include <gtest/gtest.h>

namespace catena::internal {
namespace {

FeRefinementState state(std::vector<double> estimates) {
  FeRefinementState s;
  s.elements = 400;
  s.max_elements = 51200;
  s.tolerance = 1e-9;
  s.richardson = true;
  s.estimates = std::move(estimates);
  return s;
}

TEST(FeRefinement, NoTargetOrEveryModeWithinItMeansNoRefinement) {
  FeRefinementState s = state({5e-10, 1e-9, -1.0});  // -1: no estimate, which refining cannot give
  EXPECT_EQ(fe_refined_elements(s).elements, 0);
  EXPECT_TRUE(fe_refined_elements(s).stop_reason.empty());
  s.estimates = {1e-6};
  s.tolerance = 0.0;
  EXPECT_EQ(fe_refined_elements(s).elements, 0);
}

TEST(FeRefinement, PredictsTheMeshFromTheOrderOfTheEstimates) {
  // Worst miss 16x the target: (16)^(1/4) = 2 with Richardson, times the margin 1.25: 1000.
  EXPECT_EQ(fe_refined_elements(state({1e-10, 1.6e-8})).elements, 1000);
  // Without Richardson the order is 2: sqrt(16) x 1.25 = 5.
  FeRefinementState s = state({1.6e-8});
  s.richardson = false;
  EXPECT_EQ(fe_refined_elements(s).elements, 2000);
}

TEST(FeRefinement, StepsAreBetweenTwoAndEightTimesAndMultiplesOfFour) {
  EXPECT_EQ(fe_refined_elements(state({1.01e-9})).elements, 800);  // at least 2x
  EXPECT_EQ(fe_refined_elements(state({1.0})).elements, 3200);     // at most 8x
  FeRefinementState s = state({1.6e-8});
  s.elements = 402;
  EXPECT_EQ(fe_refined_elements(s).elements % 4, 0);
}

TEST(FeRefinement, StopsAtTheCapAndWhenARefinementDidNotHalveTheWorstMiss) {
  FeRefinementState s = state({1.0});
  s.max_elements = 1000;
  EXPECT_EQ(fe_refined_elements(s).elements, 1000);  // capped
  s.elements = 1000;
  const FeRefinementStep at_cap = fe_refined_elements(s);
  EXPECT_EQ(at_cap.elements, 0);
  EXPECT_NE(at_cap.stop_reason.find("max_elements = 1000"), std::string::npos)
      << at_cap.stop_reason;
  s = state({6e-9});
  s.previous_worst = 1e-8;  // fell by less than 2x: held up by a floor
  const FeRefinementStep stalled = fe_refined_elements(s);
  EXPECT_EQ(stalled.elements, 0);
  EXPECT_NE(stalled.stop_reason.find("from 1.0e-08 only to 6.0e-09"), std::string::npos)
      << stalled.stop_reason;
  s.previous_worst = 1.3e-8;
  EXPECT_GT(fe_refined_elements(s).elements, 0);
}

TEST(FeRefinement, WorstMissIgnoresModesWithinTheTargetAndWithoutAnEstimate) {
  EXPECT_DOUBLE_EQ(fe_worst_miss({1e-10, 3e-9, -1.0, 2e-9}, 1e-9), 3e-9);
  EXPECT_DOUBLE_EQ(fe_worst_miss({1e-10, -1.0}, 1e-9), 0.0);
}

}  // namespace
}  // namespace catena::internal
