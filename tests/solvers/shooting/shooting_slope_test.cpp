// SPDX-License-Identifier: MIT
// Tests of the frequency derivative a shot can carry (shooting_integrator.hpp, "Frequency
// derivative"): the slopes of the normalised end determinant and of the end angle against central
// finite differences of two shots, on a taut string (both planes, with frequent
// re-orthonormalisations) and on a two-piece line with a point mass at the joint (the jump), with
// the balancing off (carried variables independent of the frequency) and on (the slope includes
// the balancing's own change with the frequency, so that it is that of the values returned).
#include <gtest/gtest.h>

#include <cmath>

#include "catena/core/types.hpp"
#include "shooting_test_strings.hpp"
#include "solvers/shooting/shooting_integrator.hpp"

namespace catena::internal {
namespace {

IntegratorSettings tight(double max_condition = 1e2, bool balance = false) {
  IntegratorSettings settings;
  settings.relative_tolerance = 1e-12;
  settings.absolute_tolerance = 1e-14;
  settings.max_condition = max_condition;
  settings.balance = balance;
  return settings;
}

// Two pieces of a weightless string (T = 1 N, EA = 4 N) of different normal mass, a point mass
// of 0.3 kg at the joint.
ShootingCoefficients line_with_point() {
  ShootingCoefficients k = testing::horizontal_string(1.0, 1.0, 4.0);
  ShootingPiece first;
  first.s_begin = 0.0;
  first.s_end = 0.4;
  first.compliance = 0.25;
  first.m = 1.0;
  first.M = 1.0;
  ShootingPiece second = first;
  second.s_begin = 0.4;
  second.s_end = 1.0;
  second.m = 2.0;
  second.M = 3.0;
  k.pieces = {first, second};
  ShootingPoint point;
  point.s = 0.4;
  point.mass_tangential = point.mass_normal = point.mass_outofplane = 0.3;
  k.points = {point};
  return k;
}

// The slope of the shot at omega against the central difference of the plain shots at
// omega (1 -+ 1e-5).
void expect_slopes_match(Plane plane,
                         const ShootingCoefficients& k,
                         double omega,
                         double max_condition = 1e2,
                         bool balance = false) {
  ShootingIntegrator integrator(plane, k, tight(max_condition, balance));
  const Shot shot = integrator.shoot(omega, 1.0, nullptr, false, true);
  ASSERT_TRUE(shot.has_slope);
  const Shot plain = integrator.shoot(omega);
  EXPECT_FALSE(plain.has_slope);
  EXPECT_EQ(shot.count, plain.count);
  EXPECT_NEAR(shot.determinant, plain.determinant, 1e-9);
  const double d = 1e-5 * omega;
  const Shot lo = integrator.shoot(omega - d), hi = integrator.shoot(omega + d);
  const double det_difference = (hi.determinant - lo.determinant) / (2.0 * d);
  EXPECT_NEAR(shot.determinant_slope, det_difference, 1e-6 * (std::abs(det_difference) + 1.0))
      << "omega " << omega;
  if (plane == Plane::OutOfPlane && lo.count == hi.count) {
    const double angle_difference = (hi.angle_min - lo.angle_min) / (2.0 * d);
    EXPECT_NEAR(shot.angle_slope, angle_difference, 1e-6 * std::abs(angle_difference))
        << "omega " << omega;
    EXPECT_GT(shot.angle_slope, 0.0);  // the continuous count rises with the frequency
  }
}

TEST(ShootingSlope, InPlaneStringMatchesFiniteDifference) {
  const ShootingCoefficients string = testing::horizontal_string(1.0, 1.0, 4.0);
  for (double omega : {1.3, 4.7, 9.1, 17.3}) expect_slopes_match(Plane::InPlane, string, omega);
}

TEST(ShootingSlope, SurvivesReorthonormalisation) {
  // cond(G) > 1.01 restarts the pair after nearly every step: S is carried as S R^{-1}.
  const ShootingCoefficients string = testing::horizontal_string(1.0, 1.0, 4.0);
  for (double omega : {4.7, 17.3}) expect_slopes_match(Plane::InPlane, string, omega, 1.01);
}

TEST(ShootingSlope, OutOfPlaneStringMatchesFiniteDifference) {
  const ShootingCoefficients string = testing::horizontal_string(1.0, 1.0, 4.0);
  for (double omega : {1.3, 4.7, 9.1, 17.3}) expect_slopes_match(Plane::OutOfPlane, string, omega);
}

TEST(ShootingSlope, CrossesAPointMassJump) {
  const ShootingCoefficients line = line_with_point();
  for (double omega : {1.7, 6.1, 13.9}) {
    expect_slopes_match(Plane::InPlane, line, omega);
    expect_slopes_match(Plane::OutOfPlane, line, omega);
  }
}

TEST(ShootingSlope, IncludesTheBalancing) {
  // kappa^2 = max(Omega, 1) moves with the frequency above Omega = 1 (Omega = omega here).
  const ShootingCoefficients string = testing::horizontal_string(1.0, 1.0, 4.0);
  const ShootingCoefficients line = line_with_point();
  for (double omega : {4.7, 17.3}) {
    expect_slopes_match(Plane::InPlane, string, omega, 1e2, true);
    expect_slopes_match(Plane::OutOfPlane, string, omega, 1e2, true);
    expect_slopes_match(Plane::InPlane, line, omega, 1e2, true);
    expect_slopes_match(Plane::OutOfPlane, line, omega, 1e2, true);
  }
}

TEST(ShootingSlope, NotCarriedAtZeroFrequency) {
  ShootingIntegrator integrator(Plane::InPlane, testing::horizontal_string(1.0, 1.0, 4.0), tight());
  EXPECT_FALSE(integrator.shoot(0.0, 1.0, nullptr, false, true).has_slope);
}

}  // namespace
}  // namespace catena::internal
