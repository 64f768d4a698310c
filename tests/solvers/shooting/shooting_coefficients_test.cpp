// SPDX-License-Identifier: MIT
// Tests of the shooting solver's static coefficients (src/solvers/shooting/shooting_coefficients):
// tension, tangent and normal of the catenary in closed form, and the transverse travel time.
#include "solvers/shooting/shooting_coefficients.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "catena/statics/problem_builders.hpp"
#include "shooting_test_strings.hpp"
#include "solvers/common/solver_test_support.hpp"

namespace catena::internal {
namespace {

TEST(ShootingCoefficients, TensionTangentAndNormalFollowTheLinearVerticalForce) {
  // V(s) = V_A + W0 s: V = -3 at s = 0 and +3 at s = 6, with H = 4, so T = 5 at both ends.
  ShootingCoefficients k;
  k.length_m = 6.0;
  k.H = 4.0;
  k.V_A = -3.0;
  k.W0 = 1.0;
  EXPECT_DOUBLE_EQ(k.tension(0.0), 5.0);
  EXPECT_DOUBLE_EQ(k.tension(6.0), 5.0);
  EXPECT_DOUBLE_EQ(k.tension(3.0), 4.0);
  EXPECT_DOUBLE_EQ(k.tangent(0.0).x(), 0.8);
  EXPECT_DOUBLE_EQ(k.tangent(0.0).y(), -0.6);
  EXPECT_DOUBLE_EQ(k.normal(0.0).x(), 0.6);
  EXPECT_DOUBLE_EQ(k.normal(0.0).y(), 0.8);
  for (double s : {0.0, 1.3, 4.7, 6.0}) {
    EXPECT_NEAR(k.tangent(s).dot(k.normal(s)), 0.0, 1e-15);
    EXPECT_NEAR(k.tangent(s).norm(), 1.0, 1e-15);
    // The normal is the tangent turned +90 degrees.
    EXPECT_NEAR(k.tangent(s).x() * k.normal(s).y() - k.tangent(s).y() * k.normal(s).x(), 1.0,
                1e-15);
  }
}

TEST(ShootingCoefficients, ScaledFrequencyIsOmegaSquaredLSquaredMOverTref) {
  ShootingCoefficients k = testing::horizontal_string(50.0, 2.0);
  k.M = 3.0;
  EXPECT_DOUBLE_EQ(k.scaled_omega2(5.0), 25.0 * 4.0 * 3.0 / 50.0);
}

TEST(ShootingCoefficients, TravelTimeOfAUniformStringIsExact) {
  // Constant integrand: Simpson's rule is exact, sqrt(M (1+e) / T) L.
  const ShootingCoefficients k = testing::horizontal_string(100.0, 10.0, 1e4);
  EXPECT_NEAR(transverse_travel_time(k), 10.0 * std::sqrt(1.01 / 100.0), 1e-15);
}

TEST(ShootingCoefficients, StraightInextensibleNeedsBothNoHorizontalForceAndNoCompliance) {
  ShootingCoefficients k = testing::horizontal_string(100.0, 10.0);
  EXPECT_FALSE(is_straight_inextensible(k));
  k.H = 0.0;
  EXPECT_TRUE(is_straight_inextensible(k));
  k.compliance = 1e-6;
  EXPECT_FALSE(is_straight_inextensible(k));
}

TEST(ShootingCoefficients, FromStaticsTakesTheCableAndTheLargerEndTension) {
  const auto solved = testing::prepare(make_taut_inclined_problem(0.1, 30.0, 50.0, 0.8));
  const ShootingCoefficients k = ShootingCoefficients::from_statics(solved.statics);
  const CableProperties& cable = solved.problem.cable;
  EXPECT_EQ(k.length_m, cable.length_m);
  EXPECT_EQ(k.M, cable.normal_mass_kg_per_m());
  EXPECT_EQ(k.m, cable.mass_kg_per_m);
  EXPECT_DOUBLE_EQ(k.compliance, 1.0 / cable.axial_stiffness_n);
  EXPECT_DOUBLE_EQ(
      k.t_ref, std::max(solved.statics.tension_n(0.0), solved.statics.tension_n(cable.length_m)));
  for (double s : {0.0, 0.5 * cable.length_m, cable.length_m}) {
    EXPECT_NEAR(k.tension(s), solved.statics.tension_n(s), 1e-9 * k.t_ref) << s;
  }
}

}  // namespace
}  // namespace catena::internal
