// SPDX-License-Identifier: MIT
// fe's convergence at a point that kinks the static line without adding inertia (a buoy given by
// its volume alone, as MoorDyn decks give them: MoorPy tests/case6.dat, issue 31), against
// shooting at rtol 1e-13 (docs/explanation/methods/fe.md, "Lines"):
// - the Richardson-extrapolated in-plane frequencies converge at order 4, measured from three
//   meshes (N, 2N, 4N) without a reference. Until 2026-12 the line's own mass at such a node was
//   lumped in the bisector frame (only a point with inertia switched to each half element's frame),
//   an O(h) error that left fe first order after Richardson (on case6: 4.1e-6, 1.0e-6, 2.6e-7 at
//   N = 400, 1600, 6400, with estimates 4.5e-7, 4.1e-7, 1.2e-7). In each half element's own
//   frame the order was 3 (the frame differs from the interior nodes' bisector by O(h^2) on one
//   node): the half cells now take the bisector their piece's interior scheme would give them;
//   measured here 9.8e-8, 6.2e-9, 3.9e-10 in mode 1 (16x per halving);
// - on each mesh every mode's error estimate bounds its distance from shooting.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "catena/solvers/fe_solver.hpp"
#include "catena/solvers/shooting_solver.hpp"
#include "solvers/common/solver_test_support.hpp"
#include "test_utils.hpp"

namespace catena {
namespace {

using Solved = catena::testing::SolvedProblem;

constexpr int kModes = 4;

// One section on both sides of the joint (so that nothing but the point marks the node), with a
// normal added mass and none along the line: m = 40 kg/m along, M = 70 kg/m across, the case where
// the frame of the lumped mass matters. The buoy (no mass, no added mass) lifts the joint by 2.5e4
// N against 3.6e4 N of line weight: the tangents on either side differ by about 60 degrees.
Problem line_with_massless_buoy() {
  Problem p;
  const LineSegment chain{60.0, 300.0, 1e8, 40.0, 30.0};
  p.line.segments = {chain, chain};
  PointAttachment buoy;
  buoy.s_m = 60.0;
  buoy.mass_kg = 0.0;
  buoy.weight_n = -2.5e4;
  p.line.points = {buoy};
  p.supports.b_m = Vec2(95.0, 10.0);
  return p;
}

Solved solve_fe_on(const Problem& problem, int elements) {
  FeSolverOptions options;
  options.elements = elements;
  options.tolerance = 0.0;  // this mesh, no refinement
  return catena::testing::solve_problem(solve_fe, problem,
                                        catena::testing::modes_request(kModes, 0), options);
}

TEST(LineBuoyKink, FeConvergesAtOrderFourAndItsEstimateBoundsItsErrorAgainstShooting) {
  const Problem problem = line_with_massless_buoy();
  ShootingSolverOptions tight;
  tight.relative_tolerance = 1e-13;
  const Solved reference = catena::testing::solve_problem(
      solve_shooting, problem, catena::testing::modes_request(kModes, 0), tight);
  ASSERT_EQ(reference.output.summary.termination, Termination::Converged)
      << reference.output.summary.full_report();
  const std::vector<int> meshes = {40, 80, 160};
  std::vector<Solved> runs;
  for (int elements : meshes) {
    runs.push_back(solve_fe_on(problem, elements));
    ASSERT_EQ(runs.back().output.summary.termination, Termination::Converged)
        << runs.back().output.summary.full_report();
  }
  for (std::size_t i = 0; i < kModes; ++i) {
    const double exact = reference.output.inplane->modes[i].omega_rad_s;
    std::vector<double> omega;
    for (std::size_t r = 0; r < runs.size(); ++r) {
      const Mode& mode = runs[r].output.inplane->modes[i];
      omega.push_back(mode.omega_rad_s);
      const double actual = catena::testing::relative_error(mode.omega_rad_s, exact);
      EXPECT_LE(actual, mode.relative_error_estimate)
          << "mode " << i + 1 << ", N = " << meshes[r] << ": estimate not an upper bound";
      EXPECT_LT(actual, 1e-4) << "mode " << i + 1 << ", N = " << meshes[r];
    }
    const double order = std::log2((omega[0] - omega[1]) / (omega[1] - omega[2]));
    EXPECT_NEAR(order, 4.0, 0.5) << "mode " << i + 1 << " (errors against shooting "
                                 << (omega[0] - exact) / exact << ", " << (omega[1] - exact) / exact
                                 << ", " << (omega[2] - exact) / exact << ")";
  }
}

}  // namespace
}  // namespace catena
