// SPDX-License-Identifier: MIT
// Each method's validity limit at the points of issue 32, where a solver reported "converged" for
// numbers it could not stand behind. Here each either declines with its reason or states an error
// estimate that bounds its actual error against an independent closed form:
//  - asymptotic at lambda^2 = 0.1, static strain 0.098: eq. (21) has no axial modes, and its root
//    at kL/pi = 4 was compared with the exact spectrum's axial mode (8 % to 29 % off). Reference:
//    the axial bar, kL = pi sqrt(EA M / (T0 m)) (EA, M, m of the problem, T0 of the groups);
//  - airy and shooting in plane at eps <= 1e-7: the stretching of a nearly straight cable is a
//    difference known only to rounding / (tangent turn); airy was off by 2e-7 with an estimate of
//    1.8e-15 at eps = 1e-10, shooting by 7e-7 with 1.1e-9. Reference: the roots of eq. (21)
//    (Grinfogel), exact to O(eps^2) + T0/(2 EA) <= 1e-13 at these points, as the frequencies
//    there are taut-string-with-stretching values; the formula is the asymptotic solver's public
//    function, a closed form independent of both solvers' code.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "catena/solvers/airy_solver.hpp"
#include "catena/solvers/asymptotic_solver.hpp"
#include "catena/solvers/shooting_solver.hpp"
#include "catena/statics/problem_builders.hpp"
#include "solvers/common/solver_test_support.hpp"

namespace catena {
namespace {

using catena::testing::modes_request;
using catena::testing::solve_problem;
using catena::testing::SolvedProblem;

// The reference's own error at these points: eps^2 + T0/(2 EA) <= 1e-13 (eq. (21)'s model error).
constexpr double kReferenceError = 1e-13;

// Each in-plane mode's frequency error against eq. (21) is within its own estimate (plus the
// reference's error).
void expect_estimates_bound_eq21(const SolvedProblem& s, const std::string& what) {
  ASSERT_TRUE(s.output.inplane.has_value()) << what;
  const auto& modes = s.output.inplane->modes;
  ASSERT_FALSE(modes.empty()) << what << ": " << s.output.inplane->summary.message;
  const std::vector<double> roots = grinfogel_eq21_roots(
      static_cast<int>(modes.size()), s.groups.eps, s.groups.chord_angle_rad, s.groups.lambda2);
  for (std::size_t i = 0; i < modes.size(); ++i) {
    const double reference = s.groups.omega_from_k_l_over_pi(roots[i] / kPi);
    const double error = std::abs(modes[i].omega_rad_s - reference) / reference;
    EXPECT_LE(error, modes[i].relative_error_estimate + kReferenceError)
        << what << " mode " << i + 1 << ": " << modes[i].omega_rad_s << " vs " << reference;
  }
}

TEST(ValidityLimits, AsymptoticReturnsNoInPlaneRootBeyondTheFirstAxialMode) {
  const Problem problem = make_taut_inclined_problem(std::sqrt(0.098 * 0.1), 30.0, 0.1, 1.0);
  const auto s =
      solve_problem(solve_asymptotic, problem, modes_request(6, 2), AsymptoticSolverOptions{});
  const ModalResult& inplane = *s.output.inplane;
  const double EA = problem.cable.axial_stiffness_n, m = problem.cable.mass_kg_per_m;
  const double M = problem.cable.normal_mass_kg_per_m();
  const double axial_kl = kPi * std::sqrt(EA * M / (s.groups.t0_n * m));  // about 3.69 pi
  EXPECT_EQ(inplane.summary.termination, Termination::NoConvergence) << inplane.summary.message;
  EXPECT_NE(inplane.summary.message.find("first axial mode"), std::string::npos)
      << inplane.summary.message;
  ASSERT_EQ(inplane.modes.size(), 3u) << inplane.summary.message;
  for (const Mode& mode : inplane.modes) {
    const double kl = mode.omega_rad_s / s.groups.taut_frequency_scale_rad_s;
    EXPECT_LT(kl, axial_kl) << "mode " << mode.index;
  }
  EXPECT_EQ(s.output.outofplane->summary.termination, Termination::Converged);
}

TEST(ValidityLimits, AiryDeclinesInPlaneWhereRoundingSwampsTheStretching) {
  const Problem problem = make_taut_inclined_problem(1e-10, 30.0, 1e-4, 1.0);
  const auto s = solve_problem(solve_airy, problem, modes_request(4, 4), AirySolverOptions{});
  EXPECT_EQ(s.output.inplane->summary.termination, Termination::NotApplicable);
  EXPECT_NE(s.output.inplane->summary.message.find("eps cos(phi_a)"), std::string::npos)
      << s.output.inplane->summary.message;
  EXPECT_TRUE(s.output.inplane->modes.empty());
  EXPECT_EQ(s.output.outofplane->summary.termination, Termination::Converged);
}

TEST(ValidityLimits, AiryInPlaneEstimateBoundsItsErrorAtSmallEps) {
  for (const double phi : {10.0, 30.0, 89.0}) {
    for (const double lambda2 : {1.0, 100.0}) {
      const Problem problem = make_taut_inclined_problem(1e-7, phi, lambda2, 1.0);
      const auto s = solve_problem(solve_airy, problem, modes_request(4, 0), AirySolverOptions{});
      expect_estimates_bound_eq21(
          s, "airy phi " + std::to_string(phi) + " lambda2 " + std::to_string(lambda2));
    }
  }
}

TEST(ValidityLimits, ShootingInPlaneEstimateBoundsItsErrorAtSmallEps) {
  for (const double eps : {1e-10, 1e-12}) {
    for (const double phi : {10.0, 60.0}) {
      const Problem problem = make_taut_inclined_problem(eps, phi, 100.0, 1.0);
      const auto s =
          solve_problem(solve_shooting, problem, modes_request(4, 0), ShootingSolverOptions{});
      expect_estimates_bound_eq21(
          s, "shooting eps " + std::to_string(eps) + " phi " + std::to_string(phi));
    }
  }
}

TEST(ValidityLimits, ShootingDeclinesInPlaneWhereTheTangentBarelyTurns) {
  const Problem problem = make_taut_inclined_problem(1e-12, 89.0, 100.0, 1.0);
  const auto s =
      solve_problem(solve_shooting, problem, modes_request(4, 2), ShootingSolverOptions{});
  EXPECT_EQ(s.output.inplane->summary.termination, Termination::NotApplicable);
  EXPECT_NE(s.output.inplane->summary.message.find("tangent turns by only"), std::string::npos)
      << s.output.inplane->summary.message;
  EXPECT_EQ(s.output.outofplane->summary.termination, Termination::Converged);
}

}  // namespace
}  // namespace catena
