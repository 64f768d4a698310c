// SPDX-License-Identifier: MIT
// The lowest eigenpairs of one fe operator pair: see fe_eigen.hpp and
// docs/explanation/methods/fe.md.
#include "solvers/fe/fe_eigen.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "solvers/fe/fe_banded_ldlt.hpp"
#include "solvers/fe/fe_spectra_eigs.hpp"

namespace catena::internal {
namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Thrown from the operator when FeEigenWorkspace::should_stop says so: it unwinds Spectra's
// iteration (which has no stop hook of its own) back to solve_iteratively.
struct StopRequested {};

// K - sigma M is singular (or nearly) at the shift: the shift is moved (solve_iteratively). A type
// of its own, so that it is not confused with Spectra's std::invalid_argument for bad arguments.
class SingularShift : public std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

// Operator y = (K - sigma M)^{-1} x through a banded LDLT of K - sigma M, factored
// without forming the shifted matrix (BandedLdlt::factorize(K, M, sigma)).
class ShiftInvertOperator {
 public:
  using Scalar = double;
  ShiftInvertOperator(const SparseMatrix& stiffness, const SparseMatrix& mass, BandedLdlt& ldlt)
      : stiffness_(stiffness), mass_(mass), ldlt_(ldlt) {}
  Eigen::Index rows() const { return stiffness_.rows(); }
  Eigen::Index cols() const { return stiffness_.cols(); }
  void set_shift(double sigma) {
    const auto start = Clock::now();
    bool ok = ldlt_.factorize(stiffness_, mass_, sigma);
    factorization_time_s += seconds_since(start);
    ok = ok && ldlt_.pivot_ratio() > 1e-14;
    if (!ok) throw SingularShift(fmt::format("K - sigma M is singular at sigma = {:.6e}", sigma));
  }
  /// Solves (K - sigma M) Y = X in place for a block of right-hand sides.
  void solve_in_place(Eigen::MatrixXd& X) const { ldlt_.solve_in_place(X); }
  void solve_in_place(double* x) const { ldlt_.solve_in_place(x); }
  void perform_op(const double* x_in, double* y_out) const {
    std::copy(x_in, x_in + rows(), y_out);
    ldlt_.solve_in_place(y_out);
  }
  double factorization_time_s = 0.0;

 private:
  const SparseMatrix& stiffness_;
  const SparseMatrix& mass_;
  BandedLdlt& ldlt_;
};

// The block-diagonal Cholesky factor L of the lumped mass, M = L L^T: per node l11, l21, l22 of
// a 2x2 block in plane (l21 = l22 = 0 and l11 alone out of plane), and the products with L, L^T
// and L^{-T} as plain loops over the nodes. Each product does the operations of the
// compressed-column sparse product it replaces, in the same order, so the results are the same
// to the last bit (up to the multiply-adds the compiler fuses when it targets FMA,
// cmake/instruction_set.cmake); it only saves the index indirection and the sparse matrices'
// memory.
class MassFactor {
 public:
  MassFactor(const SparseMatrix& mass, int dofs_per_node)
      : dofs_(dofs_per_node),
        nodes_(mass.rows() / dofs_per_node),
        l11_(nodes_),
        l21_(nodes_),
        l22_(nodes_) {
    for (Eigen::Index node = 0; node < nodes_; ++node) {
      const Eigen::Index i = node * dofs_;
      l11_[node] = std::sqrt(mass.coeff(i, i));
      if (dofs_ == 1) continue;
      l21_[node] = mass.coeff(i + 1, i) / l11_[node];
      l22_[node] = std::sqrt(mass.coeff(i + 1, i + 1) - l21_[node] * l21_[node]);
    }
  }
  /// y = L x.
  void lower(const double* x, double* y) const {
    if (dofs_ == 1) {
      for (Eigen::Index i = 0; i < nodes_; ++i) y[i] = l11_[i] * x[i];
      return;
    }
    for (Eigen::Index node = 0, i = 0; node < nodes_; ++node, i += 2) {
      y[i] = l11_[node] * x[i];
      y[i + 1] = l21_[node] * x[i] + l22_[node] * x[i + 1];
    }
  }
  /// y = L^T x.
  void lower_transpose(const double* x, double* y) const { lower_transpose_nodes(x, y, 0, nodes_); }
  /// The rows of nodes [first, first + count) of L^T x, into y[0 .. count * dofs).
  void lower_transpose_nodes(const double* x,
                             double* y,
                             Eigen::Index first,
                             Eigen::Index count) const {
    const Eigen::Index offset = first * dofs_;
    if (dofs_ == 1) {
      for (Eigen::Index node = first; node < first + count; ++node)
        y[node - offset] = l11_[node] * x[node];
      return;
    }
    for (Eigen::Index node = first, i = offset; node < first + count; ++node, i += 2) {
      y[i - offset] = l11_[node] * x[i] + l21_[node] * x[i + 1];
      y[i + 1 - offset] = l22_[node] * x[i + 1];
    }
  }
  /// X^T M X = (L^T X)^T (L^T X), a block of node rows at a time: L is block-diagonal per node, so
  /// each block of L^T X needs only the same rows of X, and the whole product is one pass over X
  /// (k products M x_i and X^T (M x_i) read X k times). A block of 128 nodes (20 KB for 10 modes
  /// in plane) fits in memory the solve's heap already has; 1024 nodes took 36 fresh pages of a
  /// fresh process's first solve at N = 1000, about 0.08 ms of its 2.85.
  Eigen::MatrixXd gram(const Eigen::MatrixXd& X) const {
    constexpr Eigen::Index kBlockNodes = 128;
    Eigen::MatrixXd gram = Eigen::MatrixXd::Zero(X.cols(), X.cols());
    Eigen::MatrixXd block(std::min(kBlockNodes, nodes_) * dofs_, X.cols());
    for (Eigen::Index first = 0; first < nodes_; first += kBlockNodes) {
      const Eigen::Index count = std::min(kBlockNodes, nodes_ - first), rows = count * dofs_;
      for (Eigen::Index c = 0; c < X.cols(); ++c)
        lower_transpose_nodes(X.col(c).data(), block.col(c).data(), first, count);
      gram.noalias() += block.topRows(rows).transpose() * block.topRows(rows);
    }
    return gram;
  }
  /// X = L^{-T} X in place, column by column; L^{-1} = [1/l11, 0; -l21/(l11 l22), 1/l22] per
  /// node.
  void inverse_transpose_in_place(Eigen::MatrixXd& X) const {
    for (Eigen::Index c = 0; c < X.cols(); ++c) {
      double* x = X.col(c).data();
      for (Eigen::Index node = 0, i = 0; node < nodes_; ++node, i += dofs_) {
        const double second = dofs_ == 1 ? 0.0 : x[i + 1];
        x[i] = (1.0 / l11_[node]) * x[i];
        if (dofs_ == 1) continue;
        x[i] += (-l21_[node] / (l11_[node] * l22_[node])) * second;
        x[i + 1] = (1.0 / l22_[node]) * second;
      }
    }
  }

 private:
  int dofs_;
  Eigen::Index nodes_;
  Vector l11_, l21_, l22_;
};

// The standard-form operator for the Lanczos iteration: with A = L^{-1} K L^{-T},
// (A - sigma I)^{-1} x = L^T (K - sigma M)^{-1} L x. Spectra's standard symmetric solver on it
// avoids the M-inner products of its generalized one, SymGEigsShiftSolver (which cost more than
// the banded solves here).
class StandardFormOperator {
 public:
  using Scalar = double;
  StandardFormOperator(ShiftInvertOperator& inner, const MassFactor& factor)
      : inner_(inner), factor_(factor), solved_(inner.rows()) {}
  Eigen::Index rows() const { return inner_.rows(); }
  Eigen::Index cols() const { return inner_.cols(); }
  void set_shift(double sigma) { inner_.set_shift(sigma); }
  void perform_op(const double* x_in, double* y_out) const {
    factor_.lower(x_in, solved_.data());
    inner_.solve_in_place(solved_.data());
    factor_.lower_transpose(solved_.data(), y_out);
  }

 private:
  ShiftInvertOperator& inner_;
  const MassFactor& factor_;
  mutable Vector solved_;
};

// ||.||_1 of a symmetric matrix: the largest absolute column sum.
double norm1(const SparseMatrix& A) {
  double best = 0.0;
  for (Eigen::Index c = 0; c < A.outerSize(); ++c) {
    double sum = 0.0;
    for (SparseMatrix::InnerIterator it(A, c); it; ++it) sum += std::abs(it.value());
    best = std::max(best, sum);
  }
  return best;
}

// M-normalises each eigenvector (the Ritz vectors are M-orthonormal already; this removes rounding
// drift) and measures residual and backward error. K and M are symmetric, so a block of their
// columns, transposed, is the same block of rows: K phi and M phi are formed a block of rows at a
// time for all vectors at once (K and M read once, not once per vector; a block x k temporary,
// not n x k), and their norms accumulated, scaled by the M-norm at the end.
void normalise_and_measure_residuals(const FeMatrices& matrices, FeEigenSolution& out) {
  constexpr Eigen::Index kRows = 512;
  Eigen::MatrixXd& phi = out.eigenvectors;
  const Eigen::Index k = phi.cols();
  // Per vector: phi^T M phi, |K phi|^2, |K phi - lambda M phi|^2 and |phi|^2.
  Eigen::ArrayXd m_norm2 = Eigen::ArrayXd::Zero(k), k_phi2 = m_norm2, residual2 = m_norm2,
                 phi2 = m_norm2;
  Eigen::MatrixXd K_phi, M_phi;
  for (Eigen::Index r = 0; r < phi.rows(); r += kRows) {
    const Eigen::Index rows = std::min(kRows, phi.rows() - r);
    K_phi.noalias() = matrices.stiffness.middleCols(r, rows).transpose() * phi;
    M_phi.noalias() = matrices.mass.middleCols(r, rows).transpose() * phi;
    for (Eigen::Index i = 0; i < k; ++i) {
      const auto x = phi.col(i).segment(r, rows);
      m_norm2[i] += x.dot(M_phi.col(i));
      k_phi2[i] += K_phi.col(i).squaredNorm();
      residual2[i] += (K_phi.col(i) - out.eigenvalues[i] * M_phi.col(i)).squaredNorm();
      phi2[i] += x.squaredNorm();
    }
  }
  out.max_residual = 0.0;
  out.max_backward_error = 0.0;
  const double k_norm = norm1(matrices.stiffness), m_norm = norm1(matrices.mass);
  for (Eigen::Index i = 0; i < k; ++i) {
    const double norm = std::sqrt(m_norm2[i]);
    phi.col(i) /= norm;
    const double denominator = std::sqrt(k_phi2[i]) / norm, r = std::sqrt(residual2[i]) / norm;
    out.max_residual = std::max(out.max_residual, denominator > 0.0 ? r / denominator : r);
    out.max_backward_error = std::max(
        out.max_backward_error,
        r / ((k_norm + std::abs(out.eigenvalues[i]) * m_norm) * (std::sqrt(phi2[i]) / norm)));
  }
}

// max_{i != j} |phi_i^T M phi_j| and the diagonal's distance from 1, once, for the final vectors.
void measure_orthogonality(const MassFactor& factor, FeEigenSolution& out) {
  const Eigen::MatrixXd gram = factor.gram(out.eigenvectors);
  out.max_orthogonality_error =
      (gram - Eigen::MatrixXd::Identity(gram.rows(), gram.cols())).cwiseAbs().maxCoeff();
}

// Extra Lanczos vectors beyond the modes asked, from a pseudo-random start and from a guess.
// Spectra tests convergence only once its subspace is full, and a subspace one vector short of
// convergence costs a whole implicit restart: on the mooring line (10 in-plane modes, N = 1000
// and 1e5) the first factorisation converges with 22 extra vectors from a pseudo-random start
// (with 20: 42 operator applications and a restart instead of 33) and with 16 from the previous
// mesh's modes (31 applications with the former 20; 14 extra needed a restart at N = 1000).
constexpr int kExtraVectorsCold = 22;
constexpr int kExtraVectorsWarm = 16;

// The Lanczos subspace for `modes` modes of an operator with `unknowns` unknowns, started from a
// guess (`warm`) or not.
int lanczos_subspace(Eigen::Index unknowns, int modes, bool warm) {
  const int extra = warm ? kExtraVectorsWarm : kExtraVectorsCold;
  return static_cast<int>(std::min<Eigen::Index>(unknowns, std::max(2 * modes + 1, modes + extra)));
}

// Small problems, and those asking for nearly every mode, are solved densely.
bool solved_densely(Eigen::Index unknowns, int modes) {
  return unknowns <= 64 || lanczos_subspace(unknowns, modes, true) <= modes;
}

// Normwise backward error at which the eigenpairs are as good as double precision allows.
constexpr double kBackwardErrorGoal = 1e-14;

// M-normalises the vectors and measures residual, backward error and M-orthogonality.
void normalise_and_check(const FeMatrices& matrices, FeEigenSolution& out) {
  normalise_and_measure_residuals(matrices, out);
  measure_orthogonality(MassFactor(matrices.mass, matrices.dofs_per_node), out);
}

// Subspace (inverse) iteration with Rayleigh-Ritz on the converged Ritz vectors, with the
// factorisation the Lanczos iteration already used. Lanczos leaves components along the stiff axial
// directions of size ~ tolerance; K amplifies them by EA/l0 into the residual. One
// inverse-iteration step damps them by lambda/lambda_axial (<= 1e-4 here), so one or two steps
// reach the rounding floor.
void refine(const FeMatrices& matrices, const ShiftInvertOperator& op, FeEigenSolution& out) {
  {
    Eigen::MatrixXd Y = matrices.mass * out.eigenvectors;
    op.solve_in_place(Y);
    const Eigen::MatrixXd KY = matrices.stiffness * Y;
    const Eigen::MatrixXd MY = matrices.mass * Y;
    Eigen::MatrixXd Kr = Y.transpose() * KY, Mr = Y.transpose() * MY;
    Kr = 0.5 * (Kr + Kr.transpose()).eval();
    Mr = 0.5 * (Mr + Mr.transpose()).eval();
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> ritz(Kr, Mr);
    if (ritz.info() != Eigen::Success) return;
    out.eigenvalues = ritz.eigenvalues();
    out.eigenvectors = Y * ritz.eigenvectors();
    out.operations += Y.cols();
  }
}

// Small problems: a dense generalized solve is exact and cheaper than a Lanczos iteration.
void solve_dense(const FeMatrices& matrices, int modes, FeEigenSolution& out) {
  const auto start = Clock::now();
  const Eigen::MatrixXd K(matrices.stiffness), M(matrices.mass);
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> dense(K, M);
  out.iteration_time_s = seconds_since(start);
  if (dense.info() != Eigen::Success) {
    out.termination = Termination::NumericalFailure;
    out.message = "dense generalized eigensolver failed";
    return;
  }
  out.eigenvalues = dense.eigenvalues().head(modes);
  out.eigenvectors = dense.eigenvectors().leftCols(modes);
  out.termination = Termination::Converged;
}

// lambda = sigma + 1 / theta, ascending, with the vectors mapped back by L^{-T} in place (the
// Lanczos vectors become the eigenvectors: no second n x k matrix).
void take_ritz_pairs(LanczosResult&& lanczos,
                     double sigma,
                     const MassFactor& factor,
                     FeEigenSolution& out) {
  const auto count = lanczos.values.size();
  std::vector<Eigen::Index> order(static_cast<std::size_t>(count));
  for (Eigen::Index i = 0; i < count; ++i) order[static_cast<std::size_t>(i)] = i;
  auto lambda = [&](Eigen::Index i) { return sigma + 1.0 / lanczos.values[i]; };
  std::stable_sort(order.begin(), order.end(),
                   [&](auto a, auto b) { return lambda(a) < lambda(b); });
  out.eigenvalues.resize(count);
  for (Eigen::Index i = 0; i < count; ++i)
    out.eigenvalues[i] = lambda(order[static_cast<std::size_t>(i)]);
  factor.inverse_transpose_in_place(lanczos.vectors);
  out.eigenvectors = std::move(lanczos.vectors);
  // Largest theta first is already ascending lambda unless the shift moved into the spectrum.
  if (!std::is_sorted(order.begin(), order.end())) {
    const Eigen::MatrixXd unsorted = out.eigenvectors;
    for (Eigen::Index i = 0; i < count; ++i)
      out.eigenvectors.col(i) = unsorted.col(order[static_cast<std::size_t>(i)]);
  }
  out.termination = Termination::Converged;
}

// Polishes converged Ritz pairs: one or two inverse-iteration steps, only until the normwise
// backward error is at rounding level; the M-orthogonality of the final vectors is measured once.
void polish(const FeMatrices& matrices,
            const ShiftInvertOperator& op,
            const MassFactor& factor,
            FeEigenSolution& out) {
  for (int step = 0; step < 3; ++step) {
    normalise_and_measure_residuals(matrices, out);
    if (out.max_backward_error <= kBackwardErrorGoal || step == 2) break;
    refine(matrices, op, out);
  }
  measure_orthogonality(factor, out);
}

// A guess in the standard form's coordinates, y = L^T x (empty without a usable guess).
Vector standard_form_guess(const Vector* guess, const MassFactor& factor, Eigen::Index rows) {
  Vector y;
  if (!guess || guess->size() != rows) return y;
  y.resize(rows);
  factor.lower_transpose(guess->data(), y.data());
  return y;
}

// Spectra's Lanczos (fe_spectra_eigs.hpp) on the standard form, polished. The operator's Ritz
// values theta = 1 / (lambda - sigma) of largest magnitude are the lambda nearest sigma. Shift 0
// targets the lowest modes (K is positive definite for a taut chain); if it is singular (a chain
// with a zero-stiffness mode), the shift is moved below the bottom of the spectrum, and the move
// reported. Spectra's failure to converge (CompInfo::NotConverging) is NoConvergence, with its
// counts; its std::invalid_argument (arguments out of range, which the callers rule out) is a
// NumericalFailure.
void solve_iteratively(const FeMatrices& matrices,
                       int modes,
                       int subspace,
                       double tolerance,
                       int max_restarts,
                       FeEigenWorkspace& workspace,
                       const Vector* guess,
                       FeEigenSolution& out) {
  ShiftInvertOperator op(matrices.stiffness, matrices.mass, workspace.factor);
  const MassFactor factor(matrices.mass, matrices.dofs_per_node);
  StandardFormOperator standard(op, factor);
  const SymmetricOperator apply = [&standard, &workspace](const double* x, double* y) {
    if (workspace.should_stop && workspace.should_stop()) throw StopRequested();
    standard.perform_op(x, y);
  };
  const Vector start_guess = standard_form_guess(guess, factor, standard.rows());
  double sigma = 0.0;
  for (int attempt = 0; attempt < 4; ++attempt) {
    try {
      standard.set_shift(sigma);
      const auto start = Clock::now();
      LanczosResult lanczos = largest_magnitude_eigenpairs(
          apply, standard.rows(), modes, subspace, tolerance, max_restarts,
          start_guess.size() > 0 ? start_guess.data() : nullptr);
      out.iteration_time_s += seconds_since(start);
      out.restarts += lanczos.restarts;
      out.operations += lanczos.operations;
      if (lanczos.converged && workspace.should_stop && workspace.should_stop()) {
        throw StopRequested();  // polishing hundreds of Ritz pairs costs as much again
      } else if (lanczos.converged) {
        take_ritz_pairs(std::move(lanczos), sigma, factor, out);
        const auto start_polish = Clock::now();
        polish(matrices, op, factor, out);
        out.iteration_time_s += seconds_since(start_polish);
      } else {
        out.termination = Termination::NoConvergence;
        out.message = fmt::format(
            "Spectra's Lanczos did not converge (CompInfo::{}): {} of {} modes after {} restarts, "
            "{} operator applications",
            lanczos.outcome, lanczos.converged_count, modes, lanczos.restarts, lanczos.operations);
      }
      break;
    } catch (const SingularShift& error) {
      const double scale =
          (matrices.stiffness.diagonal().array() / matrices.mass.diagonal().array())
              .abs()
              .maxCoeff();
      const double moved = -1e-8 * scale * std::pow(100.0, attempt);
      out.warnings.push_back(
          fmt::format("shift {:.3e} rejected ({}); moved to {:.3e}", sigma, error.what(), moved));
      sigma = moved;
      out.termination = Termination::NumericalFailure;
      out.message = error.what();
    } catch (const StopRequested&) {
      out.termination = Termination::NoConvergence;
      out.message = "Lanczos iteration stopped by the run's time limit";
      break;
    } catch (const std::invalid_argument& error) {
      // Spectra rejected its arguments (solved_densely keeps them in range): nothing to retry.
      out.termination = Termination::NumericalFailure;
      out.message = fmt::format("Spectra: {}", error.what());
      break;
    }
  }
  out.factorization_time_s += op.factorization_time_s;
}

// Sylvester: the negative pivots of LDLT(K - sigma_top M) count the eigenvalues below sigma_top.
// sigma_top sits a relative max(1e-9, 10 r) above the top eigenvalue (r the relative residual):
// above the eigenvalue's rounding error, which for a stiff penalised chain is set by the residual
// floor eps ||K|| / ||K phi|| rather than by the convergence tolerance, and far below any physical
// gap between modes.
void prove_mode_count(const FeMatrices& matrices,
                      int modes,
                      BandedLdlt& factor,
                      FeEigenSolution& out) {
  const auto start = Clock::now();
  const double top = out.eigenvalues[out.eigenvalues.size() - 1];
  out.inertia_shift = top + std::max(1e-9, 10.0 * out.max_residual) * std::abs(top);
  out.inertia_count = count_eigenvalues_below(matrices, out.inertia_shift, factor);
  out.factorization_time_s += seconds_since(start);
  if (out.inertia_count != modes) {
    out.termination = Termination::NoConvergence;
    out.message = fmt::format(
        "mode count not proved: LDLT(K - sigma M) at sigma = {:.9e} has {} negative pivots, but "
        "{} modes were found below it",
        out.inertia_shift, out.inertia_count, modes);
  } else {
    out.message = fmt::format("{} modes, inertia count {} below sigma = {:.9e}", modes,
                              out.inertia_count, out.inertia_shift);
  }
}

}  // namespace

Vector mode_sum_guess(const Eigen::MatrixXd& modes, int dofs_per_node, Eigen::Index rows) {
  const Vector sum = modes.rowwise().sum();
  if (sum.size() == rows) return sum;
  const Eigen::Index d = dofs_per_node, coarse_nodes = sum.size() / d;  // free nodes 1 .. Nc - 1
  if (sum.size() % d != 0 || rows != d * (2 * coarse_nodes + 1)) return {};
  Vector fine = Vector::Zero(rows);
  // Fine free node f (1-based) is coarse node f / 2 when f is even, else the mean of its two
  // coarse neighbours; coarse node c (0 and Nc fixed, so zero) is free unknown block c - 1.
  auto coarse = [&](Eigen::Index c, Eigen::Index dof) {
    return c >= 1 && c <= coarse_nodes ? sum[(c - 1) * d + dof] : 0.0;
  };
  for (Eigen::Index f = 1; f <= 2 * coarse_nodes + 1; ++f)
    for (Eigen::Index dof = 0; dof < d; ++dof)
      fine[(f - 1) * d + dof] =
          f % 2 == 0 ? coarse(f / 2, dof) : 0.5 * (coarse(f / 2, dof) + coarse(f / 2 + 1, dof));
  return fine;
}

int count_eigenvalues_below(const FeMatrices& matrices, double shift, BandedLdlt& factor) {
  if (!factor.factorize(matrices.stiffness, matrices.mass, shift)) return -1;
  return factor.negative_pivots();
}

int count_eigenvalues_below(const FeMatrices& matrices, double shift) {
  BandedLdlt factor;
  return count_eigenvalues_below(matrices, shift, factor);
}

FeEigenSolution solve_lowest_modes(const FeMatrices& matrices,
                                   int modes,
                                   double tolerance,
                                   int max_restarts,
                                   FeEigenWorkspace* workspace,
                                   const Vector* guess) {
  FeEigenSolution out;
  const auto n = static_cast<int>(matrices.stiffness.rows());
  if (modes <= 0) {
    out.termination = Termination::Converged;
    out.message = "no modes asked";
    return out;
  }
  const int subspace = lanczos_subspace(n, modes, guess != nullptr && guess->size() == n);
  const bool dense = solved_densely(n, modes);
  FeEigenWorkspace own;
  FeEigenWorkspace& work = workspace ? *workspace : own;
  if (dense) {
    solve_dense(matrices, modes, out);
  } else {
    solve_iteratively(matrices, modes, subspace, tolerance, max_restarts, work, guess, out);
  }
  if (out.termination != Termination::Converged) return out;
  if (dense) normalise_and_check(matrices, out);
  prove_mode_count(matrices, modes, work.factor, out);
  return out;
}

}  // namespace catena::internal
