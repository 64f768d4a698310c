// SPDX-License-Identifier: MIT
// Thick-restart Lanczos with DGKS re-orthogonalisation: see fe_lanczos.hpp and
// docs/explanation/methods/fe.md.
#include "solvers/fe/fe_lanczos.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>

namespace catena::internal {

void LanczosWorkspace::reserve(Eigen::Index rows, int subspace) {
  const auto basis_size = static_cast<std::size_t>(rows) * static_cast<std::size_t>(subspace);
  if (basis_capacity_ < basis_size) {
    basis_.reset();  // release before allocating: the old and new bases are never both alive
    basis_ = std::make_unique_for_overwrite<double[]>(basis_size);
    basis_capacity_ = basis_size;
  }
  if (residual_.size() < static_cast<std::size_t>(rows))
    residual_.resize(static_cast<std::size_t>(rows));
  if (coefficients_.size() < static_cast<std::size_t>(subspace)) {
    coefficients_.resize(static_cast<std::size_t>(subspace));
    correction_.resize(static_cast<std::size_t>(subspace));
  }
  rows_ = rows;
  subspace_ = subspace;
  projection_.setZero(subspace, subspace);
}

namespace {

using Matrix = Eigen::MatrixXd;
using BasisMap = Eigen::Map<Eigen::MatrixXd>;

// 1/sqrt(2): a Gram-Schmidt pass that keeps less than this fraction of the norm has cancelled
// enough that rounding may have left components along the basis; one more pass removes them.
constexpr double kKeptNormForOnePass = 0.70710678118654752;
// Early convergence checks every step from this many rows per subspace vector squared: the m x m
// eigenproblem (~10 m^3 flops) then costs a few percent of a step's Gram-Schmidt pass (~4 rows m
// flops). Smaller operators are checked every ceil(64 m^2 / rows) steps, the same share of the
// cost, and not at all when that stride leaves no step to save.
constexpr Eigen::Index kEarlyCheckRowsPerSubspaceSquared = 64;

// Steps between early convergence checks (0: none before the subspace is full).
int early_check_stride(Eigen::Index rows, int subspace, int wanted) {
  const Eigen::Index work = kEarlyCheckRowsPerSubspaceSquared * subspace * subspace;
  const auto stride = static_cast<int>((work + rows - 1) / rows);
  return stride < subspace - wanted - 1 ? stride : 0;
}
// Rows of the basis rotated at a time in a restart (the block fits in cache).
constexpr Eigen::Index kRotationRows = 512;

// A fixed pseudo-random vector (splitmix64), the same on every platform and run.
void fill_pseudo_random(Eigen::Ref<Eigen::VectorXd> x, std::uint64_t& state) {
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    z ^= z >> 31;
    x[i] = static_cast<double>(z >> 11) * 0x1.0p-53 - 0.5;
  }
}

struct Orthogonalised {
  double norm = 0.0;
  bool in_span = false;  // what is left of w is rounding: w lay in the span of the basis
};

// Rows of the basis combined at a time when subtracting V c from w (their partial sums stay in
// the first-level cache).
constexpr Eigen::Index kCombinationRows = 256;

// acc += V(rows r0 .. r0 + count, columns k0 .. k1) c(k0 .. k1), the columns in order, four at a
// time.
void accumulate_columns(const double* V,
                        Eigen::Index rows,
                        Eigen::Index r0,
                        Eigen::Index count,
                        Eigen::Index k0,
                        Eigen::Index k1,
                        const double* c,
                        double* acc) {
  Eigen::Index k = k0;
  for (; k + 4 <= k1; k += 4) {
    const double* v0 = V + k * rows + r0;
    const double *v1 = v0 + rows, *v2 = v1 + rows, *v3 = v2 + rows;
    const double c0 = c[k], c1 = c[k + 1], c2 = c[k + 2], c3 = c[k + 3];
    for (Eigen::Index r = 0; r < count; ++r)
      acc[r] = (((acc[r] + v0[r] * c0) + v1[r] * c1) + v2[r] * c2) + v3[r] * c3;
  }
  for (; k < k1; ++k) {
    const double* v = V + k * rows + r0;
    const double ck = c[k];
    for (Eigen::Index r = 0; r < count; ++r) acc[r] = acc[r] + v[r] * ck;
  }
}

// w -= V c, returning ||w|| afterwards. Eigen's product forms each row's sum over a block of
// columns (all of them below 128 columns) at once, reading every column's next cache line in turn:
// 30 concurrent streams, more than the prefetcher follows, so at a million rows it ran at a third
// of the speed of the V^T w pass over the same memory. Here a block of rows sums four columns at
// a time (four streams). Each row gets the same sums as from Eigen's product: per column block
// (Eigen's split: all columns below 128, else 16 or 4), acc = 0, acc += v_k c_k in order, then
// w + (-1) acc; and the norm is taken over the whole vector. So the result was the same to the
// last bit in the SSE2 build that introduced it; compiled for FMA (cmake/instruction_set.cmake)
// the compiler and Eigen each decide which multiply-adds to fuse, and the two may differ in the
// last bit.
double subtract_combination(const BasisMap& basis,
                            Eigen::Index columns,
                            const Eigen::Ref<const Eigen::VectorXd>& c,
                            Eigen::Ref<Eigen::VectorXd> w) {
  const Eigen::Index rows = w.size();
  const Eigen::Index column_block =
      columns < 128 ? columns : (rows * static_cast<Eigen::Index>(sizeof(double)) < 32000 ? 16 : 4);
  double* x = w.data();
  alignas(64) double acc[kCombinationRows];
  for (Eigen::Index r0 = 0; r0 < rows; r0 += kCombinationRows) {
    const Eigen::Index count = std::min(kCombinationRows, rows - r0);
    for (Eigen::Index k0 = 0; k0 < columns; k0 += column_block) {
      std::fill(acc, acc + count, 0.0);
      accumulate_columns(basis.data(), rows, r0, count, k0, std::min(k0 + column_block, columns),
                         c.data(), acc);
      for (Eigen::Index r = 0; r < count; ++r) x[r0 + r] = x[r0 + r] - acc[r];
    }
  }
  return w.norm();
}

// Classical Gram-Schmidt of w against the first `columns` basis vectors, a second pass only when
// the first kept less than 1/sqrt(2) of the norm (DGKS). `h` receives the total coefficients.
Orthogonalised orthogonalise(const BasisMap& basis,
                             Eigen::Index columns,
                             Eigen::Ref<Eigen::VectorXd> w,
                             Eigen::Ref<Eigen::VectorXd> h,
                             Eigen::Ref<Eigen::VectorXd> correction) {
  const auto V = basis.leftCols(columns);
  auto coefficients = h.head(columns);
  const double before = w.norm();
  coefficients.noalias() = V.transpose() * w;
  const double after = subtract_combination(basis, columns, coefficients, w);
  if (after > kKeptNormForOnePass * before) return {after, false};
  auto again = correction.head(columns);
  again.noalias() = V.transpose() * w;
  const double twice = subtract_combination(basis, columns, again, w);
  coefficients += again;
  return {twice, !(twice > kKeptNormForOnePass * after)};
}

// One run's state: the workspace's buffers seen at this run's size.
struct Run {
  const SymmetricOperator& apply;
  BasisMap basis;
  Eigen::Map<Eigen::VectorXd> residual, coefficients, correction;
  Matrix& projection;
  Matrix& block;
  int subspace;
  int wanted;
  double tolerance;
  // The size of the Krylov decomposition: `subspace`, or fewer when the wanted pairs converged
  // before the subspace was full.
  int size;
  // Test for convergence every `check_stride` steps, not only when the subspace is full (0: only
  // then), see early_check_stride.
  int check_stride;
  double residual_norm = 0.0;  // beta_m
  std::uint64_t seed = 0x5eed5eedULL;
  long operations = 0;
};

// A new unit direction orthogonal to the first `columns` basis vectors (after a breakdown).
void fresh_direction(Run& run, Eigen::Index columns, Eigen::Ref<Eigen::VectorXd> w) {
  fill_pseudo_random(w, run.seed);
  orthogonalise(run.basis, columns, w, run.coefficients, run.correction);
  orthogonalise(run.basis, columns, w, run.coefficients, run.correction);
  w.normalize();
}

// The Ritz pairs of the projection, ordered by decreasing magnitude.
struct RitzPairs {
  Eigen::VectorXd values;     // ordered
  Matrix vectors;             // columns in the same order
  Eigen::VectorXd residuals;  // |beta_m s_mi|
};

RitzPairs ritz_pairs(const Run& run) {
  const int m = run.size;
  Eigen::SelfAdjointEigenSolver<Matrix> eigen(run.projection.topLeftCorner(m, m));
  std::vector<int> order(static_cast<std::size_t>(m));
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return std::abs(eigen.eigenvalues()[a]) > std::abs(eigen.eigenvalues()[b]);
  });
  RitzPairs ritz{Eigen::VectorXd(m), Matrix(m, m), Eigen::VectorXd(m)};
  for (int i = 0; i < m; ++i) {
    ritz.values[i] = eigen.eigenvalues()[order[static_cast<std::size_t>(i)]];
    ritz.vectors.col(i) = eigen.eigenvectors().col(order[static_cast<std::size_t>(i)]);
    ritz.residuals[i] = std::abs(run.residual_norm * ritz.vectors(m - 1, i));
  }
  return ritz;
}

int converged_count(const RitzPairs& ritz, int wanted, double tolerance) {
  // Below eps^(2/3) a Ritz value's magnitude is no scale for its residual.
  const double floor = std::pow(std::numeric_limits<double>::epsilon(), 2.0 / 3.0);
  int count = 0;
  for (int i = 0; i < wanted; ++i)
    if (ritz.residuals[i] < tolerance * std::max(floor, std::abs(ritz.values[i]))) ++count;
  return count;
}

// After step j (new vector j + 1 with coupling beta): on a checked step, whether the wanted Ritz
// pairs of the first j + 1 vectors have converged already; if so the decomposition ends there,
// vector j + 1 standing for the residual direction. A breakdown (beta = 0) is never a stop: the
// invariant subspace found may lack some wanted eigenvalues.
bool converged_early(Run& run, int j, double beta) {
  if (run.check_stride == 0 || j + 1 <= run.wanted || (j + 1 - run.wanted) % run.check_stride != 0)
    return false;
  run.size = j + 1;
  run.residual_norm = beta;
  if (converged_count(ritz_pairs(run), run.wanted, run.tolerance) >= run.wanted) return true;
  run.size = run.subspace;
  return false;
}

// Lanczos steps from basis vector `from` to the end of the subspace. Column j + 1 (or the
// residual after the last step) receives A v_j orthogonalised against v_0..v_j (full
// re-orthogonalisation); the projection
// gets alpha_j on the diagonal and beta_j beside it (a breakdown gives beta_j = 0 and a fresh
// direction).
void extend(Run& run, int from) {
  const int m = run.subspace;
  for (int j = from; j < m; ++j) {
    const bool last = j + 1 == m;
    Eigen::Ref<Eigen::VectorXd> w = last ? Eigen::Ref<Eigen::VectorXd>(run.residual)
                                         : Eigen::Ref<Eigen::VectorXd>(run.basis.col(j + 1));
    run.apply(run.basis.col(j).data(), w.data());
    ++run.operations;
    // The three-term recurrence first (after a restart, step `from` couples to every kept vector
    // and has none); the Gram-Schmidt pass then only removes what rounding left, so it seldom
    // cancels enough to need the second pass.
    double alpha = 0.0;
    if (j > from) {
      w -= run.projection(j - 1, j) * run.basis.col(j - 1);
      alpha = run.basis.col(j).dot(w);
      w -= alpha * run.basis.col(j);
    }
    const Orthogonalised o = orthogonalise(run.basis, j + 1, w, run.coefficients, run.correction);
    run.projection(j, j) = alpha + run.coefficients[j];
    const double beta = o.in_span ? 0.0 : o.norm;
    if (last) {
      run.residual_norm = beta;
      if (beta > 0.0) w /= beta;
      return;
    }
    if (beta > 0.0) {
      w /= beta;
      if (converged_early(run, j, beta)) return;
    } else {
      fresh_direction(run, j + 1, w);
    }
    run.projection(j, j + 1) = run.projection(j + 1, j) = beta;
  }
}

// Replaces the first `columns` basis vectors by basis * s (the Ritz vectors), in place, a block of
// rows at a time.
void rotate_basis(Run& run, const Matrix& s, int columns) {
  const auto rows = run.basis.rows();
  const auto S = s.leftCols(columns);
  for (Eigen::Index r = 0; r < rows; r += kRotationRows) {
    const Eigen::Index count = std::min(kRotationRows, rows - r);
    run.block.noalias() = run.basis.middleRows(r, count) * S;
    run.basis.block(r, 0, count, columns) = run.block;
  }
}

// Thick restart: keep `kept` Ritz vectors; the projection becomes diag(theta) bordered by the
// couplings beta_m s_mi to the residual direction, which becomes basis vector `kept`.
void restart(Run& run, const RitzPairs& ritz, int kept) {
  const int m = run.subspace;
  rotate_basis(run, ritz.vectors, kept);
  run.projection.setZero();
  for (int i = 0; i < kept; ++i) {
    run.projection(i, i) = ritz.values[i];
    run.projection(i, kept) = run.projection(kept, i) = run.residual_norm * ritz.vectors(m - 1, i);
  }
  run.basis.col(kept) = run.residual;
}

// How many Ritz vectors to keep: the wanted ones plus some converged extra ones, which speed up
// the wanted ones' convergence, and always room for at least one new step.
int kept_vectors(int wanted, int converged, int subspace) {
  int kept = wanted + std::min(converged, (subspace - wanted) / 2);
  if (kept == 1) kept = subspace >= 6 ? subspace / 2 : std::min(2, subspace - 1);
  return std::max(1, std::min(kept, subspace - 1));
}

// Relative size of the pseudo-random part mixed into a guessed start vector.
constexpr double kGuessPerturbation = 1e-6;

// The start vector: A r for r a fixed pseudo-random vector or the guess. For a shift-invert
// operator this damps the components along eigenvalues far from the shift (a stiff chain's axial
// modes) by their tiny theta, which Ritz vectors would otherwise carry at the size of the
// convergence tolerance.
void start(Run& run, const double* guess) {
  fill_pseudo_random(run.residual, run.seed);
  if (guess) {
    const Eigen::Map<const Eigen::VectorXd> g(guess, run.residual.size());
    const double g_norm = g.norm(), r_norm = run.residual.norm();
    if (g_norm > 0.0 && std::isfinite(g_norm))
      run.residual = g / g_norm + (kGuessPerturbation / r_norm) * run.residual;
  }
  run.apply(run.residual.data(), run.basis.col(0).data());
  ++run.operations;
  if (!(run.basis.col(0).norm() > 0.0)) run.basis.col(0) = run.residual;
  run.basis.col(0).normalize();
}

}  // namespace

LanczosResult largest_magnitude_eigenpairs(const SymmetricOperator& apply,
                                           Eigen::Index rows,
                                           int wanted,
                                           int subspace,
                                           double tolerance,
                                           int max_restarts,
                                           LanczosWorkspace& workspace,
                                           const double* guess) {
  const int m = static_cast<int>(std::min<Eigen::Index>(rows, std::max(subspace, wanted + 1)));
  workspace.reserve(rows, m);
  Run run{apply,
          workspace.basis(),
          workspace.residual(),
          workspace.coefficients(),
          workspace.correction(),
          workspace.projection(),
          workspace.block(),
          m,
          wanted,
          tolerance,
          m,
          early_check_stride(rows, m, wanted)};
  run.block.resize(std::min(kRotationRows, rows), m);
  start(run, guess);
  LanczosResult result;
  int from = 0;
  for (;; ++result.restarts) {
    extend(run, from);
    const RitzPairs ritz = ritz_pairs(run);
    const int converged = converged_count(ritz, wanted, tolerance);
    if (converged >= wanted || m == rows || result.restarts >= max_restarts) {
      result.converged = converged >= wanted;
      result.values = ritz.values.head(wanted);
      result.vectors.noalias() = run.basis.leftCols(run.size) * ritz.vectors.leftCols(wanted);
      break;
    }
    from = kept_vectors(wanted, converged, m);
    restart(run, ritz, from);
  }
  result.operations = run.operations;
  return result;
}

}  // namespace catena::internal
