// SPDX-License-Identifier: MIT
// Tests of the asymptotic solver's light damping (first-order perturbation from its own undamped
// modes, src/solvers/common/modal_damping.hpp).
//
// Compared with: the solver's own undamped frequencies (proportional damping, exact); the taut
// string's delta = c_n / 2M; Irvine's horizontal cable with Kelvin-Voigt damping, delta = (c_a/2)
// d(omega^2)/dEA from Irvine's frequency equation (closed form, solved here by bisection). No
// other solver is used (independence rule).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "catena/solvers/asymptotic_solver.hpp"
#include "catena/statics/problem_builders.hpp"
#include "solvers/common/damped_model_checks.hpp"
#include "test_utils.hpp"

namespace catena {
namespace {

using catena::testing::relative_error;

SolverOutput asymptotic(const Problem& problem,
                        const StaticSolution& statics,
                        const DimensionlessGroups& groups,
                        const SolveRequest& request) {
  return solve_asymptotic(problem, statics, groups, request);
}

TEST(AsymptoticDamping, ProportionalDampingIsExactAgainstTheUndampedRoots) {
  for (double zeta1 : {1e-4, 0.05}) {
    testing::expect_proportional_damping_exact(
        asymptotic, make_taut_inclined_problem(0.18, 23.46, 38.0, 0.6), zeta1);
    testing::expect_proportional_damping_exact(
        asymptotic, make_taut_inclined_problem(0.05, 60.0, 400.0, 1.0), zeta1);
  }
}

TEST(AsymptoticDamping, OverdampedRootsAreListedApart) {
  testing::expect_overdamped_listed_apart(asymptotic,
                                          make_taut_inclined_problem(0.1, 30.0, 100.0, 0.7));
}

TEST(AsymptoticDamping, TautStringWithUniformNormalDamping) {
  testing::expect_taut_string_normal_damping(asymptotic,
                                             make_taut_inclined_problem(0.01, 30.0, 1e4, 0.5));
}

TEST(AsymptoticDamping, KelvinVoigtOnIrvinesSymmetricModeMatchesTheClosedForm) {
  for (double lambda2 : {10.0, 30.0, 60.0}) {
    Problem problem = make_taut_inclined_problem(0.01, 0.0, lambda2, 0.8);
    const double ea = problem.cable.axial_stiffness_n;
    // c_a / EA = 1e-3 s: delta ~ 1e-3 omega^2 times the axial share of the stiffness, light.
    const double c_a = 1e-3 * ea;
    problem.cable.damping.axial_n_s = c_a;
    const testing::SolvedProblem damped =
        testing::solve_model(asymptotic, problem, testing::modes_request(2, 1));
    ASSERT_EQ(damped.output.summary.termination, Termination::Converged)
        << damped.output.summary.message;
    const double lambda2_groups = damped.groups.lambda2;
    const double x = testing::irvine_first_symmetric_x(lambda2_groups);
    const double expected = testing::irvine_kelvin_voigt_decay_rate(x, lambda2_groups, ea, c_a);
    // Irvine's symmetric mode is the first below cross-over (lambda^2 < 4 pi^2), the second above.
    const Mode& mode = damped.output.inplane->modes[lambda2 < 4.0 * kPi * kPi ? 0 : 1];
    EXPECT_LE(relative_error(mode.omega_rad_s, damped.groups.omega_from_k_l_over_pi(2.0 * x / kPi)),
              mode.relative_error_estimate);
    EXPECT_GT(mode.decay_rate_error_estimate, 0.0);
    EXPECT_LE(relative_error(mode.decay_rate_1_s, expected), mode.decay_rate_error_estimate)
        << "lambda2 " << lambda2 << ": delta " << mode.decay_rate_1_s << " Irvine " << expected;
    std::printf("asymptotic Kelvin-Voigt lambda2 %g: delta rel. error %.3e, estimate %.3e\n",
                lambda2, relative_error(mode.decay_rate_1_s, expected),
                mode.decay_rate_error_estimate);
    // Out of plane the motion does not stretch the cable to first order: no Kelvin-Voigt decay.
    EXPECT_EQ(damped.output.outofplane->modes[0].decay_rate_1_s, 0.0);
  }
}

TEST(AsymptoticDamping, DeclinesStrongNonProportionalDampingInPlaneOnly) {
  Problem problem = make_taut_inclined_problem(0.1, 30.0, 100.0, 0.7);
  // c_n/M = 6 rad/s, c_t = 0: D = 3 rad/s against in-plane mode gaps of ~ 1 to 3 rad/s.
  problem.cable.damping.normal_n_s_per_m2 = 6.0 * problem.cable.normal_mass_kg_per_m();
  const testing::SolvedProblem damped =
      testing::solve_model(asymptotic, problem, testing::modes_request(4, 4));
  EXPECT_EQ(damped.output.inplane->summary.termination, Termination::NotApplicable);
  EXPECT_TRUE(damped.output.inplane->modes.empty());
  // Out of plane uniform normal damping is proportional: exact, kept.
  EXPECT_EQ(damped.output.outofplane->summary.termination, Termination::Converged);
  EXPECT_EQ(damped.output.outofplane->modes.size(), 4u);
}

TEST(AsymptoticDamping, ZeroDampingKeepsTheUndampedPath) {
  Problem problem = make_taut_inclined_problem(0.18, 23.46, 38.0, 0.6);
  SolveRequest request = testing::modes_request(4, 3);
  request.shapes = true;
  const testing::SolvedProblem plain = testing::solve_model(asymptotic, problem, request);
  problem.cable.damping = SectionDamping{0.0, 0.0, 0.0};
  problem.seabed.reset();
  ASSERT_FALSE(problem.is_damped());
  const testing::SolvedProblem zero = testing::solve_model(asymptotic, problem, request);
  for (const auto& [a, b] : {std::pair{*plain.output.inplane, *zero.output.inplane},
                             std::pair{*plain.output.outofplane, *zero.output.outofplane}}) {
    ASSERT_EQ(a.modes.size(), b.modes.size());
    EXPECT_EQ(a.proved_count_below_top, b.proved_count_below_top);
    EXPECT_TRUE(b.overdamped.empty());
    for (std::size_t i = 0; i < a.modes.size(); ++i) {
      EXPECT_EQ(a.modes[i].omega_rad_s, b.modes[i].omega_rad_s);
      EXPECT_EQ(b.modes[i].decay_rate_1_s, 0.0);
      EXPECT_EQ(b.modes[i].decay_rate_error_estimate, -1.0);
      EXPECT_EQ(b.modes[i].w_imag.size(), 0);
      EXPECT_EQ(a.modes[i].w, b.modes[i].w);
    }
  }
}

}  // namespace
}  // namespace catena
