// SPDX-License-Identifier: MIT
// The modal mass of a general line's mode (src/solvers/common/line_modal_mass.hpp): each
// segment's density on its own stretch, each point attachment's mass at its own arc length.
#include "solvers/common/line_modal_mass.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "catena/core/types.hpp"
#include "catena/statics/elastic_catenary.hpp"

namespace catena {
namespace {

// A weightless taut line of two segments (4 m of normal mass 3 kg/m, 6 m of 1 kg/m) with a 5 kg
// point (1 kg added mass) at s = 5 m, on 101 stations (one on the joint): a uniform motion and
// v = s.
TEST(LineModalMass, EachSegmentsDensityAndEachPointAtItsArcLength) {
  Problem problem;
  problem.line.segments = {{4.0, 0.0, 1e7, 2.0, 1.0}, {6.0, 0.0, 1e7, 0.5, 0.5}};
  PointAttachment point;
  point.s_m = 5.0;
  point.mass_kg = 5.0;
  point.added_mass_kg = 1.0;
  problem.line.points = {point};
  problem.supports.b_m = Vec2(10.001, 0.0);
  const StaticSolution statics = solve_statics(problem);
  Mode mode;
  mode.s_m = Vector::LinSpaced(101, 0.0, 10.0);
  mode.v = Vector::Ones(101);  // uniform motion: the modal mass is the total moving mass
  const double total = 4.0 * 3.0 + 6.0 * 1.0 + 5.0 + 1.0;
  EXPECT_NEAR(internal::line_modal_mass(Plane::OutOfPlane, mode, problem.line, statics), total,
              1e-12 * total);
  // v = s: int_0^4 3 s^2 + int_4^10 s^2 = 64 + 312 = 376, plus 6 x 25 at the point; the
  // trapezoid on 0.1 m intervals overestimates int s^2 by h^2 f''/12 = h^2/6 per metre and density.
  mode.v = mode.s_m;
  const double trapezoid_excess = 0.01 / 6.0 * (4.0 * 3.0 + 6.0 * 1.0);
  EXPECT_NEAR(internal::line_modal_mass(Plane::OutOfPlane, mode, problem.line, statics),
              376.0 + 150.0 + trapezoid_excess, 1e-9);
}

}  // namespace
}  // namespace catena
