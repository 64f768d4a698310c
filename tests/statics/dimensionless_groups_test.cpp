// SPDX-License-Identifier: MIT
// Frequency units and their conversions through the dimensionless groups.
#include "catena/statics/dimensionless_groups.hpp"

#include <gtest/gtest.h>

#include "catena/core/error.hpp"
#include "catena/statics/problem_builders.hpp"

namespace catena {
namespace {

TEST(DimensionlessGroups, UnitNamesRoundTrip) {
  for (auto unit : {FrequencyUnit::RadPerSecond, FrequencyUnit::Hertz, FrequencyUnit::KLOverPi,
                    FrequencyUnit::GaleRatio}) {
    EXPECT_EQ(parse_frequency_unit(to_string(unit)), unit);
  }
  EXPECT_EQ(parse_frequency_unit("hz"), FrequencyUnit::Hertz);
  EXPECT_FALSE(parse_frequency_unit("rpm"));
}

TEST(DimensionlessGroups, ConversionsInvertEachOther) {
  const Problem problem = make_gale_xi_problem(-1.0, 2.0);
  const DimensionlessGroups g = compute_dimensionless_groups(problem, solve_statics(problem));
  // make_gale_xi_problem sets sqrt(g/a) = 1 rad/s: Gale's ratio is omega itself.
  EXPECT_NEAR(g.gale_frequency_scale_rad_s, 1.0, 1e-12);
  EXPECT_NEAR(to_rad_per_second(1.0, FrequencyUnit::Hertz, g), 2.0 * kPi, 1e-15);
  for (auto unit : {FrequencyUnit::RadPerSecond, FrequencyUnit::Hertz, FrequencyUnit::KLOverPi,
                    FrequencyUnit::GaleRatio}) {
    EXPECT_NEAR(from_rad_per_second(to_rad_per_second(3.5, unit, g), unit, g), 3.5, 1e-13)
        << to_string(unit);
  }
}

TEST(DimensionlessGroups, GaleRatioIsUndefinedForAVerticalCable) {
  Problem vertical;
  vertical.cable = {10.0, 1.0, 1e6, 1.0, 0.0};
  vertical.supports.b_m = Vec2(0.0, 10.01);
  const DimensionlessGroups g = compute_dimensionless_groups(vertical, solve_statics(vertical));
  EXPECT_FALSE(g.has_apex_parameterization);
  EXPECT_FALSE(g.gale_ratio(1.0));
  EXPECT_THROW(to_rad_per_second(1.0, FrequencyUnit::GaleRatio, g), InvalidInput);
  EXPECT_THROW(from_rad_per_second(1.0, FrequencyUnit::GaleRatio, g), InvalidInput);
}

}  // namespace
}  // namespace catena
