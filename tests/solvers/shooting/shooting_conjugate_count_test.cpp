// SPDX-License-Identifier: MIT
// Tests of conjugate-point counting (src/solvers/shooting/shooting_conjugate_count) on frames of
// uncoupled strings, whose conjugate points and phase are known in closed form: for
// Phi' = k F, F' = -k Phi from Phi = 0, F = 1 the solution is Phi = sin(k x), F = cos(k x),
// Z = Phi + i F = i e^{-i k x}, so theta = pi/2 - k x (unwrapped) and the conjugate points on
// (0, x] are the floor(k x / pi) zeros of sin.
#include "solvers/shooting/shooting_conjugate_count.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>

#include "catena/core/types.hpp"

namespace catena::internal {
namespace {

TEST(ShootingConjugateCount, ScalarStringCountsTheZerosOfSine) {
  for (double x : {0.3, 2.0, 3.5, 7.0, 10.0, 30.0}) {
    FrameBlock<1> Phi, F;
    Phi(0, 0) = std::sin(x);
    F(0, 0) = std::cos(x);
    const ConjugateCount c = count_conjugate_points<1>(Phi, F, initial_phase(1) - x);
    EXPECT_EQ(c.count, static_cast<int>(std::floor(x / kPi))) << x;
    EXPECT_NEAR(c.determinant, std::sin(x), 1e-14) << x;
    EXPECT_NEAR(c.phase_defect, 0.0, 1e-12) << x;
    // The continuous count (Pruefer) passes n exactly at the n-th zero: below it negative, above
    // it positive, and equal to x / pi - n in between.
    const int n = static_cast<int>(std::floor(x / kPi)) + 1;
    const double h = count_function(c.count, c.angle_min, c.angle_max, n);
    EXPECT_NEAR(h, x / kPi - n, 1e-12) << x;
  }
}

TEST(ShootingConjugateCount, PhaseErrorBelowPiOnlyShowsAsDefect) {
  FrameBlock<1> Phi, F;
  const double x = 5.0;
  Phi(0, 0) = std::sin(x);
  F(0, 0) = std::cos(x);
  const ConjugateCount c = count_conjugate_points<1>(Phi, F, initial_phase(1) - x + 0.4);
  EXPECT_EQ(c.count, 1);
  EXPECT_NEAR(c.phase_defect, 0.4, 1e-12);
}

// Two uncoupled strings with wavenumbers 1 and 2, seen in a rotated frame (R Phi, R F with R a
// rotation: the determinant, G and the eigen-angles of U are unchanged).
TEST(ShootingConjugateCount, TwoStringsCountBothFamiliesInAnyFrame) {
  const double angle = 0.7;
  Eigen::Matrix2d R;
  R << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
  for (double x : {0.5, 1.7, 3.3, 4.0, 6.5, 9.9}) {
    FrameBlock<2> Phi = FrameBlock<2>::Zero(), F = FrameBlock<2>::Zero();
    Phi(0, 0) = std::sin(x);
    Phi(1, 1) = std::sin(2.0 * x);
    F(0, 0) = std::cos(x);
    F(1, 1) = std::cos(2.0 * x);
    const double theta = initial_phase(2) - 3.0 * x;
    const ConjugateCount c = count_conjugate_points<2>(R * Phi, R * F, theta);
    const int expected = static_cast<int>(std::floor(x / kPi) + std::floor(2.0 * x / kPi));
    EXPECT_EQ(c.count, expected) << x;
    EXPECT_NEAR(c.determinant, std::sin(x) * std::sin(2.0 * x), 1e-13) << x;
    EXPECT_LE(c.angle_min, c.angle_max);
    EXPECT_GE(c.angle_min, kPi - 1e-12);
    EXPECT_LT(c.angle_max, 3.0 * kPi);
  }
}

TEST(ShootingConjugateCount, StartingFrameHasNoConjugatePoint) {
  // Phi = 0, F = I: every eigen-angle at pi, counted as not yet crossed.
  const ConjugateCount c =
      count_conjugate_points<2>(FrameBlock<2>::Zero(), FrameBlock<2>::Identity(), initial_phase(2));
  EXPECT_EQ(c.count, 0);
  EXPECT_NEAR(c.angle_min, kPi, 1e-9);
  EXPECT_NEAR(c.angle_max, kPi, 1e-9);
  EXPECT_EQ(c.determinant, 0.0);
}

TEST(ShootingConjugateCount, CountFunctionUsesTheAngleOnTheSideOfTheMode) {
  // Below mode n (count < n) the largest angle leads; at or above it the smallest.
  EXPECT_DOUBLE_EQ(count_function(1, kPi, 2.0 * kPi, 2), -1.0 + 0.5);
  EXPECT_DOUBLE_EQ(count_function(2, 1.5 * kPi, 2.0 * kPi, 2), 0.25);
}

}  // namespace
}  // namespace catena::internal
