// SPDX-License-Identifier: MIT
// What adding a solver costs: a complete sixth solver, the taut string (omega_n = n pi
// sqrt(T0/M)/L, both planes), written against the skeleton in taut_string_solver.hpp (its
// numerics, its knob table and its registry entry, with its roles). The test runs it through the
// same run_solver() as the five real ones and compares it with shooting on a taut string, where it
// is exact to the sag (eps = 1e-6). tests/verification/sixth_solver_harness_test.cpp registers it
// and runs it through the harness and the mutation score.
#include <gtest/gtest.h>

#include "catena/solvers/shooting_solver.hpp"
#include "catena/statics/problem_builders.hpp"
#include "solver_test_support.hpp"
#include "taut_string_solver.hpp"

namespace catena {
namespace {

using testing::make_string_entry;

TEST(SixthSolver, RunsThroughTheSharedDriverAndMatchesShootingOnATautString) {
  const SolverEntry entry = make_string_entry();
  testing::SolvedProblem solved =
      testing::prepare(make_taut_inclined_problem(1e-6, 0.0, 1e-4, 1.0));
  const SolveRequest request = testing::modes_request(4, 4);
  const SolveContext context{solved.problem, solved.statics, solved.groups, request};
  const SolverOutput string = run_solver(entry, context, {});
  const SolverOutput shooting =
      solve_shooting(solved.problem, solved.statics, solved.groups, request);
  ASSERT_EQ(string.summary.termination, Termination::Converged) << string.summary.message;
  ASSERT_TRUE(string.inplane && string.outofplane);
  ASSERT_TRUE(shooting.outofplane);
  EXPECT_EQ(string.summary.solver, "string");
  EXPECT_GE(string.summary.wall_time_s, 0.0);
  ASSERT_EQ(string.outofplane->modes.size(), 4u);
  for (int i = 0; i < 4; ++i) {
    // Out of plane the taut string differs from the exact cable by the static strain and sag,
    // both about 1e-6 here.
    EXPECT_NEAR(string.outofplane->modes[i].omega_rad_s / shooting.outofplane->modes[i].omega_rad_s,
                1.0, 1e-5);
  }
}

TEST(SixthSolver, KnobsAndApplicabilityComeFromTheSkeleton) {
  const SolverEntry entry = make_string_entry();
  ASSERT_EQ(entry.knobs.size(), 1u);
  EXPECT_EQ(entry.knobs[0].default_value, "0.001");
  EXPECT_EQ(entry.knobs[0].valid, "(0, 1]");
  EXPECT_THROW(entry.validate_knobs({{"max_eps", 2.0}}), InvalidInput);
  EXPECT_THROW(entry.validate_knobs({{"elements", 2L}}), InvalidInput);
  testing::SolvedProblem sagging =
      testing::prepare(make_taut_inclined_problem(0.5, 20.0, 10.0, 1.0));
  const SolveRequest request = testing::modes_request(2, 0);
  const SolveContext context{sagging.problem, sagging.statics, sagging.groups, request};
  const SolverOutput output = run_solver(entry, context, {});
  EXPECT_EQ(output.summary.termination, Termination::NotApplicable);
  EXPECT_FALSE(output.inplane.has_value());
}

}  // namespace
}  // namespace catena
