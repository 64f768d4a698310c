// SPDX-License-Identifier: MIT
// Tests of the Airy root scan (src/solvers/airy/airy_root_scan.cpp): the spurious-root
// cutoff against the tensions it bounds, roots that are sign changes of the determinant, a close
// near-cross-over pair that hides between two samples, and the scan limit.
#include "solvers/airy/airy_root_scan.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "catena/statics/problem_builders.hpp"
#include "solvers/airy/airy_boundary_system.hpp"
#include "solvers/common/solver_test_support.hpp"
#include "test_utils.hpp"

namespace catena::internal {
namespace {

using catena::testing::relative_error;

struct Fixture {
  catena::testing::SolvedProblem solved;
  AiryModel model;
};

Fixture make(double eps, double phi_deg, double lambda2) {
  Fixture f{catena::testing::prepare(make_taut_inclined_problem(eps, phi_deg, lambda2, 1.0)), {}};
  f.model = build_airy_model(f.solved.problem, f.solved.statics, f.solved.groups,
                             AiryCurvatureFit::Tangent, 4);
  return f;
}

AiryRootScan scan(const Fixture& f, int count, const AirySolverOptions& options = {}) {
  return scan_airy_roots(f.model, f.solved.groups, f.solved.statics, count, options);
}

TEST(AiryRootScan, CutoffIsAFractionOfTheSmallestStringBound) {
  // pi sqrt(T/(1+T/EA) / T0) at the station of least tension, sampled on 2001 stations: the
  // cutoff (fraction 1) is below every sample and within 1e-6 of the smallest.
  for (double phi_deg : {5.0, 45.0}) {
    const Fixture f = make(0.49, phi_deg, 64.0);
    const StaticSolution& statics = f.solved.statics;
    const double L = f.model.length;
    double smallest = INFINITY;
    for (int j = 0; j <= 2000; ++j) {
      const double t = statics.tension_n(j * L / 2000);
      smallest = std::min(
          smallest, kPi * std::sqrt(t / (1.0 + t * f.model.inverse_ea) / f.solved.groups.t0_n));
    }
    const double bound = spurious_root_cutoff_k_l(f.model, statics, f.solved.groups, 1.0);
    EXPECT_LE(bound, smallest * (1.0 + 1e-14)) << phi_deg;
    EXPECT_LE(relative_error(bound, smallest), 1e-6) << phi_deg;
    EXPECT_DOUBLE_EQ(spurious_root_cutoff_k_l(f.model, statics, f.solved.groups, 0.75),
                     0.75 * bound);
  }
}

TEST(AiryRootScan, RootsAreAscendingSignChangesAboveTheCutoff) {
  const Fixture f = make(0.18, 23.46, 38.0);
  const AiryRootScan result = scan(f, 6);
  ASSERT_EQ(result.roots.size(), 6u);
  EXPECT_TRUE(std::is_sorted(result.roots.begin(), result.roots.end()));
  EXPECT_GT(result.roots.front(), result.cutoff_kl);
  EXPECT_EQ(result.sign_changes + 2 * result.pairs_from_minima, 6);
  for (double root : result.roots) {
    const double below = airy_determinant_at(f.model, f.solved.groups, root * (1.0 - 1e-12));
    const double above = airy_determinant_at(f.model, f.solved.groups, root * (1.0 + 1e-12));
    EXPECT_LE(below * above, 0.0) << root / kPi;
  }
  EXPECT_EQ(result.limit_kl, (2.0 * 6 + 20.0) * kPi);  // the automatic limit
  // One determinant per scan step at least, from the cutoff to the last root.
  EXPECT_GE(result.evaluations,
            static_cast<long>((result.roots.back() - result.cutoff_kl) / (0.05 * kPi)));
}

TEST(AiryRootScan, FindsAClosePairBetweenTwoSamplesAtAMinimumOfTheDeterminant) {
  // lambda^2 = 4 pi^2, eps = 0.01, phi = 30 deg: the first two roots straddle kL = 2 pi about
  // 3e-3 apart in kL/pi (1.9984 and 2.0016), far below a coarse step of 0.37. With the grid
  // starting at the cutoff (kL/pi = 0.749) both fall between the samples 1.859 and 2.229.
  const Fixture f = make(0.01, 30.0, 4.0 * kPi * kPi);
  AirySolverOptions options;
  options.scan_step_k_l_over_pi = 0.37;
  const AiryRootScan result = scan(f, 2, options);
  ASSERT_EQ(result.roots.size(), 2u);
  EXPECT_EQ(result.pairs_from_minima, 1);
  EXPECT_EQ(result.sign_changes, 0);
  EXPECT_LT(result.roots[0], 2.0 * kPi);
  EXPECT_GT(result.roots[1], 2.0 * kPi);
  EXPECT_LT((result.roots[1] - result.roots[0]) / kPi, 0.01);
  // The same pair from a fine grid, which straddles each root: agreement to the tolerance.
  options.scan_step_k_l_over_pi = 1e-3;
  const AiryRootScan fine = scan(f, 2, options);
  ASSERT_EQ(fine.roots.size(), 2u);
  EXPECT_EQ(fine.pairs_from_minima, 0);
  for (int i = 0; i < 2; ++i) EXPECT_LE(relative_error(result.roots[i], fine.roots[i]), 1e-13) << i;
}

TEST(AiryRootScan, StopsAtTheScanLimit) {
  const Fixture f = make(0.18, 23.46, 38.0);
  AirySolverOptions options;
  options.max_k_l_over_pi = 2.5;
  const AiryRootScan result = scan(f, 6, options);
  EXPECT_EQ(result.limit_kl, 2.5 * kPi);
  EXPECT_LT(result.roots.size(), 6u);
  EXPECT_GE(result.roots.size(), 1u);
  for (double root : result.roots) EXPECT_LE(root, result.limit_kl + 0.5 * 0.05 * kPi);
}

}  // namespace
}  // namespace catena::internal
