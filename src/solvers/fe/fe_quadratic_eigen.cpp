// SPDX-License-Identifier: MIT
// The damped eigenpairs of one fe level: see fe_quadratic_eigen.hpp and
// docs/explanation/methods/fe.md, "Damping".
// GCC 12 at -O3 reports a use-after-free inside Spectra's UpperHessenbergEigen (an Eigen vector
// freed on resize, then reassigned): a false positive of its inliner in library code. Set before
// any include: the warning is placed at Eigen's Memory.h.
#if defined(__GNUC__) && !defined(__clang__) && __GNUC__ >= 12
#pragma GCC diagnostic ignored "-Wuse-after-free"
#endif
#include "solvers/fe/fe_quadratic_eigen.hpp"

#include <Spectra/GenEigsSolver.h>
#include <Spectra/Util/SimpleRandom.h>
#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <numeric>

#include "solvers/fe/fe_argument_count.hpp"
#include "solvers/fe/fe_banded_ldlt.hpp"
#include "solvers/fe/fe_complex_banded_ldlt.hpp"
#include "solvers/fe/fe_rayleigh_quotient.hpp"

namespace catena::internal {
namespace {

using Clock = std::chrono::steady_clock;
using Complex = std::complex<double>;
double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// y = A^{-1} B x = [-K_s^{-1} (C_s x1 + M x2); x1] (header), Spectra's custom-operator interface.
class LinearisedOperator {
 public:
  using Scalar = double;
  LinearisedOperator(const SparseMatrix& shifted_damping, const SparseMatrix& mass, BandedLdlt& K)
      : C_(shifted_damping), M_(mass), K_(K), n_(mass.rows()) {}
  Eigen::Index rows() const { return 2 * n_; }
  Eigen::Index cols() const { return 2 * n_; }
  void perform_op(const double* x_in, double* y_out) const {
    const Eigen::Map<const Vector> x1(x_in, n_), x2(x_in + n_, n_);
    Eigen::Map<Vector> y1(y_out, n_), y2(y_out + n_, n_);
    y1.noalias() = C_ * x1;
    y1.noalias() += M_ * x2;
    y1 = -y1;
    K_.solve_in_place(y1.data());
    y2 = x1;
  }

 private:
  const SparseMatrix& C_;
  const SparseMatrix& M_;
  BandedLdlt& K_;
  Eigen::Index n_;
};

double norm1(const SparseMatrix& A) {
  double best = 0.0;
  for (Eigen::Index c = 0; c < A.outerSize(); ++c) {
    double sum = 0.0;
    for (SparseMatrix::InnerIterator it(A, c); it; ++it) sum += std::abs(it.value());
    best = std::max(best, sum);
  }
  return best;
}

// The smallest eigenvalue of the lumped (block-diagonal) mass: per node block, closed form.
double smallest_mass(const SparseMatrix& M, int dofs) {
  double smallest = std::numeric_limits<double>::infinity();
  for (Eigen::Index i = 0; i < M.rows(); i += dofs) {
    if (dofs == 1) {
      smallest = std::min(smallest, M.coeff(i, i));
      continue;
    }
    const double a = M.coeff(i, i), b = M.coeff(i + 1, i), d = M.coeff(i + 1, i + 1);
    const double mean = 0.5 * (a + d), radius = std::hypot(0.5 * (a - d), b);
    smallest = std::min(smallest, mean - radius);
  }
  return smallest;
}

// One root found by the Arnoldi iteration, before polishing.
struct RawRoot {
  Complex lambda;
  Eigen::VectorXcd phi;
};

// What a run of the Arnoldi iteration found.
struct ArnoldiRun {
  bool converged = false;
  std::string outcome;
  std::vector<RawRoot> roots;  // Im lambda >= 0 only
  double radius = 0.0;
};

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

// Keeps the roots with Im >= 0 from eigenvalues nu = 1 / (lambda - sigma) and vectors z.
void keep_roots(const Eigen::VectorXcd& nu,
                const Eigen::MatrixXcd& z,
                double sigma,
                Eigen::Index n,
                ArnoldiRun& run) {
  for (Eigen::Index i = 0; i < nu.size(); ++i) {
    if (nu[i] == Complex(0.0)) continue;
    const Complex mu = 1.0 / nu[i];
    run.radius = std::max(run.radius, std::abs(mu));
    Complex lambda = sigma + mu;
    // A real root comes from the real Schur form with Im exactly 0; a pair's member with Im < 0
    // is the conjugate of one kept.
    if (lambda.imag() < 0.0) continue;
    run.roots.push_back({lambda, z.col(i).head(n)});
  }
}

// Small problems: the operator formed column by column and solved densely (Eigen's EigenSolver).
ArnoldiRun dense_roots(const LinearisedOperator& op, double sigma, Eigen::Index n) {
  const Eigen::Index size = op.rows();
  Eigen::MatrixXd A(size, size);
  Vector e = Vector::Zero(size);
  for (Eigen::Index c = 0; c < size; ++c) {
    e.setZero();
    e[c] = 1.0;
    op.perform_op(e.data(), A.col(c).data());
  }
  Eigen::EigenSolver<Eigen::MatrixXd> eigen(A);
  ArnoldiRun run;
  run.converged = eigen.info() == Eigen::Success;
  run.outcome = run.converged ? "dense" : "dense EigenSolver failed";
  if (run.converged) keep_roots(eigen.eigenvalues(), eigen.eigenvectors(), sigma, n, run);
  run.radius = std::numeric_limits<double>::infinity();  // every root was computed
  return run;
}

ArnoldiRun arnoldi_roots(const LinearisedOperator& op,
                         double sigma,
                         Eigen::Index n,
                         int wanted,
                         double tolerance,
                         int max_restarts,
                         FeDampedEigenSolution& out) {
  const Eigen::Index size = op.rows();
  const int ncv =
      static_cast<int>(std::min<Eigen::Index>(size, std::max(2 * wanted + 1, wanted + 20)));
  Spectra::GenEigsSolver<LinearisedOperator> eigs(const_cast<LinearisedOperator&>(op), wanted, ncv);
  Spectra::SimpleRandom<double> random(0);
  const Vector start = random.random_vec(size);
  eigs.init(start.data());
  eigs.compute(Spectra::SortRule::LargestMagn, max_restarts, tolerance,
               Spectra::SortRule::LargestMagn);
  out.restarts += static_cast<long>(eigs.num_iterations()) - 1;
  out.operations += static_cast<long>(eigs.num_operations());
  ArnoldiRun run;
  run.converged = eigs.info() == Spectra::CompInfo::Successful;
  run.outcome = outcome_name(eigs.info());
  if (run.converged) keep_roots(eigs.eigenvalues(), eigs.eigenvectors(), sigma, n, run);
  return run;
}

// The pencil's products for complex vectors, on the real and imaginary parts (no complex copy of
// the sparse matrices).
Eigen::VectorXcd times(const SparseMatrix& A, const Eigen::VectorXcd& x) {
  Eigen::VectorXcd y(x.size());
  y.real() = A * Vector(x.real());
  y.imag() = A * Vector(x.imag());
  return y;
}

// ||Q(lambda) phi|| / ((||K|| + |lambda| ||C|| + |lambda|^2 ||M||) ||phi||).
double backward_error(const FeMatrices& matrices,
                      const SparseMatrix& C,
                      Complex lambda,
                      const Eigen::VectorXcd& phi,
                      const std::array<double, 3>& norms) {
  const Eigen::VectorXcd r = times(matrices.stiffness, phi) + lambda * times(C, phi) +
                             (lambda * lambda) * times(matrices.mass, phi);
  const double a = std::abs(lambda);
  return r.norm() / ((norms[0] + a * norms[1] + a * a * norms[2]) * phi.norm());
}

// How far a polishing step may move a root from the Arnoldi value, relative: Spectra's tolerance
// leaves the roots far closer; a step that moves one farther has jumped to a neighbouring root
// (whose own Ritz value is polished separately) and is rejected.
constexpr double kMaxPolishMove = 1e-6;

// Inverse iteration phi <- Q(lambda)^{-1} Q'(lambda) phi with the Rayleigh functional's root,
// while the backward error is above rounding (at most three steps). `factor` holds the pencil.
void polish_root(const FeChain& chain,
                 Plane plane,
                 const FeMatrices& matrices,
                 const SparseMatrix& C,
                 const std::array<double, 3>& norms,
                 ComplexBandedLdlt& factor,
                 RawRoot& root,
                 double& error) {
  const Complex arnoldi = root.lambda;
  auto close = [&](Complex lambda) {
    return std::abs(lambda - arnoldi) <= kMaxPolishMove * std::abs(arnoldi);
  };
  const Complex functional =
      damped_rayleigh_root(chain, plane, root.phi, matrices.mass, C, root.lambda);
  if (close(functional)) root.lambda = functional;
  error = backward_error(matrices, C, root.lambda, root.phi, norms);
  for (int step = 0; step < 3 && error > 1e-15; ++step) {
    if (!factor.factorize(root.lambda)) return;
    Eigen::VectorXcd next =
        times(C, root.phi) + (2.0 * root.lambda) * times(matrices.mass, root.phi);
    factor.solve_in_place(next.data());
    if (!next.allFinite() || next.norm() == 0.0) return;
    next /= next.norm();
    const Complex lambda = damped_rayleigh_root(chain, plane, next, matrices.mass, C, root.lambda);
    const double next_error = backward_error(matrices, C, lambda, next, norms);
    if (!(next_error < error) || !close(lambda)) return;
    root.phi = std::move(next);
    root.lambda = lambda;
    error = next_error;
  }
}

}  // namespace

Complex damped_rayleigh_root(const FeChain& chain,
                             Plane plane,
                             const Eigen::VectorXcd& phi,
                             const SparseMatrix& mass,
                             const SparseMatrix& damping,
                             Complex near) {
  double m = 0.0, c = 0.0, k = 0.0;
  for (const Vector& x : {Vector(phi.real()), Vector(phi.imag())}) {
    const double mx = x.dot(mass * x);
    if (!(mx > 0.0)) continue;
    m += mx;
    c += x.dot(damping * x);
    k += element_rayleigh_quotient(chain, plane, x, mass).value * mx;
  }
  if (!(m > 0.0)) return near;
  const double delta = c / (2.0 * m), discriminant = k / m - delta * delta;
  // A real root stays real (its vector is real up to a phase: the discriminant is <= 0 but for
  // rounding near critical damping).
  if (discriminant > 0.0 && near.imag() == 0.0) return near;
  if (discriminant > 0.0) {
    // A complex pair: the one on the side of `near` (Im >= 0 for the roots kept).
    const double omega = std::sqrt(discriminant);
    return Complex(-delta, near.imag() < 0.0 ? -omega : omega);
  }
  if (near.imag() != 0.0) return near;  // the functional says real, the root is not: keep it
  const double root = std::sqrt(-discriminant);
  const double a = -delta + root, b = -delta - root;
  return std::abs(a - near.real()) <= std::abs(b - near.real()) ? Complex(a, 0.0) : Complex(b, 0.0);
}

namespace {

// Operators of at most this many unknowns (2n of the linearised problem) are solved densely.
constexpr Eigen::Index kDenseSize = 160;

// Factors K_s = K + sigma C + sigma^2 M at sigma = 0, or, when K is singular to rounding (a chain
// with a zero-stiffness mode), at a shift moved below the spectrum as the undamped solve does.
double factor_shifted_stiffness(const FeMatrices& matrices,
                                const SparseMatrix& C,
                                BandedLdlt& factor,
                                FeDampedEigenSolution& out) {
  double sigma = 0.0;
  for (int attempt = 0; attempt < 4; ++attempt) {
    const SparseMatrix Ks =
        sigma == 0.0
            ? matrices.stiffness
            : SparseMatrix(matrices.stiffness + sigma * C + (sigma * sigma) * matrices.mass);
    if (factor.factorize(Ks) && factor.pivot_ratio() > 1e-14) return sigma;
    const double scale =
        (matrices.stiffness.diagonal().array() / matrices.mass.diagonal().array()).abs().maxCoeff();
    const double moved = -1e-8 * std::sqrt(scale) * std::pow(100.0, attempt);
    out.warnings.push_back(
        fmt::format("K_s singular at sigma = {:.3e}; moved to {:.3e}", sigma, moved));
    sigma = moved;
  }
  return std::numeric_limits<double>::quiet_NaN();
}

// Sorts the polished roots into the underdamped (ascending Im) and overdamped (ascending -lambda)
// lists of `out`, the underdamped cut at `modes`.
void sort_roots(std::vector<RawRoot>& roots, int modes, FeDampedEigenSolution& out) {
  std::vector<RawRoot*> under, over;
  for (RawRoot& root : roots) (root.lambda.imag() > 0.0 ? under : over).push_back(&root);
  std::stable_sort(under.begin(), under.end(),
                   [](auto* a, auto* b) { return a->lambda.imag() < b->lambda.imag(); });
  std::stable_sort(over.begin(), over.end(),
                   [](auto* a, auto* b) { return a->lambda.real() > b->lambda.real(); });
  const auto kept = static_cast<Eigen::Index>(std::min<std::size_t>(under.size(), modes));
  const Eigen::Index n = roots.empty() ? 0 : roots.front().phi.size();
  out.roots.resize(kept);
  out.vectors.resize(n, kept);
  for (Eigen::Index i = 0; i < kept; ++i) {
    out.roots[i] = under[static_cast<std::size_t>(i)]->lambda;
    out.vectors.col(i) = under[static_cast<std::size_t>(i)]->phi;
  }
  const auto spare = static_cast<Eigen::Index>(under.size()) - kept;
  out.spare_roots.resize(spare);
  out.spare_vectors.resize(n, spare);
  for (Eigen::Index i = 0; i < spare; ++i) {
    out.spare_roots[i] = under[static_cast<std::size_t>(kept + i)]->lambda;
    out.spare_vectors.col(i) = under[static_cast<std::size_t>(kept + i)]->phi;
  }
  out.real_roots.resize(static_cast<Eigen::Index>(over.size()));
  out.real_vectors.resize(n, static_cast<Eigen::Index>(over.size()));
  for (std::size_t i = 0; i < over.size(); ++i) {
    out.real_roots[static_cast<Eigen::Index>(i)] = over[i]->lambda.real();
    out.real_vectors.col(static_cast<Eigen::Index>(i)) = over[i]->phi;
  }
}

// The counted region for the roots found: Im lambda from half the lowest underdamped root (the
// overdamped roots on the real axis stay as far from the boundary) to midway between the last one
// kept and the next (5 % above the last when there is no next); Re lambda from a quarter of the
// top right of the imaginary axis (no root has Re lambda > 0: C is
// positive semi-definite) leftwards to beyond the decay bound (every non-real root lies right of
// it), but no farther than keeps the rectangle inside 0.9 of the disk |lambda - sigma| < radius
// that Spectra searched: there every root is known, and the steps of the count keep clear of them
// (fe_argument_count.hpp). Empty (im_max <= 0) when that disk leaves no room.
FeCountRegion count_region(
    const std::vector<RawRoot>& roots, int modes, double decay_bound, double sigma, double radius) {
  std::vector<double> imag;
  for (const RawRoot& root : roots)
    if (root.lambda.imag() > 0.0) imag.push_back(root.lambda.imag());
  std::sort(imag.begin(), imag.end());
  const auto kept = std::min<std::size_t>(imag.size(), static_cast<std::size_t>(modes));
  FeCountRegion region;
  region.im_min = 0.5 * imag.front();
  region.im_max = kept < imag.size() ? 0.5 * (imag[kept - 1] + imag[kept]) : 1.05 * imag.back();
  region.re_max = 0.25 * region.im_max;
  region.re_min = -(1.01 * decay_bound + 0.25 * region.im_max);
  const double reach = 0.9 * radius, top = region.im_max;
  if (std::hypot(region.re_max - sigma, top) >= reach) return FeCountRegion{};
  const double disk_edge = sigma - std::sqrt(reach * reach - top * top);
  // Clipped by the disk only when the decay bound reaches beyond it; then the region must still
  // reach half the top to the left (else the caller searches a larger disk).
  if (disk_edge > region.re_min) {
    region.re_min = disk_edge;
    if (region.re_min > -0.5 * top) return FeCountRegion{};
  }
  return region;
}

// The roots found and their conjugates, which the count's steps keep clear of.
std::vector<Complex> known_roots(const std::vector<RawRoot>& roots) {
  std::vector<Complex> known;
  for (const RawRoot& root : roots) {
    known.push_back(root.lambda);
    if (root.lambda.imag() != 0.0) known.push_back(std::conj(root.lambda));
  }
  return known;
}

bool inside(const FeCountRegion& region, Complex z) {
  return z.real() > region.re_min && z.real() < region.re_max && z.imag() > region.im_min &&
         z.imag() < region.im_max;
}

}  // namespace

namespace {

// The plane's status from the argument-principle count: proved when it counts exactly the roots
// found in the region and the region holds every root returned.
void set_count_outcome(const FeArgumentCount& count,
                       int expected,
                       int outside,
                       FeDampedEigenSolution& out) {
  const bool covers = outside == 0;
  out.counted = count.ok && count.count == expected && covers ? count.count : -1;
  out.termination = Termination::Converged;
  if (count.ok && count.count == expected && !covers) {
    out.termination = Termination::NoConvergence;
    out.message = fmt::format(
        "root count not proved for every root returned: {} lie outside the counted region {}",
        outside, out.count_region);
  } else if (!count.ok) {
    out.termination = Termination::NoConvergence;
    out.message = "root count not proved: " + count.failure;
  } else if (count.count != expected) {
    out.termination = Termination::NoConvergence;
    out.message = fmt::format(
        "root count not proved: the argument principle counts {} roots in {}, {} were found",
        count.count, out.count_region, expected);
  } else {
    out.message = fmt::format("{} underdamped roots, argument-principle count {} in {}", expected,
                              count.count, out.count_region);
  }
}

}  // namespace

FeDampedEigenSolution solve_damped_modes(const FeChain& chain,
                                         Plane plane,
                                         const FeMatrices& matrices,
                                         const SparseMatrix& damping,
                                         int modes,
                                         double tolerance,
                                         int max_restarts) {
  FeDampedEigenSolution out;
  const Eigen::Index n = matrices.mass.rows();
  if (modes <= 0) {
    out.termination = Termination::Converged;
    out.message = "no modes asked";
    return out;
  }
  const auto start = Clock::now();
  const std::array<double, 3> norms = {norm1(matrices.stiffness), norm1(damping),
                                       norm1(matrices.mass)};
  out.decay_bound = norms[1] / (2.0 * smallest_mass(matrices.mass, matrices.dofs_per_node));
  BandedLdlt stiffness;
  const double sigma = factor_shifted_stiffness(matrices, damping, stiffness, out);
  out.factorization_time_s += seconds_since(start);
  if (!std::isfinite(sigma)) {
    out.message = "K + sigma C + sigma^2 M is singular at every shift tried";
    return out;
  }
  const SparseMatrix shifted =
      sigma == 0.0 ? damping : SparseMatrix(damping + (2.0 * sigma) * matrices.mass);
  const LinearisedOperator op(shifted, matrices.mass, stiffness);
  const bool dense = op.rows() <= kDenseSize;
  const auto limit = static_cast<int>(op.rows()) - 2;
  int wanted = std::min(limit, 2 * (modes + 1) + 4);
  ComplexBandedLdlt complex_factor;
  for (;;) {
    const auto start_iteration = Clock::now();
    ArnoldiRun run = dense ? dense_roots(op, sigma, n)
                           : arnoldi_roots(op, sigma, n, wanted, tolerance, max_restarts, out);
    if (!run.converged) {
      out.termination = Termination::NoConvergence;
      out.message = fmt::format(
          "Spectra's Arnoldi iteration (GenEigsSolver) did not converge (CompInfo::{}) for {} "
          "roots",
          run.outcome, wanted);
      out.iteration_time_s += seconds_since(start_iteration);
      return out;
    }
    out.max_backward_error = 0.0;
    complex_factor.set_pencil(matrices.stiffness, damping, matrices.mass);
    for (RawRoot& root : run.roots) {
      double error = 0.0;
      polish_root(chain, plane, matrices, damping, norms, complex_factor, root, error);
      out.max_backward_error = std::max(out.max_backward_error, error);
    }
    out.iteration_time_s += seconds_since(start_iteration);
    out.radius = run.radius;
    sort_roots(run.roots, modes, out);
    const auto found =
        static_cast<int>(std::count_if(run.roots.begin(), run.roots.end(), [](const RawRoot& root) {
          return root.lambda.imag() > 0.0;
        }));
    const bool can_grow = !dense && wanted < limit;
    if (found < modes + 1 && can_grow) {
      wanted = std::min(limit, 2 * wanted);
      continue;
    }
    if (found == 0) {
      out.termination = Termination::NoConvergence;
      out.message = fmt::format("no underdamped root among the {} roots of smallest |lambda|",
                                run.roots.size());
      return out;
    }
    const FeCountRegion region = count_region(run.roots, modes, out.decay_bound, sigma, run.radius);
    // The disk searched must hold the region (count_region).
    if (!(region.im_max > 0.0) && can_grow) {
      wanted = std::min(limit, 2 * wanted);
      continue;
    }
    const auto start_count = Clock::now();
    FeArgumentCount count;
    if (region.im_max > 0.0) {
      count = count_roots_in_rectangle(matrices.stiffness, damping, matrices.mass, region,
                                       known_roots(run.roots), complex_factor);
    } else {
      count.failure =
          fmt::format("the disk searched (radius {:.6g}) holds no region to count", run.radius);
    }
    out.factorization_time_s += seconds_since(start_count);
    out.operations += count.evaluations;
    out.count_region = region.describe();
    // The roots found in the region, and whether it holds every root returned.
    int expected = 0;
    for (const RawRoot& root : run.roots) expected += inside(region, root.lambda) ? 1 : 0;
    int outside = 0;
    for (Eigen::Index i = 0; i < out.roots.size(); ++i)
      outside += inside(region, out.roots[i]) ? 0 : 1;
    if (count.ok && count.count > expected && can_grow) {
      wanted = std::min(limit, 2 * wanted);
      continue;
    }
    set_count_outcome(count, expected, outside, out);
    return out;
  }
}

}  // namespace catena::internal
