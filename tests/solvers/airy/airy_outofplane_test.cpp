// SPDX-License-Identifier: MIT
// Tests of the `airy` solver's own out-of-plane model: the string of linear tension solved by
// Bessel functions (src/solvers/airy/airy_tension_string.hpp, docs/explanation/methods/airy.md).
//
// Compared with:
// - `shooting` (the exact linear answer; used here only as a reference, never by the solver):
//   the error falls as eps^2 and stays below airy's own min-max bound;
// - `asymptotic`'s WKB string: a different O(eps^2) model, so the two must differ;
// - the mode count and the zeros of the shapes (Sturm: mode n has n - 1 interior zeros).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "catena/solvers/airy_solver.hpp"
#include "catena/solvers/asymptotic_solver.hpp"
#include "catena/solvers/shooting_solver.hpp"
#include "catena/statics/problem_builders.hpp"
#include "solvers/common/solver_test_support.hpp"
#include "test_utils.hpp"

namespace catena {
namespace {

using catena::testing::relative_error;
using Solved = catena::testing::SolvedProblem;

constexpr int kModes = 4;

Solved taut(double eps, double phi_deg = 30.0, double lambda2 = 50.0) {
  return catena::testing::prepare(make_taut_inclined_problem(eps, phi_deg, lambda2, 0.8));
}

ModalResult airy_outofplane(const Solved& s, bool shapes = false) {
  SolveRequest request = catena::testing::modes_request(0, kModes);
  request.shapes = shapes;
  const SolverOutput out = solve_airy(s.problem, s.statics, s.groups, request, {});
  EXPECT_TRUE(out.outofplane.has_value());
  return out.outofplane.value_or(ModalResult{});
}

std::vector<double> shooting_outofplane(const Solved& s) {
  ShootingSolverOptions options;
  options.relative_tolerance = 1e-12;
  const SolverOutput out = solve_shooting(s.problem, s.statics, s.groups,
                                          catena::testing::modes_request(0, kModes), options);
  std::vector<double> omegas;
  if (out.outofplane) {
    for (const Mode& mode : out.outofplane->modes) omegas.push_back(mode.omega_rad_s);
  }
  return omegas;
}

// Largest relative error of airy against shooting over the modes, and airy's estimate.
struct Measured {
  double error = 0.0;
  double estimate = 0.0;
};

Measured measure(double eps, double phi_deg) {
  const Solved s = taut(eps, phi_deg);
  const ModalResult airy = airy_outofplane(s);
  const std::vector<double> exact = shooting_outofplane(s);
  Measured measured;
  EXPECT_EQ(airy.modes.size(), exact.size());
  for (std::size_t i = 0; i < std::min(airy.modes.size(), exact.size()); ++i) {
    measured.error = std::max(measured.error, relative_error(airy.modes[i].omega_rad_s, exact[i]));
    measured.estimate = airy.modes[i].relative_error_estimate;
  }
  return measured;
}

TEST(AiryOutOfPlane, ErrorAgainstShootingFallsAsEpsSquaredAndStaysBelowTheBound) {
  // Measured (largest over 4 modes, mass ratio 0.8, lambda^2 = 50), error / estimate:
  //   phi 10: eps 0.4 1.46e-3/4.83e-3, 0.2 3.72e-4/1.22e-3, 0.1 9.33e-5/3.06e-4,
  //   0.05 2.33e-5/7.65e-5 phi 30: eps 0.4 1.13e-3/3.76e-3, 0.2 2.87e-4/9.45e-4,
  //   0.1 7.21e-5/2.37e-4, 0.05 1.80e-5/5.92e-5 phi 60: eps 0.4 3.76e-4/1.28e-3,
  //   0.2 9.57e-5/3.17e-4, 0.1 2.40e-5/7.90e-5, 0.05 6.01e-6/1.97e-5
  // observed order 1.97-2.00; the estimate (a rigorous bound) is 3.3 times the error.
  const std::vector<double> eps_values{0.4, 0.2, 0.1, 0.05};
  for (double phi_deg : {10.0, 30.0, 60.0}) {
    std::vector<Measured> measured;
    for (double eps : eps_values) {
      measured.push_back(measure(eps, phi_deg));
      EXPECT_LE(measured.back().error, measured.back().estimate)
          << "eps " << eps << " phi " << phi_deg;
      EXPECT_GE(measured.back().error, measured.back().estimate / 10.0)
          << "eps " << eps << " phi " << phi_deg;
    }
    for (std::size_t i = 1; i < measured.size(); ++i) {
      const double order = std::log(measured[i - 1].error / measured[i].error) /
                           std::log(eps_values[i - 1] / eps_values[i]);
      EXPECT_NEAR(order, 2.0, 0.1) << "eps " << eps_values[i] << " phi " << phi_deg;
    }
  }
}

TEST(AiryOutOfPlane, DiffersFromTheAsymptoticWkbString) {
  // Two models of the same order, computed by different code: on an inclined taut cable their
  // frequencies differ by far more than the root tolerance (measured 1e-4 .. 1e-3 here).
  const Solved s = taut(0.18, 23.46, 38.0);
  const ModalResult airy = airy_outofplane(s);
  const SolverOutput asymptotic = solve_asymptotic(s.problem, s.statics, s.groups,
                                                   catena::testing::modes_request(0, kModes), {});
  ASSERT_TRUE(asymptotic.outofplane.has_value());
  ASSERT_EQ(airy.modes.size(), asymptotic.outofplane->modes.size());
  for (std::size_t i = 0; i < airy.modes.size(); ++i) {
    EXPECT_GT(
        relative_error(airy.modes[i].omega_rad_s, asymptotic.outofplane->modes[i].omega_rad_s),
        1e-5)
        << "mode " << i + 1;
  }
}

TEST(AiryOutOfPlane, CountIsProvedAndModeNHasNMinusOneInteriorZeros) {
  const Solved s = taut(0.4, 45.0);
  SolveRequest request = catena::testing::modes_request(0, 8);
  request.shapes = true;
  request.tension = true;
  request.points = 401;
  const SolverOutput out = solve_airy(s.problem, s.statics, s.groups, request, {});
  ASSERT_TRUE(out.outofplane.has_value());
  const ModalResult& result = *out.outofplane;
  EXPECT_EQ(result.summary.termination, Termination::Converged);
  EXPECT_EQ(result.proved_count_below_top, 8);
  ASSERT_EQ(result.modes.size(), 8u);
  for (const Mode& mode : result.modes) {
    const Vector& v = mode.v;
    ASSERT_EQ(v.size(), 401);
    EXPECT_TRUE(v.allFinite());
    EXPECT_DOUBLE_EQ(v.cwiseAbs().maxCoeff(), 1.0);
    EXPECT_LE(std::abs(v[0]) + std::abs(v[400]), 1e-12) << mode.index;
    int zeros = 0;
    for (Index j = 2; j < 400; ++j) zeros += (v[j] > 0.0) != (v[j - 1] > 0.0);
    EXPECT_EQ(zeros, mode.index - 1);
    EXPECT_EQ(mode.tension_n.cwiseAbs().maxCoeff(), 0.0);
    EXPECT_GT(mode.modal_mass_kg, 0.0);
  }
}

}  // namespace
}  // namespace catena
