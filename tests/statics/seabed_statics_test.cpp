// SPDX-License-Identifier: MIT
// Statics of a line on a flat seabed (docs/explanation/physics.md, "Seabed contact").
// Anchors: an independent 50-digit solve of the contact equations (a different formulation: the
// suspended tension at the fairlead height in closed form from a quadratic, the grounded stretch
// integrated by hand, bisection on H); Turchetto's touchdown form
// (catena/statics/touchdown_catenary.hpp); a touchdown exactly at A against the line without a
// seabed; the friction law at the anchor; a chain-wire line against the general-line statics of its
// suspended part; bad input.
#include "catena/statics/seabed_statics.hpp"

#include <gtest/gtest.h>

#include <boost/multiprecision/cpp_bin_float.hpp>
#include <cmath>

#include "catena/statics/line_statics.hpp"
#include "catena/statics/touchdown_catenary.hpp"
#include "test_utils.hpp"

namespace catena {
namespace {

using testing::expect_invalid;
using testing::relative_error;
using Real = boost::multiprecision::cpp_bin_float_50;

// A chain of 1000 m in 200 m of water, 40% of it on the seabed without friction.
constexpr double kDepth = 200.0;
constexpr double kReach = 955.85;

Problem chain_on_seabed(double friction) {
  Problem p;
  p.cable = {1000.0, 1200.0, 8e8, 150.0, 20.0};
  p.supports.a_m = Vec2(0.0, -kDepth);
  p.supports.b_m = Vec2(kReach, 0.0);
  p.seabed = Seabed{-kDepth, friction, 3e6, 0.0};
  return p;
}

// The contact equations of a uniform elastic line in 50 digits. For a trial H: the suspended
// part leaves the seabed with V = 0 and reaches height h where its tension T solves
// T^2/(2EA) + T = H^2/(2EA) + H + w h (from z = (T - H)/w + (T^2 - H^2)/(2 w EA)); its unstretched
// length is V/w with V = sqrt(T^2 - H^2); the grounded tension H - C_B w (L_g - s), clipped at
// 0, stretches the grounded part. Bisection on H closes the horizontal reach.
struct ExactContact {
  Real H, grounded_length, fairlead_vertical, anchor_horizontal;
};

ExactContact exact_contact(
    double L_d, double w_d, double EA_d, double h_d, double reach_d, double friction_d) {
  const Real L = L_d, w = w_d, EA = EA_d, h = h_d, reach = reach_d, friction = friction_d;
  auto state = [&](const Real& H) {
    const Real C = H * H / (2 * EA) + H + w * h;
    const Real T = EA * (sqrt(1 + 2 * C / EA) - 1);
    const Real V = sqrt(T * T - H * H);
    const Real suspended = V / w;
    const Real Lg = L - suspended;
    const Real drop = friction * w * Lg;
    return ExactContact{H, Lg, V, drop <= H ? H - drop : Real(0)};
  };
  auto x_of = [&](const Real& H) {
    const ExactContact c = state(H);
    const Real drop = friction * w * c.grounded_length;
    const Real integral =
        drop <= H ? H * c.grounded_length - friction * w * c.grounded_length * c.grounded_length / 2
                  : H * H / (2 * friction * w);
    const Real suspended = L - c.grounded_length;
    return c.grounded_length + integral / EA + H * suspended / EA +
           (H / w) * asinh(c.fairlead_vertical / H);
  };
  Real lo = 1e3, hi = 1e8;
  for (int i = 0; i < 400; ++i) {
    const Real mid = (lo + hi) / 2;
    (x_of(mid) < reach ? lo : hi) = mid;
  }
  return state((lo + hi) / 2);
}

class FortyPercentGrounded : public ::testing::TestWithParam<double> {};

TEST_P(FortyPercentGrounded, MatchesTheIndependentSolveToOneIn1e9) {
  const double friction = GetParam();
  const Problem p = chain_on_seabed(friction);
  const StaticSolution s = solve_statics(p);
  ASSERT_TRUE(s.converged) << s.message;
  const ExactContact exact = exact_contact(1000.0, 1200.0, 8e8, kDepth, kReach, friction);
  const double L = 1000.0;
  EXPECT_NEAR(s.grounded_length_m() / L, 0.4, 0.01);
  const double errors[] = {
      relative_error(s.horizontal_force_n(), double(exact.H)),
      relative_error(s.grounded_length_m(), double(exact.grounded_length)),
      relative_error(s.vertical_force_n(L), double(exact.fairlead_vertical)),
      relative_error(s.anchor_horizontal_force_n(), double(exact.anchor_horizontal))};
  for (double e : errors) EXPECT_LT(e, 1e-9);
  std::printf("C_B = %g: H %.3e, L_g %.3e, V_B %.3e, anchor %.3e (relative errors)\n", friction,
              errors[0], errors[1], errors[2], errors[3]);
  EXPECT_EQ(s.vertical_force_a_n(), 0.0);
  // One contact interval, from the anchor to the touchdown point.
  ASSERT_EQ(s.contact_intervals().size(), 1u);
  EXPECT_EQ(s.contact_intervals()[0].s_begin_m, 0.0);
  EXPECT_DOUBLE_EQ(s.contact_intervals()[0].s_end_m, s.grounded_length_m());
  EXPECT_TRUE(s.anchor_grounded());
  EXPECT_EQ(s.slack_length_m(), 0.0);
}

INSTANTIATE_TEST_SUITE_P(Friction, FortyPercentGrounded, ::testing::Values(0.0, 0.1, 1.0));

TEST(SeabedStatics, GroundedPartLiesFlatOnTheSeabedAndSuspendedPartLeavesTangentially) {
  const StaticSolution s = solve_statics(chain_on_seabed(1.0));
  const double Lg = s.grounded_length_m();
  ASSERT_GT(Lg, 0.0);
  for (double f : {0.0, 0.3, 0.999}) {
    const double sg = f * Lg;
    EXPECT_DOUBLE_EQ(s.position_m(sg).y(), -kDepth);
    EXPECT_EQ(s.vertical_force_n(sg), 0.0);
    EXPECT_EQ(s.tangent(sg), Vec2(1.0, 0.0));
    EXPECT_EQ(s.normal(sg), Vec2(0.0, 1.0));
    EXPECT_EQ(s.angle_rad(sg), 0.0);
    EXPECT_DOUBLE_EQ(s.strain(sg), s.tension_n(sg) / 8e8);
    // The MAP++/MoorPy friction law: T(s) = H - C_B w (L_g - s).
    EXPECT_NEAR(s.tension_n(sg), s.horizontal_force_n() - 1200.0 * (Lg - sg),
                1e-6 * s.horizontal_force_n());
  }
  EXPECT_TRUE(s.pieces().front().grounded);
  EXPECT_FALSE(s.pieces().back().grounded);
  EXPECT_EQ(s.vertical_force_n(Lg), 0.0);
  EXPECT_NEAR(s.position_m(Lg).y(), -kDepth, 1e-12 * kDepth);
  // Continuity of position and tension at touchdown.
  const Vec2 before = s.position_m(Lg * (1.0 - 1e-12));
  EXPECT_NEAR(before.x(), s.position_m(Lg).x(), 1e-8);
  EXPECT_NEAR(s.tension_n(Lg * (1.0 - 1e-12)), s.tension_n(Lg), 1e-6);
}

// Turchetto's touchdown form (C_B = 0): the suspended length, reach and fairlead tension at our H.
TEST(SeabedStatics, MatchesTurchettosTouchdownForm) {
  const Problem p = chain_on_seabed(0.0);
  const StaticSolution s = solve_statics(p);
  const TouchdownLine t = touchdown_from_depth_and_tension(p.cable, kDepth, s.horizontal_force_n());
  const double L = p.cable.length_m;
  EXPECT_LT(relative_error(t.suspended_length_m, L - s.grounded_length_m()), 1e-10);
  const Vec2 touchdown = s.position_m(s.grounded_length_m());
  EXPECT_LT(relative_error(t.horizontal_reach_m, kReach - touchdown.x()), 1e-10);
  EXPECT_LT(relative_error(t.fairlead_tension_n, s.tension_n(L)), 1e-10);
  // And the inverse form from the reach finds the same H.
  const TouchdownLine r = touchdown_from_depth_and_reach(p.cable, kDepth, kReach - touchdown.x());
  EXPECT_LT(relative_error(r.horizontal_tension_n, s.horizontal_force_n()), 1e-9);
}

// A line whose free catenary has V_A = 0 at A touches down exactly there: with and without the
// seabed the solutions agree.
TEST(SeabedStatics, TouchdownExactlyAtTheAnchorReproducesTheFreeLine) {
  Problem p = chain_on_seabed(0.5);
  const double H = 1.5e6;
  p.supports.b_m = p.supports.a_m + catenary_end_offset(p.cable, H, 0.0);
  Problem free = p;
  free.seabed.reset();
  const StaticSolution with = solve_statics(p);
  const StaticSolution without = solve_statics(free);
  ASSERT_TRUE(with.converged && without.converged);
  EXPECT_TRUE(with.has_seabed());
  EXPECT_LT(with.grounded_length_m(), 1e-6);
  const double L = p.cable.length_m;
  EXPECT_LT(relative_error(with.horizontal_force_n(), without.horizontal_force_n()), 1e-9);
  EXPECT_LT(relative_error(with.tension_n(L), without.tension_n(L)), 1e-9);
  EXPECT_LT(relative_error(with.anchor_horizontal_force_n(), without.horizontal_force_n()), 1e-9);
  for (double f : {0.25, 0.5, 1.0})
    EXPECT_LT((with.position_m(f * L) - without.position_m(f * L)).norm(), 1e-7);
}

// Without contact the answer is the free line's, bit for bit.
TEST(SeabedStatics, NoContactIsTheFreeSolutionBitForBit) {
  Problem p = chain_on_seabed(0.3);
  p.supports.b_m = Vec2(980.0, 0.0);
  Problem free = p;
  free.seabed.reset();
  const StaticSolution with = solve_statics(p);
  const StaticSolution without = solve_statics(free);
  EXPECT_FALSE(with.has_contact());
  EXPECT_TRUE(with.has_seabed());
  EXPECT_EQ(with.horizontal_force_n(), without.horizontal_force_n());
  EXPECT_EQ(with.vertical_force_a_n(), without.vertical_force_a_n());
  EXPECT_EQ(with.anchor_horizontal_force_n(), without.horizontal_force_n());
  EXPECT_EQ(with.grounded_length_m(), 0.0);
  EXPECT_GE(with.vertical_force_a_n(), 0.0);
}

// Friction: the anchor load is H - C_B w L_g while positive, never negative; a long slack stretch
// carries no tension.
TEST(SeabedStatics, AnchorLoadIsFairleadHMinusFrictionAndNeverNegative) {
  for (double friction : {0.0, 0.1, 0.5, 1.0, 1.5, 3.0, 10.0}) {
    const StaticSolution s = solve_statics(chain_on_seabed(friction));
    ASSERT_TRUE(s.converged) << s.message;
    const double expected = s.horizontal_force_n() - friction * 1200.0 * s.grounded_length_m();
    EXPECT_GE(s.anchor_horizontal_force_n(), 0.0);
    if (expected > 0.0) {
      EXPECT_NEAR(s.anchor_horizontal_force_n(), expected, 1e-9 * s.horizontal_force_n())
          << friction;
    } else {
      EXPECT_EQ(s.anchor_horizontal_force_n(), 0.0) << friction;
      // Slack from A to where C_B w (L_g - s) = H.
      const double slack_end = s.grounded_length_m() - s.horizontal_force_n() / (friction * 1200.0);
      EXPECT_EQ(s.tension_n(0.5 * slack_end), 0.0);
      EXPECT_EQ(s.strain(0.5 * slack_end), 0.0);
      EXPECT_GT(s.tension_n(slack_end + 1.0), 0.0);
    }
  }
}

// A clump weight on the grounded part adds C_B times its weight to the friction.
TEST(SeabedStatics, ClumpWeightOnTheGroundedPartAddsItsFriction) {
  Problem p = chain_on_seabed(0.5);
  p.line.segments.push_back({1000.0, 1200.0, 8e8, 150.0, 20.0});
  PointAttachment clump;
  clump.s_m = 100.0;
  clump.mass_kg = 5000.0;
  clump.weight_n = 4e4;
  p.line.points.push_back(clump);
  const StaticSolution s = solve_statics(p);
  ASSERT_TRUE(s.converged) << s.message;
  ASSERT_GT(s.grounded_length_m(), 100.0);
  const double expected = s.horizontal_force_n() - 0.5 * (1200.0 * s.grounded_length_m() + 4e4);
  EXPECT_NEAR(s.anchor_horizontal_force_n(), expected, 1e-9 * s.horizontal_force_n());
  EXPECT_NEAR(s.tension_n(100.0) - s.tension_n(99.999), 0.5 * 4e4 + 0.5 * 1200.0 * 1e-3, 1e-6);
}

// Chain (600 m) and wire (500 m) touching down in the chain: the suspended part, solved as a
// free general line from the touchdown point (Newton, solve_line_statics), has the same H and
// leaves with V = 0.
TEST(SeabedStatics, ChainWireLineTouchingDownInTheChain) {
  Problem p;
  p.line.segments.push_back({600.0, 1200.0, 8e8, 150.0, 20.0});
  p.line.segments.push_back({500.0, 250.0, 5e8, 30.0, 5.0});
  p.supports.a_m = Vec2(0.0, -250.0);
  p.supports.b_m = Vec2(1040.0, 0.0);
  p.seabed = Seabed{-250.0, 0.2, 3e6, 0.0};
  const StaticSolution s = solve_statics(p);
  ASSERT_TRUE(s.converged) << s.message;
  const double Lg = s.grounded_length_m();
  ASSERT_GT(Lg, 50.0);
  ASSERT_LT(Lg, 600.0);
  EXPECT_LT(s.closure_error_m, 1e-9);
  Problem suspended;
  suspended.line.segments.push_back({600.0 - Lg, 1200.0, 8e8, 150.0, 20.0});
  suspended.line.segments.push_back({500.0, 250.0, 5e8, 30.0, 5.0});
  suspended.supports.a_m = s.position_m(Lg);
  suspended.supports.b_m = p.supports.b_m;
  const StaticSolution free = solve_line_statics(suspended);
  ASSERT_TRUE(free.converged);
  EXPECT_LT(relative_error(free.horizontal_force_n(), s.horizontal_force_n()), 1e-8);
  EXPECT_LT(std::abs(free.vertical_force_a_n()), 1e-8 * s.horizontal_force_n());
  EXPECT_NEAR(s.anchor_horizontal_force_n(), s.horizontal_force_n() - 0.2 * 1200.0 * Lg, 1e-6);
  EXPECT_EQ(s.pieces().front().segment, 0u);
  EXPECT_EQ(s.pieces().back().segment, 1u);
}

// The pieces the dynamics builds on: grounded first, cut where the friction tension reaches 0 and
// at joints; the suspended pieces start at L_g with V = 0.
TEST(SeabedStatics, GroundedPiecesAreCutAtTheSlackEndAndAtJoints) {
  const StaticSolution slack = solve_statics(chain_on_seabed(3.0));
  const double Lg = slack.grounded_length_m();
  const auto& pieces = slack.pieces();
  ASSERT_GE(pieces.size(), 3u);
  EXPECT_TRUE(pieces[0].grounded && pieces[1].grounded && !pieces[2].grounded);
  EXPECT_LE(pieces[0].grounded_tension_begin_n, 0.0);
  EXPECT_NEAR(pieces[1].s_begin_m, Lg - slack.horizontal_force_n() / (3.0 * 1200.0), 1e-9 * Lg);
  EXPECT_NEAR(pieces[2].s_begin_m, Lg, 1e-12 * Lg);
  EXPECT_EQ(pieces[2].vertical_begin_n, 0.0);
  // 300 m of chain then 900 m of chain of another EA: touchdown in the second segment.
  Problem p = chain_on_seabed(0.5);
  p.line.segments.push_back({300.0, 1200.0, 6e8, 150.0, 20.0});
  p.line.segments.push_back({700.0, 1200.0, 8e8, 150.0, 20.0});
  const StaticSolution s = solve_statics(p);
  ASSERT_TRUE(s.converged) << s.message;
  ASSERT_GT(s.grounded_length_m(), 300.0);
  EXPECT_TRUE(s.pieces()[0].grounded && s.pieces()[1].grounded);
  EXPECT_EQ(s.pieces()[1].s_begin_m, 300.0);
  EXPECT_EQ(s.pieces()[1].segment, 1u);
  EXPECT_DOUBLE_EQ(s.strain(100.0), s.tension_n(100.0) / 6e8);
  EXPECT_DOUBLE_EQ(s.strain(350.0), s.tension_n(350.0) / 8e8);
}

// Chain on the seabed, a buoyant stretch that lifts off, chain again: the chain beyond the buoyant
// stretch touches down a second time (general contact, tests/statics/general_contact_test.cpp):
// the buoyant segment's lift (3e5 N) holds 250 m of chain off the seabed, V = 0 at both ends.
TEST(SeabedStatics, ASecondContactIntervalBeyondABuoyantStretch) {
  Problem p;
  p.line.segments.push_back({400.0, 1200.0, 8e8, 150.0, 20.0});
  p.line.segments.push_back({100.0, -3000.0, 8e8, 150.0, 20.0});
  p.line.segments.push_back({700.0, 1200.0, 8e8, 150.0, 20.0});
  p.supports.a_m = Vec2(0.0, -200.0);
  p.supports.b_m = Vec2(1000.0, 0.0);
  p.seabed = Seabed{-200.0, 0.0, 0.0, 0.0};
  const StaticSolution s = solve_statics(p);
  ASSERT_TRUE(s.converged) << s.message;
  const auto intervals = s.contact_intervals();
  ASSERT_EQ(intervals.size(), 2u);
  // The lifted arc weighs nothing in total: 1200 (l_arc) = 3000 * 100.
  const double lifted = intervals[1].s_begin_m - intervals[0].s_end_m;
  EXPECT_NEAR(lifted, 100.0 + 3e5 / 1200.0, 1e-9 * 1200.0);
  EXPECT_NEAR(s.position_m(intervals[1].s_begin_m).y(), -200.0, 1e-9 * 1200.0);
  for (int i = 0; i <= 1200; ++i) EXPECT_GE(s.position_m(i).y(), -200.0 - 1e-9 * 1200.0);
}

// A buoy on the chain lying on the seabed lifts a short arc (1e4 N holds 1e4 / 1200 m of chain).
TEST(SeabedStatics, ABuoyOnTheGroundedPartLiftsAShortArc) {
  Problem p = chain_on_seabed(0.0);
  p.line.segments.push_back({1000.0, 1200.0, 8e8, 150.0, 20.0});
  PointAttachment buoy;
  buoy.s_m = 100.0;
  buoy.weight_n = -1e4;
  p.line.points.push_back(buoy);
  const StaticSolution s = solve_statics(p);
  ASSERT_TRUE(s.converged) << s.message;
  const auto intervals = s.contact_intervals();
  ASSERT_EQ(intervals.size(), 2u);
  EXPECT_NEAR(intervals[0].s_end_m, 100.0 - 1e4 / 2400.0, 1e-10 * 1000.0);
  EXPECT_NEAR(intervals[1].s_begin_m, 100.0 + 1e4 / 2400.0, 1e-10 * 1000.0);
  EXPECT_GT(s.position_m(100.0).y(), -200.0);
}

TEST(SeabedStatics, BadInputNamesTheField) {
  Problem p = chain_on_seabed(0.1);
  p.supports.a_m = Vec2(0.0, -201.0);
  expect_invalid([&] { solve_statics(p); }, "end A must not be below the seabed");
  p = chain_on_seabed(0.1);
  p.supports.b_m = Vec2(900.0, -250.0);
  expect_invalid([&] { solve_statics(p); }, "seabed.z");
  p.supports.b_m = Vec2(900.0, -200.0);
  expect_invalid([&] { solve_statics(p); }, "entirely on the seabed");
  p = chain_on_seabed(-0.1);
  expect_invalid([&] { solve_statics(p); }, "seabed.friction");
  p = chain_on_seabed(0.1);
  p.seabed->stiffness_n_per_m2 = -1.0;
  expect_invalid([&] { solve_statics(p); }, "seabed.stiffness");
  p.seabed->stiffness_n_per_m2 = 1.0;
  p.seabed->tangential_stiffness_n_per_m2 = -1.0;
  expect_invalid([&] { solve_statics(p); }, "seabed.tangential_stiffness");
  p = chain_on_seabed(0.1);
  p.seabed->z_m = NAN;
  expect_invalid([&] { solve_statics(p); }, "seabed.z");
}

}  // namespace
}  // namespace catena
