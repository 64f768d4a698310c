// SPDX-License-Identifier: MIT
// fe's eigen engine, Spectra's implicitly restarted Lanczos behind
// src/solvers/fe/fe_spectra_eigs.hpp, on matrices with known spectra: the fixed-fixed string (1-D
// Laplacian) through its inverse, as fe uses it; the clustered top of the same Laplacian
// (restarts); repeated and negative eigenvalues found through Krylov breakdowns when the subspace
// is the whole space; runs of several sizes one after another; a warm start; Spectra's
// NotConverging when restarts run out. Expected values: the Laplacian's eigenvalues 4 sin^2(k pi /
// 2(n + 1)) and a diagonal matrix's.
#include "solvers/fe/fe_spectra_eigs.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace catena {
namespace {

using internal::LanczosResult;
using internal::largest_magnitude_eigenpairs;

constexpr double kPi = 3.14159265358979323846;

// Eigenvalue k (1-based, ascending) of the n x n Laplacian tridiag(-1, 2, -1).
double laplacian_eigenvalue(int k, int n) {
  const double s = std::sin(k * kPi / (2.0 * (n + 1)));
  return 4.0 * s * s;
}

// y = tridiag(-1, 2, -1) x.
internal::SymmetricOperator laplacian(int n) {
  return [n](const double* x, double* y) {
    for (int i = 0; i < n; ++i)
      y[i] = 2.0 * x[i] - (i > 0 ? x[i - 1] : 0.0) - (i + 1 < n ? x[i + 1] : 0.0);
  };
}

// y = tridiag(-1, 2, -1)^{-1} x by the Thomas algorithm: a shift-invert operator at sigma = 0.
internal::SymmetricOperator inverse_laplacian(int n) {
  return [n](const double* x, double* y) {
    std::vector<double> c(static_cast<std::size_t>(n));
    double pivot = 2.0;
    y[0] = x[0] / pivot;
    for (int i = 1; i < n; ++i) {
      c[static_cast<std::size_t>(i)] = -1.0 / pivot;
      pivot = 2.0 + c[static_cast<std::size_t>(i)];
      y[i] = (x[i] + y[i - 1]) / pivot;
    }
    for (int i = n - 2; i >= 0; --i) y[i] -= c[static_cast<std::size_t>(i + 1)] * y[i + 1];
  };
}

// Unit vectors, mutually orthogonal, and A v = theta v to the tolerance.
void expect_eigenpairs(const internal::SymmetricOperator& apply,
                       const LanczosResult& result,
                       double tolerance) {
  const auto n = result.vectors.rows();
  const Eigen::MatrixXd gram = result.vectors.transpose() * result.vectors;
  EXPECT_LT((gram - Eigen::MatrixXd::Identity(gram.rows(), gram.cols())).cwiseAbs().maxCoeff(),
            1e-13);
  Eigen::VectorXd image(n);
  for (Eigen::Index i = 0; i < result.values.size(); ++i) {
    apply(result.vectors.col(i).data(), image.data());
    const double residual = (image - result.values[i] * result.vectors.col(i)).norm();
    EXPECT_LT(residual, tolerance * std::abs(result.values[i])) << "Ritz pair " << i;
  }
}

TEST(FeSpectraEigs, LowestStringModesThroughTheInverse) {
  const int n = 2000;
  const auto apply = inverse_laplacian(n);
  const LanczosResult result = largest_magnitude_eigenpairs(apply, n, 10, 30, 1e-13, 1000);
  ASSERT_TRUE(result.converged);
  ASSERT_EQ(result.values.size(), 10);
  for (int k = 1; k <= 10; ++k) {
    const double exact = laplacian_eigenvalue(k, n);
    EXPECT_NEAR(1.0 / result.values[k - 1], exact, 1e-12 * exact) << "mode " << k;
  }
  expect_eigenpairs(apply, result, 1e-11);
}

TEST(FeSpectraEigs, ClusteredTopOfTheLaplacianNeedsRestarts) {
  // The top eigenvalues 4 cos^2(k pi / 2(n+1)) differ by ~1e-3 relative: many restarts.
  const int n = 100;
  const auto apply = laplacian(n);
  const LanczosResult result = largest_magnitude_eigenpairs(apply, n, 4, 20, 1e-12, 2000);
  ASSERT_TRUE(result.converged);
  EXPECT_GT(result.restarts, 1);
  for (int k = 0; k < 4; ++k) {
    const double exact = laplacian_eigenvalue(n - k, n);
    EXPECT_NEAR(result.values[k], exact, 1e-11 * exact) << "eigenvalue " << k;
  }
  expect_eigenpairs(apply, result, 1e-10);
}

TEST(FeSpectraEigs, RepeatedAndNegativeEigenvaluesWithASubspaceLargerThanTheMatrix) {
  // A Krylov space holds one vector per distinct eigenvalue; with the subspace clamped to n the
  // iteration breaks down and continues with fresh directions, which find the repeated copies.
  const std::vector<double> diagonal = {10.0, -10.5, 10.0, 9.0, 10.0, 9.0,
                                        5.0,  4.0,   3.0,  2.0, 1.0,  0.5};
  const int n = static_cast<int>(diagonal.size());
  const internal::SymmetricOperator apply = [&](const double* x, double* y) {
    for (int i = 0; i < n; ++i) y[i] = diagonal[static_cast<std::size_t>(i)] * x[i];
  };
  const LanczosResult result = largest_magnitude_eigenpairs(apply, n, 6, 30, 1e-13, 100);
  ASSERT_TRUE(result.converged);
  const std::vector<double> expected = {-10.5, 10.0, 10.0, 10.0, 9.0, 9.0};
  ASSERT_EQ(result.values.size(), 6);
  for (int i = 0; i < 6; ++i)
    EXPECT_NEAR(result.values[i], expected[static_cast<std::size_t>(i)], 1e-12);
  expect_eigenpairs(apply, result, 1e-12);
}

TEST(FeSpectraEigs, AllButOneEigenpairOfASmallMatrix) {
  // Spectra wants fewer pairs than rows (nev < ncv <= n); the subspace is clamped to n.
  const int n = 8;
  const auto apply = laplacian(n);
  const LanczosResult result = largest_magnitude_eigenpairs(apply, n, n - 1, 20, 1e-13, 10);
  ASSERT_TRUE(result.converged);
  for (int k = 0; k < n - 1; ++k)
    EXPECT_NEAR(result.values[k], laplacian_eigenvalue(n - k, n), 1e-13);
  expect_eigenpairs(apply, result, 1e-12);
}

TEST(FeSpectraEigs, RunsOfSeveralSizesInTurn) {
  for (int n : {500, 1500, 300}) {
    const auto apply = inverse_laplacian(n);
    const LanczosResult result = largest_magnitude_eigenpairs(apply, n, 6, 20, 1e-13, 1000);
    ASSERT_TRUE(result.converged) << "n = " << n;
    for (int k = 1; k <= 6; ++k) {
      const double exact = laplacian_eigenvalue(k, n);
      EXPECT_NEAR(1.0 / result.values[k - 1], exact, 1e-12 * exact)
          << "n = " << n << ", mode " << k;
    }
  }
}

TEST(FeSpectraEigs, AGuessNearTheWantedVectorsSavesStepsAndChangesNoEigenpair) {
  // The guess: the sum of the 10 lowest string modes of a mesh half as fine, interpolated (what
  // fe passes from its coarser mesh), off by about 1e-4 along the other modes.
  const int n = 4001, coarse = 2000;
  Eigen::VectorXd guess = Eigen::VectorXd::Zero(n);
  for (int k = 1; k <= 10; ++k) {
    // Fine unknown i is fine node i + 1: coarse node (i + 1) / 2 when i is odd, else a midpoint.
    auto at_coarse_node = [&](int c) { return std::sin(k * kPi * c / (coarse + 1)); };
    for (int i = 0; i < n; ++i)
      guess[i] += i % 2 == 1 ? at_coarse_node((i + 1) / 2)
                             : 0.5 * (at_coarse_node(i / 2) + at_coarse_node(i / 2 + 1));
  }
  const auto apply = inverse_laplacian(n);
  // Spectra tests convergence only once the subspace is full: with 20 vectors the pseudo-random
  // start needs restarts, the guess fewer (with 30, both converge in the first 29 steps).
  const LanczosResult plain = largest_magnitude_eigenpairs(apply, n, 10, 20, 1e-13, 1000);
  const LanczosResult guessed =
      largest_magnitude_eigenpairs(apply, n, 10, 20, 1e-13, 1000, guess.data());
  ASSERT_TRUE(plain.converged);
  ASSERT_TRUE(guessed.converged);
  EXPECT_LT(guessed.restarts, plain.restarts);
  EXPECT_LT(guessed.operations, plain.operations);
  // The same eigenvalues of this operator as from the pseudo-random start (at n = 4001 the
  // inverse's own rounding, ~1e-11 relative in the lowest mode, exceeds the exact spectrum's test).
  for (int k = 0; k < 10; ++k)
    EXPECT_NEAR(guessed.values[k], plain.values[k], 1e-13 * plain.values[k]) << "mode " << k;
  expect_eigenpairs(apply, guessed, 1e-11);
}

TEST(FeSpectraEigs, ReportsNoConvergenceWhenRestartsRunOut) {
  const int n = 400;
  const LanczosResult result = largest_magnitude_eigenpairs(laplacian(n), n, 4, 8, 1e-13, 2);
  EXPECT_FALSE(result.converged);
  EXPECT_EQ(result.outcome, "NotConverging");
  EXPECT_LT(result.converged_count, 4);
  EXPECT_EQ(result.restarts, 2);
  EXPECT_EQ(result.values.size(), 0);
}

}  // namespace
}  // namespace catena
