// SPDX-License-Identifier: MIT
// Tests of the grounded run of a shot (src/solvers/shooting/shooting_grounded,
// docs/explanation/methods/ shooting.md "Seabed contact: the grounded run"):
//  - at constant tension each direction is a constant-coefficient pair with a closed form from
//    (phi, F) = (0, 1): b sinh(q x) / q, cosh(q x) on a stiff foundation (growth up to e^17500,
//    beyond the range of a double), b sin(q x) / q, cos(q x) above the foundation's cut-off: the
//    run's unit columns, log scales and zero counts against it;
//  - with friction (tension linear in s) the count of a shot from A (the grounded run) equals the
//    count of a shot from B (the general CVODE shot, which never takes the run) at trial
//    frequencies between the solver's roots, in both planes.
#include "solvers/shooting/shooting_grounded.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "catena/core/types.hpp"
#include "catena/solvers/shooting_solver.hpp"
#include "solvers/common/solver_test_support.hpp"
#include "solvers/shooting/shooting_integrator.hpp"
#include "test_utils.hpp"

namespace catena::internal {
namespace {

// A 100 m line lying on the seabed at constant tension T = 1e5 N (T_ref = T), EA = 5e6 N.
ShootingCoefficients grounded_line(double k_s, double k_t) {
  ShootingCoefficients k;
  k.length_m = 100.0;
  k.H = 1e5;
  k.t_ref = 1e5;
  k.m = 10.0;
  k.M = 12.0;
  k.compliance = 1.0 / 5e6;
  ShootingPiece p;
  p.s_end = k.length_m;
  p.compliance = k.compliance;
  p.m = k.m;
  p.M = k.M;
  p.grounded = true;
  p.tension_begin = k.H;
  p.foundation_normal = k_s;
  p.foundation_tangential = k_t;
  k.pieces = {p};
  return k;
}

// The exact column from (0, 1) at x for phi' = b F, F' = -c phi: its direction, log scale and
// the zeros of phi on (0, x].
struct ExactColumn {
  double phi = 0.0, force = 0.0, log_scale = 0.0;
  int zeros = 0;
};

ExactColumn exact_column(double b, double c, double x) {
  ExactColumn out;
  const double q = std::sqrt(std::abs(b * c)), qx = q * x;
  double phi = 0.0, force = 0.0, log_factor = 0.0;
  if (c < 0.0) {
    // sinh and cosh scaled by e^{-q x}, so that e^{17500} stays representable.
    const double decay = std::exp(-2.0 * qx);
    phi = b / q * 0.5 * (1.0 - decay);
    force = 0.5 * (1.0 + decay);
    log_factor = qx;
  } else {
    phi = b / q * std::sin(qx);
    force = std::cos(qx);
    out.zeros = static_cast<int>(std::floor(qx / kPi));
  }
  const double norm = std::hypot(phi, force);
  out.phi = phi / norm;
  out.force = force / norm;
  out.log_scale = log_factor + std::log(norm);
  return out;
}

TEST(ShootingGrounded, ConstantTensionRunMatchesTheClosedForms) {
  for (double k_s : {3e9, 2e4}) {
    const ShootingCoefficients k = grounded_line(k_s, 5e3);
    for (int dimension : {2, 1}) {
      ASSERT_EQ(grounded_run_length(k, dimension), 1u);
      GroundedRun run(k, dimension, 1, 200000);
      for (double omega : {5.0, 60.0, 200.0}) {
        const double omega2 = k.scaled_omega2(omega);
        double b[2], c[2];
        grounded_coefficients(k, k.pieces[0], dimension, omega2, 0.0, b, c);
        run.begin(omega2, 1e-11, 1e-13);
        int expected_count = 0;
        for (double x : {0.001, 0.3, 0.77, 1.0}) {
          const GroundedFrame f = run.advance_to(x);
          expected_count = 0;
          for (int d = 0; d < dimension; ++d) {
            const ExactColumn e = exact_column(b[d], c[d], x);
            EXPECT_NEAR(f.phi(d), e.phi, 1e-9) << "omega " << omega << ", x " << x << ", d " << d;
            EXPECT_NEAR(f.force(d), e.force, 1e-9) << "omega " << omega << ", x " << x;
            EXPECT_NEAR(f.log_scale(d), e.log_scale, 1e-9 * std::max(1.0, e.log_scale));
            expected_count += e.zeros;
          }
          EXPECT_EQ(f.count, expected_count) << "k_s " << k_s << ", omega " << omega << ", x " << x;
        }
        // Stiff: a few dozen steps for e^17500 of growth.
        EXPECT_LT(run.steps(), 2000) << "k_s " << k_s << ", omega " << omega;
      }
    }
  }
}

TEST(ShootingGrounded, CountWithFrictionFromAEqualsTheGeneralShotFromB) {
  const Problem p = testing::forty_percent_grounded_chain(0.1, 3e6);
  const StaticSolution statics = solve_statics(p);
  ASSERT_TRUE(statics.converged && statics.has_contact());
  const ShootingCoefficients k = ShootingCoefficients::from_statics(statics);
  ShootingSolverOptions options;
  const DimensionlessGroups groups = compute_dimensionless_groups(p, statics);
  const SolverOutput out =
      solve_shooting(p, statics, groups, testing::modes_request(6, 6), options);
  IntegratorSettings settings;
  for (Plane plane : {Plane::InPlane, Plane::OutOfPlane}) {
    const ModalResult& r = plane == Plane::InPlane ? *out.inplane : *out.outofplane;
    ASSERT_EQ(r.summary.termination, Termination::Converged) << r.summary.message;
    ShootingIntegrator integrator(plane, k, settings);
    for (std::size_t j = 0; j < r.modes.size(); ++j) {
      const double below = j == 0 ? 0.0 : r.modes[j - 1].omega_rad_s;
      const double omega = 0.5 * (below + r.modes[j].omega_rad_s);
      for (bool from_b : {false, true}) {
        const Shot shot = integrator.shoot(omega, 1.0, nullptr, from_b);
        EXPECT_EQ(shot.count, static_cast<int>(j)) << to_string(plane) << ", from b " << from_b;
        EXPECT_LT(shot.phase_defect, 1e-3);
      }
    }
  }
}

}  // namespace
}  // namespace catena::internal
