// SPDX-License-Identifier: MIT
// Tests of the frobenius solver's conjugate-point count: the number of natural frequencies below
// omega, whatever the root scan found.
#include "solvers/frobenius/frobenius_conjugate_points.hpp"

#include <gtest/gtest.h>

#include "solvers/frobenius/frobenius_test_support.hpp"

namespace catena::internal {
namespace {

using catena::testing::frobenius_plane;

TEST(FrobeniusConjugatePointsTest, CountsTheFrequenciesBelowOmega) {
  const PlaneSetup setup = frobenius_plane(true, -0.6, 1.2);
  const PlaneRoots found = find_frequencies(setup, 4, RootSettings{});
  ASSERT_EQ(found.roots.size(), 4u);
  EXPECT_EQ(conjugate_point_count(Precision::Double, setup, 0.5 * found.roots[0].omega, 600), 0);
  for (std::size_t n = 0; n + 1 < 4; ++n) {
    const double between = 0.5 * (found.roots[n].omega + found.roots[n + 1].omega);
    EXPECT_EQ(conjugate_point_count(Precision::Double, setup, between, 600),
              static_cast<int>(n) + 1)
        << n;
  }
  // The same count in long double.
  const double above_all = found.roots[3].omega * 1.01;
  EXPECT_EQ(conjugate_point_count(Precision::LongDouble, setup, above_all, 600), 4);
}

TEST(FrobeniusConjugatePointsTest, ConfirmsACompleteScanAndNotesIt) {
  const PlaneSetup setup = frobenius_plane(true, -0.6, 1.2);
  PlaneRoots found = find_frequencies(setup, 3, RootSettings{});
  const std::size_t notes = found.notes.size();
  EXPECT_EQ(confirm_inplane_count(setup, 3, RootSettings{}, found), 3);
  ASSERT_EQ(found.notes.size(), notes + 1);
  EXPECT_NE(found.notes.back().find("conjugate points"), std::string::npos);
}

TEST(FrobeniusConjugatePointsTest, AScanThatMissedARootIsRepeatedFiner) {
  // Drop the second root, as a too-coarse scan would: the count just above the highest root
  // (the third) is 3, not 2, so the plane is rescanned finer and all three are found.
  const PlaneSetup setup = frobenius_plane(true, -0.6, 1.2);
  PlaneRoots found = find_frequencies(setup, 3, RootSettings{});
  ASSERT_EQ(found.roots.size(), 3u);
  const double second = found.roots[1].omega;
  found.roots.erase(found.roots.begin() + 1);
  EXPECT_EQ(confirm_inplane_count(setup, 3, RootSettings{}, found), 3);
  ASSERT_EQ(found.roots.size(), 3u);
  EXPECT_NEAR(found.roots[1].omega, second, 1e-10 * second);
  bool rescanned = false;
  for (const auto& note : found.notes)
    rescanned = rescanned || note.find("rescanned") != std::string::npos;
  EXPECT_TRUE(rescanned);
}

}  // namespace
}  // namespace catena::internal
