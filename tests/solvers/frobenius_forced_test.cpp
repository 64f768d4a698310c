// Tests of the frobenius solver's forced response: the driven end's displacement in Gale's units
// and the response's end conditions in each direction.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "solvers/frobenius_test_support.hpp"
#include "solvers/internal/frobenius_forced.hpp"

namespace catena::internal {
namespace {

using catena::testing::frobenius_plane;

FieldStations stations_between(double sigma1, double sigma2, int points) {
  FieldStations out;
  out.s_m = Vector::LinSpaced(points, 0.0, 1.0);
  for (int i = 0; i < points; ++i) out.sigma.push_back(sigma1 + (sigma2 - sigma1) * i / (points - 1));
  return out;
}

TEST(FrobeniusForcedTest, EndDisplacementIsInUnitsOfTheCatenaryParameter) {
  ForcedRequest forced;
  forced.amplitude_m = 0.03;
  forced.direction = ForcingDirection::Tangential;
  EndDisplacement end = forced_end_displacement(forced, 0.5, 2.0);
  EXPECT_DOUBLE_EQ(end.u, 0.015);
  EXPECT_EQ(end.v, 0.0);
  forced.direction = ForcingDirection::Normal;
  end = forced_end_displacement(forced, 0.5, 2.0);
  EXPECT_EQ(end.u, 0.0);
  EXPECT_DOUBLE_EQ(end.v, 0.015);
}

TEST(FrobeniusForcedTest, AGivenVectorIsResolvedOnTheEndsTangentAndNormal) {
  // At sigma = 0.75 the tangent is (0.8, 0.6) and the normal (-0.6, 0.8).
  ForcedRequest forced;
  forced.amplitude_m = 1.0;
  forced.direction = ForcingDirection::GivenVector;
  forced.vector = Vec2(4.0, 3.0);  // along the tangent, not unit
  EndDisplacement end = forced_end_displacement(forced, 0.75, 1.0);
  EXPECT_NEAR(end.u, 1.0, 1e-15);
  EXPECT_NEAR(end.v, 0.0, 1e-15);
  forced.vector = Vec2(1.0, 0.0);
  end = forced_end_displacement(forced, 0.75, 1.0);
  EXPECT_NEAR(end.u, 0.8, 1e-15);
  EXPECT_NEAR(end.v, -0.6, 1e-15);
}

TEST(FrobeniusForcedTest, InPlaneResponseMeetsItsEndConditions) {
  const PlaneSetup base = frobenius_plane(true, -0.4, 1.3);
  ForcedRequest forced;
  forced.end = CableEnd::A;
  forced.direction = ForcingDirection::GivenVector;
  forced.vector = Vec2(0.0, 1.0);
  forced.amplitude_m = 0.02;
  forced.omegas_rad_s = {0.7, 2.9};
  const FieldStations stations = stations_between(-0.4, 1.3, 41);
  const auto responses = frobenius_forced_responses(base, forced, stations, CableUnits{});
  ASSERT_EQ(responses.size(), 2u);
  const EndDisplacement end = forced_end_displacement(forced, -0.4, 1.0);
  for (const ForcedResponse& r : responses) {
    ASSERT_TRUE(r.diagnostic.empty()) << r.diagnostic;
    ASSERT_EQ(r.u.size(), 41);
    EXPECT_NEAR(r.u(0), end.u, 1e-12);
    EXPECT_NEAR(r.w(0), end.v, 1e-12);
    EXPECT_NEAR(r.u(40), 0.0, 1e-12);
    EXPECT_NEAR(r.w(40), 0.0, 1e-12);
    EXPECT_NEAR(r.max_abs_tension_n, r.tension_n.cwiseAbs().maxCoeff(), 0.0);
    EXPECT_EQ(r.v.size(), 0);
  }
}

TEST(FrobeniusForcedTest, OutOfPlaneResponseMeetsItsEndConditions) {
  const PlaneSetup base = frobenius_plane(true, -0.4, 1.3);
  ForcedRequest forced;
  forced.end = CableEnd::B;
  forced.direction = ForcingDirection::OutOfPlane;
  forced.amplitude_m = 0.05;
  forced.omegas_rad_s = {1.1};
  const auto responses = frobenius_forced_responses(base, forced, stations_between(-0.4, 1.3, 21), CableUnits{});
  ASSERT_EQ(responses.size(), 1u);
  const ForcedResponse& r = responses.front();
  ASSERT_EQ(r.v.size(), 21);
  EXPECT_NEAR(r.v(0), 0.0, 1e-12);
  EXPECT_NEAR(r.v(20), 0.05, 1e-12);
  EXPECT_EQ(r.u.size(), 0);
}

}  // namespace
}  // namespace catena::internal
