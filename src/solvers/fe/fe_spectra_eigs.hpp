// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The largest-magnitude eigenpairs of a symmetric operator by Spectra's implicitly restarted
/// Lanczos (Spectra::SymEigsSolver, Debian libspectra-dev 1.0), for fe's shift-invert operator
/// (docs/explanation/methods/fe.md, "The Lanczos iteration"). Spectra runs the whole iteration:
/// the Lanczos steps with its re-orthogonalisation, the convergence test
/// |beta_m s_mi| < tolerance * max(eps^(2/3), |theta_i|), the implicit restarts. This adapter only
/// builds the start vector from a guess, wraps the operator in Spectra's operator interface and
/// reports Spectra's outcome with its counts; Spectra's types stay out of this header.

#include <Eigen/Core>
#include <functional>
#include <string>

namespace catena::internal {

/// y = A x for a symmetric A of the given size.
using SymmetricOperator = std::function<void(const double* x, double* y)>;

struct LanczosResult {
  /// Spectra's CompInfo::Successful: every wanted pair converged.
  bool converged = false;
  /// Wanted pairs that passed Spectra's test (all of them when `converged`).
  long converged_count = 0;
  /// Spectra's outcome by name ("Successful", "NotConverging", ...), for messages.
  std::string outcome;
  /// When converged, the `wanted` Ritz values of largest magnitude (largest first) and their unit
  /// Ritz vectors; empty otherwise.
  Eigen::VectorXd values;
  Eigen::MatrixXd vectors;
  /// Implicit restarts (0 when the first Lanczos factorisation converged) and operator
  /// applications, as Spectra counts them.
  long restarts = 0;
  long operations = 0;
};

/// The `wanted` eigenpairs of largest magnitude of the symmetric operator `apply` of size `rows`
/// (1 <= wanted < rows), with a Krylov subspace of `subspace` vectors (clamped to
/// [wanted + 1, rows]), at most `max_restarts` restarts. Spectra starts from A r: r is its own
/// fixed pseudo-random vector (Spectra::SimpleRandom, seed 0), so runs are reproducible; a `guess`
/// (length `rows`, e.g. the sum of approximations to the wanted eigenvectors) replaces r but for
/// that pseudo-random part at relative size 1e-6, which keeps every direction in the Krylov space.
/// Spectra throws std::invalid_argument only for arguments outside these ranges.
LanczosResult largest_magnitude_eigenpairs(const SymmetricOperator& apply,
                                           Eigen::Index rows,
                                           int wanted,
                                           int subspace,
                                           double tolerance,
                                           int max_restarts,
                                           const double* guess = nullptr);

}  // namespace catena::internal
