// SPDX-License-Identifier: MIT
// Statics of the elastic catenary (docs/explanation/physics.md).
// Compared: the Newton solution against its own closure equations, against the inextensible
// catenary (EA -> inf, observed rate), and against itself after rescaling units. Expected values
// are properties of the exact solution, not numbers copied from a run. Turchetto's touchdown form
// is tested in touchdown_catenary_test.cpp.
#include "catena/statics/elastic_catenary.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "test_utils.hpp"

namespace catena {
namespace {

using testing::relative_error;

Problem mooring_problem() {
  Problem p;
  p.cable = {1000.0, 1000.0, 5e8, 120.0, 80.0};
  p.supports.a_m = Vec2(0.0, 0.0);
  p.supports.b_m = Vec2(900.0, 300.0);
  return p;
}

// Newton stops at a relative closure of 1e-14, or at the rounding floor (1e-11) it can reach.
constexpr double kClosureRel = 1e-11;

TEST(ElasticCatenary, ClosesOnSupportBForVariedGeometries) {
  struct Case {
    double L, W0, EA, bx, bz;
  };
  const std::vector<Case> cases = {{1000, 1000, 5e8, 900, 300}, {1000, 1000, kInfinity, 900, 300},
                                   {100, 10, 1e7, 50, -40},     {100, 10, kInfinity, 10, 0},
                                   {100, 10, 1e5, 100.5, 0},    {1, 1, kInfinity, 0.999, 0.01},
                                   {1, 1, 10, 0.2, 0.9},        {50, 2, kInfinity, 5, 49},
                                   {10, 1, 1e3, 12, 3}};
  for (const auto& c : cases) {
    Problem p;
    p.cable = {c.L, c.W0, c.EA, 1.0, 0.0};
    p.supports.b_m = Vec2(c.bx, c.bz);
    const StaticSolution s = solve_statics(p);
    const Vec2 end = s.position_m(c.L);
    EXPECT_LE((end - p.supports.b_m).norm(), kClosureRel * std::max(c.L, p.supports.b_m.norm()))
        << "L=" << c.L << " b=(" << c.bx << "," << c.bz << ") " << s.brief_report();
    EXPECT_GT(s.horizontal_force_n(), 0.0);
    EXPECT_LT(s.iterations, 60) << s.brief_report();
  }
}

TEST(ElasticCatenary, NewtonStallIsAStatusNotAnException) {
  // One Newton step from the parabolic guess cannot close a 1000 m mooring line to 1e-14: the
  // solve must report it (converged = false, with the closure error) instead of throwing.
  StaticsOptions options;
  options.max_iterations = 1;
  StaticSolution s;
  EXPECT_NO_THROW(s = solve_statics(mooring_problem(), options));
  EXPECT_FALSE(s.converged);
  EXPECT_EQ(s.iterations, 1);
  EXPECT_GT(s.closure_error_m, 1e-11 * 1000.0);
  EXPECT_NE(s.message.find("did not converge"), std::string::npos) << s.message;
  EXPECT_NE(s.message.find("1 Newton iterations"), std::string::npos) << s.message;

  const StaticSolution converged = solve_statics(mooring_problem());
  EXPECT_TRUE(converged.converged);
  EXPECT_TRUE(converged.message.empty()) << converged.message;
}

TEST(ElasticCatenary, TangentIsDerivativeOfPositionOverStretch) {
  // r'(s) = (1 + e) t: check with a centred difference at interior points.
  const StaticSolution s = solve_statics(mooring_problem());
  for (double si : {1.0, 250.0, 500.0, 999.0}) {
    const double h = 1e-3;
    const Vec2 derivative = (s.position_m(si + h) - s.position_m(si - h)) / (2 * h);
    const Vec2 expected = (1.0 + s.strain(si)) * s.tangent(si);
    EXPECT_LT((derivative - expected).norm(), 1e-8) << "s = " << si;
    EXPECT_NEAR(s.tangent(si).dot(s.normal(si)), 0.0, 1e-15);
    EXPECT_NEAR(s.tangent(si).norm(), 1.0, 1e-15);
  }
}

TEST(ElasticCatenary, VerticalEquilibriumOfTheEndForces) {
  // V_B - V_A = W0 L: the weight of the whole cable.
  const Problem p = mooring_problem();
  const StaticSolution s = solve_statics(p);
  EXPECT_LT(relative_error(s.vertical_force_n(p.cable.length_m) - s.vertical_force_a_n(),
                           p.cable.weight_n_per_m * p.cable.length_m),
            1e-14);
}

TEST(ElasticCatenary, TendsToInextensibleAsStiffnessGrows) {
  // H(EA) - H(inf) = O(1/EA): observed rate between EA and 10 EA must be 1.0 +- 0.05. Sampled
  // from EA = 1e9 (static strain ~1e-3): at EA = 1e8 the strain is ~1% and the O(1/EA^2) term
  // still shows (observed 0.93 there).
  Problem p = mooring_problem();
  p.cable.axial_stiffness_n = kInfinity;
  const double H_inf = solve_statics(p).horizontal_force_n();
  std::vector<double> errors;
  for (double ea : {1e9, 1e10, 1e11, 1e12}) {
    p.cable.axial_stiffness_n = ea;
    errors.push_back(std::abs(solve_statics(p).horizontal_force_n() - H_inf) / H_inf);
  }
  for (std::size_t i = 1; i < errors.size(); ++i) {
    const double rate = std::log10(errors[i - 1] / errors[i]);
    std::printf("EA -> inf: rel. error of H %.3e -> %.3e, observed rate %.4f (expected 1)\n",
                errors[i - 1], errors[i], rate);
    EXPECT_NEAR(rate, 1.0, 0.05);
  }
}

TEST(ElasticCatenary, ResultsInvariantUnderUnitScaling) {
  // Lengths x Ls, forces x Fs: H, V scale by Fs; positions by Ls; EA by Fs; W0 by Fs/Ls.
  const Problem base = mooring_problem();
  const StaticSolution reference = solve_statics(base);
  for (double Ls : {1e-3, 1.0, 1e3}) {
    for (double Fs : {1e-3, 1.0, 1e6}) {
      Problem p = base;
      p.cable.length_m *= Ls;
      p.cable.weight_n_per_m *= Fs / Ls;
      p.cable.axial_stiffness_n *= Fs;
      p.supports.b_m *= Ls;
      const StaticSolution s = solve_statics(p);
      EXPECT_LT(relative_error(s.horizontal_force_n() / Fs, reference.horizontal_force_n()), 1e-12)
          << "Ls=" << Ls << " Fs=" << Fs;
      EXPECT_LT(relative_error(s.vertical_force_a_n() / Fs, reference.vertical_force_a_n()), 1e-12);
      const double mid = 0.37 * p.cable.length_m;
      EXPECT_LT((s.position_m(mid) / Ls - reference.position_m(0.37 * base.cable.length_m)).norm(),
                1e-12 * base.cable.length_m);
    }
  }
}

TEST(ElasticCatenary, VerticalTautCableIsStraight) {
  Problem p;
  p.cable = {100.0, 10.0, 1e6, 1.0, 0.0};
  p.supports.b_m = Vec2(0.0, 100.5);
  const StaticSolution s = solve_statics(p);
  EXPECT_EQ(s.horizontal_force_n(), 0.0);
  // z(L) = L + (V_A L + W0 L^2/2)/EA = 100.5 -> V_A = 0.5 EA / L - W0 L / 2.
  EXPECT_LT(relative_error(s.vertical_force_a_n(), 0.5 * 1e6 / 100.0 - 0.5 * 10.0 * 100.0), 1e-14);
  EXPECT_NEAR(s.position_m(100.0).y(), 100.5, 1e-12);
}

TEST(ElasticCatenary, StretchedLengthMatchesIntegralOfStrain) {
  const Problem p = mooring_problem();
  const StaticSolution s = solve_statics(p);
  // Simpson on (1 + T/EA) with 2000 intervals: error ~1e-13 relative.
  const int n = 2000;
  const double L = p.cable.length_m, h = L / n;
  double sum = 0.0;
  for (int i = 0; i <= n; ++i) {
    const double weight = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
    sum += weight * (1.0 + s.strain(i * h));
  }
  EXPECT_LT(relative_error(s.stretched_length_m(L), sum * h / 3.0), 1e-12);
}

}  // namespace
}  // namespace catena
