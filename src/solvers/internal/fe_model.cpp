#include "solvers/internal/fe_model.hpp"

#include "solvers/internal/fe_banded_ldlt.hpp"

#include <fmt/format.h>

#include <Spectra/SymEigsShiftSolver.h>
#include <algorithm>
#include <cassert>
#include <chrono>
#include <cmath>
#include <stdexcept>

namespace catena::internal {
namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}


// Fills the per-element forces, lengths and node positions of a chain with support forces (H, V_A).
void build_chain(FeChain& chain, double H, double V_A, double W0) {
  const int N = chain.elements;
  const double l0 = chain.element_length_m;
  chain.horizontal_force_n = H;
  chain.vertical_force_a_n = V_A;
  chain.tension_n.resize(N);
  chain.stretched_length_m.resize(N);
  chain.direction.resize(static_cast<std::size_t>(N));
  chain.node_offset_m.assign(static_cast<std::size_t>(N) + 1, Vec2::Zero());
  for (int j = 0; j < N; ++j) {
    // Half of node 0's weight goes into support a, so element j carries the continuous force at
    // its midpoint s = (j + 1/2) l0.
    const double V = V_A + W0 * l0 * (j + 0.5);
    const double T = std::hypot(H, V);
    chain.tension_n[j] = T;
    chain.direction[static_cast<std::size_t>(j)] = T > 0.0 ? Vec2(H / T, V / T) : Vec2(0.0, 1.0);
    chain.stretched_length_m[j] = l0 * (1.0 + T / chain.axial_stiffness_n);
    chain.node_offset_m[static_cast<std::size_t>(j) + 1] =
        chain.node_offset_m[static_cast<std::size_t>(j)] +
        chain.stretched_length_m[j] * chain.direction[static_cast<std::size_t>(j)];
  }
}

// d(r_N)/d(H, V_A) = sum_j l0 [(I - t t^T)/T + I/EA] (symmetric).
Eigen::Matrix2d closure_jacobian(const FeChain& chain) {
  Eigen::Matrix2d J = Eigen::Matrix2d::Zero();
  const double l0 = chain.element_length_m;
  for (int j = 0; j < chain.elements; ++j) {
    const Vec2& t = chain.direction[static_cast<std::size_t>(j)];
    J += l0 * ((Eigen::Matrix2d::Identity() - t * t.transpose()) / chain.tension_n[j] +
               Eigen::Matrix2d::Identity() / chain.axial_stiffness_n);
  }
  return J;
}

}  // namespace

FeChain solve_chain_statics(const Problem& problem,
                            const StaticSolution& statics,
                            int elements,
                            double axial_stiffness_n) {
  const CableProperties& cable = problem.cable;
  FeChain chain;
  chain.elements = elements;
  chain.element_length_m = cable.length_m / elements;
  chain.axial_stiffness_n = axial_stiffness_n;
  chain.mass_kg_per_m = cable.mass_kg_per_m;
  chain.normal_mass_kg_per_m = cable.normal_mass_kg_per_m();
  const double W0 = cable.weight_n_per_m;
  const Vec2 chord = problem.supports.chord_m();

  if (problem.prescribed_forces) {
    // Tension-specified problems keep their forces: re-solving them from the geometry would
    // determine the tension of a taut cable only to ~ rounding / strain (see Problem).
    build_chain(chain, problem.prescribed_forces->horizontal_n,
                problem.prescribed_forces->vertical_a_n, W0);
  } else {
    double H = statics.horizontal_force_n();
    double V_A = statics.vertical_force_a_n();
    const bool vertical = H == 0.0;
    const double tolerance = 1e-14 * std::max(cable.length_m, chord.norm());
    build_chain(chain, H, V_A, W0);
    Vec2 residual = chain.node_offset_m.back() - chord;
    int iteration = 0;
    for (; iteration < 100 && residual.norm() > tolerance; ++iteration) {
      const Eigen::Matrix2d J = closure_jacobian(chain);
      Vec2 step;
      if (vertical) {
        step = Vec2(0.0, -residual.y() / J(1, 1));
      } else {
        step = -J.ldlt().solve(residual);
      }
      // Backtrack so that H stays positive and the residual decreases.
      double alpha = 1.0;
      FeChain trial = chain;
      for (int k = 0; k < 40; ++k, alpha *= 0.5) {
        const double H_trial = H + alpha * step.x();
        if (!vertical && H_trial <= 0.0) continue;
        build_chain(trial, H_trial, V_A + alpha * step.y(), W0);
        if ((trial.node_offset_m.back() - chord).norm() < residual.norm() || k == 39) break;
      }
      H = trial.horizontal_force_n;
      V_A = trial.vertical_force_a_n;
      chain = std::move(trial);
      const Vec2 next = chain.node_offset_m.back() - chord;
      if (next.norm() >= residual.norm() && next.norm() > tolerance) {
        // No further progress: accept the rounding floor if it is close, else fail below.
        residual = next;
        break;
      }
      residual = next;
    }
    chain.newton_iterations = iteration;
    if (!(residual.norm() <= 1e-9 * std::max(cable.length_m, chord.norm()))) {
      throw std::runtime_error(fmt::format(
          "discrete statics (N = {}) did not close: |r_N - (B - A)| = {:.3e} m after {} Newton "
          "iterations",
          elements, residual.norm(), iteration));
    }
  }
  chain.closure_error_m = (chain.node_offset_m.back() - chord).norm();
  for (int j = 0; j < elements; ++j) {
    if (!(chain.tension_n[j] > 0.0) || !std::isfinite(chain.tension_n[j])) {
      throw std::runtime_error(fmt::format(
          "discrete statics (N = {}): tension {:.3e} N in element {} is not positive: the chain "
          "is slack there",
          elements, chain.tension_n[j], j));
    }
  }
  return chain;
}

namespace {

// Builds the compressed-column block-tridiagonal matrix of the free nodes 1..N-1 directly (no
// triplets: at N = 1e6 the triplet list and its sort cost more than everything but the Lanczos
// iterations, mostly in first-touch page faults). `element[j]` is the P x P block of element j
// (nodes j, j+1); the block of free nodes (a, b) is sum of element blocks on the diagonal and
// minus the shared element's block off it. With `diagonal_only`, only the diagonal blocks
// `node[i]` are stored (the lumped mass).
// Filled in place: Eigen 3.4's SparseMatrix has no move assignment, and a copy of a large matrix
// costs mostly first-touch page faults.
template <int P>
void fill_block_tridiagonal(SparseMatrix& matrix,
                            const std::vector<Eigen::Matrix<double, P, P>>& element,
                            const std::vector<Eigen::Matrix<double, P, P>>& node,
                            int elements,
                            bool diagonal_only) {
  const int free_nodes = elements - 1;
  const Eigen::Index n = static_cast<Eigen::Index>(P) * free_nodes;
  const Eigen::Index nonzeros = diagonal_only ? P * n : 3 * P * n - 2 * P * P;
  matrix.resize(n, n);
  matrix.resizeNonZeros(nonzeros);
  auto* outer = matrix.outerIndexPtr();
  auto* inner = matrix.innerIndexPtr();
  double* values = matrix.valuePtr();
  Eigen::Index at = 0;
  for (int i = 1; i <= free_nodes; ++i) {  // free node i, unknowns P (i - 1) ..
    for (int c = 0; c < P; ++c) {
      outer[P * (i - 1) + c] = static_cast<int>(at);
      auto put = [&](int node_j, const Eigen::Matrix<double, P, P>& block, double sign) {
        for (int r = 0; r < P; ++r) {
          inner[at] = P * (node_j - 1) + r;
          values[at] = sign * block(r, c);
          ++at;
        }
      };
      if (diagonal_only) {
        put(i, node[static_cast<std::size_t>(i)], 1.0);
        continue;
      }
      const auto& left = element[static_cast<std::size_t>(i) - 1];  // nodes i-1, i
      const auto& right = element[static_cast<std::size_t>(i)];     // nodes i, i+1
      if (i > 1) put(i - 1, left, -1.0);
      const Eigen::Matrix<double, P, P> diagonal = left + right;
      put(i, diagonal, 1.0);
      if (i < free_nodes) put(i + 1, right, -1.0);
    }
  }
  outer[n] = static_cast<int>(at);
  assert(at == nonzeros);
}

}  // namespace

FeMatrices assemble_inplane(const FeChain& chain) {
  const int N = chain.elements;
  const double l0 = chain.element_length_m;
  FeMatrices out;
  out.dofs_per_node = 2;
  std::vector<Eigen::Matrix2d> element(static_cast<std::size_t>(N)), node(static_cast<std::size_t>(N) + 1);
  for (int j = 0; j < N; ++j) {
    const Vec2& t = chain.direction[static_cast<std::size_t>(j)];
    const Eigen::Matrix2d ttT = t * t.transpose();
    element[static_cast<std::size_t>(j)] =
        (chain.axial_stiffness_n / l0) * ttT +
        (chain.tension_n[j] / chain.stretched_length_m[j]) * (Eigen::Matrix2d::Identity() - ttT);
  }
  for (int i = 1; i < N; ++i) {
    // The node tangent bisects the two element directions; the mass is m along it and M across.
    const Vec2 t = (chain.direction[static_cast<std::size_t>(i) - 1] +
                    chain.direction[static_cast<std::size_t>(i)])
                       .normalized();
    const Vec2 nrm(-t.y(), t.x());
    node[static_cast<std::size_t>(i)] = l0 * (chain.mass_kg_per_m * t * t.transpose() +
                                              chain.normal_mass_kg_per_m * nrm * nrm.transpose());
  }
  fill_block_tridiagonal<2>(out.stiffness, element, node, N, false);
  fill_block_tridiagonal<2>(out.mass, element, node, N, true);
  // Columns 0-1: node a's (x, z); columns 2-3: node b's.
  const Eigen::Index n = out.stiffness.rows();
  std::vector<Eigen::Triplet<double>> b_entries;
  for (int r = 0; r < 2; ++r) {
    for (int c = 0; c < 2; ++c) {
      b_entries.emplace_back(r, c, -element.front()(r, c));
      b_entries.emplace_back(n - 2 + r, 2 + c, -element.back()(r, c));
    }
  }
  out.boundary_coupling.resize(n, 4);
  out.boundary_coupling.setFromTriplets(b_entries.begin(), b_entries.end());
  return out;
}

FeMatrices assemble_outofplane(const FeChain& chain) {
  const int N = chain.elements;
  const double l0 = chain.element_length_m;
  FeMatrices out;
  out.dofs_per_node = 1;
  using Block = Eigen::Matrix<double, 1, 1>;
  std::vector<Block> element(static_cast<std::size_t>(N)), node(static_cast<std::size_t>(N) + 1);
  // Only the string part T/l resists motion normal to the plane.
  for (int j = 0; j < N; ++j)
    element[static_cast<std::size_t>(j)](0, 0) = chain.tension_n[j] / chain.stretched_length_m[j];
  for (int i = 1; i < N; ++i) node[static_cast<std::size_t>(i)](0, 0) = l0 * chain.normal_mass_kg_per_m;
  fill_block_tridiagonal<1>(out.stiffness, element, node, N, false);
  fill_block_tridiagonal<1>(out.mass, element, node, N, true);
  const Eigen::Index n = out.stiffness.rows();
  const std::vector<Eigen::Triplet<double>> b_entries = {{0, 0, -element.front()(0, 0)},
                                                   {static_cast<int>(n) - 1, 1, -element.back()(0, 0)}};
  out.boundary_coupling.resize(n, 2);
  out.boundary_coupling.setFromTriplets(b_entries.begin(), b_entries.end());
  return out;
}

namespace {

// Spectra operator y = (K - sigma M)^{-1} x through a banded sparse LDLT.
class ShiftInvertOperator {
 public:
  using Scalar = double;
  ShiftInvertOperator(const SparseMatrix& stiffness, const SparseMatrix& mass)
      : stiffness_(stiffness), mass_(mass) {}
  Eigen::Index rows() const { return stiffness_.rows(); }
  Eigen::Index cols() const { return stiffness_.cols(); }
  void set_shift(double sigma) {
    const auto start = Clock::now();
    shifted_ = stiffness_ - sigma * mass_;
    bool ok = ldlt_.factorize(shifted_);
    factorization_time_s += seconds_since(start);
    ok = ok && ldlt_.pivot_ratio() > 1e-14;
    // Same exception type as Spectra's own SymShiftInvert, so callers handle both alike.
    if (!ok) throw std::invalid_argument(fmt::format("K - sigma M is singular at sigma = {:.6e}", sigma));
  }
  /// Solves (K - sigma M) Y = X for a block of right-hand sides.
  Eigen::MatrixXd solve(const Eigen::MatrixXd& X) const {
    Eigen::MatrixXd Y = X;
    ldlt_.solve_in_place(Y);
    return Y;
  }
  void perform_op(const double* x_in, double* y_out) const {
    std::copy(x_in, x_in + rows(), y_out);
    ldlt_.solve_in_place(y_out);
  }
  double factorization_time_s = 0.0;

 private:
  const SparseMatrix& stiffness_;
  const SparseMatrix& mass_;
  SparseMatrix shifted_;
  BandedLdlt ldlt_;
};

// The block-diagonal Cholesky factor L of the lumped mass (M = L L^T, 2x2 blocks in plane,
// diagonal out of plane) and L^{-T}.
struct MassFactor {
  SparseMatrix lower;              // L
  SparseMatrix inverse_transpose;  // L^{-T}
};
MassFactor factor_mass(const SparseMatrix& mass, int dofs_per_node) {
  const Eigen::Index n = mass.rows();
  std::vector<Eigen::Triplet<double>> l_entries, inv_entries;
  l_entries.reserve(static_cast<std::size_t>(3 * n));
  inv_entries.reserve(static_cast<std::size_t>(3 * n));
  for (Eigen::Index i = 0; i < n; i += dofs_per_node) {
    if (dofs_per_node == 1) {
      const double l = std::sqrt(mass.coeff(i, i));
      l_entries.emplace_back(i, i, l);
      inv_entries.emplace_back(i, i, 1.0 / l);
    } else {
      const double a = mass.coeff(i, i), b = mass.coeff(i + 1, i), c = mass.coeff(i + 1, i + 1);
      const double l11 = std::sqrt(a), l21 = b / l11, l22 = std::sqrt(c - l21 * l21);
      l_entries.emplace_back(i, i, l11);
      l_entries.emplace_back(i + 1, i, l21);
      l_entries.emplace_back(i + 1, i + 1, l22);
      // L^{-1} = [1/l11, 0; -l21/(l11 l22), 1/l22]; stored transposed.
      inv_entries.emplace_back(i, i, 1.0 / l11);
      inv_entries.emplace_back(i, i + 1, -l21 / (l11 * l22));
      inv_entries.emplace_back(i + 1, i + 1, 1.0 / l22);
    }
  }
  MassFactor factor;
  factor.lower.resize(n, n);
  factor.lower.setFromTriplets(l_entries.begin(), l_entries.end());
  factor.inverse_transpose.resize(n, n);
  factor.inverse_transpose.setFromTriplets(inv_entries.begin(), inv_entries.end());
  return factor;
}

// The standard-form operator for Spectra: with A = L^{-1} K L^{-T},
// (A - sigma I)^{-1} x = L^T (K - sigma M)^{-1} L x. A standard symmetric Lanczos avoids the
// M-inner products of the generalized solver (which cost more than the banded solves here).
class StandardFormOperator {
 public:
  using Scalar = double;
  StandardFormOperator(ShiftInvertOperator& inner, const MassFactor& factor)
      : inner_(inner), factor_(factor), work_(inner.rows()), solved_(inner.rows()) {}
  Eigen::Index rows() const { return inner_.rows(); }
  Eigen::Index cols() const { return inner_.cols(); }
  void set_shift(double sigma) { inner_.set_shift(sigma); }
  void perform_op(const double* x_in, double* y_out) const {
    Eigen::Map<const Vector> x(x_in, rows());
    Eigen::Map<Vector> y(y_out, rows());
    work_.noalias() = factor_.lower * x;
    inner_.perform_op(work_.data(), solved_.data());
    y.noalias() = factor_.lower.transpose() * solved_;
  }

 private:
  ShiftInvertOperator& inner_;
  const MassFactor& factor_;
  mutable Vector work_, solved_;
};

// Residual and M-orthogonality of M-normalised eigenvectors.
void check_eigenpairs(const FeMatrices& matrices, FeEigenSolution& out) {
  const Eigen::MatrixXd K_phi = matrices.stiffness * out.eigenvectors;
  const Eigen::MatrixXd M_phi = matrices.mass * out.eigenvectors;
  out.max_residual = 0.0;
  out.max_backward_error = 0.0;
  // ||.||_1 of a symmetric matrix: the largest absolute column sum.
  auto norm1 = [](const SparseMatrix& A) {
    double best = 0.0;
    for (Eigen::Index c = 0; c < A.outerSize(); ++c) {
      double sum = 0.0;
      for (SparseMatrix::InnerIterator it(A, c); it; ++it) sum += std::abs(it.value());
      best = std::max(best, sum);
    }
    return best;
  };
  const double k_norm = norm1(matrices.stiffness), m_norm = norm1(matrices.mass);
  for (Eigen::Index i = 0; i < out.eigenvectors.cols(); ++i) {
    const double denominator = K_phi.col(i).norm();
    const double r = (K_phi.col(i) - out.eigenvalues[i] * M_phi.col(i)).norm();
    out.max_residual = std::max(out.max_residual, denominator > 0.0 ? r / denominator : r);
    out.max_backward_error = std::max(
        out.max_backward_error,
        r / ((k_norm + std::abs(out.eigenvalues[i]) * m_norm) * out.eigenvectors.col(i).norm()));
  }
  const Eigen::MatrixXd gram = out.eigenvectors.transpose() * M_phi;
  out.max_orthogonality_error =
      (gram - Eigen::MatrixXd::Identity(gram.rows(), gram.cols())).cwiseAbs().maxCoeff();
}

// Normwise backward error at which the eigenpairs are as good as double precision allows.
constexpr double kBackwardErrorGoal = 1e-14;

// M-normalises the vectors (the Ritz vectors are M-orthonormal already; this removes rounding
// drift) and measures residual, backward error and M-orthogonality.
void normalise_and_check(const FeMatrices& matrices, FeEigenSolution& out) {
  for (Eigen::Index i = 0; i < out.eigenvectors.cols(); ++i) {
    const double norm2 = out.eigenvectors.col(i).dot(matrices.mass * out.eigenvectors.col(i));
    out.eigenvectors.col(i) /= std::sqrt(norm2);
  }
  check_eigenpairs(matrices, out);
}

// Subspace (inverse) iteration with Rayleigh-Ritz on the converged Ritz vectors, with the
// factorisation Spectra already used. Lanczos leaves components along the stiff axial directions
// of size ~ tolerance; K amplifies them by EA/l0 into the residual. One inverse-iteration step
// damps them by lambda/lambda_axial (<= 1e-4 here), so one or two steps reach the rounding floor.
void refine(const FeMatrices& matrices, const ShiftInvertOperator& op, FeEigenSolution& out) {
  {
    const Eigen::MatrixXd Y = op.solve(matrices.mass * out.eigenvectors);
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

// Small problems: a dense generalized solve is exact and avoids Lanczos' nev < ncv <= n limits.
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

}  // namespace

int count_eigenvalues_below(const FeMatrices& matrices, double shift) {
  const SparseMatrix shifted = matrices.stiffness - shift * matrices.mass;
  BandedLdlt ldlt;
  if (!ldlt.factorize(shifted)) return -1;
  return ldlt.negative_pivots();
}

FeEigenSolution solve_lowest_modes(const FeMatrices& matrices,
                                   int modes,
                                   double tolerance,
                                   int max_restarts) {
  FeEigenSolution out;
  const auto n = static_cast<int>(matrices.stiffness.rows());
  if (modes <= 0) {
    out.termination = Termination::Converged;
    out.message = "no modes asked";
    return out;
  }
  const int subspace = std::min(n, std::max(2 * modes + 1, modes + 20));
  if (n <= 64 || subspace <= modes) {
    solve_dense(matrices, modes, out);
  } else {
    ShiftInvertOperator op(matrices.stiffness, matrices.mass);
    const MassFactor factor = factor_mass(matrices.mass, matrices.dofs_per_node);
    StandardFormOperator standard(op, factor);
    // Shift 0 targets the lowest modes (K is positive definite for a taut chain). If it is
    // singular (a chain with a zero-stiffness mode), move the shift below the spectrum's bottom.
    double sigma = 0.0;
    for (int attempt = 0; attempt < 4; ++attempt) {
      try {
        const auto start = Clock::now();
        Spectra::SymEigsShiftSolver<StandardFormOperator> eigs(standard, modes, subspace, sigma);
        eigs.init();
        eigs.compute(Spectra::SortRule::LargestMagn, max_restarts, tolerance,
                     Spectra::SortRule::SmallestAlge);
        out.iteration_time_s += seconds_since(start);
        out.restarts += eigs.num_iterations();
        out.operations += eigs.num_operations();
        if (eigs.info() == Spectra::CompInfo::Successful) {
          out.eigenvalues = eigs.eigenvalues();
          out.eigenvectors = factor.inverse_transpose * eigs.eigenvectors();
          out.termination = Termination::Converged;
          // Refine only what needs it: one or two inverse-iteration steps until the normwise
          // backward error is at rounding level.
          const auto start_refine = Clock::now();
          for (int step = 0; step < 3; ++step) {
            normalise_and_check(matrices, out);
            if (out.max_backward_error <= kBackwardErrorGoal || step == 2) break;
            refine(matrices, op, out);
          }
          out.iteration_time_s += seconds_since(start_refine);
        } else {
          out.termination = Termination::NoConvergence;
          out.message = fmt::format("Spectra did not converge: {} restarts, {} operator applications",
                                    eigs.num_iterations(), eigs.num_operations());
        }
        break;
      } catch (const std::invalid_argument& error) {
        const double scale = (matrices.stiffness.diagonal().array() /
                              matrices.mass.diagonal().array()).abs().maxCoeff();
        const double moved = -1e-8 * scale * std::pow(100.0, attempt);
        out.warnings.push_back(fmt::format("shift {:.3e} rejected ({}); moved to {:.3e}", sigma,
                                           error.what(), moved));
        sigma = moved;
        out.termination = Termination::NumericalFailure;
        out.message = error.what();
      }
    }
    out.factorization_time_s += op.factorization_time_s;
    out.iteration_time_s -= op.factorization_time_s;
  }
  if (out.termination != Termination::Converged) return out;

  if (n <= 64 || subspace <= modes) normalise_and_check(matrices, out);

  // Sylvester: the negative pivots of LDLT(K - sigma_top M) count the eigenvalues below sigma_top.
  // sigma_top sits a relative max(1e-9, 10 r) above the top eigenvalue (r the relative residual):
  // above the eigenvalue's rounding error, which for a stiff penalised chain is set by the
  // residual floor eps ||K|| / ||K phi|| rather than by the convergence tolerance, and far below
  // any physical gap between modes.
  const auto start = Clock::now();
  const double top = out.eigenvalues[out.eigenvalues.size() - 1];
  out.inertia_shift = top + std::max(1e-9, 10.0 * out.max_residual) * std::abs(top);
  out.inertia_count = count_eigenvalues_below(matrices, out.inertia_shift);
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
  return out;
}

}  // namespace catena::internal
