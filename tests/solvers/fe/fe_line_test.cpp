// SPDX-License-Identifier: MIT
// fe on a general line (docs/explanation/methods/fe.md, "Lines"), against anchors that need no
// other solver:
// - a uniform cable written as a line of 2 and 7 identical segments: the same frequencies as the
//   one-segment cable to 1e-12 (the meshes coincide: N = 140 splits evenly);
// - a weightless taut line of two segments with different mass densities: out of plane, the exact
//   frequency equation k1 cot(k1 L1) = -k2 cot(k2 L2), k_i = w sqrt(M_i (1 + e) / T), solved here
//   by bracketing and bisection;
// - a weightless taut line with a point mass P at mid-span: out of plane the antisymmetric modes
//   keep k L = 2 n pi and the symmetric ones solve cot(k L / 2) = k P / (2 M);
// - the forced response of the split line equals the cable's;
// - the mesh: nodes at every joint and point, counts proportional to length, doubled per level.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

#include "catena/core/types.hpp"
#include "catena/solvers/fe_solver.hpp"
#include "solvers/common/solver_test_support.hpp"
#include "solvers/fe/fe_levels.hpp"
#include "solvers/fe/fe_line_mesh.hpp"
#include "test_utils.hpp"

namespace catena {
namespace {

using catena::testing::split_into_segments;

using catena::testing::modes_request;
using catena::testing::relative_error;
using Solved = catena::testing::SolvedProblem;

Solved solve(const Problem& problem, const SolveRequest& request, const FeSolverOptions& options) {
  return catena::testing::solve_problem(solve_fe, problem, request, options);
}

// EA / T ~ 10: the in-plane chain's rounding floor (FePlan::rounding_floor, ~ eps (EA/T) N^2) stays
// below 1e-13, so 1e-12 measures the line against the cable, not rounding. (With EA = 4e8, EA/T ~
// 1.3e3, the split line's statics differ from the cable's by one ulp of H and the in-plane
// frequencies by 3.6e-12, the chain's own rounding level.)
Problem sagging_cable() {
  Problem p;
  p.cable = {700.0, 900.0, 4e6, 100.0, 30.0};
  p.supports.b_m = Vec2(600.0, 150.0);
  return p;
}

PointAttachment point(double s, double mass, double weight) {
  PointAttachment p;
  p.s_m = s;
  p.mass_kg = mass;
  p.weight_n = weight;
  return p;
}

// The roots of f on (0, top], bracketed on a fine grid and bisected to rounding.
std::vector<double> roots(const std::function<double(double)>& f, double top, int count) {
  std::vector<double> out;
  const int steps = 200000;
  double a = top / steps, fa = f(a);
  for (int i = 2; i <= steps && static_cast<int>(out.size()) < count; ++i) {
    const double b = top * i / steps, fb = f(b);
    if (fa == 0.0 || (fa < 0.0) != (fb < 0.0)) {
      double lo = a, hi = b, flo = fa;
      for (int k = 0; k < 200 && hi - lo > 1e-15 * hi; ++k) {
        const double mid = 0.5 * (lo + hi), fm = f(mid);
        if ((fm < 0.0) == (flo < 0.0)) {
          lo = mid;
          flo = fm;
        } else {
          hi = mid;
        }
      }
      out.push_back(0.5 * (lo + hi));
    }
    a = b;
    fa = fb;
  }
  return out;
}

void expect_same_frequencies(const ModalResult& a, const ModalResult& b, double tolerance) {
  ASSERT_EQ(a.modes.size(), b.modes.size());
  for (std::size_t i = 0; i < a.modes.size(); ++i)
    EXPECT_LE(relative_error(a.modes[i].omega_rad_s, b.modes[i].omega_rad_s), tolerance)
        << "mode " << i + 1;
}

TEST(FeLine, UniformLineSplitIntoIdenticalSegmentsReproducesTheCable) {
  const Problem cable = sagging_cable();
  const FeSolverOptions options{.elements = 140};
  const Solved one = solve(cable, modes_request(8, 8), options);
  ASSERT_EQ(one.output.summary.termination, Termination::Converged)
      << one.output.summary.full_report();
  for (int pieces : {2, 7}) {
    const Solved line = solve(split_into_segments(cable, pieces), modes_request(8, 8), options);
    ASSERT_EQ(line.output.summary.termination, Termination::Converged)
        << line.output.summary.full_report();
    expect_same_frequencies(*one.output.inplane, *line.output.inplane, 1e-12);
    expect_same_frequencies(*one.output.outofplane, *line.output.outofplane, 1e-12);
  }
}

// Two weightless segments, EA = 1e7 N, stretched from 100 m to 100.1 m: T = 1e4 N.
Problem two_density_line() {
  Problem p;
  p.line.segments = {{40.0, 0.0, 1e7, 10.0, 2.0}, {60.0, 0.0, 1e7, 2.0, 0.5}};
  p.supports.b_m = Vec2(100.1, 0.0);
  return p;
}

TEST(FeLine, TwoDensityTautLineSatisfiesTheExactFrequencyEquation) {
  const Problem p = two_density_line();
  const Solved solved = solve(p, modes_request(0, 10), {.elements = 1000});
  ASSERT_EQ(solved.output.summary.termination, Termination::Converged)
      << solved.output.summary.full_report();
  const double T = solved.statics.horizontal_force_n();
  ASSERT_LE(relative_error(T, 1e7 * (100.1 / 100.0 - 1.0)), 1e-9);
  const double stretch = 1.0 + T / 1e7;
  const double L1 = 40.0, L2 = 60.0, M1 = 12.0, M2 = 2.5;
  // k1 cot(k1 L1) = -k2 cot(k2 L2), multiplied by sin(k1 L1) sin(k2 L2) to remove the poles.
  auto equation = [&](double w) {
    const double k1 = w * std::sqrt(M1 * stretch / T), k2 = w * std::sqrt(M2 * stretch / T);
    return k1 * std::cos(k1 * L1) * std::sin(k2 * L2) + k2 * std::sin(k1 * L1) * std::cos(k2 * L2);
  };
  const std::vector<double> exact = roots(equation, 40.0, 10);
  ASSERT_EQ(exact.size(), 10u);
  const auto& modes = solved.output.outofplane->modes;
  ASSERT_EQ(modes.size(), 10u);
  for (std::size_t i = 0; i < 10; ++i) {
    const double error = relative_error(modes[i].omega_rad_s, exact[i]);
    EXPECT_LE(error, 1e-9) << "mode " << i + 1 << ": fe " << modes[i].omega_rad_s << ", exact "
                           << exact[i];
    EXPECT_LE(error, modes[i].relative_error_estimate)
        << "mode " << i + 1 << ": the estimate must cover the error";
  }
}

// One weightless segment, L = 100 m, M = 5 kg/m, a 200 kg point (20 kg of it added mass) at 50 m.
Problem midspan_point_line() {
  Problem p;
  p.line.segments = {{100.0, 0.0, 1e7, 4.0, 1.0}};
  PointAttachment mass = point(50.0, 180.0, 0.0);
  mass.added_mass_kg = 20.0;
  p.line.points = {mass};
  p.supports.b_m = Vec2(100.1, 0.0);
  return p;
}

TEST(FeLine, MidSpanPointMassKeepsAntisymmetricModesAndShiftsSymmetricOnes) {
  const Solved solved = solve(midspan_point_line(), modes_request(0, 10), {.elements = 1000});
  ASSERT_EQ(solved.output.summary.termination, Termination::Converged)
      << solved.output.summary.full_report();
  const double T = solved.statics.horizontal_force_n(), L = 100.0, M = 5.0, P = 200.0;
  const double wave = std::sqrt(M * (1.0 + T / 1e7) / T);  // k = w * wave
  // Symmetric: cot(kL/2) = k P / (2 M), i.e. 2 M cos(kL/2) - k P sin(kL/2) = 0; antisymmetric: kL =
  // 2 n pi.
  auto symmetric = [&](double w) {
    const double k = w * wave;
    return 2.0 * M * std::cos(0.5 * k * L) - k * P * std::sin(0.5 * k * L);
  };
  std::vector<double> exact = roots(symmetric, 11.0 * kPi / (L * wave), 6);
  for (int n = 1; n <= 5; ++n) exact.push_back(2.0 * n * kPi / (L * wave));
  std::sort(exact.begin(), exact.end());
  const auto& modes = solved.output.outofplane->modes;
  ASSERT_EQ(modes.size(), 10u);
  for (std::size_t i = 0; i < 10; ++i) {
    const double error = relative_error(modes[i].omega_rad_s, exact[i]);
    EXPECT_LE(error, 1e-9) << "mode " << i + 1 << ": fe " << modes[i].omega_rad_s << ", exact "
                           << exact[i];
    EXPECT_LE(error, modes[i].relative_error_estimate) << "mode " << i + 1;
  }
}

TEST(FeLine, ForcedResponseOfASplitLineEqualsTheCables) {
  SolveRequest request = modes_request(0, 0);
  ForcedRequest forced;
  forced.end = CableEnd::B;
  forced.direction = ForcingDirection::Normal;
  forced.amplitude_m = 0.1;
  forced.omegas_rad_s = {0.05, 0.3};
  request.forced = forced;
  const FeSolverOptions options{.elements = 140};
  const Solved one = solve(sagging_cable(), request, options);
  const Solved line = solve(split_into_segments(sagging_cable(), 7), request, options);
  ASSERT_EQ(one.output.forced.size(), 2u);
  ASSERT_EQ(line.output.forced.size(), 2u);
  for (std::size_t f = 0; f < 2; ++f) {
    ASSERT_TRUE(line.output.forced[f].diagnostic.empty()) << line.output.forced[f].diagnostic;
    EXPECT_LE(relative_error(one.output.forced[f].max_abs_tension_n,
                             line.output.forced[f].max_abs_tension_n),
              1e-9);
  }
}

// A sagging line with a heavy point weight at s = 20 m: the static line has a kink there. Pieces of
// 20, 20 and 60 m take N = 50, 100, 200 elements exactly in proportion, so the three meshes are
// nested and the unextrapolated frequencies show the chain's order of convergence. It must be 2 in
// both planes; with the kink node's distributed mass lumped in the bisector frame (m along the
// bisector, M across it, although the two half elements meet at an O(1) angle) the in-plane order
// fell towards 1, and Richardson left an O(h) error (docs/explanation/methods/fe.md, "Lines").
void expect_second_order_in_both_planes(const Problem& p, int coarsest = 50) {
  std::vector<Solved> runs;
  for (int elements : {coarsest, 2 * coarsest, 4 * coarsest})
    runs.push_back(solve(p, modes_request(4, 4),
                         {.elements = elements, .richardson = false, .tolerance = 0.0}));
  for (const Solved& run : runs)
    ASSERT_EQ(run.output.summary.termination, Termination::Converged)
        << run.output.summary.full_report();
  for (const auto plane : {&SolverOutput::inplane, &SolverOutput::outofplane}) {
    for (std::size_t i = 0; i < 4; ++i) {
      const double w1 = (runs[0].output.*plane)->modes[i].omega_rad_s;
      const double w2 = (runs[1].output.*plane)->modes[i].omega_rad_s;
      const double w3 = (runs[2].output.*plane)->modes[i].omega_rad_s;
      const double order = std::log2((w1 - w2) / (w2 - w3));
      EXPECT_NEAR(order, 2.0, 0.02)
          << (plane == &SolverOutput::inplane ? "in plane" : "out of plane") << " mode " << i + 1;
    }
  }
}

TEST(FeLine, KinkAtAPointWeightKeepsSecondOrderInPlane) {
  Problem p;
  p.line.segments = {{40.0, 100.0, 1e8, 10.0, 10.0}, {60.0, 150.0, 5e7, 6.0, 4.0}};
  p.line.points = {point(20.0, 500.0, 5000.0)};
  p.supports.b_m = Vec2(80.0, 30.0);
  expect_second_order_in_both_planes(p);
}

// The same at a point without inertia on a joint of one section (a buoy given by its volume alone,
// as in MoorDyn decks): only the point marks the node, and until 2026-12 the node's mass was then
// lumped in the bisector frame (in plane on N = 100, 200, 400: orders 1.06, 0.76, 1.52 and a
// sign change). N = 50 is not yet in the asymptotic range of this kink (1.95 to 2.06).
TEST(FeLine, KinkAtAMasslessBuoyOnAJointOfOneSectionKeepsSecondOrderInPlane) {
  Problem p;
  const LineSegment section{50.0, 120.0, 1e8, 10.0, 10.0};
  p.line.segments = {section, section};
  p.line.points = {point(50.0, 0.0, -4000.0)};
  p.supports.b_m = Vec2(80.0, 10.0);
  expect_second_order_in_both_planes(p, 100);
}

TEST(FeLine, MeshHasNodesAtJointsAndPointsAndDoublesEveryPieceBetweenLevels) {
  Problem p;
  p.line.segments = {{250.0, 1400.0, 7.5e8, 160.0, 25.0},
                     {600.0, 60.0, 2e8, 8.0, 4.0},
                     {100.0, 1400.0, 7.5e8, 160.0, 25.0}};
  p.line.points = {point(400.0, 2e4, 1.5e5), point(800.0, 3e3, -4e4)};
  p.supports.a_m = Vec2(0.0, -300.0);
  p.supports.b_m = Vec2(800.0, 0.0);
  const StaticSolution statics = solve_statics(p);
  // The distribution: 95 elements, 10 per 100 m, cut at 250, 400, 800, 850.
  const internal::FeLineMesh mesh = internal::make_line_mesh(p, statics, 95);
  ASSERT_EQ(mesh.pieces.size(), 5u);
  const std::vector<int> expected = {25, 15, 40, 5, 10};
  for (std::size_t k = 0; k < mesh.pieces.size(); ++k)
    EXPECT_EQ(mesh.pieces[k].elements, expected[k]) << "piece " << k;
  EXPECT_EQ(mesh.pieces[2].point_at_start, 0);
  EXPECT_EQ(mesh.pieces[4].point_at_start, -1);  // the joint at 850 m carries no point
  EXPECT_EQ(mesh.pieces[3].point_at_start, 1);
  // With Richardson the plan evens every piece (25 -> 26, 15 -> 16, 5 -> 6), doubles it for the
  // fine mesh and halves it for the estimate mesh, piece by piece.
  const internal::FePlan plan = internal::make_fe_plan(p, statics, {.elements = 95}, 4, 4);
  ASSERT_EQ(plan.mesh_layouts.size(), 3u);
  ASSERT_EQ(plan.estimate_coarse, 0);
  const std::vector<int> evened = {26, 16, 40, 6, 10};
  for (std::size_t k = 0; k < evened.size(); ++k) {
    EXPECT_EQ(plan.mesh_layouts[0].pieces[k].elements, evened[k] / 2) << "piece " << k;
    EXPECT_EQ(plan.mesh_layouts[1].pieces[k].elements, evened[k]) << "piece " << k;
    EXPECT_EQ(plan.mesh_layouts[2].pieces[k].elements, 2 * evened[k]) << "piece " << k;
  }
  EXPECT_EQ(plan.meshes[0], 49);
  EXPECT_EQ(plan.meshes[1], 98);
  EXPECT_EQ(plan.meshes[2], 196);
}

}  // namespace
}  // namespace catena
