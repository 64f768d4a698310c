// SPDX-License-Identifier: MIT
// The mode counts of the forced conditioning's solve
// (src/verification/internal/forced_conditioning_solve.hpp): skipping counts must not change the
// list the doubling keeps.
#include "verification/internal/forced_conditioning_solve.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace catena::internal {
namespace {

// omega_n = n (a string's spacing) for the lowest `count` modes.
std::vector<double> string_modes(int count) {
  std::vector<double> omegas;
  for (int n = 1; n <= count; ++n) omegas.push_back(static_cast<double>(n));
  return omegas;
}

TEST(ForcedConditioningSolve, TheDoublingStopsAtTheFirstCountWhoseTopModeLiesAbove) {
  const std::vector<double> modes = string_modes(64);
  EXPECT_EQ(doubling_count(modes, 7.5), 8u);
  EXPECT_EQ(doubling_count(modes, 8.0), 16u);  // the top mode must lie above, not at
  EXPECT_EQ(doubling_count(modes, 20.0), 32u);
  EXPECT_EQ(doubling_count(modes, 40.0), 64u);
  EXPECT_EQ(doubling_count(modes, 100.0), 64u);             // none above: the largest tried
  EXPECT_EQ(doubling_count(string_modes(40), 100.0), 40u);  // a solver that returned fewer
  EXPECT_EQ(doubling_count({}, 1.0), 0u);
}

TEST(ForcedConditioningSolve, TheNextCountSkipsOnlyCountsPredictedTooLow) {
  EXPECT_EQ(next_count(8, 8.0, 10.0), 16);   // the doubling's own next count
  EXPECT_EQ(next_count(8, 8.0, 30.0), 32);   // 16 modes would reach about 16
  EXPECT_EQ(next_count(8, 8.0, 105.0), 64);  // never beyond the largest count
  EXPECT_EQ(next_count(32, 32.0, 40.0), 64);
  EXPECT_EQ(next_count(8, 0.0, 10.0), 16);  // no modes to extrapolate from
}

TEST(ForcedConditioningSolve, SkippingAndCuttingBackKeepsTheDoublingsList) {
  // Modes that grow faster than linearly at first (a raised first mode) and then as a string.
  std::vector<double> modes = string_modes(64);
  for (double& w : modes) w += 3.0;
  for (const double top : {9.0, 12.0, 18.0, 30.0, 50.0, 70.0}) {
    // The plain doubling: 8, 16, 32, 64 until the top mode lies above `top`.
    std::size_t plain = 8;
    while (plain < 64 && modes[plain - 1] <= top) plain *= 2;
    // The skipping search: from 8, next_count, then cut back.
    int count = 8;
    while (count < 64 && modes[static_cast<std::size_t>(count) - 1] <= top)
      count = next_count(count, modes[static_cast<std::size_t>(count) - 1], top);
    const std::vector<double> solved(modes.begin(), modes.begin() + count);
    EXPECT_EQ(doubling_count(solved, top), plain) << "top " << top;
  }
}

}  // namespace
}  // namespace catena::internal
