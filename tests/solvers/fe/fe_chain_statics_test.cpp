// SPDX-License-Identifier: MIT
// fe discrete statics (src/solvers/fe/fe_chain_statics.cpp): the chain closes on support b
// and approaches the continuous catenary at O(h^2); prescribed end forces are kept; a slack chain
// is reported as a failure, never thrown.
#include "solvers/fe/fe_chain_statics.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "catena/statics/problem_builders.hpp"
#include "test_utils.hpp"

namespace catena {
namespace {

using catena::testing::relative_error;

Problem inclined_catenary() {
  Problem problem;
  problem.cable = {.length_m = 1000.0,
                   .weight_n_per_m = 1000.0,
                   .axial_stiffness_n = 5e8,
                   .mass_kg_per_m = 120.0,
                   .added_mass_kg_per_m = 80.0};
  problem.supports.b_m = Vec2(900.0, 300.0);
  return problem;
}

// The element forces are the continuous force at the element midpoints (exact by construction),
// and the nodes converge to the catenary at O(h^2): with h = L/400 within 1e-5 of the chord.
constexpr double kRelTolChainPosition = 1e-5;

TEST(FeChainStatics, ClosesOnSupportBAndApproachesTheCatenary) {
  const Problem problem = inclined_catenary();
  const StaticSolution statics = solve_statics(problem);
  const internal::FeChain chain =
      internal::solve_chain_statics(problem, statics, 400, problem.cable.axial_stiffness_n);
  ASSERT_TRUE(chain.in_equilibrium()) << chain.failure;
  EXPECT_LE(chain.closure_error_m, 1e-9);
  EXPECT_GT(chain.newton_iterations, 0);
  const double chord = problem.supports.chord_m().norm();
  for (int i = 0; i <= 400; i += 50) {
    const double s = i * chain.element_length_m[0];
    const Vec2 difference = chain.node_offset_m[static_cast<std::size_t>(i)] - statics.offset_m(s);
    EXPECT_LE(difference.norm() / chord, kRelTolChainPosition) << "node " << i;
  }
  EXPECT_LE(relative_error(chain.horizontal_force_n, statics.horizontal_force_n()), 1e-4);
}

TEST(FeChainStatics, ElementForceIsTheContinuousForceAtTheElementMidpoint) {
  const Problem problem = inclined_catenary();
  const StaticSolution statics = solve_statics(problem);
  const internal::FeChain chain =
      internal::solve_chain_statics(problem, statics, 100, problem.cable.axial_stiffness_n);
  ASSERT_TRUE(chain.in_equilibrium()) << chain.failure;
  const double W0 = problem.cable.weight_n_per_m, l0 = chain.element_length_m[0];
  for (int j : {0, 37, 99}) {
    const double V = chain.vertical_force_a_n + W0 * l0 * (j + 0.5);
    EXPECT_DOUBLE_EQ(chain.tension_n[j], std::hypot(chain.horizontal_force_n, V))
        << "element " << j;
    EXPECT_DOUBLE_EQ(chain.stretched_length_m[j],
                     l0 * (1.0 + chain.tension_n[j] / problem.cable.axial_stiffness_n));
  }
}

TEST(FeChainStatics, PrescribedEndForcesAreKeptWithoutNewton) {
  const Problem problem = make_gale_xi_problem(-0.5, 0.5);
  ASSERT_TRUE(problem.prescribed_forces.has_value());
  const StaticSolution statics = solve_statics(problem);
  const internal::FeChain chain = internal::solve_chain_statics(problem, statics, 200, 1e9);
  ASSERT_TRUE(chain.in_equilibrium()) << chain.failure;
  EXPECT_EQ(chain.newton_iterations, 0);
  EXPECT_EQ(chain.horizontal_force_n, problem.prescribed_forces->horizontal_n);
  EXPECT_EQ(chain.vertical_force_a_n, problem.prescribed_forces->vertical_a_n);
}

TEST(FeChainStatics, ASlackChainIsAReportedFailureNotAnException) {
  // A vertical hanging chain whose first element carries no force: V_A = -W0 l0 / 2, H = 0.
  Problem problem = inclined_catenary();
  const StaticSolution statics = solve_statics(problem);
  const int elements = 10;
  problem.prescribed_forces =
      EndForces{0.0, -0.5 * problem.cable.weight_n_per_m * problem.cable.length_m / elements};
  internal::FeChain chain;
  EXPECT_NO_THROW(chain = internal::solve_chain_statics(problem, statics, elements, 1e9));
  EXPECT_FALSE(chain.in_equilibrium());
  EXPECT_NE(chain.failure.find("slack"), std::string::npos) << chain.failure;
}

}  // namespace
}  // namespace catena
