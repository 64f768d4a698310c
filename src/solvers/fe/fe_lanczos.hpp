// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Thick-restart Lanczos for the largest-magnitude eigenpairs of a symmetric operator, written for
/// fe's shift-invert operator (docs/explanation/methods/fe.md, "The Lanczos iteration"). Each step
/// applies the operator once and orthogonalises the new vector against the whole basis by classical
/// Gram-Schmidt, a second time only when the first pass cancelled more than 1 - 1/sqrt(2) of its
/// norm (the test of Daniel, Gragg, Kaufman and Stewart, 1976: docs/reference/references.md). After
/// m steps the tridiagonal (arrowhead after a restart) projection is diagonalised; Ritz pairs whose
/// residual |beta_m s_mi| is below tolerance * max(eps^(2/3), |theta_i|) are converged; otherwise
/// the best Ritz vectors are kept and the iteration restarts from them (Wu and Simon, 2000:
/// docs/reference/references.md). All storage lives in a LanczosWorkspace that callers keep across
/// solves of the same or smaller size, so a restart or a second solve allocates nothing.

#include <Eigen/Core>
#include <functional>
#include <memory>
#include <vector>

namespace catena::internal {

/// Buffers of one Lanczos run, kept between runs: the n x m basis, the projected matrix and
/// work vectors. Growing reallocates, neither copying nor zeroing the basis (every run writes
/// each column before reading it); a run of the same or smaller size reuses the memory, so a
/// caller that reserves for its largest run first touches the basis pages once.
class LanczosWorkspace {
 public:
  /// Makes room for a basis of `subspace` vectors of length `rows`.
  void reserve(Eigen::Index rows, int subspace);
  Eigen::Map<Eigen::MatrixXd> basis() { return {basis_.get(), rows_, subspace_}; }
  Eigen::Map<Eigen::VectorXd> residual() { return {residual_.data(), rows_}; }
  Eigen::Map<Eigen::VectorXd> coefficients() { return {coefficients_.data(), subspace_}; }
  Eigen::Map<Eigen::VectorXd> correction() { return {correction_.data(), subspace_}; }
  Eigen::MatrixXd& projection() { return projection_; }
  Eigen::MatrixXd& block() { return block_; }

 private:
  Eigen::Index rows_ = 0;
  int subspace_ = 0;
  std::unique_ptr<double[]> basis_;
  std::size_t basis_capacity_ = 0;
  std::vector<double> residual_, coefficients_, correction_;
  Eigen::MatrixXd projection_, block_;
};

/// y = A x for a symmetric A of the given size.
using SymmetricOperator = std::function<void(const double* x, double* y)>;

struct LanczosResult {
  bool converged = false;
  /// The `wanted` Ritz values of largest magnitude (largest first) and their unit Ritz vectors.
  Eigen::VectorXd values;
  Eigen::MatrixXd vectors;
  long restarts = 0;
  long operations = 0;
};

/// The `wanted` eigenpairs of largest magnitude of the symmetric operator `apply` of size `rows`,
/// with a Krylov subspace of `subspace` vectors (clamped to [wanted + 1, rows]; wanted <= rows).
/// The start vector is A r for a fixed pseudo-random r, so runs are reproducible; a `guess`
/// (length `rows`, e.g. the sum of approximations to the wanted eigenvectors) replaces r but for a
/// pseudo-random part of relative size 1e-6, which keeps every direction in the Krylov space.
LanczosResult largest_magnitude_eigenpairs(const SymmetricOperator& apply,
                                           Eigen::Index rows,
                                           int wanted,
                                           int subspace,
                                           double tolerance,
                                           int max_restarts,
                                           LanczosWorkspace& workspace,
                                           const double* guess = nullptr);

}  // namespace catena::internal
