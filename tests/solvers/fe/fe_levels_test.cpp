// SPDX-License-Identifier: MIT
// fe plan and levels (src/solvers/fe/fe_levels.cpp): which meshes and penalties are solved,
// the rounding floor's scaling, and the statics and eigen solves on every level.
#include "solvers/fe/fe_levels.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "catena/solvers/fe_solver.hpp"
#include "catena/statics/problem_builders.hpp"

namespace catena {
namespace {

TEST(FeLevels, PlanMeshesFollowTheOptions) {
  const Problem problem = make_taut_inclined_problem(0.1, 30.0, 50.0, 0.6);
  const StaticSolution statics = solve_statics(problem);
  const auto plan = [&](const FeSolverOptions& options, int inplane = 3) {
    return internal::make_fe_plan(problem, statics, options, inplane, 0);
  };
  // Richardson on N, 2N, with N/2 for the error estimate (it resolves the 3 modes).
  const internal::FePlan richardson = plan({.elements = 100});
  EXPECT_EQ(richardson.meshes, (std::vector<int>{50, 100, 200}));
  EXPECT_TRUE(richardson.richardson && richardson.has_coarse() && richardson.has_estimate_mesh());
  EXPECT_EQ(richardson.meshes[static_cast<std::size_t>(richardson.main_coarse)], 100);
  EXPECT_EQ(richardson.finest_elements(), 200);
  EXPECT_EQ(plan({.elements = 100, .observed_order = true}).meshes,
            (std::vector<int>{50, 100, 200, 400}));
  // N/2 = 5 elements resolve 2 modes, not 3: no estimate mesh; an odd N/2 count is not halved.
  EXPECT_EQ(plan({.elements = 10}).meshes, (std::vector<int>{10, 20}));
  EXPECT_EQ(plan({.elements = 101}, 1).meshes, (std::vector<int>{101, 202}));
  EXPECT_FALSE(plan({.elements = 10}).has_estimate_mesh());
  const internal::FePlan estimate = plan({.elements = 100, .richardson = false});
  EXPECT_EQ(estimate.meshes, (std::vector<int>{50, 100}));
  EXPECT_FALSE(estimate.richardson);
  EXPECT_EQ(estimate.finest_elements(), 100);
  // N/2 = 2 elements hold 2 in-plane unknowns: too few for 3 modes, so no estimate mesh.
  const internal::FePlan single = plan({.elements = 4, .richardson = false});
  EXPECT_EQ(single.meshes, (std::vector<int>{4}));
  EXPECT_FALSE(single.has_coarse());
  // Extensible: one penalty, the cable's own EA.
  EXPECT_EQ(richardson.penalties(), 1u);
  EXPECT_EQ(richardson.axial_stiffness_n[0], problem.cable.axial_stiffness_n);
}

TEST(FeLevels, InextensibleCablesGetThreePenalties) {
  const Problem problem = make_gale_xi_problem(-0.5, 0.5);
  ASSERT_TRUE(problem.cable.is_inextensible());
  const StaticSolution statics = solve_statics(problem);
  const internal::FePlan plan = internal::make_fe_plan(problem, statics, {.kappa = 1e-5}, 3, 3);
  ASSERT_EQ(plan.penalties(), 3u);  // kappa, 2 kappa for the result, 4 kappa for its estimate
  EXPECT_EQ(plan.kappas, (std::vector<double>{1e-5, 2e-5, 4e-5}));
  EXPECT_DOUBLE_EQ(plan.axial_stiffness_n[0], statics.horizontal_force_n() / 1e-5);
  EXPECT_DOUBLE_EQ(plan.axial_stiffness_n[0], 2.0 * plan.axial_stiffness_n[1]);
}

TEST(FeLevels, RoundingFloorGrowsLikeNSquaredOverModeSquared) {
  internal::FePlan plan;
  plan.meshes = {100, 200};
  plan.main_fine = 1;
  plan.axial_stiffness_n = {1e6};
  const double floor1 = plan.rounding_floor(10.0, 1);
  EXPECT_DOUBLE_EQ(floor1, 0.5 * 2.220446049250313e-16 * 1e5 * 200.0 * 200.0 / (kPi * kPi));
  EXPECT_DOUBLE_EQ(plan.rounding_floor(10.0, 2), floor1 / 4.0);
  plan.meshes = {100, 400};
  EXPECT_DOUBLE_EQ(plan.rounding_floor(10.0, 1), 4.0 * floor1);
}

TEST(FeLevels, StaticsFloorGrowsLikeNAndTheStiffnessRatio) {
  internal::FePlan plan;
  plan.meshes = {100, 200};
  plan.main_fine = 1;
  plan.axial_stiffness_n = {1e6};
  EXPECT_DOUBLE_EQ(plan.statics_floor(10.0), 0.5 * 2.220446049250313e-16 * 1e5 * 200.0);
  plan.axial_stiffness_n = {2e6};
  EXPECT_DOUBLE_EQ(plan.statics_floor(10.0), 2.0 * 0.5 * 2.220446049250313e-16 * 1e5 * 200.0);
}

TEST(FeLevels, EveryLevelIsSolvedAndProved) {
  const Problem problem = make_gale_xi_problem(-0.5, 0.5);
  const StaticSolution statics = solve_statics(problem);
  const FeSolverOptions options{.elements = 60};
  const internal::FePlan plan = internal::make_fe_plan(problem, statics, options, 4, 0);
  internal::FeTimings timings;
  std::string failure;
  internal::FeLevels levels =
      internal::solve_level_statics(problem, statics, plan, timings, failure);
  ASSERT_TRUE(failure.empty()) << failure;
  ASSERT_EQ(levels.size(), 3u);     // N/2, N, 2N
  ASSERT_EQ(levels[0].size(), 3u);  // three penalties
  EXPECT_EQ(levels[0][1].chain.elements, 30);
  EXPECT_EQ(levels[2][1].chain.elements, 120);
  EXPECT_EQ(levels[2][1].chain.axial_stiffness_n[0], plan.axial_stiffness_n[1]);
  const internal::FePlaneEigenReport report =
      internal::solve_level_modes(levels, Plane::InPlane, 4, options, timings);
  EXPECT_EQ(report.termination, Termination::Converged);
  EXPECT_TRUE(report.warnings.empty());
  EXPECT_GT(report.max_residual, 0.0);
  EXPECT_EQ(internal::modes_on_every_level(levels, Plane::InPlane, 4), 4);
  EXPECT_TRUE(internal::inertia_proved_on_every_level(levels, Plane::InPlane));
  EXPECT_GT(timings.statics_s, 0.0);
  // The forced response's operators: only the missing plane is assembled, on the meshes asked.
  internal::assemble_missing(levels, Plane::OutOfPlane, {1});
  EXPECT_TRUE(levels[1][0].matrices.count(Plane::OutOfPlane) &&
              levels[1][1].matrices.count(Plane::OutOfPlane));
  EXPECT_FALSE(levels[0][0].matrices.count(Plane::OutOfPlane));
}

}  // namespace
}  // namespace catena
