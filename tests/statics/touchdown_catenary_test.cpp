// SPDX-License-Identifier: MIT
// Turchetto's touchdown form of the elastic catenary (Turchetto 2016; docs/reference/references.md,
// eqs. 1.6-1.10): exact values of the inextensible line, the equilibrium of the suspended part, the
// closed forms against the general solver (StaticSolution from the lowest point, and solve_statics
// given the same ends), the inverse from the reach, and bad input.
#include "catena/statics/touchdown_catenary.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>

#include "catena/core/error.hpp"
#include "catena/statics/elastic_catenary.hpp"
#include "test_utils.hpp"

namespace catena {
namespace {

using testing::relative_error;

std::string invalid_input_message(const std::function<void()>& call) {
  try {
    call();
  } catch (const InvalidInput& error) {
    return error.what();
  }
  return "";
}

TEST(TouchdownCatenary, InextensibleLineAtFortyFiveDegreesHasItsExactValues) {
  // EA = inf, c = T_H / W0 = 100 m, depth = c (sqrt 2 - 1): the fairlead angle is 45 degrees, the
  // suspended length c tan(45) = c and the reach c ln(sec + tan) = c asinh(1).
  const CableProperties cable{1.0, 1000.0, kInfinity, 120.0, 0.0};
  const double c = 100.0;
  const TouchdownLine line =
      touchdown_from_depth_and_tension(cable, c * (std::sqrt(2.0) - 1.0), 1e5);
  EXPECT_DOUBLE_EQ(line.horizontal_tension_n, 1e5);
  EXPECT_LT(relative_error(line.fairlead_angle_rad, kPi / 4.0), 1e-14);
  EXPECT_LT(relative_error(line.fairlead_tension_n, 1e5 * std::sqrt(2.0)), 1e-14);
  EXPECT_LT(relative_error(line.suspended_length_m, c), 1e-14);
  EXPECT_EQ(line.suspended_stretched_length_m, line.suspended_length_m);  // no stretch
  EXPECT_LT(relative_error(line.horizontal_reach_m, c * std::asinh(1.0)), 1e-14);
  EXPECT_LT(relative_error(line.depth_m, c * (std::sqrt(2.0) - 1.0)), 1e-14);
}

TEST(TouchdownCatenary, SuspendedWeightIsCarriedByTheFairlead) {
  // The vertical tension at the fairlead is the weight of the suspended part, W0 times its
  // unstretched length (W0 is per unstretched length): T_H tan(theta) = W0 L_s and
  // T_fairlead^2 = T_H^2 + (W0 L_s)^2. An elastic line stretches: its stretched length is longer.
  for (double ea : {5e8, 2e7, kInfinity}) {
    const CableProperties cable{1.0, 800.0, ea, 100.0, 0.0};
    const TouchdownLine line = touchdown_from_depth_and_tension(cable, 150.0, 4e5);
    const double weight = 800.0 * line.suspended_length_m;
    EXPECT_LT(relative_error(4e5 * std::tan(line.fairlead_angle_rad), weight), 1e-13)
        << "EA " << ea;
    EXPECT_LT(relative_error(line.fairlead_tension_n, std::hypot(4e5, weight)), 1e-14)
        << "EA " << ea;
    if (std::isinf(ea)) {
      EXPECT_EQ(line.suspended_stretched_length_m, line.suspended_length_m);
    } else {
      EXPECT_GT(line.suspended_stretched_length_m, line.suspended_length_m) << "EA " << ea;
    }
  }
}

TEST(TouchdownCatenary, ClosedFormsAreTheElasticCatenaryFromItsLowestPoint) {
  // StaticSolution with V_A = 0 at the touchdown point is the same line written with the general
  // closed forms (docs/explanation/physics.md): its fairlead is at (reach, depth), with the same
  // angle, tension and stretched length. No Newton iteration is involved.
  for (double ea : {5e8, 1e7, 3e6, kInfinity}) {
    CableProperties cable{1.0, 1000.0, ea, 120.0, 80.0};
    const TouchdownLine line = touchdown_from_depth_and_tension(cable, 300.0, 7.5e5);
    cable.length_m = line.suspended_length_m;
    const StaticSolution s(cable, Vec2::Zero(), line.horizontal_tension_n, 0.0);
    const double L = cable.length_m;
    EXPECT_LT(relative_error(s.offset_m(L).x(), line.horizontal_reach_m), 1e-12) << "EA " << ea;
    EXPECT_LT(relative_error(s.offset_m(L).y(), line.depth_m), 1e-12) << "EA " << ea;
    EXPECT_LT(relative_error(s.angle_rad(L), line.fairlead_angle_rad), 1e-13) << "EA " << ea;
    EXPECT_LT(relative_error(s.tension_n(L), line.fairlead_tension_n), 1e-13) << "EA " << ea;
    EXPECT_LT(relative_error(s.stretched_length_m(L), line.suspended_stretched_length_m), 1e-12)
        << "EA " << ea;
  }
}

// --- against the general two-support solver (solve_statics) ---

TEST(TouchdownCatenary, AgreesWithGeneralSolverFromLowestPoint) {
  // A line from its lowest point (V_A = 0) to the fairlead: the general solver given the same end
  // points must find H = T_H and V_A = 0, and the same shape and tensions, to 1e-10.
  for (double ea : {5e8, 1e7, kInfinity}) {
    CableProperties cable{1.0, 1000.0, ea, 120.0, 80.0};
    const TouchdownLine line = touchdown_from_depth_and_tension(cable, 300.0, 7.5e5);
    Problem p;
    p.cable = cable;
    p.cable.length_m = line.suspended_length_m;
    p.supports.b_m = Vec2(line.horizontal_reach_m, line.depth_m);
    const StaticSolution s = solve_statics(p);
    EXPECT_LT(relative_error(s.horizontal_force_n(), line.horizontal_tension_n), 1e-10)
        << "EA " << ea;
    EXPECT_LT(std::abs(s.vertical_force_a_n()) / line.horizontal_tension_n, 1e-10) << "EA " << ea;
    EXPECT_LT(relative_error(s.tension_n(p.cable.length_m), line.fairlead_tension_n), 1e-10);
    EXPECT_LT(relative_error(s.angle_rad(p.cable.length_m), line.fairlead_angle_rad), 1e-10);
    EXPECT_LT(
        relative_error(s.stretched_length_m(p.cable.length_m), line.suspended_stretched_length_m),
        1e-10);
  }
}

TEST(TouchdownCatenary, EquationOneTenHolds) {
  // (1.10): depth = y(theta_max) - y(0), checked with y from (1.8) written out independently.
  CableProperties cable{1.0, 800.0, 2e8, 100.0, 0.0};
  const double depth = 150.0, T_H = 4e5;
  const TouchdownLine line = touchdown_from_depth_and_tension(cable, depth, T_H);
  const double c = T_H / 800.0, k = T_H / 2e8, sec = 1.0 / std::cos(line.fairlead_angle_rad);
  const double y_top = c * sec * (1.0 + 0.5 * k * sec), y_bottom = c * (1.0 + 0.5 * k);
  EXPECT_LT(relative_error(y_top - y_bottom, depth), 1e-12);
}

TEST(TouchdownCatenary, InverseFromReachRecoversTension) {
  CableProperties cable{1.0, 1000.0, 5e8, 120.0, 0.0};
  const TouchdownLine forward = touchdown_from_depth_and_tension(cable, 300.0, 7.5e5);
  const TouchdownLine inverse =
      touchdown_from_depth_and_reach(cable, 300.0, forward.horizontal_reach_m);
  EXPECT_LT(relative_error(inverse.horizontal_tension_n, 7.5e5), 1e-12);
}

TEST(TouchdownCatenary, RejectsNonPositiveDepthAndTension) {
  CableProperties cable{1.0, 1000.0, 5e8, 120.0, 0.0};
  EXPECT_THROW(touchdown_from_depth_and_tension(cable, 0.0, 1e5), InvalidInput);
  EXPECT_THROW(touchdown_from_depth_and_tension(cable, 100.0, -1.0), InvalidInput);
  EXPECT_THROW(touchdown_from_depth_and_reach(cable, 100.0, std::nan("")), InvalidInput);
}

TEST(TouchdownCatenary, ReachGrowsWithHorizontalTension) {
  // The inverse brackets T_H on this monotonicity (a tauter line reaches farther at the same
  // depth).
  for (double ea : {1e7, kInfinity}) {
    const CableProperties cable{1.0, 1000.0, ea, 120.0, 0.0};
    double previous = 0.0;
    for (double T_H = 1e3; T_H < 1e9; T_H *= 3.0) {
      const double reach = touchdown_from_depth_and_tension(cable, 300.0, T_H).horizontal_reach_m;
      EXPECT_GT(reach, previous) << "EA " << ea << ", T_H " << T_H;
      previous = reach;
    }
  }
}

TEST(TouchdownCatenary, InverseFindsTheReachFromShortToLong) {
  // From nearly vertical (reach 1 % of the depth) to nearly flat (reach 50 depths): the returned
  // line has the asked reach and depth.
  for (double ea : {5e8, kInfinity}) {
    const CableProperties cable{1.0, 1000.0, ea, 120.0, 0.0};
    for (double reach : {3.0, 150.0, 900.0, 15000.0}) {
      const TouchdownLine line = touchdown_from_depth_and_reach(cable, 300.0, reach);
      EXPECT_LT(relative_error(line.horizontal_reach_m, reach), 1e-12)
          << "EA " << ea << ", reach " << reach;
      EXPECT_LT(relative_error(line.depth_m, 300.0), 1e-12) << "EA " << ea << ", reach " << reach;
      EXPECT_GT(line.horizontal_tension_n, 0.0);
    }
  }
}

TEST(TouchdownCatenary, BadInputNamesTheField) {
  const CableProperties cable{1.0, 1000.0, 5e8, 120.0, 0.0};
  EXPECT_NE(invalid_input_message([&] {
              touchdown_from_depth_and_tension(cable, -5.0, 1e5);
            }).find("depth_m = -5"),
            std::string::npos);
  EXPECT_NE(invalid_input_message([&] {
              touchdown_from_depth_and_tension(cable, 100.0, 0.0);
            }).find("horizontal_tension_n = 0"),
            std::string::npos);
  EXPECT_NE(invalid_input_message([&] {
              touchdown_from_depth_and_reach(cable, 100.0, 0.0);
            }).find("reach_m = 0"),
            std::string::npos);
  EXPECT_THROW(touchdown_from_depth_and_tension(cable, kInfinity, 1e5), InvalidInput);
  EXPECT_THROW(touchdown_from_depth_and_reach(cable, 100.0, -1.0), InvalidInput);
  // The cable itself is validated: a weightless line has no catenary.
  CableProperties weightless = cable;
  weightless.weight_n_per_m = 0.0;
  EXPECT_THROW(touchdown_from_depth_and_tension(weightless, 100.0, 1e5), InvalidInput);
  EXPECT_THROW(touchdown_from_depth_and_reach(weightless, 100.0, 50.0), InvalidInput);
}

}  // namespace
}  // namespace catena
