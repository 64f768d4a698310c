// SPDX-License-Identifier: MIT
// The fe solver's banded LDL^T without pivoting: solves against a dense solve, the Sylvester
// inertia count against the eigenvalues from Eigen's SelfAdjointEigenSolver, storage of one or
// both triangles, and the pivot ratio that tells a shift sitting on an eigenvalue.
#include "solvers/fe/fe_banded_ldlt.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <random>

#include "catena/core/types.hpp"

namespace catena::internal {
namespace {

using Dense = Eigen::MatrixXd;
using Sparse = Eigen::SparseMatrix<double>;

// A random symmetric matrix of half bandwidth `band`, made positive definite by a dominant diagonal
// (fixed seed: the same matrix every run).
Dense random_banded_spd(int n, int band, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> entry(-1.0, 1.0);
  Dense A = Dense::Zero(n, n);
  for (int i = 0; i < n; ++i) {
    for (int j = std::max(0, i - band); j < i; ++j) A(i, j) = A(j, i) = entry(rng);
  }
  for (int i = 0; i < n; ++i) A(i, i) = 2.0 * band + 1.0 + entry(rng);
  return A;
}

Sparse to_sparse(const Dense& A) { return A.sparseView(); }

// Only the lower triangle, as the fe assembly may store it.
Sparse lower_only(const Dense& A) { return Dense(A.triangularView<Eigen::Lower>()).sparseView(); }

int negative_eigenvalues(const Dense& A) {
  const Eigen::SelfAdjointEigenSolver<Dense> eigen(A, Eigen::EigenvaluesOnly);
  return static_cast<int>((eigen.eigenvalues().array() < 0.0).count());
}

// A shift halfway between two neighbouring eigenvalues of A: A - sigma I is indefinite with exactly
// `below` negative eigenvalues and no eigenvalue near zero.
double shift_between(const Dense& A, int below) {
  const Eigen::SelfAdjointEigenSolver<Dense> eigen(A, Eigen::EigenvaluesOnly);
  return 0.5 * (eigen.eigenvalues()[below - 1] + eigen.eigenvalues()[below]);
}

double relative_residual(const Dense& A, const Dense& x, const Dense& b) {
  return (A * x - b).norm() / b.norm();
}

TEST(BandedLdlt, SolvesASpdBandedSystemLikeADenseSolve) {
  const Dense A = random_banded_spd(60, 3, 1);
  BandedLdlt ldlt;
  ASSERT_TRUE(ldlt.factorize(to_sparse(A)));
  EXPECT_EQ(ldlt.rows(), 60);
  EXPECT_EQ(ldlt.negative_pivots(), 0);
  EXPECT_GT(ldlt.pivot_ratio(), 0.0);
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> entry(-1.0, 1.0);
  Dense b(60, 3);
  for (Index i = 0; i < b.size(); ++i) b.data()[i] = entry(rng);
  Dense x = b;
  ldlt.solve_in_place(x);  // several right-hand sides at once
  const Dense dense = A.ldlt().solve(b);
  EXPECT_LT((x - dense).norm() / dense.norm(), 1e-13);
  EXPECT_LT(relative_residual(A, x, b), 1e-14);
  // The pointer form solves one column the same way.
  Eigen::VectorXd column = b.col(1);
  ldlt.solve_in_place(column.data());
  EXPECT_TRUE(column == x.col(1));
}

TEST(BandedLdlt, SolvesAnIndefiniteSystemAndCountsItsNegativeEigenvalues) {
  // K - sigma M with sigma between eigenvalues, as in the fe solver's shift-invert: no pivoting
  // is needed when no leading minor is singular, and the negative pivots are the eigenvalues
  // below sigma (Sylvester's law of inertia).
  const Dense A = random_banded_spd(50, 3, 3);
  for (int below : {1, 7, 25, 49}) {
    const Dense shifted = A - shift_between(A, below) * Dense::Identity(50, 50);
    BandedLdlt ldlt;
    ASSERT_TRUE(ldlt.factorize(to_sparse(shifted))) << below;
    EXPECT_EQ(ldlt.negative_pivots(), below);
    EXPECT_EQ(ldlt.negative_pivots(), negative_eigenvalues(shifted));
    Dense x = Dense::Ones(50, 1);
    const Dense b = x;
    ldlt.solve_in_place(x);
    EXPECT_LT((x - shifted.fullPivLu().solve(b)).norm() / x.norm(), 1e-10) << below;
    EXPECT_LT(relative_residual(shifted, x, b), 1e-11) << below;
  }
}

TEST(BandedLdlt, InertiaOfTridiagonalMatricesMatchesTheEigenvalues) {
  // Half bandwidth 1, the fe out-of-plane case: the 1-D Laplacian has eigenvalues
  // 2 - 2 cos(k pi / (n + 1)), k = 1..n. (The shifts avoid the eigenvalues of the leading minors,
  // where a pivot is zero: see ZeroOrNonFinitePivotFails.)
  const int n = 30;
  Dense laplacian = Dense::Zero(n, n);
  for (int i = 0; i < n; ++i) {
    laplacian(i, i) = 2.0;
    if (i > 0) laplacian(i, i - 1) = laplacian(i - 1, i) = -1.0;
  }
  for (double sigma : {0.5, 1.3, 2.5, 3.9}) {
    const Dense shifted = laplacian - sigma * Dense::Identity(n, n);
    BandedLdlt ldlt;
    ASSERT_TRUE(ldlt.factorize(to_sparse(shifted))) << sigma;
    int expected = 0;
    for (int k = 1; k <= n; ++k) expected += 2.0 - 2.0 * std::cos(k * kPi / (n + 1)) < sigma;
    EXPECT_EQ(ldlt.negative_pivots(), expected) << sigma;
    EXPECT_EQ(ldlt.negative_pivots(), negative_eigenvalues(shifted)) << sigma;
  }
}

TEST(BandedLdlt, ReadsOnlyTheLowerTriangle) {
  const Dense A = random_banded_spd(40, 3, 4);
  BandedLdlt both, lower;
  ASSERT_TRUE(both.factorize(to_sparse(A)));
  ASSERT_TRUE(lower.factorize(lower_only(A)));
  EXPECT_EQ(both.pivots(), lower.pivots());
  // Garbage above the diagonal (within the band) changes nothing.
  Dense garbage = A;
  for (int i = 0; i + 2 < 40; ++i) garbage(i, i + 2) = 100.0;
  BandedLdlt ignoring;
  ASSERT_TRUE(ignoring.factorize(to_sparse(garbage)));
  EXPECT_EQ(ignoring.pivots(), both.pivots());
}

TEST(BandedLdlt, DiagonalMatrixHasItsDiagonalAsPivots) {
  const Eigen::VectorXd d = (Eigen::VectorXd(4) << 2.0, -3.0, 0.5, -1.0).finished();
  BandedLdlt ldlt;
  ASSERT_TRUE(ldlt.factorize(to_sparse(Dense(d.asDiagonal()))));
  EXPECT_EQ(ldlt.pivots(), d);
  EXPECT_EQ(ldlt.negative_pivots(), 2);
  EXPECT_DOUBLE_EQ(ldlt.pivot_ratio(), 0.5 / 3.0);
  Eigen::VectorXd x = Eigen::VectorXd::Ones(4);
  ldlt.solve_in_place(x.data());
  EXPECT_EQ(x, (Eigen::VectorXd(4) << 0.5, -1.0 / 3.0, 2.0, -1.0).finished());
}

TEST(BandedLdlt, SingularMatrixFailsAndANearlySingularOneHasATinyPivotRatio) {
  // The free-free 1-D Laplacian (path graph) is singular: its last pivot is exactly 0.
  const int n = 10;
  Dense free = Dense::Zero(n, n);
  for (int i = 0; i + 1 < n; ++i) {
    free(i, i) += 1.0;
    free(i + 1, i + 1) += 1.0;
    free(i, i + 1) = free(i + 1, i) = -1.0;
  }
  BandedLdlt ldlt;
  EXPECT_FALSE(ldlt.factorize(to_sparse(free)));
  // Shifted by delta off its zero eigenvalue, the last pivot is about n delta (the determinant is
  // delta times the product n of the other eigenvalues, while the other pivots stay near 1).
  const double delta = 1e-12;
  ASSERT_TRUE(ldlt.factorize(to_sparse(free + delta * Dense::Identity(n, n))));
  EXPECT_EQ(ldlt.negative_pivots(), 0);
  EXPECT_LT(ldlt.pivot_ratio(), 1e-10);
  EXPECT_GT(ldlt.pivot_ratio(), 1e-13);
  ASSERT_TRUE(ldlt.factorize(to_sparse(free - delta * Dense::Identity(n, n))));
  EXPECT_EQ(ldlt.negative_pivots(), 1);  // the shift passed the zero eigenvalue
  EXPECT_LT(ldlt.pivot_ratio(), 1e-10);
  // A well-conditioned matrix is far from that.
  ASSERT_TRUE(ldlt.factorize(to_sparse(random_banded_spd(n, 3, 5))));
  EXPECT_GT(ldlt.pivot_ratio(), 0.1);
}

TEST(BandedLdlt, ZeroOrNonFinitePivotFails) {
  // Without pivoting, a zero leading entry stops the factorisation even though the matrix
  // [[0, 1], [1, 0]] is regular: the callers then move the shift.
  BandedLdlt ldlt;
  EXPECT_FALSE(ldlt.factorize(to_sparse((Dense(2, 2) << 0.0, 1.0, 1.0, 0.0).finished())));
  // The same inside a matrix: tridiag(-1, 1, -1) of order 30 is regular (1 is not an eigenvalue of
  // tridiag(-1, 2, -1)), but its leading 2 x 2 minor [[1, -1], [-1, 1]] is singular.
  Dense shifted = Dense::Zero(30, 30);
  for (int i = 0; i < 30; ++i) {
    shifted(i, i) = 1.0;
    if (i > 0) shifted(i, i - 1) = shifted(i - 1, i) = -1.0;
  }
  ASSERT_EQ(shifted.fullPivLu().rank(), 30);
  EXPECT_FALSE(ldlt.factorize(to_sparse(shifted)));
  EXPECT_FALSE(ldlt.factorize(to_sparse((Dense(2, 2) << 1.0, 0.0, 0.0, std::nan("")).finished())));
  EXPECT_FALSE(
      ldlt.factorize(to_sparse((Dense(2, 2) << 1.0e-300, 1.0e200, 1.0e200, 1.0).finished())));
}

}  // namespace
}  // namespace catena::internal
