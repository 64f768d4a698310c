// SPDX-License-Identifier: MIT
// General seabed contact and slack lines (docs/explanation/physics.md, "Seabed contact"): W and U
// shapes, a shared line between two floaters, a buoy lifting an arc off a line anchored on the
// seabed, slack lines (H = 0), and the cases refused.
// Anchors: for each shape an independent 50-digit solve written from the closed forms of an elastic
// catenary measured from its lowest point (x = H s/EA + (H/w) asinh(w s/H), z = w s^2/(2 EA) +
// (sqrt(H^2 + w^2 s^2) - H)/w), using the shape's symmetry where it has one: one unknown H by
// bisection, the hanging lengths by bisection on z; and the vertical hanging chain in closed form
// for the slack lines. None of it calls the library.
#include <gtest/gtest.h>

#include <boost/math/constants/constants.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <cmath>
#include <cstdio>
#include <functional>

#include "catena/statics/seabed_statics.hpp"
#include "test_utils.hpp"

namespace catena {
namespace {

using testing::expect_invalid;
using testing::relative_error;
using Real = boost::multiprecision::cpp_bin_float_50;

constexpr double kPi = boost::math::constants::pi<double>();
// MoorPy tests/case6.dat and case5.dat: chain of 0.2 m, 500 kg/m, EA 2e9 in 300 m of water
// (g = 9.81, rho = 1025), and case6's buoy of 200 m^3.
const double kChainWeight = (500.0 - 1025.0 * kPi * 0.01) * 9.81;
const double kBuoyWeight = -200.0 * 1025.0 * 9.81;
constexpr double kChainEA = 2e9;
constexpr double kDepth = 300.0;

// An elastic catenary of weight w and stiffness EA, measured from its lowest point (V = 0).
struct Catenary {
  Real w, EA;
  Real x(const Real& H, const Real& s) const { return H * s / EA + H / w * asinh(w * s / H); }
  Real z(const Real& H, const Real& s) const {
    return w * s * s / (2 * EA) + (sqrt(H * H + w * w * s * s) - H) / w;
  }
  // The length from the lowest point that rises by h.
  Real hanging_length(const Real& H, const Real& h) const {
    Real lo = 0, hi = 10 * h + 10 * H / w;
    for (int i = 0; i < 400; ++i) {
      const Real mid = (lo + hi) / 2;
      (z(H, mid) < h ? lo : hi) = mid;
    }
    return (lo + hi) / 2;
  }
};

// Bisection on H in 50 digits for an increasing reach(H) = target.
Real solve_for_H(const std::function<Real(const Real&)>& reach,
                 double target,
                 double lo_d,
                 double hi_d) {
  Real lo = lo_d, hi = hi_d;
  for (int i = 0; i < 400; ++i) {
    const Real mid = (lo + hi) / 2;
    (reach(mid) < target ? lo : hi) = mid;
  }
  return (lo + hi) / 2;
}

LineSegment chain(double length) { return {length, kChainWeight, kChainEA, 500.0, 0.0}; }

// The W shape: 660/330/330 m of chain, the buoy at the first joint, both ends at z = 0.
Problem w_shape() {
  Problem p;
  p.line.segments = {chain(660.0), chain(330.0), chain(330.0)};
  PointAttachment buoy;
  buoy.s_m = 660.0;
  buoy.weight_n = kBuoyWeight;
  p.line.points.push_back(buoy);
  p.supports.a_m = Vec2(0.0, 0.0);
  p.supports.b_m = Vec2(400.0 * std::sqrt(2.0), 0.0);
  p.seabed = Seabed{-kDepth, 0.0, 0.0, 0.0};
  return p;
}

// The general checks of a contact solution: closure, nothing below the seabed, contact intervals
// at the seabed's height, V = 0 on every grounded stretch and where it ends.
void expect_consistent_contact(const StaticSolution& s, const Problem& p) {
  ASSERT_TRUE(s.converged) << s.message;
  const double L = p.length_m();
  const double z_s = p.seabed->z_m;
  EXPECT_LT(s.closure_error_m, 1e-11 * L);
  for (int i = 0; i <= 4000; ++i) {
    EXPECT_GE(s.position_m(L * i / 4000.0).y(), z_s - 1e-9 * L) << "s = " << L * i / 4000.0;
  }
  double grounded = 0.0;
  for (const ContactInterval& c : s.contact_intervals()) {
    grounded += c.s_end_m - c.s_begin_m;
    for (double f : {0.0, 0.5, 1.0 - 1e-9}) {
      const double sg = c.s_begin_m + f * (c.s_end_m - c.s_begin_m);
      EXPECT_NEAR(s.position_m(sg).y(), z_s, 1e-12 * L);
      EXPECT_EQ(s.vertical_force_n(sg), 0.0);
    }
    if (c.s_begin_m > 0.0) {
      EXPECT_NEAR(s.vertical_force_before_n(c.s_begin_m), 0.0, 1e-9 * kChainWeight * L);
    }
    if (c.s_end_m < L) EXPECT_NEAR(s.vertical_force_n(c.s_end_m), 0.0, 1e-9 * kChainWeight * L);
  }
  EXPECT_NEAR(s.grounded_length_m(), grounded, 1e-12 * L);
}

// The W shape: symmetric about the buoy; each half is an arc from its end down to the seabed,
// a grounded stretch at tension H, and half of the buoy's arc, whose length is fixed by V = 0 at
// both its ends: the buoy holds up G/(2w) of chain on each side.
TEST(GeneralContact, WShapeMatchesTheIndependentSolve) {
  const Problem p = w_shape();
  const StaticSolution s = solve_seabed_statics(p);
  expect_consistent_contact(s, p);
  const auto intervals = s.contact_intervals();
  ASSERT_EQ(intervals.size(), 2u);
  EXPECT_FALSE(s.anchor_grounded());

  const Catenary c{kChainWeight, kChainEA};
  const Real half_arc = Real(-kBuoyWeight) / (2 * c.w);
  auto reach = [&](const Real& H) {
    const Real hanging = c.hanging_length(H, kDepth);
    const Real grounded = 660 - hanging - half_arc;
    return 2 * (c.x(H, hanging) + grounded * (1 + H / c.EA) + c.x(H, half_arc));
  };
  const Real H = solve_for_H(reach, 400.0 * std::sqrt(2.0), 1e3, 1e7);
  const double hanging = static_cast<double>(c.hanging_length(H, kDepth));
  const double lift_off = 660.0 - static_cast<double>(half_arc);
  EXPECT_LT(relative_error(s.horizontal_force_n(), static_cast<double>(H)), 1e-12);
  std::printf("W shape: H %.3e, touchdown %.3e, lift-off %.3e (relative errors), %d evaluations\n",
              relative_error(s.horizontal_force_n(), static_cast<double>(H)),
              relative_error(intervals[0].s_begin_m, hanging),
              relative_error(intervals[0].s_end_m, lift_off), s.iterations);
  EXPECT_NEAR(intervals[0].s_begin_m, hanging, 1e-10 * 660.0);
  EXPECT_NEAR(intervals[0].s_end_m, lift_off, 1e-10 * 660.0);
  EXPECT_NEAR(intervals[1].s_begin_m, 1320.0 - lift_off, 1e-10 * 660.0);
  EXPECT_NEAR(intervals[1].s_end_m, 1320.0 - hanging, 1e-10 * 660.0);
  const double end_tension = static_cast<double>(sqrt(H * H + c.w * c.w * hanging * hanging));
  EXPECT_LT(relative_error(s.tension_n(0.0), end_tension), 1e-12);
  EXPECT_LT(relative_error(s.tension_n(1320.0), end_tension), 1e-12);
  EXPECT_EQ(s.anchor_horizontal_force_n(), s.horizontal_force_n());
  // The buoy's height: the rise of the half arc.
  EXPECT_NEAR(s.position_m(660.0).y(), -kDepth + static_cast<double>(c.z(H, half_arc)),
              1e-10 * kDepth);
  EXPECT_EQ(s.slack_length_m(), 0.0);
}

// A symmetric U shape (a uniform chain with both ends at the same height above the seabed): each
// end arc is a catenary from its lowest point at the touchdown; between them the chain lies on
// the seabed at tension H.
TEST(GeneralContact, SymmetricUShapeMatchesTheClosedForm) {
  Problem p;
  p.cable = {1200.0, kChainWeight, kChainEA, 500.0, 0.0};
  p.supports.a_m = Vec2(0.0, -20.0);
  p.supports.b_m = Vec2(800.0, -20.0);
  p.seabed = Seabed{-kDepth, 0.3, 0.0, 0.0};
  const StaticSolution s = solve_seabed_statics(p);
  expect_consistent_contact(s, p);
  ASSERT_EQ(s.contact_intervals().size(), 1u);

  const Catenary c{kChainWeight, kChainEA};
  const Real h = kDepth - 20.0;
  auto reach = [&](const Real& H) {
    const Real hanging = c.hanging_length(H, h);
    return 2 * c.x(H, hanging) + (1200 - 2 * hanging) * (1 + H / c.EA);
  };
  const Real H = solve_for_H(reach, 800.0, 1e2, 1e7);
  const double hanging = static_cast<double>(c.hanging_length(H, h));
  EXPECT_LT(relative_error(s.horizontal_force_n(), static_cast<double>(H)), 1e-12);
  std::printf("U shape: H %.3e (relative error)\n",
              relative_error(s.horizontal_force_n(), static_cast<double>(H)));
  EXPECT_NEAR(s.contact_intervals()[0].s_begin_m, hanging, 1e-10 * 1200.0);
  EXPECT_NEAR(s.contact_intervals()[0].s_end_m, 1200.0 - hanging, 1e-10 * 1200.0);
  // Friction is not mobilised between two suspended parts: the tension is H all along.
  EXPECT_EQ(s.tension_n(600.0), s.horizontal_force_n());
  EXPECT_LT(relative_error(s.vertical_force_a_n(), -static_cast<double>(c.w) * hanging), 1e-12);
}

// A shared line between two floaters at different draughts: a U shape with unequal end arcs.
TEST(GeneralContact, SharedLineBetweenTwoFloatersMatchesTheIndependentSolve) {
  Problem p;
  p.line.segments = {chain(500.0), chain(700.0)};
  p.supports.a_m = Vec2(0.0, -14.0);
  p.supports.b_m = Vec2(1000.0, -60.0);
  p.seabed = Seabed{-200.0, 0.5, 0.0, 0.0};
  const StaticSolution s = solve_seabed_statics(p);
  expect_consistent_contact(s, p);
  ASSERT_EQ(s.contact_intervals().size(), 1u);

  const Catenary c{kChainWeight, kChainEA};
  auto reach = [&](const Real& H) {
    const Real hanging_a = c.hanging_length(H, 186.0);
    const Real hanging_b = c.hanging_length(H, 140.0);
    return c.x(H, hanging_a) + c.x(H, hanging_b) + (1200 - hanging_a - hanging_b) * (1 + H / c.EA);
  };
  const Real H = solve_for_H(reach, 1000.0, 1e2, 1e7);
  EXPECT_LT(relative_error(s.horizontal_force_n(), static_cast<double>(H)), 1e-12);
  std::printf("shared line: H %.3e (relative error)\n",
              relative_error(s.horizontal_force_n(), static_cast<double>(H)));
  EXPECT_NEAR(s.contact_intervals()[0].s_begin_m, static_cast<double>(c.hanging_length(H, 186.0)),
              1e-10 * 1200.0);
  EXPECT_NEAR(s.contact_intervals()[0].s_end_m,
              1200.0 - static_cast<double>(c.hanging_length(H, 140.0)), 1e-10 * 1200.0);
}

// Anchor on the seabed, a buoy lifting an arc off the grounded chain: friction on the stretch from
// the anchor only; the arc holds G/(2w) of chain on each side of the buoy; a second contact
// interval beyond it at tension H; then the arc up to the fairlead.
TEST(GeneralContact, BuoyLiftsAnArcOffALineAnchoredOnTheSeabed) {
  const double w = 1200.0, EA = 8e8, G = 1.2e5, friction = 0.5;
  Problem p;
  p.line.segments = {{1000.0, w, EA, 150.0, 0.0}};
  PointAttachment buoy;
  buoy.s_m = 300.0;
  buoy.weight_n = -G;
  p.line.points.push_back(buoy);
  p.supports.a_m = Vec2(0.0, -200.0);
  p.supports.b_m = Vec2(900.0, 0.0);
  p.seabed = Seabed{-200.0, friction, 0.0, 0.0};
  const StaticSolution s = solve_seabed_statics(p);
  expect_consistent_contact(s, p);
  const auto intervals = s.contact_intervals();
  ASSERT_EQ(intervals.size(), 2u);
  EXPECT_TRUE(s.anchor_grounded());

  const Catenary c{w, EA};
  const Real half_arc = Real(G) / (2 * w);
  const Real first = 300 - half_arc;
  auto reach = [&](const Real& H) {
    const Real drop = friction * w * first;
    const Real integral =
        drop <= H ? H * first - friction * w * first * first / 2 : H * H / (2 * friction * w);
    const Real hanging = c.hanging_length(H, 200.0);
    const Real second = 1000 - 300 - half_arc - hanging;
    return first + integral / EA + 2 * c.x(H, half_arc) + second * (1 + H / EA) + c.x(H, hanging);
  };
  const Real H = solve_for_H(reach, 900.0, 1e2, 1e8);
  EXPECT_LT(relative_error(s.horizontal_force_n(), static_cast<double>(H)), 1e-12);
  std::printf("lifted arc: H %.3e (relative error)\n",
              relative_error(s.horizontal_force_n(), static_cast<double>(H)));
  EXPECT_NEAR(intervals[0].s_end_m, static_cast<double>(first), 1e-10 * 1000.0);
  EXPECT_NEAR(intervals[1].s_begin_m, static_cast<double>(300 + half_arc), 1e-10 * 1000.0);
  EXPECT_NEAR(intervals[1].s_end_m, 1000.0 - static_cast<double>(c.hanging_length(H, 200.0)),
              1e-10 * 1000.0);
  const double H_d = static_cast<double>(H);
  EXPECT_NEAR(s.anchor_horizontal_force_n(), std::max(H_d - friction * w * double(first), 0.0),
              1e-9 * H_d);
  // Between two suspended parts the friction is not mobilised.
  EXPECT_EQ(s.tension_n(0.5 * (intervals[1].s_begin_m + intervals[1].s_end_m)),
            s.horizontal_force_n());
}

// The vertical hanging chain from a height h: h = L_h + w L_h^2 / (2 EA).
double hanging_chain_length(double w, double EA, double h) {
  return 2.0 * h / (1.0 + std::sqrt(1.0 + 2.0 * w * h / EA));
}

// No NaN anywhere along a slack line, and the directions it is given.
void expect_finite_everywhere(const StaticSolution& s, double L) {
  for (int i = 0; i <= 2000; ++i) {
    const double sg = L * i / 2000.0;
    EXPECT_TRUE(std::isfinite(s.tension_n(sg)) && std::isfinite(s.strain(sg)) &&
                std::isfinite(s.angle_rad(sg)) && s.tangent(sg).allFinite() &&
                s.normal(sg).allFinite() && s.position_m(sg).allFinite() &&
                std::isfinite(s.stretched_length_m(sg)))
        << "s = " << sg;
    EXPECT_NEAR(s.tangent(sg).norm(), 1.0, 1e-15) << "s = " << sg;
  }
}

// MoorPy tests/case5.dat: 890 m of chain from an anchor 400 m away in 300 m of water: longer than
// span plus depth. H = 0: the hanging part is vertical under B, the rest on the seabed with zero
// tension; what does not fit in the span lies in a heap at the foot.
// MoorPy tests/case3.dat: anchored on the seabed, a buoy (200 m^3) at s = 400 m and a clump weight
// (1e5 kg) at s = 650 m beyond the touchdown. The one-interval state from the anchor satisfies
// every contact condition, so it is the equilibrium (a regression: general contact once refused
// this line as passing below the seabed).
TEST(GeneralContact, BuoyAndClumpBeyondTheTouchdownKeepOneIntervalFromTheAnchor) {
  Problem p;
  p.line.segments = {chain(400.0), chain(250.0), chain(250.0)};
  PointAttachment buoy;
  buoy.s_m = 400.0;
  buoy.weight_n = kBuoyWeight;
  PointAttachment clump;
  clump.s_m = 650.0;
  clump.weight_n = 1e5 * 9.81;
  p.line.points = {buoy, clump};
  p.supports.a_m = Vec2(0.0, -kDepth);
  p.supports.b_m = Vec2(800.0, 0.0);
  p.seabed = Seabed{-kDepth, 0.0, 0.0, 0.0};
  const StaticSolution s = solve_seabed_statics(p);
  ASSERT_TRUE(s.converged) << s.message;
  ASSERT_EQ(s.contact_intervals().size(), 1u);
  EXPECT_EQ(s.contact_intervals()[0].s_begin_m, 0.0);
  const double touchdown = s.contact_intervals()[0].s_end_m;
  EXPECT_GT(touchdown, 0.0);
  EXPECT_LT(std::abs(s.vertical_force_n(touchdown)), 1e-6 * s.horizontal_force_n());
  for (int i = 0; i <= 9000; ++i) {
    const double at = 0.1 * i;
    EXPECT_GE(s.position_m(at).y(), -kDepth - 1e-9 * kDepth) << "s = " << at;
  }
  EXPECT_LT((s.position_m(900.0) - p.supports.b_m).norm(), 1e-9 * 900.0);
}

TEST(GeneralContact, SlackLineIsTheVerticalHangingChainAndAHeap) {
  Problem p;
  p.cable = {890.0, kChainWeight, kChainEA, 500.0, 0.0};
  p.supports.a_m = Vec2(-400.0, -kDepth);
  p.supports.b_m = Vec2(0.0, 0.0);
  p.seabed = Seabed{-kDepth, 1.0, 0.0, 0.0};
  const StaticSolution s = solve_seabed_statics(p);
  ASSERT_TRUE(s.converged) << s.message;
  const double hanging = hanging_chain_length(kChainWeight, kChainEA, kDepth);
  EXPECT_EQ(s.horizontal_force_n(), 0.0);
  ASSERT_EQ(s.contact_intervals().size(), 1u);
  EXPECT_EQ(s.contact_intervals()[0].s_begin_m, 0.0);
  EXPECT_NEAR(s.contact_intervals()[0].s_end_m, 890.0 - hanging, 1e-12 * 890.0);
  EXPECT_NEAR(s.slack_length_m(), 890.0 - hanging - 400.0, 1e-12 * 890.0);
  EXPECT_LT(relative_error(s.tension_n(890.0), kChainWeight * hanging), 1e-13);
  EXPECT_EQ(s.tension_n(100.0), 0.0);
  EXPECT_EQ(s.anchor_horizontal_force_n(), 0.0);
  EXPECT_LT(s.closure_error_m, 1e-11 * 890.0);
  // The foot of the hanging part is under B; the tangent there points up.
  const double foot = s.contact_intervals()[0].s_end_m;
  EXPECT_NEAR(s.position_m(foot).x(), 0.0, 1e-12 * 890.0);
  EXPECT_NEAR(s.position_m(foot).y(), -kDepth, 1e-12 * 890.0);
  EXPECT_EQ(s.tangent(foot), Vec2(0.0, 1.0));
  EXPECT_EQ(s.tangent(0.5 * (foot + 890.0)), Vec2(0.0, 1.0));
  EXPECT_EQ(s.tangent(100.0), Vec2(1.0, 0.0));
  expect_finite_everywhere(s, 890.0);
}

// Both ends above the seabed with H = 0 (MoorPy's U profile type 5): two vertical parts.
TEST(GeneralContact, SlackUShapeHasTwoVerticalParts) {
  Problem p;
  p.cable = {1000.0, kChainWeight, kChainEA, 500.0, 0.0};
  p.supports.a_m = Vec2(0.0, -100.0);
  p.supports.b_m = Vec2(200.0, -50.0);
  p.seabed = Seabed{-kDepth, 0.0, 0.0, 0.0};
  const StaticSolution s = solve_seabed_statics(p);
  ASSERT_TRUE(s.converged) << s.message;
  const double hanging_a = hanging_chain_length(kChainWeight, kChainEA, 200.0);
  const double hanging_b = hanging_chain_length(kChainWeight, kChainEA, 250.0);
  EXPECT_EQ(s.horizontal_force_n(), 0.0);
  ASSERT_EQ(s.contact_intervals().size(), 1u);
  EXPECT_NEAR(s.contact_intervals()[0].s_begin_m, hanging_a, 1e-12 * 1000.0);
  EXPECT_NEAR(s.contact_intervals()[0].s_end_m, 1000.0 - hanging_b, 1e-12 * 1000.0);
  EXPECT_NEAR(s.slack_length_m(), 1000.0 - hanging_a - hanging_b - 200.0, 1e-12 * 1000.0);
  EXPECT_LT(relative_error(s.tension_n(0.0), kChainWeight * hanging_a), 1e-13);
  EXPECT_LT(relative_error(s.tension_n(1000.0), kChainWeight * hanging_b), 1e-13);
  EXPECT_EQ(s.tangent(hanging_a * 0.5), Vec2(0.0, -1.0));
  EXPECT_NEAR(s.position_m(hanging_a).x(), 0.0, 1e-12);
  expect_finite_everywhere(s, 1000.0);
}

TEST(GeneralContact, RefusesWhatTheModelCannotTake) {
  // A slack line with a buoy: its lifted arc would fold on itself.
  Problem slack;
  slack.line.segments = {chain(890.0)};
  PointAttachment buoy;
  buoy.s_m = 200.0;
  buoy.weight_n = -1e5;
  slack.line.points.push_back(buoy);
  slack.supports.a_m = Vec2(-400.0, -kDepth);
  slack.supports.b_m = Vec2(0.0, 0.0);
  slack.seabed = Seabed{-kDepth, 0.0, 0.0, 0.0};
  expect_invalid([&] { solve_seabed_statics(slack); }, "slack line");
  // End B on the seabed with A above it.
  Problem mirrored = w_shape();
  mirrored.supports.b_m = Vec2(565.0, -kDepth);
  expect_invalid([&] { solve_seabed_statics(mirrored); }, "end B lies on the seabed");
  // A weightless segment lying on the seabed between two hanging chains.
  Problem weightless;
  weightless.line.segments = {chain(500.0), {200.0, 0.0, kChainEA, 50.0, 0.0}, chain(500.0)};
  weightless.supports.a_m = Vec2(0.0, 0.0);
  weightless.supports.b_m = Vec2(500.0, 0.0);
  weightless.seabed = Seabed{-kDepth, 0.0, 0.0, 0.0};
  expect_invalid([&] { solve_seabed_statics(weightless); }, "line.segments[1]");
  // An end below the seabed.
  Problem below = w_shape();
  below.supports.a_m = Vec2(0.0, -kDepth - 1.0);
  expect_invalid([&] { solve_seabed_statics(below); }, "end A must not be below the seabed");
}

}  // namespace
}  // namespace catena
