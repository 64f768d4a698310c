// SPDX-License-Identifier: MIT
// fe's damped modes with a seabed dashpot (docs/explanation/methods/fe.md, "Damped modes"):
// - a taut line lying entirely on the seabed with a foundation dashpot c_s on its vertical motion:
//   the exact roots of M lambda^2 + c_s lambda + H/(1+e) (n pi/L)^2 + k_s = 0 (overdamped for the
//   lowest n, complex with delta = c_s / 2M above), undamped axial modes;
// - a chain with 55 % on the seabed and a dashpot strong enough for a heavily damped branch
//   (delta ~ c_s / 2M) whose omega_d moves by tens of per cent between fe's meshes: every mode
//   returned lies in the passive line's half plane (delta >= 0, bounded by c_s / 2M since the
//   dashpot is the only damping), none is dropped, and a root the meshes do not resolve comes
//   back without an estimate (a declared miss) rather than extrapolated.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <vector>

#include "catena/core/types.hpp"
#include "catena/solvers/fe_solver.hpp"
#include "catena/statics/dimensionless_groups.hpp"
#include "catena/statics/seabed_statics.hpp"
#include "solvers/common/solver_test_support.hpp"
#include "test_utils.hpp"

namespace catena {
namespace {

using catena::testing::modes_request;
using Complex = std::complex<double>;

SolverOutput solve(const Problem& problem,
                   const StaticSolution& statics,
                   const SolveRequest& request,
                   const FeSolverOptions& options) {
  const DimensionlessGroups groups = compute_dimensionless_groups(problem, statics);
  return solve_fe(problem, statics, groups, request, options);
}

// A 100 m line on the seabed at z = -50 pulled to tension H (as fe_seabed_test.cpp), with a soft
// foundation (k_s / M = 2 s^-2) and a dashpot c_s / 2M = 3 1/s: n = 1..4 overdamped, n >= 5
// complex with damping ratios 0.87 down to 0.47, the axial modes above 23 rad/s undamped.
constexpr double kLength = 100.0, kTension = 2e4, kAxial = 2e7, kMass = 40.0, kAdded = 10.0;
constexpr double kVertical = 100.0, kTangential = 1.5e3, kDashpot = 300.0;

Problem line_on_seabed() {
  Problem p;
  p.cable = {kLength, 300.0, kAxial, kMass, kAdded};
  p.supports.a_m = Vec2(0.0, -50.0);
  p.supports.b_m = Vec2(kLength * (1.0 + kTension / kAxial), -50.0);
  p.seabed = Seabed{-50.0, 0.0, kVertical, kTangential};
  p.seabed->damping_n_s_per_m2 = kDashpot;
  return p;
}

// The two roots of M lambda^2 + c_s lambda + K_n of the vertical string mode n.
std::pair<Complex, Complex> vertical_roots(int n) {
  const double M = kMass + kAdded, e = kTension / kAxial;
  const double stiffness = kTension / (1.0 + e) * std::pow(n * kPi / kLength, 2) + kVertical;
  const Complex root = std::sqrt(Complex(kDashpot * kDashpot - 4.0 * M * stiffness, 0.0));
  return {(-kDashpot + root) / (2.0 * M), (-kDashpot - root) / (2.0 * M)};
}

TEST(FeDampedSeabed, TheDashpotsRootsOfALineOnTheSeabedAreExact) {
  const Problem problem = line_on_seabed();
  const StaticSolution statics(problem.as_line(), problem.supports.a_m, *problem.seabed, kTension,
                               kLength);
  ASSERT_TRUE(statics.has_contact());
  FeSolverOptions options;
  options.elements = 400;
  const SolverOutput out = solve(problem, statics, modes_request(6, 0), options);
  ASSERT_TRUE(out.inplane) << out.summary.message;
  const ModalResult& plane = *out.inplane;
  ASSERT_EQ(plane.modes.size(), 6u) << plane.summary.message;
  // The lowest six by omega_d are the vertical modes n = 5..10 (the axial ones start at 23 rad/s).
  for (int n = 5; n <= 10; ++n) {
    const Mode& mode = plane.modes[static_cast<std::size_t>(n - 5)];
    const Complex exact = vertical_roots(n).first;
    ASSERT_GT(exact.imag(), 0.0);
    const double omega_error = std::abs(mode.omega_rad_s - exact.imag()) / exact.imag();
    const double delta_error = std::abs(mode.decay_rate_1_s + exact.real()) / -exact.real();
    EXPECT_LT(omega_error, 1e-8) << "n = " << n;
    EXPECT_LE(omega_error, mode.relative_error_estimate) << "n = " << n;
    EXPECT_LT(delta_error, 1e-8) << "n = " << n;
    EXPECT_GT(mode.damping_ratio, 0.45) << "n = " << n;
  }
  // The overdamped roots fe lists (those within its searched disk) are among n = 1..4's.
  std::vector<double> exact_real;
  for (int n = 1; n <= 4; ++n) {
    const auto [slow, fast] = vertical_roots(n);
    ASSERT_EQ(slow.imag(), 0.0);
    exact_real.push_back(-slow.real());
    exact_real.push_back(-fast.real());
  }
  ASSERT_FALSE(plane.overdamped.empty());
  for (const Mode& root : plane.overdamped) {
    double nearest = 1e300;
    for (double delta : exact_real)
      nearest = std::min(nearest, std::abs(root.decay_rate_1_s - delta) / delta);
    EXPECT_LT(nearest, 1e-8) << "overdamped " << root.index << ": " << root.decay_rate_1_s;
    EXPECT_LE(nearest, root.decay_rate_error_estimate) << "overdamped " << root.index;
  }
}

// A chain of 470 m from an anchor on the seabed at 146 m depth to a fairlead 395 m away: 258 m
// grounded, a foundation dashpot c_s = k_s = 2400 (c_s / 2M = 8.9 1/s against k_s / M = 18 s^-2,
// so the grounded stretch's own vertical motion is overdamped up to a wavenumber and heavily
// damped beyond it).
TEST(FeDampedSeabed, EveryRootOfAChainOnADampedSeabedIsPassive) {
  Problem problem;
  problem.cable = {470.0, 1200.0, 6e8, 130.0, 5.0};
  problem.supports.a_m = Vec2(0.0, -150.0);
  problem.supports.b_m = Vec2(395.0, -4.0);
  problem.seabed = Seabed{-150.0, 0.0, 2400.0, 0.0};
  problem.seabed->damping_n_s_per_m2 = 2400.0;
  const StaticSolution statics = solve_seabed_statics(problem);
  ASSERT_TRUE(statics.converged) << statics.message;
  ASSERT_GT(statics.grounded_length_m(), 200.0);
  const double bound = 2400.0 / (2.0 * (130.0 + 5.0));
  FeSolverOptions options;
  options.elements = 334;
  const SolverOutput out = solve(problem, statics, modes_request(6, 0), options);
  ASSERT_TRUE(out.inplane) << out.summary.message;
  const ModalResult& plane = *out.inplane;
  // None dropped: six modes, ascending omega_d.
  ASSERT_EQ(plane.modes.size(), 6u) << plane.summary.message;
  int heavy = 0;
  for (const Mode& mode : plane.modes) {
    EXPECT_GT(mode.omega_rad_s, 0.0) << "mode " << mode.index;
    EXPECT_GE(mode.decay_rate_1_s, 0.0) << "mode " << mode.index;
    // The Rayleigh functional's delta = phi^H C phi / 2 phi^H M phi with C the dashpot alone.
    const double slack = std::max(mode.decay_rate_error_estimate, 0.0);
    EXPECT_LE(mode.decay_rate_1_s, bound * (1.0 + slack)) << "mode " << mode.index;
    if (mode.damping_ratio > 0.9) ++heavy;
    // A lightly damped mode is paired across the levels with itself: its delta converges like its
    // omega_d (a pairing with a heavily damped root of another level, as when the levels' lowest
    // six differ, extrapolates delta from 0.03 and 8.9 and gives estimates of order 1 and more).
    if (mode.damping_ratio < 0.1) {
      EXPECT_GE(mode.decay_rate_error_estimate, 0.0) << "mode " << mode.index;
      EXPECT_LT(mode.decay_rate_error_estimate, 1e-3) << "mode " << mode.index;
    }
  }
  EXPECT_GE(heavy, 1) << "the dashpot's heavily damped branch reaches the lowest six";
  for (std::size_t i = 1; i < plane.modes.size(); ++i)
    EXPECT_LE(plane.modes[i - 1].omega_rad_s, plane.modes[i].omega_rad_s);
  for (const Mode& root : plane.overdamped) EXPECT_GT(root.decay_rate_1_s, 0.0);
}

}  // namespace
}  // namespace catena
