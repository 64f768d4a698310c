// SPDX-License-Identifier: MIT
// Tests of the shooting root finder's Newton refinement (shooting_root_finder.hpp,
// set_slope_shots) on synthetic shots whose end frames and slopes are exact: strings of phase
// pi r p(omega), one (out of plane) or two (in plane) at once. Checked: every mode to the
// tolerance in order, fewer shots than Brent's method on a smooth (string) spectrum, and the
// safeguard on a phase with a steep step (a mode localised at a heavy point mass), where Newton's
// steps leave the bracket.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "catena/core/types.hpp"
#include "shooting_test_strings.hpp"
#include "solvers/shooting/shooting_conjugate_count.hpp"
#include "solvers/shooting/shooting_integrator.hpp"
#include "solvers/shooting/shooting_root_finder.hpp"

namespace catena::internal {
namespace {

using Phase = std::function<double(double)>;

// The exact end frame of D strings with phases pi rates[j] p(omega); with_slope adds the slopes
// of the normalised determinant and of the end angle (central differences of the closed form,
// accurate to ~1e-9 relative: far beyond what Newton needs).
template <int D>
Shot string_shot(
    const Phase& p, const double (&rates)[D], double omega, bool with_slope, long& shots) {
  ++shots;
  Shot shot = testing::exact_string_frame<D>(p, omega, rates);
  if (with_slope && omega > 0.0) {
    const double h = 1e-6 * omega;
    const Shot up = testing::exact_string_frame<D>(p, omega + h, rates);
    const Shot down = testing::exact_string_frame<D>(p, omega - h, rates);
    shot.has_slope = true;
    shot.determinant_slope = (up.determinant - down.determinant) / (2.0 * h);
    // D = 1: the angle is 2 pi r p - pi, continuous (mod 2 pi) across a crossing.
    shot.angle_slope = 2.0 * kPi * rates[0] * (p(omega + h) - p(omega - h)) / (2.0 * h);
  }
  return shot;
}

RootFinderSettings settings(double tolerance) {
  RootFinderSettings s;
  s.relative_tolerance = tolerance;
  s.root_tolerance = tolerance;
  s.error_estimate = true;
  s.target = 11.0 * tolerance;
  return s;
}

struct Outcome {
  std::vector<Root> roots;
  long shots = 0;
  int proved = -1;
  ShotTally tally;
};

template <int D>
Outcome find(const Phase& p, const double (&rates)[D], int modes, bool newton, double first_guess) {
  Outcome out;
  long& shots = out.shots;
  ShootingRootFinder finder(
      [&](double omega, double) { return string_shot<D>(p, rates, omega, false, shots); },
      settings(1e-12), first_guess, D == 1);
  if (newton) {
    finder.set_slope_shots(
        [&](double omega, double) { return string_shot<D>(p, rates, omega, true, shots); });
  }
  std::vector<std::string> warnings;
  out.roots = finder.find(modes, warnings);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  EXPECT_EQ(finder.shots(), shots);
  out.proved = finder.proved_count();
  out.tally = finder.tally();
  return out;
}

// The n-th root of rate * p(omega) = n, by bisection to rounding.
double exact_root(const Phase& p, double rate, int n, double hi) {
  double lo = 0.0;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (rate * p(mid) < n ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

double smooth_phase(double omega) { return omega + 0.2 * std::sin(omega); }

// A steep step of height 0.9 at omega = 7.31, 2e-4 wide: the count rises through the roots near it
// hundreds of times faster than between them, as at a mode localised at a heavy point mass.
double stepped_phase(double omega) {
  return omega + 0.9 * (std::atan((omega - 7.31) / 2e-4) / kPi + 0.5);
}

TEST(ShootingNewton, OutOfPlaneStringInFewerShotsThanBrent) {
  const double rates[1] = {1.0};
  const Outcome newton = find<1>(smooth_phase, rates, 20, true, 2.3);
  const Outcome brent = find<1>(smooth_phase, rates, 20, false, 2.3);
  ASSERT_EQ(newton.roots.size(), 20u);
  for (int n = 1; n <= 20; ++n) {
    const double exact = exact_root(smooth_phase, 1.0, n, 40.0);
    EXPECT_NEAR(newton.roots[n - 1].omega, exact, 2e-12 * exact) << n;
    // The estimate bounds the error (up to rounding).
    EXPECT_GE(newton.roots[n - 1].relative_error + 4e-16,
              std::abs(newton.roots[n - 1].omega / exact - 1.0))
        << n;
  }
  EXPECT_EQ(newton.proved, 20);
  EXPECT_LT(newton.shots, brent.shots);
  // Brent: 144 here (7.2 per mode at the tolerance 1e-12 on a spectrum the predictor follows
  // poorly); Newton from 1e-2 away needs three slope shots.
  EXPECT_LE(newton.shots, 6 * 20) << newton.tally.bracketing << " " << newton.tally.refining << " "
                                  << newton.tally.estimate << " brent " << brent.shots;
}

TEST(ShootingNewton, InPlanePairInFewerShotsThanBrent) {
  const double rates[2] = {1.0, 0.37};  // two interleaved families, as transverse and axial modes
  const Outcome newton = find<2>(smooth_phase, rates, 20, true, 2.3);
  const Outcome brent = find<2>(smooth_phase, rates, 20, false, 2.3);
  std::vector<double> exact;
  for (int n = 1; n <= 20; ++n) exact.push_back(exact_root(smooth_phase, 1.0, n, 60.0));
  for (int n = 1; n <= 8; ++n) exact.push_back(exact_root(smooth_phase, 0.37, n, 60.0));
  std::sort(exact.begin(), exact.end());
  ASSERT_EQ(newton.roots.size(), 20u);
  for (std::size_t j = 0; j < 20; ++j) {
    EXPECT_NEAR(newton.roots[j].omega, exact[j], 2e-12 * exact[j]) << j;
  }
  EXPECT_EQ(newton.proved, 20);
  EXPECT_LT(newton.shots, brent.shots);
}

TEST(ShootingNewton, SafeguardFindsEveryModeThroughASteepStep) {
  const double rates[1] = {1.0};
  const double inplane_rates[2] = {1.0, 0.37};
  const Outcome scalar = find<1>(stepped_phase, rates, 12, true, 2.3);
  const Outcome pair = find<2>(stepped_phase, inplane_rates, 12, true, 2.3);
  ASSERT_EQ(scalar.roots.size(), 12u);
  ASSERT_EQ(pair.roots.size(), 12u);
  std::vector<double> exact;
  for (int n = 1; n <= 12; ++n) exact.push_back(exact_root(stepped_phase, 1.0, n, 40.0));
  for (int n = 1; n <= 12; ++n) {
    EXPECT_NEAR(scalar.roots[n - 1].omega, exact[n - 1], 2e-12 * exact[n - 1]) << n;
  }
  for (int n = 1; n <= 5; ++n) exact.push_back(exact_root(stepped_phase, 0.37, n, 40.0));
  std::sort(exact.begin(), exact.end());
  for (std::size_t j = 0; j < 12; ++j) {
    EXPECT_NEAR(pair.roots[j].omega, exact[j], 2e-12 * exact[j]) << j;
  }
  EXPECT_EQ(scalar.proved, 12);
  EXPECT_EQ(pair.proved, 12);
}

// The real shot on a taut string (T = 1 N, EA = 4 N, L = 1 m, m = M = 1 kg/m), out of plane:
// omega_n = n pi / sqrt(1.25), found with the slopes to 1e-11 in fewer shots than by Brent
// (50 against 76).
TEST(ShootingNewton, TautStringWithTheIntegratorsSlope) {
  IntegratorSettings integration;
  integration.relative_tolerance = 1e-12;
  integration.absolute_tolerance = 1e-14;
  ShootingIntegrator integrator(Plane::OutOfPlane, testing::horizontal_string(1.0, 1.0, 4.0),
                                integration);
  long with_newton = 0;
  for (const bool newton : {true, false}) {
    ShootingRootFinder finder([&](double w, double f) { return integrator.shoot(w, f); },
                              settings(1e-12), 2.3, true);
    if (newton) {
      finder.set_slope_shots(
          [&](double w, double f) { return integrator.shoot(w, f, nullptr, false, true); });
    }
    std::vector<std::string> warnings;
    const std::vector<Root> roots = finder.find(12, warnings);
    ASSERT_EQ(roots.size(), 12u);
    for (int n = 1; n <= 12; ++n) {
      const double exact = n * kPi / std::sqrt(1.25);
      EXPECT_NEAR(roots[n - 1].omega, exact, 1e-11 * exact) << n << " newton " << newton;
    }
    EXPECT_EQ(finder.proved_count(), 12);
    if (newton) {
      with_newton = finder.shots();
      // 50 here: 17 counting samples, 25 Newton shots, 8 estimate shots (4 roots from a tight
      // first shot).
      EXPECT_LE(with_newton, 54) << finder.tally().bracketing << " " << finder.tally().refining
                                 << " " << finder.tally().estimate;
    } else {
      EXPECT_LT(with_newton, finder.shots()) << "brent " << finder.shots();
    }
  }
}

}  // namespace
}  // namespace catena::internal
