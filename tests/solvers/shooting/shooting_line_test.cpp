// SPDX-License-Identifier: MIT
// Tests of the `shooting` solver on general lines (docs/explanation/physics.md, "General lines";
// docs/explanation/methods/shooting.md, "General lines"):
//  - a uniform cable given as a line of 2 and 7 identical segments reproduces the one-segment
//    frequencies (both planes);
//  - a weightless taut line of two segments of different mass: the out-of-plane modes satisfy
//    k1 cot(k1 L1) = -k2 cot(k2 L2), k_i = w sqrt(M_i (1 + e)/T), solved here by bisection;
//  - a weightless taut line with a heavy point mass P at mid-span: antisymmetric string modes
//    kL = 2 n pi, symmetric ones cot(kL/2) = k P / (2 M); in plane the same string modes merged
//    with the axial bar modes of the same form (ka = w sqrt(m/EA)), so the conjugate-point count
//    stays exact across the jump.
// The forced response of a line: tests/solvers/common/line_forced_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include "catena/solvers/shooting_solver.hpp"
#include "solvers/common/solver_test_support.hpp"
#include "test_utils.hpp"

namespace catena {
namespace {

using catena::testing::omegas;
using catena::testing::split_into_segments;

// rtol 1e-12 gives the frequencies of smooth problems to a few 1e-12 (shooting_solver_test.cpp).
constexpr double kRelTol = 1e-9;

ShootingSolverOptions tight() {
  ShootingSolverOptions options;
  options.relative_tolerance = 1e-12;
  return options;
}

testing::SolvedProblem solve(const Problem& problem, int inplane, int outofplane) {
  return testing::solve_problem(solve_shooting, problem,
                                testing::modes_request(inplane, outofplane), tight());
}

void expect_close(const std::vector<double>& got, const std::vector<double>& want, double tol) {
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t j = 0; j < got.size(); ++j) {
    EXPECT_NEAR(got[j] / want[j], 1.0, tol) << "mode " << j + 1;
  }
}

// The first `count` roots of f on (0, upper], by scanning in `step` and bisecting to rounding.
std::vector<double> roots_of(const std::function<double(double)>& f, double step, int count) {
  std::vector<double> roots;
  double lo = step * 1e-3, f_lo = f(lo);
  while (static_cast<int>(roots.size()) < count) {
    const double hi = lo + step, f_hi = f(hi);
    if (f_lo * f_hi <= 0.0) {
      double a = lo, b = hi, fa = f_lo;
      for (int i = 0; i < 200 && b - a > 1e-15 * b; ++i) {
        const double c = 0.5 * (a + b), fc = f(c);
        if (fa * fc <= 0.0) {
          b = c;
        } else {
          a = c;
          fa = fc;
        }
      }
      roots.push_back(0.5 * (a + b));
    }
    lo = hi;
    f_lo = f_hi;
  }
  return roots;
}

// A sagging inclined cable, given once as one cable and once as `pieces` identical segments.
Problem sagging_cable() {
  Problem p;
  p.cable = {1000.0, 1000.0, 5e8, 120.0, 80.0};
  p.supports.a_m = Vec2(0.0, 0.0);
  p.supports.b_m = Vec2(900.0, 300.0);
  return p;
}

// Weightless taut line along x: strain 1 %, so T = EA / 100 and e = 0.01.
constexpr double kEA = 1e6;
constexpr double kStrain = 0.01;

Problem taut_line(std::vector<LineSegment> segments) {
  Problem p;
  p.line.segments = std::move(segments);
  const double L = p.line.length_m();
  p.supports.a_m = Vec2(0.0, 0.0);
  p.supports.b_m = Vec2(L * (1.0 + kStrain), 0.0);
  return p;
}

TEST(ShootingLine, SplitUniformCableReproducesOneSegment) {
  const Problem uniform = sagging_cable();
  const testing::SolvedProblem reference = solve(uniform, 8, 8);
  for (int pieces : {2, 7}) {
    const testing::SolvedProblem line = solve(split_into_segments(uniform, pieces), 8, 8);
    ASSERT_EQ(line.output.summary.termination, Termination::Converged)
        << line.output.summary.message;
    expect_close(omegas(*line.output.inplane), omegas(*reference.output.inplane), 1e-10);
    expect_close(omegas(*line.output.outofplane), omegas(*reference.output.outofplane), 1e-10);
  }
}

// The modal mass of a line's mode (src/solvers/common/line_modal_mass.hpp): a uniform cable
// given as 2 identical segments has the cable's modal masses, in both planes.
TEST(ShootingLine, SplitUniformCableHasTheCablesModalMasses) {
  SolveRequest request = testing::modes_request(4, 4);
  request.shapes = true;
  request.points = 201;
  const Problem uniform = sagging_cable();
  const auto reference = testing::solve_problem(solve_shooting, uniform, request, tight());
  const auto line =
      testing::solve_problem(solve_shooting, split_into_segments(uniform, 2), request, tight());
  for (const auto plane : {&SolverOutput::inplane, &SolverOutput::outofplane}) {
    const auto& want = (reference.output.*plane)->modes;
    const auto& got = (line.output.*plane)->modes;
    ASSERT_EQ(got.size(), want.size());
    for (std::size_t j = 0; j < got.size(); ++j) {
      ASSERT_GT(want[j].modal_mass_kg, 0.0);
      EXPECT_NEAR(got[j].modal_mass_kg / want[j].modal_mass_kg, 1.0, 1e-8) << "mode " << j + 1;
    }
  }
}

TEST(ShootingLine, TwoMassesOutOfPlaneMatchTheMatchingCondition) {
  const double L1 = 4.0, L2 = 6.3, m1 = 1.0, m2 = 3.7;
  const Problem p = taut_line({{L1, 0.0, kEA, m1, 0.0}, {L2, 0.0, kEA, m2, 0.0}});
  const testing::SolvedProblem solved = solve(p, 0, 10);
  ASSERT_EQ(solved.output.summary.termination, Termination::Converged)
      << solved.output.summary.message;
  const double T = kEA * kStrain, c = (1.0 + kStrain) / T;
  // k1 cot(k1 L1) + k2 cot(k2 L2) = 0, multiplied by sin(k1 L1) sin(k2 L2) (no poles).
  auto f = [&](double w) {
    const double k1 = w * std::sqrt(m1 * c), k2 = w * std::sqrt(m2 * c);
    return k1 * std::cos(k1 * L1) * std::sin(k2 * L2) + k2 * std::cos(k2 * L2) * std::sin(k1 * L1);
  };
  expect_close(omegas(*solved.output.outofplane), roots_of(f, 0.5, 10), kRelTol);
}

// Roots of a string or bar of length L, density rho and stiffness S with a point mass P at
// mid-span: antisymmetric kL = 2 n pi, symmetric cot(kL/2) = k P / (2 rho), w = k sqrt(S/rho).
std::vector<double> midspan_mass_modes(double L, double rho, double S, double P, int count) {
  const double speed = std::sqrt(S / rho);
  auto symmetric = [&](double w) {
    const double k = w / speed;
    return 2.0 * rho * std::cos(0.5 * k * L) - k * P * std::sin(0.5 * k * L);
  };
  std::vector<double> out = roots_of(symmetric, 0.05 * speed / L, count);
  for (int n = 1; n <= count; ++n) out.push_back(2.0 * n * kPi / L * speed);
  std::sort(out.begin(), out.end());
  out.resize(static_cast<std::size_t>(count));
  return out;
}

PointAttachment point_mass(double s, double mass) {
  PointAttachment a;
  a.s_m = s;
  a.mass_kg = mass;
  return a;
}

TEST(ShootingLine, HeavyMidspanMassBothPlanes) {
  const double L = 10.0, m = 2.0, P = 5.0 * m * L;
  Problem p = taut_line({{0.5 * L, 0.0, kEA, m, 0.0}, {0.5 * L, 0.0, kEA, m, 0.0}});
  p.line.points = {point_mass(0.5 * L, P)};
  const int count = 12;
  const testing::SolvedProblem solved = solve(p, count, count);
  ASSERT_EQ(solved.output.summary.termination, Termination::Converged)
      << solved.output.summary.message;
  const double T_effective = kEA * kStrain / (1.0 + kStrain);
  const std::vector<double> string = midspan_mass_modes(L, m, T_effective, P, count);
  expect_close(omegas(*solved.output.outofplane), string, kRelTol);
  // In plane: the normal (string) and axial (bar) families merged.
  std::vector<double> inplane = string;
  const std::vector<double> bar = midspan_mass_modes(L, m, kEA, P, count);
  inplane.insert(inplane.end(), bar.begin(), bar.end());
  std::sort(inplane.begin(), inplane.end());
  inplane.resize(static_cast<std::size_t>(count));
  expect_close(omegas(*solved.output.inplane), inplane, kRelTol);
}

}  // namespace
}  // namespace catena
