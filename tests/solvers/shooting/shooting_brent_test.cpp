// SPDX-License-Identifier: MIT
// Tests of Brent's zero finder (src/solvers/shooting/shooting_brent): brackets that close to the
// requested relative width around known roots, with few evaluations on smooth functions.
#include "solvers/shooting/shooting_brent.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace catena::internal {
namespace {

TEST(ShootingBrent, BracketsTheRootOfASmoothFunctionToTheTolerance) {
  // cos x = x has the root 0.7390851332151607 (Dottie number).
  const double root = 0.7390851332151607;
  int evaluations = 0;
  auto f = [&](double x) {
    ++evaluations;
    return std::cos(x) - x;
  };
  const auto [a, b] = brent_zero(f, 0.0, 1.0, f(0.0), f(1.0), 1e-10);
  EXPECT_LE(a, root);
  EXPECT_GE(b, root);
  EXPECT_LE(b - a, 1e-10 * root);
  // Superlinear convergence: far fewer than the ~33 bisections to 1e-10.
  EXPECT_LT(evaluations, 15);
}

TEST(ShootingBrent, WorksWithTheSignChangeEitherWay) {
  auto f = [](double x) { return 2.0 - x * x; };
  const auto [a, b] = brent_zero(f, 3.0, 1.0, f(3.0), f(1.0), 1e-12);
  EXPECT_LE(a, std::sqrt(2.0));
  EXPECT_GE(b, std::sqrt(2.0));
  EXPECT_LE(b - a, 1e-12 * std::sqrt(2.0));
}

TEST(ShootingBrent, ClosesOnAJump) {
  // A step function has no root, only a sign change: the bracket still closes around it.
  auto f = [](double x) { return x < 2.5 ? -1.0 : 1.0; };
  const auto [a, b] = brent_zero(f, 1.0, 4.0, -1.0, 1.0, 1e-9);
  EXPECT_LE(a, 2.5);
  EXPECT_GE(b, 2.5);
  EXPECT_LE(b - a, 2e-9 * 2.5);
}

TEST(ShootingBrent, AnExactZeroAtTheRootIsConfirmedToTheTolerance) {
  // The first secant step from (0, -1) and (2, 1) lands exactly on the root 1 of the line. Two
  // probes at 1 -+ tol/2 confirm it: the bracket is the tolerance wide around the root, not the
  // remaining half of the original bracket.
  int evaluations = 0;
  auto f = [&](double x) {
    ++evaluations;
    return x - 1.0;
  };
  const auto [a, b] = brent_zero(f, 0.0, 2.0, -1.0, 1.0, 1e-10);
  EXPECT_EQ(evaluations, 3);
  EXPECT_LE(a, 1.0);
  EXPECT_GE(b, 1.0);
  EXPECT_LE(b - a, 1.0000001e-10);
}

TEST(ShootingBrent, ASpuriousExactZeroDoesNotStopTheSearch) {
  // A noisy function that returns exactly 0 at the first secant iterate 1, while its root is
  // at 1.3: the probes next to 1 are both negative, so the search continues on (1, 2].
  auto f = [](double x) { return x == 1.0 ? 0.0 : x - 1.3; };
  const auto [a, b] = brent_zero(f, 0.0, 2.0, -1.0, 1.0, 1e-10);  // secant through (0,-1), (2,1)
  EXPECT_LE(a, 1.3);
  EXPECT_GE(b, 1.3);
  EXPECT_LE(b - a, 1e-10 * 1.3);
}

TEST(ShootingBrent, AZeroPlateauReturnsTheBracketItCannotSplit) {
  // f vanishes on all of [0.5, 1.5]: no probe decides, and the honest answer is a bracket that
  // contains the whole plateau, wider than the tolerance (the caller reports its width).
  auto f = [](double x) { return x < 0.5 ? -1.0 : (x > 1.5 ? 1.0 : 0.0); };
  const auto [a, b] = brent_zero(f, 0.0, 2.0, -1.0, 1.0, 1e-10);
  EXPECT_LE(a, 0.5);
  EXPECT_GE(b, 1.5);
}

}  // namespace
}  // namespace catena::internal
