// SPDX-License-Identifier: MIT
// Tests of the Airy boundary system (src/solvers/airy/airy_boundary_system.cpp): the station
// rows against the model's formulas, the column exponents, the equilibration (positive factors:
// the determinant keeps its sign) and a zero of the determinant at a root computed independently
// in 30-digit arithmetic.
#include "solvers/airy/airy_boundary_system.hpp"

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cmath>

#include "catena/statics/problem_builders.hpp"
#include "solvers/airy/airy_functions.hpp"
#include "solvers/common/solver_test_support.hpp"
#include "test_utils.hpp"

namespace catena::internal {
namespace {

using catena::testing::relative_error;

struct Fixture {
  catena::testing::SolvedProblem solved;
  AiryModel model;
};

Fixture make(double eps, double phi_deg, double lambda2) {
  Fixture f{catena::testing::prepare(make_taut_inclined_problem(eps, phi_deg, lambda2, 1.0)), {}};
  f.model = build_airy_model(f.solved.problem, f.solved.statics, f.solved.groups,
                             AiryCurvatureFit::Tangent, 4);
  return f;
}

TEST(AiryBoundarySystem, ColumnExponentsAreTheEndValuesOfZeta) {
  const Fixture f = make(0.05, 1.0, 1e3);  // Airy arguments of order 10-100: zeta > 0
  const double omega = f.solved.groups.omega_from_k_l_over_pi(2.5);
  auto zeta = [&](double s) {
    const double x = airy_argument(f.model, omega, s);
    return x > 0.0 ? 2.0 / 3.0 * std::pow(x, 1.5) : 0.0;
  };
  const ColumnExponents e = column_exponents(f.model, omega);
  EXPECT_LE(e.ai_ref, e.bi_ref);
  EXPECT_GT(e.bi_ref, 0.0);
  EXPECT_LE(relative_error(e.ai_ref, std::min(zeta(0.0), zeta(f.model.length))), 1e-14);
  EXPECT_LE(relative_error(e.bi_ref, std::max(zeta(0.0), zeta(f.model.length))), 1e-14);
}

TEST(AiryBoundarySystem, StationRowsAreTheSlowAndFastSolutions) {
  // With zero exponents the Ai, Bi entries are the scaled functions themselves; the fast columns
  // are c^(-1/2) (cos W, sin W) in w and alpha c^(1/2)/omega (sin W, -cos W) in u.
  const Fixture f = make(0.18, 23.46, 38.0);
  const double omega = f.solved.groups.omega_from_k_l_over_pi(1.7);
  const double s = 0.3 * f.model.length, alpha = 0.02, c = 7.0, phase = 0.4;
  const StationRows rows = station_rows(f.model, omega, s, alpha, c, phase, ColumnExponents{});
  const ScaledAiry airy = scaled_airy(airy_argument(f.model, omega, s));
  const double grow = std::exp(airy.zeta);
  EXPECT_LE(relative_error(rows.slow_ai, airy.ai / grow), 1e-15);
  EXPECT_LE(relative_error(rows.slow_bi, airy.bi * grow), 1e-15);
  EXPECT_LE(relative_error(rows.w[0], -f.model.h * alpha * rows.slow_ai), 1e-15);
  EXPECT_LE(relative_error(rows.w[1], -f.model.h * alpha * rows.slow_bi), 1e-15);
  EXPECT_LE(relative_error(rows.u[0], f.model.kappa * airy.ai_prime / grow), 1e-15);
  EXPECT_LE(relative_error(rows.u[1], f.model.kappa * airy.bi_prime * grow), 1e-15);
  EXPECT_LE(relative_error(rows.w[2], std::cos(phase) / std::sqrt(c)), 1e-15);
  EXPECT_LE(relative_error(rows.w[3], std::sin(phase) / std::sqrt(c)), 1e-15);
  EXPECT_LE(relative_error(rows.u[2], alpha * std::sqrt(c) / omega * std::sin(phase)), 1e-15);
  EXPECT_LE(relative_error(rows.u[3], -alpha * std::sqrt(c) / omega * std::cos(phase)), 1e-15);
}

TEST(AiryBoundarySystem, EquilibrationKeepsTheSignOfTheRawDeterminant) {
  // Rebuild the raw 4x4 from the station rows; its determinant must have the equilibrated one's
  // sign (positive row and column factors), and every row of the equilibrated matrix has 1 as
  // its largest magnitude.
  const Fixture f = make(0.18, 23.46, 38.0);
  for (double k_l_over_pi : {0.9, 1.3, 1.9, 2.6, 3.4}) {
    const double omega = f.solved.groups.omega_from_k_l_over_pi(k_l_over_pi);
    const BoundarySystem system = boundary_system(f.model, omega);
    Eigen::Matrix4d raw;
    const double ends[2] = {0.0, f.model.length};
    const double phases[2] = {0.0, omega * f.model.travel_time};
    for (int i = 0; i < 2; ++i) {
      const StationRows rows = station_rows(f.model, omega, ends[i], f.model.alpha_end[i],
                                            f.model.c_end[i], phases[i], system.exponents);
      for (int j = 0; j < 4; ++j) {
        raw(2 * i, j) = rows.w[j];
        raw(2 * i + 1, j) = rows.u[j];
      }
    }
    EXPECT_GT(system.matrix.determinant() * raw.determinant(), 0.0) << k_l_over_pi;
    EXPECT_TRUE((system.column_scale.array() > 0.0).all());
    for (int i = 0; i < 4; ++i) EXPECT_EQ(system.matrix.row(i).cwiseAbs().maxCoeff(), 1.0);
  }
}

TEST(AiryBoundarySystem, DeterminantVanishesAtAnIndependentlyComputedRoot) {
  // kL/pi = 1.5837168921801667 (eps 0.18, phi 23.46 deg, lambda^2 19; mpmath, 30 digits, see
  // airy_solver_test.cpp): the determinant changes sign across it within 1e-10 relative, and is
  // there far smaller than a quarter of a mode away.
  const Fixture f = make(0.18, 23.46, 19.0);
  const double root = 1.5837168921801667 * kPi;
  const double below = airy_determinant_at(f.model, f.solved.groups, root * (1.0 - 1e-10));
  const double above = airy_determinant_at(f.model, f.solved.groups, root * (1.0 + 1e-10));
  EXPECT_LT(below * above, 0.0);
  const double away = airy_determinant_at(f.model, f.solved.groups, root + 0.25 * kPi);
  EXPECT_LT(std::abs(below), 1e-8 * std::abs(away));
}

}  // namespace
}  // namespace catena::internal
