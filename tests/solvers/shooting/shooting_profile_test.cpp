// SPDX-License-Identifier: MIT
// Tests of profiles from a shot (src/solvers/shooting/shooting_profile): the physical
// displacements and tension of a combination of the final basis at recorded stations.
#include "solvers/shooting/shooting_profile.hpp"

#include <gtest/gtest.h>

#include "shooting_test_strings.hpp"

namespace catena::internal {
namespace {

TEST(ShootingProfile, ScaledStationsFollowTheDirectionOfIntegration) {
  const Vector s = (Vector(3) << 0.0, 2.0, 8.0).finished();
  const std::vector<double> forward = scaled_stations(s, 8.0, false);
  const std::vector<double> backward = scaled_stations(s, 8.0, true);
  EXPECT_EQ(forward, (std::vector<double>{0.0, 0.25, 1.0}));
  EXPECT_EQ(backward, (std::vector<double>{0.0, 0.75, 1.0}));
}

// A shot with two stations and no re-orthonormalisation: the station basis is used as is.
Shot two_station_shot() {
  Shot shot;
  Eigen::MatrixXd y0(4, 2), y1(4, 2);
  y0 << 1, 0, 0, 2, 3, 0, 0, 4;
  y1 << 5, 0, 0, 6, 7, 0, 0, 8;
  shot.station_y = {y0, y1};
  shot.station_segment = {0, 0};
  return shot;
}

TEST(ShootingProfile, InPlaneProfileIsInPhysicalUnitsAlongTangentAndNormal) {
  // Horizontal string: tangent (1, 0), normal (0, 1); Phi = L Phi^, force = T_ref F^.
  const ShootingCoefficients k = testing::horizontal_string(10.0, 2.0);
  const Vector s = (Vector(2) << 0.0, 2.0).finished();
  const Eigen::Vector2d c(1.0, 0.5);
  const Profile p = evaluate_profile(two_station_shot(), c, k, s, false, Plane::InPlane);
  EXPECT_DOUBLE_EQ(p.u[0], 2.0 * 1.0);
  EXPECT_DOUBLE_EQ(p.w[0], 2.0 * 1.0);
  EXPECT_DOUBLE_EQ(p.tension[0], 10.0 * 3.0);
  EXPECT_DOUBLE_EQ(p.u[1], 2.0 * 5.0);
  EXPECT_DOUBLE_EQ(p.w[1], 2.0 * 3.0);
  EXPECT_EQ(p.v.size(), 0);
  // Shot from b: the stations were recorded in reverse order.
  const Profile r = evaluate_profile(two_station_shot(), c, k, s, true, Plane::InPlane);
  EXPECT_DOUBLE_EQ(r.u[0], p.u[1]);
  EXPECT_DOUBLE_EQ(r.u[1], p.u[0]);
}

TEST(ShootingProfile, StringRelabelledAsInPlaneMovesNormallyWithoutTension) {
  Profile string;
  string.v = (Vector(3) << 0.0, 1.0, 0.5).finished();
  const Profile p = string_as_inplane(string);
  EXPECT_EQ(p.w, string.v);
  EXPECT_EQ(p.u, Vector::Zero(3));
  EXPECT_EQ(p.tension, Vector::Zero(3));
}

}  // namespace
}  // namespace catena::internal
