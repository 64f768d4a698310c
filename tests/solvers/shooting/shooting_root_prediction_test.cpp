// SPDX-License-Identifier: MIT
// Tests of the next-root prediction of the shooting solver (src/solvers/shooting/
// shooting_root_prediction): exact on the spectra its extrapolations describe, silent where it
// has no basis, and honest about its uncertainty.
#include "solvers/shooting/shooting_root_prediction.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace catena::internal {
namespace {

TEST(RootPredictor, NothingUntilFourRootsAreKnown) {
  RootPredictor predictor(1e-10);
  for (int n = 1; n <= 3; ++n) {
    EXPECT_FALSE(predictor.next().has_value()) << n;
    predictor.add(0.5 * n);
  }
  EXPECT_FALSE(predictor.next().has_value());
  predictor.add(2.0);
  ASSERT_TRUE(predictor.next().has_value());
}

TEST(RootPredictor, EqualSpacingIsPredictedToItsFloor) {
  RootPredictor predictor(1e-10);
  for (int n = 1; n <= 6; ++n) predictor.add(0.25 * n);
  const auto prediction = predictor.next();
  ASSERT_TRUE(prediction.has_value());
  EXPECT_NEAR(prediction->omega, 1.75, 1e-14);
  EXPECT_NEAR(prediction->half_width, 1e-10 * 1.75, 1e-20);
}

TEST(RootPredictor, AlternatingSpacingUsesThePeriodTwoExtrapolation) {
  // Spacings 1.0, 1.1, 1.0, 1.1, ...: linear and quadratic extrapolation are off by 0.1, the
  // period-two one is exact.
  RootPredictor predictor(1e-12);
  double omega = 1.0;
  for (int n = 0; n < 7; ++n) {
    predictor.add(omega);
    omega += (n % 2 == 0) ? 1.0 : 1.1;
  }
  const auto prediction = predictor.next();
  ASSERT_TRUE(prediction.has_value());
  EXPECT_NEAR(prediction->omega, omega, 1e-12);
  EXPECT_LT(prediction->half_width, 1e-10);
}

TEST(RootPredictor, TheUncertaintyCoversASmoothlyChangingSpacing) {
  // Roots of omega + 0.01 omega^2 = n (a string whose phase speed grows slowly): every prediction
  // from the fourth root on lies within its half-width of the true root.
  auto root = [](int n) { return (-1.0 + std::sqrt(1.0 + 0.04 * n)) / 0.02; };
  RootPredictor predictor(1e-12);
  for (int n = 1; n <= 30; ++n) {
    if (const auto prediction = predictor.next()) {
      EXPECT_LE(std::abs(prediction->omega - root(n)), prediction->half_width) << n;
      EXPECT_LT(prediction->half_width, 0.25 * (root(n) - root(n - 1))) << n;
    }
    predictor.add(root(n));
  }
}

TEST(RootPredictor, NoPredictionWhereTheSpacingIsIrregular) {
  // An interloper (a root of another family) breaks every extrapolation: the last two errors are
  // comparable to the spacing, so nothing is predicted.
  RootPredictor predictor(1e-12);
  for (const double omega : {1.0, 2.0, 3.0, 3.2, 4.0}) predictor.add(omega);
  EXPECT_FALSE(predictor.next().has_value());
}

TEST(RootPredictor, ADoubleRootGivesNoPrediction) {
  RootPredictor predictor(1e-12);
  for (const double omega : {1.0, 2.0, 3.0, 4.0, 4.0}) predictor.add(omega);
  EXPECT_FALSE(predictor.next().has_value());
}

}  // namespace
}  // namespace catena::internal
