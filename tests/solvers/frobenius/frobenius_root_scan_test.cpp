// SPDX-License-Identifier: MIT
// Tests of the frobenius solver's root finding: the Illinois refinement, the WKB mode spacing
// that sets the scan grid, and the roots of a plane (each a sign change of the determinant, close
// to the string frequencies for a nearly straight cable, ascending, with small error estimates).
#include "solvers/frobenius/frobenius_root_scan.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "catena/core/types.hpp"
#include "solvers/frobenius/frobenius_test_support.hpp"

namespace catena::internal {
namespace {

using catena::testing::frobenius_plane;

TEST(FrobeniusRootScanTest, RefineRootFindsPiToTheRequestedTolerance) {
  int iterations = -1;
  auto f = [](double x) { return std::sin(x); };
  const double root = refine_root(f, 3.0, 3.3, f(3.0), f(3.3), 1e-15, iterations);
  EXPECT_NEAR(root, kPi, 4e-15);
  EXPECT_GT(iterations, 0);
  EXPECT_LT(iterations, 60);  // superlinear: far from the 200-step cap
}

TEST(FrobeniusRootScanTest, RefineRootConvergesOnAFunctionThatDefeatsPlainRegulaFalsi) {
  // x^10 - 0.5 on [0, 1.5]: the plain method keeps one end fixed and crawls; Illinois does not.
  int iterations = -1;
  auto f = [](double x) { return std::pow(x, 10) - 0.5; };
  const double root = refine_root(f, 0.0, 1.5, f(0.0), f(1.5), 1e-14, iterations);
  EXPECT_NEAR(root, std::pow(0.5, 0.1), 1e-13);
  EXPECT_LT(iterations, 200);
}

TEST(FrobeniusRootScanTest, WkbSpacingIsTheStringSpacingForANearlyStraightCable) {
  // C = 1 to 5e-5 on sigma in [-0.01, 0.01], mu = 4: pi / (sqrt(4) 0.02).
  EXPECT_NEAR(wkb_mode_spacing(frobenius_plane(false, -0.01, 0.01, 4.0)), kPi / 0.04,
              1e-4 * kPi / 0.04);
  // A deep cable has a larger tension C towards the ends, hence faster waves and a wider spacing.
  EXPECT_GT(wkb_mode_spacing(frobenius_plane(false, -2.0, 2.0)), kPi / 4.0);
}

TEST(FrobeniusRootScanTest, OutOfPlaneRootsAreTheDeterminantsZerosNearTheStringFrequencies) {
  // A very shallow cable: Omega reaches ~800 at the top of the scan, where the double-precision
  // series overflow (their terms grow like Omega^n before decaying), so the scan must climb the
  // precision ladder rather than bracket a NaN.
  const PlaneSetup setup = frobenius_plane(false, -0.01, 0.01);
  const PlaneRoots found = find_frequencies(setup, 4, RootSettings{});
  EXPECT_NE(found.scan_precision, Precision::Double);
  ASSERT_EQ(found.roots.size(), 4u);
  WorkCounter work;
  for (std::size_t n = 0; n < 4; ++n) {
    const double omega = found.roots[n].omega;
    EXPECT_NEAR(omega, (n + 1.0) * kPi / 0.02, 1e-4 * omega) << n;
    EXPECT_LE(found.roots[n].relative_error, 1e-11) << n;
    const double below =
        scaled_determinant(Precision::LongDouble, setup, omega * (1.0 - 1e-9), work);
    const double above =
        scaled_determinant(Precision::LongDouble, setup, omega * (1.0 + 1e-9), work);
    EXPECT_LT(below * above, 0.0) << n;
    if (n > 0) {
      EXPECT_GT(omega, found.roots[n - 1].omega);
    }
  }
  EXPECT_GT(found.work.determinant_evaluations, 0);
  EXPECT_FALSE(found.notes.empty());  // the scan's precision is always noted
  EXPECT_TRUE(found.warnings.empty());
}

TEST(FrobeniusRootScanTest, WithoutExtendedPrecisionAnOverflowingRootIsDroppedWithAWarning) {
  // The same shallow cable in double only: the fourth root lies where the double series
  // overflow. It is dropped and said, never returned as NaN.
  RootSettings settings;
  settings.extended_precision = false;
  const PlaneRoots found = find_frequencies(frobenius_plane(false, -0.01, 0.01), 4, settings);
  EXPECT_EQ(found.scan_precision, Precision::Double);
  EXPECT_LT(found.roots.size(), 4u);
  for (const FoundRoot& root : found.roots) EXPECT_TRUE(std::isfinite(root.omega));
  ASSERT_FALSE(found.warnings.empty());
}

TEST(FrobeniusRootScanTest, InPlaneRootsOfASaggingCableAreFoundInOrderWithinTolerance) {
  const PlaneSetup setup = frobenius_plane(true, -0.6, 1.2);
  RootSettings settings;
  settings.tolerance = 1e-10;
  const PlaneRoots found = find_frequencies(setup, 5, settings);
  ASSERT_EQ(found.roots.size(), 5u);
  for (std::size_t n = 0; n < 5; ++n) {
    EXPECT_GT(found.roots[n].omega, 0.0);
    EXPECT_LE(found.roots[n].relative_error, 10.0 * settings.tolerance) << n;
    if (n > 0) {
      EXPECT_GT(found.roots[n].omega, found.roots[n - 1].omega);
    }
  }
  EXPECT_TRUE(found.warnings.empty());
}

}  // namespace
}  // namespace catena::internal
