// SPDX-License-Identifier: MIT
// Statics of a general line (docs/explanation/physics.md, "General lines").
// Compared: a uniform cable split into identical segments against the one-segment solution; a
// weightless segment against the straight bar it must be; every solution against an independent
// solve of the closure equations (long double, Gauss-Legendre quadrature of r' = (1 + T/EA) t
// along the line and a finite-difference Newton: no closed form shared with the library).
#include "catena/statics/line_statics.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "test_utils.hpp"

namespace catena {
namespace {

using catena::testing::split_into_segments;

using testing::expect_invalid;
using testing::relative_error;

Problem uniform_problem() {
  Problem p;
  p.cable = {1000.0, 1000.0, 5e8, 120.0, 80.0};
  p.supports.a_m = Vec2(0.0, 0.0);
  p.supports.b_m = Vec2(900.0, 300.0);
  return p;
}

PointAttachment point(double s, double mass, double weight, double added_mass) {
  PointAttachment p;
  p.s_m = s;
  p.mass_kg = mass;
  p.weight_n = weight;
  p.added_mass_kg = added_mass;
  return p;
}

// Chain - wire - chain with a clump weight on the wire and a buoy near the top.
Problem mooring_line() {
  Problem p;
  p.supports.a_m = Vec2(0.0, -300.0);
  p.supports.b_m = Vec2(800.0, 0.0);
  p.line.segments = {{250.0, 1400.0, 7.5e8, 160.0, 25.0},
                     {600.0, 60.0, 2.0e8, 8.0, 4.0},
                     {100.0, 1400.0, 7.5e8, 160.0, 25.0}};
  p.line.points = {point(400.0, 20000.0, 1.5e5, 0.0), point(800.0, 3000.0, -4.0e4, 5000.0)};
  return p;
}

// --- the independent closure: long double quadrature of the line's tangent ---
using Real = long double;
struct Offset {
  Real x = 0, z = 0;
};

// r(L) - r(0) for forces (H, V_A): 24-point composite Gauss-Legendre (3 points per panel) on every
// piece between breaks, with V(s) from the weights up to s.
Offset independent_offset(const Line& line, Real H, Real V_A) {
  static const std::array<Real, 3> nodes = {-0.774596669241483377035853079956L, 0.0L,
                                            0.774596669241483377035853079956L};
  static const std::array<Real, 3> weights = {5.0L / 9.0L, 8.0L / 9.0L, 5.0L / 9.0L};
  Offset r;
  Real V = V_A;
  Real s = 0;
  std::size_t next_point = 0;
  for (const LineSegment& g : line.segments) {
    const Real end = s + g.length_m;
    const Real compliance = std::isinf(g.axial_stiffness_n) ? 0.0L : 1.0L / g.axial_stiffness_n;
    while (s < end) {
      while (next_point < line.points.size() && line.points[next_point].s_m <= s + 1e-9L)
        V += line.points[next_point++].weight_n;
      const Real stop = next_point < line.points.size() && line.points[next_point].s_m < end
                            ? line.points[next_point].s_m
                            : end;
      constexpr int kPanels = 400;
      const Real h = (stop - s) / kPanels;
      for (int panel = 0; panel < kPanels; ++panel) {
        for (int i = 0; i < 3; ++i) {
          const Real local = h * (panel + 0.5L + 0.5L * nodes[i]);
          const Real v = V + g.weight_n_per_m * local;
          const Real T = std::sqrt(H * H + v * v);
          r.x += 0.5L * h * weights[i] * (1 + T * compliance) * H / T;
          r.z += 0.5L * h * weights[i] * (1 + T * compliance) * v / T;
        }
      }
      V += g.weight_n_per_m * (stop - s);
      s = stop;
    }
  }
  return r;
}

// Newton with a central-difference Jacobian from the library's answer perturbed by 1%.
std::array<Real, 2> independent_solve(const Problem& p, double H0, double V0) {
  const Real dx = p.supports.chord_m().x(), dz = p.supports.chord_m().y();
  Real H = 1.01L * H0, V = V0 + 0.01L * std::abs(V0);
  for (int it = 0; it < 30; ++it) {
    const Offset r = independent_offset(p.line, H, V);
    const Real fx = r.x - dx, fz = r.z - dz;
    const Real eh = 1e-7L * H, ev = 1e-7L * (std::abs(V) + H);
    const Offset hp = independent_offset(p.line, H + eh, V),
                 hm = independent_offset(p.line, H - eh, V);
    const Offset vp = independent_offset(p.line, H, V + ev),
                 vm = independent_offset(p.line, H, V - ev);
    const Real a = (hp.x - hm.x) / (2 * eh), b = (vp.x - vm.x) / (2 * ev);
    const Real c = (hp.z - hm.z) / (2 * eh), d = (vp.z - vm.z) / (2 * ev);
    const Real det = a * d - b * c;
    const Real stepH = -(d * fx - b * fz) / det, stepV = -(-c * fx + a * fz) / det;
    H += stepH;
    V += stepV;
    if (std::abs(stepH) < 1e-16L * H && std::abs(stepV) < 1e-16L * (H + std::abs(V))) break;
  }
  return {H, V};
}

TEST(LineStatics, UniformCableSplitIntoSegmentsReproducesTheOneSegmentSolution) {
  const Problem uniform = uniform_problem();
  const StaticSolution one = solve_statics(uniform);
  for (int pieces : {2, 7}) {
    const StaticSolution many = solve_statics(split_into_segments(uniform, pieces));
    ASSERT_TRUE(many.converged) << many.message;
    EXPECT_LT(relative_error(many.horizontal_force_n(), one.horizontal_force_n()), 1e-12) << pieces;
    EXPECT_LT(relative_error(many.vertical_force_a_n(), one.vertical_force_a_n()), 1e-12) << pieces;
    for (double s : {0.0, 123.4, 500.0, 999.0, 1000.0}) {
      EXPECT_LT((many.position_m(s) - one.position_m(s)).norm(), 1e-9) << pieces << " s = " << s;
      EXPECT_LT(relative_error(many.tension_n(s), one.tension_n(s)), 1e-12)
          << pieces << " s = " << s;
      EXPECT_LT(std::abs(many.stretched_length_m(s) - one.stretched_length_m(s)), 1e-9) << pieces;
    }
  }
}

TEST(LineStatics, MooringLineAgreesWithAnIndependentClosureSolve) {
  const Problem p = mooring_line();
  const StaticSolution statics = solve_statics(p);
  ASSERT_TRUE(statics.converged) << statics.message;
  const auto [H, V] =
      independent_solve(p, statics.horizontal_force_n(), statics.vertical_force_a_n());
  EXPECT_LT(relative_error(statics.horizontal_force_n(), double(H)), 1e-10);
  EXPECT_LT(std::abs(statics.vertical_force_a_n() - double(V)), 1e-10 * double(H));
  // V jumps by each point's weight; H is the same everywhere.
  EXPECT_NEAR(statics.vertical_force_n(400.0) - statics.vertical_force_before_n(400.0), 1.5e5,
              1e-6);
  EXPECT_NEAR(statics.vertical_force_n(800.0) - statics.vertical_force_before_n(800.0), -4.0e4,
              1e-6);
  const double total = 250.0 * 1400.0 + 600.0 * 60.0 + 100.0 * 1400.0 + 1.5e5 - 4.0e4;
  EXPECT_NEAR(statics.vertical_force_n(950.0) - statics.vertical_force_a_n(), total, 1e-6 * total);
  EXPECT_LT((statics.position_m(950.0) - p.supports.b_m).norm(), 1e-9);
}

TEST(LineStatics, BuoyantAndWeightlessSegmentsAgreeWithTheIndependentSolve) {
  Problem p;
  p.supports.a_m = Vec2(0.0, -200.0);
  p.supports.b_m = Vec2(300.0, 0.0);
  p.line.segments = {{150.0, 800.0, 4e8, 90.0, 10.0},
                     {120.0, -300.0, kInfinity, 50.0, 60.0},
                     {140.0, 0.0, 1e8, 20.0, 5.0}};
  const StaticSolution statics = solve_statics(p);
  ASSERT_TRUE(statics.converged) << statics.message;
  const auto [H, V] =
      independent_solve(p, statics.horizontal_force_n(), statics.vertical_force_a_n());
  EXPECT_LT(relative_error(statics.horizontal_force_n(), double(H)), 1e-10);
  EXPECT_LT(std::abs(statics.vertical_force_a_n() - double(V)), 1e-10 * double(H));
  // The weightless segment [270, 410] is straight with constant H and V.
  const Vec2 start = statics.position_m(270.0), end = statics.position_m(410.0);
  const Vec2 direction = (end - start).normalized();
  for (double s : {290.0, 333.3, 400.0}) {
    const Vec2 d = statics.position_m(s) - start;
    EXPECT_LT(std::abs(d.x() * direction.y() - d.y() * direction.x()), 1e-9) << s;
    EXPECT_EQ(statics.vertical_force_n(s), statics.vertical_force_n(270.0)) << s;
    EXPECT_LT((statics.tangent(s) - direction).norm(), 1e-12) << s;
  }
}

// From slack (the clump weight nearly on the seabed level of the anchor) to taut (the chord longer
// than the unstretched line): every start converges to the independent solution.
TEST(LineStatics, ConvergesFromSlackToStretchedChords) {
  for (double reach : {150.0, 400.0, 700.0, 880.0, 905.0, 906.5}) {
    Problem p = mooring_line();
    p.supports.b_m = Vec2(reach, 0.0);
    const StaticSolution statics = solve_statics(p);
    ASSERT_TRUE(statics.converged) << reach << ": " << statics.message;
    const auto [H, V] =
        independent_solve(p, statics.horizontal_force_n(), statics.vertical_force_a_n());
    EXPECT_LT(relative_error(statics.horizontal_force_n(), double(H)), 1e-9) << reach;
    EXPECT_LT(std::abs(statics.vertical_force_a_n() - double(V)), 1e-9 * double(H)) << reach;
  }
}

// A wholly buoyant line hogs: its highest point is inside, its lowest at an end.
TEST(LineStatics, BuoyantLineHogsAndAgreesWithTheIndependentSolve) {
  Problem p;
  p.supports.a_m = Vec2(0.0, 0.0);
  p.supports.b_m = Vec2(100.0, 10.0);
  p.line.segments = {{60.0, -50.0, 1e7, 5.0, 1.0}, {60.0, -80.0, 1e7, 5.0, 1.0}};
  const StaticSolution statics = solve_statics(p);
  ASSERT_TRUE(statics.converged) << statics.message;
  const auto [H, V] =
      independent_solve(p, statics.horizontal_force_n(), statics.vertical_force_a_n());
  EXPECT_LT(relative_error(statics.horizontal_force_n(), double(H)), 1e-10);
  EXPECT_LT(std::abs(statics.vertical_force_a_n() - double(V)), 1e-10 * double(H));
  EXPECT_GT(statics.vertical_force_a_n(), 0.0);
  EXPECT_GT(statics.position_m(60.0).y(), 10.0);
  EXPECT_EQ(statics.lowest_point_s_m(), 0.0);
}

TEST(LineStatics, BadInputNamesTheField) {
  Problem p = mooring_line();
  expect_invalid(
      [&] {
        Problem q = p;
        q.line.segments[2].length_m = 0.0;
        solve_statics(q);
      },
      "line.segments[2].length");
  expect_invalid(
      [&] {
        Problem q = p;
        q.line.segments[1].mass_kg_per_m = NAN;
        solve_statics(q);
      },
      "line.segments[1].mass");
  expect_invalid(
      [&] {
        Problem q = p;
        q.line.points[0].s_m = 2000.0;
        solve_statics(q);
      },
      "line.points[0].s");
  expect_invalid(
      [&] {
        Problem q = p;
        q.line.points[1].s_m = 400.0;
        solve_statics(q);
      },
      "line.points[1].s");
  expect_invalid(
      [&] {
        Problem q = p;
        q.line.points[0].weight_n = INFINITY;
        solve_statics(q);
      },
      "line.points[0].weight");
  expect_invalid(
      [&] {
        Problem q = p;
        for (auto& g : q.line.segments) g.axial_stiffness_n = kInfinity;
        q.supports.b_m = Vec2(900.0, 300.0);
        solve_statics(q);
      },
      "too short");
  expect_invalid(
      [&] {  // weightless and not stretched: slack
        Problem q;
        q.line.segments = {{60.0, 0.0, 1e7, 1.0, 0.0}, {50.0, 0.0, 1e7, 1.0, 0.0}};
        q.supports.b_m = Vec2(90.0, 10.0);
        solve_statics(q);
      },
      "line.segments[].weight");
}

// 10 m of chain, 100 m of weightless rope and 10 m of buoyant rope (as heavy as the chain is)
// between ends 50 m apart: with H > 0 the rope's vertical force would vanish, so it is straight
// only when taut, and it cannot be taut in 50 m; with H -> 0 the chain hangs, the buoyant part
// floats and the rope is slack. No equilibrium in tension exists, and the statics say so.
TEST(LineStatics, SlackWeightlessStretchIsNoEquilibriumInTension) {
  Problem p;
  p.line.segments = {
      {10.0, 10.0, 1e7, 1.0, 0.0}, {100.0, 0.0, 1e7, 1.0, 0.0}, {10.0, -10.0, 1e7, 1.0, 0.0}};
  p.supports.b_m = Vec2(50.0, 0.0);
  // Bad input (exit 2), like every other "No static equilibrium" (issue 32: it was exit 3).
  try {
    solve_statics(p);
    ADD_FAILURE() << "no InvalidInput";
  } catch (const InvalidInput& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("line.segments: No static equilibrium in tension"), std::string::npos)
        << message;
    EXPECT_NE(message.find("slack"), std::string::npos) << message;
  }
  // Moved 130 m apart the rope is taut and the same line closes.
  p.supports.b_m = Vec2(130.0, 0.0);
  EXPECT_TRUE(solve_statics(p).converged);
}

}  // namespace
}  // namespace catena
