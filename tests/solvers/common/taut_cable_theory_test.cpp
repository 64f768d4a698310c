// SPDX-License-Identifier: MIT
// Tests of what the analytic solvers share (src/solvers/common/taut_cable_theory.cpp): the
// static strain and the eps thresholds.
#include "solvers/common/taut_cable_theory.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "catena/statics/problem_builders.hpp"
#include "solvers/common/solver_test_support.hpp"
#include "test_utils.hpp"

namespace catena::internal {
namespace {

catena::testing::SolvedProblem taut(double eps = 0.18,
                                    double phi_deg = 23.46,
                                    double lambda2 = 38.0) {
  return catena::testing::prepare(make_taut_inclined_problem(eps, phi_deg, lambda2, 1.0));
}

TEST(TautCableTheory, StaticStrainIsT0OverEA) {
  const auto s = taut();
  EXPECT_DOUBLE_EQ(static_strain(s.problem, s.groups),
                   s.groups.t0_n / s.problem.cable.axial_stiffness_n);
  Problem inextensible = s.problem;
  inextensible.cable.axial_stiffness_n = kInfinity;
  ASSERT_TRUE(inextensible.cable.is_inextensible());
  EXPECT_EQ(static_strain(inextensible, s.groups), 0.0);
}

TEST(TautCableTheory, WarningThresholdAboveMaxEpsIsBadInputNamingTheKnob) {
  EXPECT_NO_THROW(require_warning_below_max_eps("airy", 0.3, 1.0));
  catena::testing::expect_invalid([] { require_warning_below_max_eps("airy", 1.5, 1.0); },
                                  "[solvers.airy].eps_warning_threshold");
}

}  // namespace
}  // namespace catena::internal
