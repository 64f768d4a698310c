// SPDX-License-Identifier: MIT
// Spectra's implicitly restarted Lanczos on an operator given as a function: see
// fe_spectra_eigs.hpp and docs/explanation/methods/fe.md.
#include "solvers/fe/fe_spectra_eigs.hpp"

#include <Spectra/SymEigsSolver.h>
#include <Spectra/Util/SimpleRandom.h>

#include <algorithm>
#include <cmath>

namespace catena::internal {
namespace {

// Spectra's custom-operator interface (Scalar, rows(), cols(), perform_op) around the function.
class SpectraOperator {
 public:
  using Scalar = double;
  SpectraOperator(const SymmetricOperator& apply, Eigen::Index rows) : apply_(apply), rows_(rows) {}
  Eigen::Index rows() const { return rows_; }
  Eigen::Index cols() const { return rows_; }
  void perform_op(const double* x_in, double* y_out) const { apply_(x_in, y_out); }

 private:
  const SymmetricOperator& apply_;
  Eigen::Index rows_;
};

// Relative size of the pseudo-random part mixed into a guessed start vector.
constexpr double kGuessPerturbation = 1e-6;

// Spectra's start vector r (init() would draw the same), or the guess plus a part of r 1e-6 its
// size. Spectra's init applies the operator to it once before the first step: for a shift-invert
// operator this damps the components along eigenvalues far from the shift (a stiff chain's axial
// modes), which Ritz vectors would otherwise carry at the size of the convergence tolerance.
Eigen::VectorXd start_vector(Eigen::Index rows, const double* guess) {
  Spectra::SimpleRandom<double> random(0);
  Eigen::VectorXd start = random.random_vec(rows);
  if (guess) {
    const Eigen::Map<const Eigen::VectorXd> g(guess, rows);
    const double g_norm = g.norm(), r_norm = start.norm();
    if (g_norm > 0.0 && std::isfinite(g_norm))
      start = g / g_norm + (kGuessPerturbation / r_norm) * start;
  }
  return start;
}

const char* outcome_name(Spectra::CompInfo info) {
  switch (info) {
    case Spectra::CompInfo::Successful:
      return "Successful";
    case Spectra::CompInfo::NotComputed:
      return "NotComputed";
    case Spectra::CompInfo::NotConverging:
      return "NotConverging";
    case Spectra::CompInfo::NumericalIssue:
      return "NumericalIssue";
  }
  return "unknown";
}

}  // namespace

LanczosResult largest_magnitude_eigenpairs(const SymmetricOperator& apply,
                                           Eigen::Index rows,
                                           int wanted,
                                           int subspace,
                                           double tolerance,
                                           int max_restarts,
                                           const double* guess) {
  const Eigen::Index m = std::min<Eigen::Index>(rows, std::max(subspace, wanted + 1));
  SpectraOperator op(apply, rows);
  Spectra::SymEigsSolver<SpectraOperator> eigs(op, wanted, m);
  const Eigen::VectorXd start = start_vector(rows, guess);
  eigs.init(start.data());
  // Largest |theta| wanted; returned largest |theta| first.
  LanczosResult result;
  result.converged_count = static_cast<long>(eigs.compute(
      Spectra::SortRule::LargestMagn, max_restarts, tolerance, Spectra::SortRule::LargestMagn));
  result.converged = eigs.info() == Spectra::CompInfo::Successful;
  result.outcome = outcome_name(eigs.info());
  // Spectra counts the first factorisation as an iteration; each further one follows a restart.
  result.restarts = static_cast<long>(eigs.num_iterations()) - 1;
  result.operations = static_cast<long>(eigs.num_operations());
  if (result.converged) {
    result.values = eigs.eigenvalues();
    result.vectors = eigs.eigenvectors();
  }
  return result;
}

}  // namespace catena::internal
