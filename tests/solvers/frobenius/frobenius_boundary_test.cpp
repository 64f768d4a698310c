// SPDX-License-Identifier: MIT
// Tests of the frobenius solver's scaled boundary matrix: its shape per plane, the column
// scaling, the agreement of the three precisions, and its determinant's zeros at the frequencies
// of a nearly straight string.
#include "solvers/frobenius/frobenius_boundary.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "catena/core/types.hpp"
#include "solvers/frobenius/frobenius_test_support.hpp"

namespace catena::internal {
namespace {

using catena::testing::frobenius_plane;

TEST(FrobeniusBoundaryTest, InPlaneIsFourByFourAndOutOfPlaneTwoByTwo) {
  const auto inplane = boundary_matrix<double>(frobenius_plane(true, -0.6, 1.1), 2.0);
  const auto outofplane = boundary_matrix<double>(frobenius_plane(false, -0.6, 1.1), 2.0);
  ASSERT_EQ(inplane.a.size(), 4u);
  ASSERT_EQ(outofplane.a.size(), 2u);
  EXPECT_EQ(inplane.error.size(), 4u);
  EXPECT_EQ(inplane.column_scale.size(), 4u);
  EXPECT_TRUE(inplane.converged);
  EXPECT_GT(inplane.terms, 0);
  EXPECT_GE(inplane.centres, 1);
}

TEST(FrobeniusBoundaryTest, ColumnsAreScaledByTheNormOfEveryDerivativeAtBothEnds) {
  // The rows hold a subset of the derivatives the norm sums, so every scaled entry is at most 1,
  // and the scale itself is positive.
  const auto m = boundary_matrix<double>(frobenius_plane(true, -0.6, 1.1), 3.0);
  for (std::size_t j = 0; j < 4; ++j) {
    EXPECT_GT(m.column_scale[j], 0.0);
    double column_sum = 0.0;
    for (std::size_t i = 0; i < 4; ++i) {
      EXPECT_LE(std::abs(m.a[i][j]), 1.0) << i << " " << j;
      column_sum += m.a[i][j] * m.a[i][j];
    }
    EXPECT_GT(column_sum, 0.0) << j;
  }
  EXPECT_GE(m.cancellation, 1.0);
}

TEST(FrobeniusBoundaryTest, DeterminantAgreesInDoubleLongDoubleAndQuad) {
  // A shallow cable (little cancellation): the three precisions agree to the series cut.
  const PlaneSetup setup = frobenius_plane(true, -0.5, 0.8);
  WorkCounter work;
  const double d = scaled_determinant(Precision::Double, setup, 2.7, work);
  const double ld = scaled_determinant(Precision::LongDouble, setup, 2.7, work);
  const double q = scaled_determinant(Precision::Quad, setup, 2.7, work);
  EXPECT_NE(d, 0.0);
  EXPECT_NEAR(d, q, 1e-10 * std::abs(q));
  EXPECT_NEAR(ld, q, 1e-10 * std::abs(q));
  EXPECT_EQ(work.determinant_evaluations, 3);
  EXPECT_FALSE(work.truncated);
}

TEST(FrobeniusBoundaryTest, OutOfPlaneDeterminantVanishesAtTheTautStringFrequencies) {
  // sigma in [-0.01, 0.01]: C = 1 to 5e-5, so the out-of-plane problem is the taut string
  // U'' + Omega^2 U = 0 on a length 0.02 (mu = 1): roots Omega_n ~ n pi / 0.02, to ~1e-4.
  const PlaneSetup setup = frobenius_plane(false, -0.01, 0.01);
  WorkCounter work;
  for (int n = 1; n <= 3; ++n) {
    const double omega = n * kPi / 0.02;
    const double below = scaled_determinant(Precision::Double, setup, omega * 0.99, work);
    const double above = scaled_determinant(Precision::Double, setup, omega * 1.01, work);
    EXPECT_LT(below * above, 0.0) << n;
  }
}

}  // namespace
}  // namespace catena::internal
