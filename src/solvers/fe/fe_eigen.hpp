// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The lowest eigenpairs of one `fe` operator pair, K phi = omega^2 M phi
/// (docs/explanation/methods/fe.md): Spectra's shift-invert Lanczos (fe_spectra_eigs.hpp) on the
/// standard form L^{-1} K L^{-T} (M = L L^T blockwise), applied through a banded LDL^T of K - sigma
/// M; at most two polishing steps of inverse subspace iteration with Rayleigh-Ritz until the
/// normwise backward error is at rounding level; and the mode count proved by Sylvester's law of
/// inertia. Problems of at most 64 unknowns are solved densely.

#include <Eigen/Dense>
#include <functional>
#include <string>
#include <vector>

#include "catena/solvers/solver_summary.hpp"
#include "solvers/fe/fe_banded_ldlt.hpp"
#include "solvers/fe/fe_operators.hpp"

namespace catena::internal {

/// The lowest eigenpairs of K phi = lambda M phi, lambda = omega^2.
struct FeEigenSolution {
  Termination termination = Termination::NumericalFailure;
  std::string message;
  /// Ascending eigenvalues lambda [rad^2/s^2] and M-orthonormal eigenvectors (columns).
  Vector eigenvalues;
  Eigen::MatrixXd eigenvectors;
  /// Per eigenvalue, the bound on its relative rounding error once the caller has replaced it by
  /// the element-wise Rayleigh quotient (fe_rayleigh_quotient.hpp); empty until then.
  Vector rounding;
  /// Negative pivots of LDLT(K - sigma_top M) with sigma_top just above the top eigenvalue.
  int inertia_count = -1;
  double inertia_shift = 0.0;
  /// max_i ||K phi_i - lambda_i M phi_i|| / ||K phi_i|| and max_{i != j} |phi_i^T M phi_j| for the
  /// M-normalised vectors.
  double max_residual = 0.0;
  double max_orthogonality_error = 0.0;
  /// Normwise backward error max_i ||K phi_i - lambda_i M phi_i|| / ((||K||_1 + lambda_i ||M||_1)
  /// ||phi_i||): unlike the relative residual above, whose rounding floor is
  /// eps ||K|| / ||K phi|| ~ eps (EA/T) (2N/pi n)^2 for a stiff chain, this one reaches ~eps.
  double max_backward_error = 0.0;
  long restarts = 0;
  long operations = 0;
  /// Wall time of the factorisation (including the inertia one) and of the iterations [s].
  double factorization_time_s = 0.0;
  double iteration_time_s = 0.0;
  std::vector<std::string> warnings;
};

/// The memory of the eigen solves of one fe run, kept between its levels: the banded factor (the
/// shift-invert one, then reused for the inertia count). Memory a solve touches first costs a page
/// fault per 4 KiB; reused, it costs nothing. (Spectra allocates its Lanczos basis per solve.)
struct FeEigenWorkspace {
  BandedLdlt factor;
  /// Asked before every operator application of the Lanczos iteration; true stops the solve
  /// (NoConvergence, "stopped: ..."). One Lanczos run at hundreds of modes takes minutes and cannot
  /// be split into smaller units of work, so a time limit must reach inside it (issue 32, item 5).
  std::function<bool()> should_stop;
};

/// Lowest `modes` eigenpairs. `modes` must be < number of unknowns (the caller validates).
/// `workspace` (optional) holds the buffers between calls: pass the same one to the solves of one
/// fe run (mesh and penalty levels) so that they allocate the factor once.
/// `guess` (optional, one value per unknown) starts the Lanczos iteration near the wanted
/// eigenvectors (mode_sum_guess); convergence is tested as without it.
FeEigenSolution solve_lowest_modes(const FeMatrices& matrices,
                                   int modes,
                                   double tolerance,
                                   int max_restarts,
                                   FeEigenWorkspace* workspace = nullptr,
                                   const Vector* guess = nullptr);

/// A start vector for the eigen solve of a level with `rows` unknowns from the eigenvectors
/// `modes` of another level of the same chain: their sum, on the same mesh as it is, on a mesh
/// twice as fine interpolated linearly (the coarse nodes are every other fine node; the end
/// nodes are fixed). Empty when the sizes fit neither.
Vector mode_sum_guess(const Eigen::MatrixXd& modes, int dofs_per_node, Eigen::Index rows);

/// Number of eigenvalues of K phi = lambda M phi below `shift` (negative pivots of
/// LDLT(K - shift M)); -1 when the factorisation fails. The second form factors into `factor`
/// (its storage reused).
int count_eigenvalues_below(const FeMatrices& matrices, double shift);
int count_eigenvalues_below(const FeMatrices& matrices, double shift, BandedLdlt& factor);

}  // namespace catena::internal
