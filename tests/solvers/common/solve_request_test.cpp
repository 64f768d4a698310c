// SPDX-License-Identifier: MIT
// What a scene asks the solvers to compute: validation of every field and limit, the stations,
// the forcing direction and the names used in messages and JSON.
#include "catena/solvers/solve_request.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>

#include "catena/core/error.hpp"
#include "test_utils.hpp"

namespace catena {
namespace {

using testing::expect_invalid;

TEST(SolveRequest, RejectsEachInvalidField) {
  auto with = [](auto change) {
    SolveRequest r;
    change(r);
    return [r] { r.validate(); };
  };
  expect_invalid(with([](SolveRequest& r) { r.inplane_modes = -1; }), "inplane_modes");
  expect_invalid(with([](SolveRequest& r) { r.outofplane_modes = -1; }), "outofplane_modes");
  expect_invalid(with([](SolveRequest& r) { r.points = 1; }), "points");
  // 1e6 shape points ran out of memory while the JSON was written.
  expect_invalid(with([](SolveRequest& r) { r.points = 1000000; }),
                 "points = 1000000: must be in [2, 100000]");
  expect_invalid(with([](SolveRequest& r) { r.inplane_modes = 100001; }), "inplane_modes");
  expect_invalid(with([](SolveRequest& r) {
                   r.shapes = true;
                   r.points = 100000;
                   r.inplane_modes = 11;
                 }),
                 "shape values");
  EXPECT_NO_THROW(with([](SolveRequest& r) {
    r.shapes = true;
    r.points = 100000;
    r.inplane_modes = 10;
  })());
  expect_invalid(with([](SolveRequest& r) { r.forced = ForcedRequest{}; }), "forcing frequency");
  expect_invalid(with([](SolveRequest& r) {
                   r.forced = ForcedRequest{};
                   r.forced->omegas_rad_s = {std::nan("")};
                 }),
                 "forcing frequency");
  expect_invalid(with([](SolveRequest& r) {
                   r.forced = ForcedRequest{};
                   r.forced->omegas_rad_s = {1.0};
                   r.forced->amplitude_m = 0.0;
                 }),
                 "amplitude_m");
}

TEST(SolveRequest, StationsAreEquallySpacedFromEndToEnd) {
  SolveRequest request;
  request.points = 5;
  const Vector s = request.stations_m(2.0);
  ASSERT_EQ(s.size(), 5);
  for (int j = 0; j < 5; ++j) EXPECT_DOUBLE_EQ(s[j], 0.5 * j);
}

TEST(SolveRequest, NamesOfEndsAndDirectionsAreTheSceneWords) {
  EXPECT_EQ(to_string(CableEnd::A), "a");
  EXPECT_EQ(to_string(CableEnd::B), "b");
  EXPECT_EQ(to_string(ForcingDirection::Tangential), "tangential");
  EXPECT_EQ(to_string(ForcingDirection::Normal), "normal");
  EXPECT_EQ(to_string(ForcingDirection::GivenVector), "vector");
  EXPECT_EQ(to_string(ForcingDirection::OutOfPlane), "out_of_plane");
}

// [1e308, 1e308] overflowed its norm (every response was 0, "converged"): the unit vector is taken
// after scaling by the larger component.
TEST(ForcedRequest, UnitVectorDoesNotOverflowOrUnderflow) {
  ForcedRequest forced;
  forced.direction = ForcingDirection::GivenVector;
  for (double scale : {1.0, 1e308, 1e-320}) {
    forced.vector = Vec2(scale, scale);
    const Vec2 unit = forced.unit_vector();
    EXPECT_NEAR(unit.x(), 1.0 / std::sqrt(2.0), 1e-15) << scale;
    EXPECT_NEAR(unit.y(), 1.0 / std::sqrt(2.0), 1e-15) << scale;
  }
  forced.vector = Vec2(3.0, -4.0);
  EXPECT_NEAR(forced.unit_vector().x(), 0.6, 1e-15);
  EXPECT_NEAR(forced.unit_vector().y(), -0.8, 1e-15);
  forced.vector = Vec2(0.0, 0.0);
  EXPECT_TRUE(forced.unit_vector().isZero(0.0));
}

}  // namespace
}  // namespace catena
