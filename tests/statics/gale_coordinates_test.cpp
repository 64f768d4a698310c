// SPDX-License-Identifier: MIT
#include "catena/statics/gale_coordinates.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace catena {
namespace {

TEST(GaleCoordinates, XiFromSigmaMatchesDefinition) {
  // xi = sign(sigma)(sqrt(1 + sigma^2) - 1): sigma = 3/4 gives sqrt(25/16) - 1 = 1/4 exactly.
  EXPECT_DOUBLE_EQ(gale_xi_from_sigma(0.75), 0.25);
  EXPECT_DOUBLE_EQ(gale_xi_from_sigma(-0.75), -0.25);
  EXPECT_EQ(gale_xi_from_sigma(0.0), 0.0);
}

TEST(GaleCoordinates, SigmaFromXiInvertsXiFromSigma) {
  for (double sigma : {-1e3, -2.5, -1e-9, 1e-9, 0.3, 7.0, 1e4}) {
    const double round_trip = gale_sigma_from_xi(gale_xi_from_sigma(sigma));
    EXPECT_NEAR(round_trip, sigma, 1e-14 * std::abs(sigma)) << "sigma = " << sigma;
  }
}

TEST(GaleCoordinates, SmallSigmaKeepsItsDigits) {
  // The naive sqrt(1 + s^2) - 1 returns 0 for s = 1e-9; the cancellation-free form gives s^2/2.
  EXPECT_NEAR(gale_xi_from_sigma(1e-9), 0.5e-18, 1e-32);
}

}  // namespace
}  // namespace catena
