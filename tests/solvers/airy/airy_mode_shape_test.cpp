// SPDX-License-Identifier: MIT
// Tests of the Airy mode shapes (src/solvers/airy/airy_mode_shape.cpp): the travel times
// against the model's whole-span quadrature, and at a root of the determinant a null vector that
// satisfies the four boundary conditions, which it does not away from a root.
#include "solvers/airy/airy_mode_shape.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "catena/statics/problem_builders.hpp"
#include "solvers/airy/airy_root_scan.hpp"
#include "solvers/common/solver_test_support.hpp"
#include "test_utils.hpp"

namespace catena::internal {
namespace {

using catena::testing::relative_error;

struct Fixture {
  catena::testing::SolvedProblem solved;
  AiryModel model;
  Vector stations;
  Vector travel_times;
};

Fixture make() {
  Fixture f{
      catena::testing::prepare(make_taut_inclined_problem(0.05, 30.0, 38.0, 1.0)), {}, {}, {}};
  f.model = build_airy_model(f.solved.problem, f.solved.statics, f.solved.groups,
                             AiryCurvatureFit::Tangent, 4);
  f.stations = Vector::LinSpaced(201, 0.0, f.model.length);
  f.travel_times = transverse_travel_times(f.solved.statics, f.model.normal_mass, f.stations);
  return f;
}

TEST(AiryModeShape, TravelTimesRiseFromZeroToTheWholeSpan) {
  const Fixture f = make();
  EXPECT_EQ(f.travel_times[0], 0.0);
  for (Index j = 1; j < f.stations.size(); ++j) EXPECT_GT(f.travel_times[j], f.travel_times[j - 1]);
  // Sub-interval quadratures summed against the model's 4 panels: T is analytic, both converged.
  EXPECT_LE(relative_error(f.travel_times[f.stations.size() - 1], f.model.travel_time), 1e-13);
}

TEST(AiryModeShape, NullVectorAtARootSatisfiesTheBoundaryConditions) {
  const Fixture f = make();
  const AiryRootScan scan = scan_airy_roots(f.model, f.solved.groups, f.solved.statics, 3, {});
  ASSERT_EQ(scan.roots.size(), 3u);
  const Index last = f.stations.size() - 1;
  for (double root : scan.roots) {
    const double omega = f.solved.groups.omega_from_k_l_over_pi(root / kPi);
    const AiryModeShape shape =
        airy_mode_shape(f.model, f.solved.statics, omega, f.stations, f.travel_times * omega);
    ASSERT_EQ(shape.w.size(), f.stations.size());
    const double size = shape.w.cwiseAbs().maxCoeff();
    ASSERT_GT(size, 0.0);
    // The roots are solved to 50 bits; the boundary values vanish to ~1e-12 of the shape's size.
    EXPECT_LE(shape.residual, 1e-10) << root / kPi;
    EXPECT_LE(std::abs(shape.w[0]) + std::abs(shape.w[last]), 1e-9 * size) << root / kPi;
    EXPECT_LE(std::abs(shape.u[0]) + std::abs(shape.u[last]), 1e-9 * size) << root / kPi;
    EXPECT_GT(shape.tension_n.cwiseAbs().maxCoeff(), 0.0);
  }
  // Half-way between two roots the system is far from singular and the ends do not vanish.
  const double omega =
      f.solved.groups.omega_from_k_l_over_pi(0.5 * (scan.roots[0] + scan.roots[1]) / kPi);
  const AiryModeShape off =
      airy_mode_shape(f.model, f.solved.statics, omega, f.stations, f.travel_times * omega);
  EXPECT_GT(off.residual, 1e-4);
}

}  // namespace
}  // namespace catena::internal
