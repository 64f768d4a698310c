// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The damped eigenpairs of one `fe` level (docs/explanation/methods/fe.md, "Damping"): the roots
/// of smallest |lambda| of the quadratic eigenproblem (lambda^2 M + lambda C + K) phi = 0.
///
/// Linearised with z = [phi; mu phi], mu = lambda - sigma (sigma a real shift, 0 unless K is
/// singular), A z = mu B z with A = [0 I; -K_s -C_s], B = diag(I, M), K_s = K + sigma C +
/// sigma^2 M, C_s = C + 2 sigma M. The operator A^{-1} B x = [-K_s^{-1} (C_s x1 + M x2); x1] has
/// the eigenvalues nu = 1 / mu: Spectra's GenEigsSolver (implicitly restarted Arnoldi, largest
/// |nu|) on it, applied through the real banded LDL^T of K_s (fe_banded_ldlt.hpp), gives the roots
/// nearest sigma in real arithmetic. Each root kept is then polished by inverse iteration with the
/// complex symmetric factor of Q(lambda) (fe_complex_banded_ldlt.hpp), and its value taken from
/// the Rayleigh functional m lambda^2 + c lambda + k = 0 (m = phi^H M phi, c = phi^H C phi,
/// k = phi^H K phi with k summed element by element as the undamped quotient,
/// fe_rayleigh_quotient.hpp): for a complex root delta = c / 2m exactly, so a small delta comes
/// from positive sums, not from the difference of two Arnoldi values. Roots with Im lambda > 0 are
/// the underdamped modes (ascending Im lambda); real roots are the overdamped ones (ascending
/// delta); the conjugates are dropped.

#include <Eigen/Dense>
#include <complex>
#include <string>
#include <vector>

#include "catena/core/types.hpp"
#include "catena/solvers/solver_summary.hpp"
#include "solvers/fe/fe_chain_statics.hpp"
#include "solvers/fe/fe_operators.hpp"

namespace catena::internal {

struct FeDampedEigenSolution {
  Termination termination = Termination::NumericalFailure;
  std::string message;
  /// Underdamped roots lambda (Im > 0), ascending Im, and their vectors (free unknowns, columns).
  Eigen::VectorXcd roots;
  Eigen::MatrixXcd vectors;
  /// The underdamped roots found beyond the `modes` kept (ascending Im) and their vectors: a
  /// poorly resolved root (a heavily damped one of a seabed dashpot) moves across the cut from
  /// level to level, and the pairing across levels (fe_damped_modes.cpp) looks among these too.
  Eigen::VectorXcd spare_roots;
  Eigen::MatrixXcd spare_vectors;
  /// Overdamped (real) roots, ascending -lambda, and their vectors.
  Eigen::VectorXd real_roots;
  Eigen::MatrixXcd real_vectors;
  /// Largest |lambda - sigma| among the roots Spectra returned: every root nearer sigma was
  /// returned (Spectra's largest-|nu| selection), which the count then checks.
  double radius = 0.0;
  /// A bound on delta = -Re lambda of every non-real root: ||C||_inf / (2 lambda_min(M))
  /// (a complex root has Re lambda = -phi^H C phi / (2 phi^H M phi)).
  double decay_bound = 0.0;
  /// The argument-principle count (fe_argument_count.hpp) and its region, when made.
  int counted = -1;
  std::string count_region;
  /// max over roots of ||Q(lambda) phi|| / ((||K|| + |lambda| ||C|| + |lambda|^2 ||M||) ||phi||).
  double max_backward_error = 0.0;
  long restarts = 0;
  long operations = 0;
  double factorization_time_s = 0.0;
  double iteration_time_s = 0.0;
  std::vector<std::string> warnings;
};

/// The lowest `modes` underdamped roots (by Im lambda) of the level, the overdamped roots Spectra
/// met on the way, and the count proving that no underdamped root with Im lambda between the
/// counted region's bounds was missed: the number of roots asked of Spectra grows (doubling, up
/// to the problem's size) until the count agrees with the roots found. `tolerance` is Spectra's
/// (relative, on nu); `max_restarts` its restarts.
FeDampedEigenSolution solve_damped_modes(const FeChain& chain,
                                         Plane plane,
                                         const FeMatrices& matrices,
                                         const SparseMatrix& damping,
                                         int modes,
                                         double tolerance,
                                         int max_restarts);

/// The Rayleigh functional of `phi` (header): the root of m lambda^2 + c lambda + k = 0 nearest
/// `near`, with k evaluated element by element.
std::complex<double> damped_rayleigh_root(const FeChain& chain,
                                          Plane plane,
                                          const Eigen::VectorXcd& phi,
                                          const SparseMatrix& mass,
                                          const SparseMatrix& damping,
                                          std::complex<double> near);

}  // namespace catena::internal
