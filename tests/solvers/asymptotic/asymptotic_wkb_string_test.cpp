// SPDX-License-Identifier: MIT
// Tests of the asymptotic solver's WKB out-of-plane string
// (src/solvers/asymptotic/asymptotic_wkb_string.cpp): harmonics of one travel time, shapes
// vanishing at the ends, no shapes when none are asked.
#include "solvers/asymptotic/asymptotic_wkb_string.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "catena/solvers/asymptotic_solver.hpp"
#include "catena/statics/problem_builders.hpp"
#include "solvers/common/solver_test_support.hpp"
#include "test_utils.hpp"

namespace catena::internal {
namespace {

using catena::testing::relative_error;

catena::testing::SolvedProblem taut() {
  return catena::testing::prepare(make_taut_inclined_problem(0.18, 23.46, 38.0, 1.0));
}

TEST(AsymptoticWkbString, WkbModesAreHarmonicsOfOneTravelTime) {
  // omega_n = n pi / tau: every frequency a multiple of the first; the shapes vanish at both
  // ends (sin(n pi) = 0 up to the quadrature, ~1e-15), are normalised to max |v| = 1, and carry
  // no first-order tension.
  const auto s = taut();
  SolveRequest request = catena::testing::modes_request(0, 4);
  request.shapes = true;
  request.tension = true;
  const double M = s.problem.cable.normal_mass_kg_per_m();
  const ModalResult result = wkb_outofplane_modes(s.statics, s.groups, request, M, 0.01, 4, "demo");
  ASSERT_EQ(result.modes.size(), 4u);
  EXPECT_EQ(result.summary.termination, Termination::Converged);
  EXPECT_EQ(result.summary.solver, "demo");
  EXPECT_EQ(result.plane, Plane::OutOfPlane);
  const std::vector<double> omegas = wkb_outofplane_omegas(s.statics, 4, 4);
  for (std::size_t i = 0; i < 4; ++i) {
    const Mode& mode = result.modes[i];
    EXPECT_EQ(mode.omega_rad_s, omegas[i]);
    EXPECT_LE(relative_error(mode.omega_rad_s, (i + 1) * result.modes[0].omega_rad_s), 1e-14);
    EXPECT_EQ(mode.relative_error_estimate, 0.01);
    const Index last = mode.v.size() - 1;
    EXPECT_LE(std::abs(mode.v[0]) + std::abs(mode.v[last]), 1e-12);
    EXPECT_DOUBLE_EQ(mode.v.cwiseAbs().maxCoeff(), 1.0);
    EXPECT_EQ(mode.tension_n.cwiseAbs().maxCoeff(), 0.0);
    EXPECT_GT(mode.modal_mass_kg, 0.0);
  }
}

TEST(AsymptoticWkbString, WkbFrequenciesWithoutShapesCarryNoShapes) {
  const auto s = taut();
  const ModalResult result =
      wkb_outofplane_modes(s.statics, s.groups, catena::testing::modes_request(0, 2),
                           s.problem.cable.normal_mass_kg_per_m(), 0.01, 4, "demo");
  ASSERT_EQ(result.modes.size(), 2u);
  EXPECT_EQ(result.modes[0].v.size(), 0);
  EXPECT_EQ(result.modes[0].s_m.size(), 0);
}

}  // namespace
}  // namespace catena::internal
