// SPDX-License-Identifier: MIT
// Tests of the shooting root finder (src/solvers/shooting/shooting_root_finder) on synthetic
// shots whose counts and end functions are exact: strings with known eigenfrequencies, including
// an exactly double root, so that any skipped, duplicated or misplaced mode shows.
#include "solvers/shooting/shooting_root_finder.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "catena/core/types.hpp"
#include "shooting_test_strings.hpp"
#include "solvers/shooting/shooting_conjugate_count.hpp"

namespace catena::internal {
namespace {

// A monotone, nonlinear "phase speed" g(omega) = omega + 0.2 sin(omega): nonlinear so that no
// secant step lands exactly on a root (an exact zero stops Brent with the remaining bracket).
double g(double omega) { return omega + 0.2 * std::sin(omega); }

// The omega with g(omega) = target (Newton; g' >= 0.8).
double g_inverse(double target) {
  double omega = target;
  for (int i = 0; i < 60; ++i) omega -= (g(omega) - target) / (1.0 + 0.2 * std::cos(omega));
  return omega;
}

// The exact end frame of strings with phases pi * rates[j] * g(omega) on a unit length: the
// eigenfrequencies of string j are g_inverse(n / rates[j]).
template <int D, typename Phase>
Shot string_shot_with(Phase phase, double omega, const double (&rates)[D], long& shots) {
  ++shots;
  return testing::exact_string_frame<D>(phase, omega, rates);
}

template <int D>
Shot string_shot(double omega, const double (&rates)[D], long& shots) {
  return string_shot_with<D>(g, omega, rates, shots);
}

// A string whose phase speed grows slowly, p(omega) = omega + c omega^2 (roots where
// rate * p = n): smoothly changing spacing, as on a real cable; c = 0.0123 puts no root on a
// round number that a bisection could hit exactly.
constexpr double kGrowth = 0.0123;
double slow_phase(double omega) { return omega + kGrowth * omega * omega; }
double slow_phase_root(double target) {
  return (-1.0 + std::sqrt(1.0 + 4.0 * kGrowth * target)) / (2.0 * kGrowth);
}

RootFinderSettings settings(double tolerance) {
  RootFinderSettings s;
  s.relative_tolerance = tolerance;
  s.root_tolerance = tolerance;
  s.error_estimate = true;
  return s;
}

TEST(ShootingRootFinder, ScalarStringModesAreFoundInOrderToTheTolerance) {
  long shots = 0;
  const double rates[1] = {1.0};
  ShootingRootFinder finder(
      [&](double omega, double) { return string_shot<1>(omega, rates, shots); }, settings(1e-12),
      2.3, true);
  std::vector<std::string> warnings;
  const std::vector<Root> roots = finder.find(5, warnings);
  EXPECT_TRUE(warnings.empty());
  ASSERT_EQ(roots.size(), 5u);
  for (std::size_t i = 0; i < roots.size(); ++i) {
    const double exact = g_inverse(i + 1.0);
    EXPECT_NEAR(roots[i].omega, exact, 1e-11 * exact) << i;
    EXPECT_EQ(roots[i].multiplicity, 1);
    EXPECT_LE(roots[i].relative_error, 1e-11);
    EXPECT_LE(roots[i].residual, 1e-10);
  }
  EXPECT_EQ(finder.shots(), shots);
  EXPECT_GE(finder.proved_count(), 5);
  EXPECT_EQ(finder.phase_retries(), 0);
}

TEST(ShootingRootFinder, DoubleRootIsOneRootOfMultiplicityTwo) {
  // Rates 1 and 2: eigenfrequencies at g = 0.5, 1 (both strings), 1.5, 2 (both), ...: at g = 1
  // the end determinant sin(pi g) sin(2 pi g) touches zero without a sign change; only the count
  // (1 below, 3 above) finds the pair.
  long shots = 0;
  const double rates[2] = {1.0, 2.0};
  ShootingRootFinder finder(
      [&](double omega, double) { return string_shot<2>(omega, rates, shots); }, settings(1e-10),
      1.2, false);
  std::vector<std::string> warnings;
  const std::vector<Root> roots = finder.find(4, warnings);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  ASSERT_EQ(roots.size(), 3u);
  EXPECT_NEAR(roots[0].omega, g_inverse(0.5), 1e-9);
  EXPECT_EQ(roots[0].multiplicity, 1);
  EXPECT_NEAR(roots[1].omega, g_inverse(1.0), 1e-9);
  EXPECT_EQ(roots[1].multiplicity, 2);
  EXPECT_NEAR(roots[2].omega, g_inverse(1.5), 1e-9);
  EXPECT_EQ(roots[2].multiplicity, 1);
}

TEST(ShootingRootFinder, AFailingShotPropagatesAsShootingFailure) {
  ShootingRootFinder finder([](double, double) -> Shot { throw ShootingFailure("CVode failed"); },
                            settings(1e-10), 1.0, true);
  std::vector<std::string> warnings;
  EXPECT_THROW(finder.find(1, warnings), ShootingFailure);
}

TEST(ShootingRootFinder, AWrongPhaseIsReShotAtTighterTolerance) {
  // The first shot at each frequency reports a phase defect above the limit; the finder re-shoots
  // at 1/100 of the tolerances and uses that shot.
  long shots = 0;
  const double rates[1] = {1.0};
  std::vector<double> factors;
  ShootingRootFinder finder(
      [&](double omega, double factor) {
        factors.push_back(factor);
        Shot shot = string_shot<1>(omega, rates, shots);
        if (factor == 1.0) shot.phase_defect = 1.0;
        return shot;
      },
      settings(1e-10), 1.5, true);
  std::vector<std::string> warnings;
  const std::vector<Root> roots = finder.find(1, warnings);
  ASSERT_EQ(roots.size(), 1u);
  // Here Brent meets an exact zero of the count function (the end angle exactly pi) and stops
  // with a bracket ~5e-4 wide: the root is then only as good as that bracket, and its error
  // estimate must say so.
  const double exact = g_inverse(1.0);
  EXPECT_LE(std::abs(roots[0].omega - exact), roots[0].relative_error * exact);
  EXPECT_LT(roots[0].relative_error, 1e-3);
  EXPECT_GT(finder.phase_retries(), 0);
  EXPECT_NE(std::find(factors.begin(), factors.end(), 0.01), factors.end());
}

TEST(ShootingRootFinder, ShotsPerModeOnASmoothSpectrumAreBounded) {
  // 30 modes of a string with slowly changing spacing, one and two components (the second, a
  // slow string standing in for a cable's axial direction, has no root among them: the
  // determinant-based search of the in-plane problem on a regular spectrum). From the fourth mode
  // on the next root is predicted from the roots found (shooting_root_prediction.hpp): 5.5 (one
  // component) and 6.7 (two) shots per mode, error estimates included; without the predictions the
  // same search took 6.2 and 9.0.
  for (const bool scalar : {true, false}) {
    long shots = 0;
    const double one[1] = {1.0};
    const double two[2] = {1.0, 0.01};
    ShotFunction shoot = [&](double omega, double) {
      return scalar ? string_shot_with<1>(slow_phase, omega, one, shots)
                    : string_shot_with<2>(slow_phase, omega, two, shots);
    };
    ShootingRootFinder finder(shoot, settings(1e-10), 40.3, scalar);
    std::vector<std::string> warnings;
    const std::vector<Root> roots = finder.find(30, warnings);
    ASSERT_EQ(roots.size(), 30u);
    EXPECT_TRUE(warnings.empty());
    const ShotTally& tally = finder.tally();
    EXPECT_EQ(tally.bracketing + tally.refining + tally.estimate + tally.tightening, shots);
    EXPECT_EQ(tally.estimate, 30);
    EXPECT_LE(shots, (scalar ? 5.7 : 7.3) * 30) << "scalar " << scalar;
  }
}

// The exact roots of strings with `rates` and phase slow_phase, ascending, the lowest `count`.
template <int D>
std::vector<double> exact_string_roots(const double (&rates)[D], int count) {
  std::vector<double> roots;
  for (int j = 0; j < D; ++j) {
    for (int n = 1; n <= count; ++n) roots.push_back(slow_phase_root(n / rates[j]));
  }
  std::sort(roots.begin(), roots.end());
  roots.resize(count);
  return roots;
}

TEST(ShootingRootFinder, EveryModeIsFoundFromABadFirstGuessAndThroughMisleadingPredictions) {
  // A slow second string puts a root of its own between those of the first now and then: the
  // spacing the predictions extrapolate breaks there. First guesses far below and far above the
  // 25 modes. Every root must be found, in order, none skipped, to the tolerance.
  const double rates[2] = {1.0, 0.173};
  const std::vector<double> exact = exact_string_roots<2>(rates, 25);
  for (const double first_guess : {1e-3, 2000.0}) {
    long shots = 0;
    ShootingRootFinder finder(
        [&](double omega, double) { return string_shot_with<2>(slow_phase, omega, rates, shots); },
        settings(1e-10), first_guess, false);
    std::vector<std::string> warnings;
    const std::vector<Root> roots = finder.find(25, warnings);
    EXPECT_TRUE(warnings.empty());
    ASSERT_EQ(roots.size(), exact.size()) << first_guess;
    for (std::size_t i = 0; i < roots.size(); ++i) {
      EXPECT_NEAR(roots[i].omega, exact[i], 1e-10 * exact[i]) << i << " guess " << first_guess;
      EXPECT_EQ(roots[i].multiplicity, 1);
    }
    EXPECT_GE(finder.proved_count(), 25);
  }
}

}  // namespace
}  // namespace catena::internal
