// SPDX-License-Identifier: MIT
// The element-wise Rayleigh quotient of an fe mode: see fe_rayleigh_quotient.hpp.
#include "solvers/fe/fe_rayleigh_quotient.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>

namespace catena::internal {

namespace {

// Node i's displacement (zero at the fixed end nodes 0 and N).
Vec2 node_displacement(const Vector& phi, int i, int elements, int dofs) {
  if (i <= 0 || i >= elements) return Vec2::Zero();
  const Eigen::Index base = static_cast<Eigen::Index>(dofs) * (i - 1);
  return dofs == 2 ? Vec2(phi[base], phi[base + 1]) : Vec2(phi[base], 0.0);
}

// The strain projections of every column on elements [first, first + rows): stretch t . d and
// turn n . d (out of plane: turn = d), scaled by the square roots of the element's springs, so
// that the block's share of V^T K V is S^T S + T^T T.
void scaled_strains(const FeChain& chain,
                    Plane plane,
                    const Eigen::MatrixXd& vectors,
                    int first,
                    int rows,
                    Eigen::MatrixXd& S,
                    Eigen::MatrixXd& T) {
  const int N = chain.elements, dofs = plane == Plane::InPlane ? 2 : 1;
  // Row of node i's first unknown, -1 at the fixed ends.
  auto row = [&](int i) {
    return (i <= 0 || i >= N) ? Eigen::Index{-1} : static_cast<Eigen::Index>(dofs) * (i - 1);
  };
  S.resize(rows, vectors.cols());
  T.resize(rows, vectors.cols());
  for (int r = 0; r < rows; ++r) {
    const int j = first + r;
    const Eigen::Index a = row(j), b = row(j + 1);
    const double axial = plane == Plane::InPlane
                             ? std::sqrt(chain.axial_stiffness_n[j] / chain.element_length_m[j])
                             : 0.0;
    const double string = std::sqrt(chain.tension_n[j] / chain.stretched_length_m[j]);
    const Vec2& t = chain.direction[static_cast<std::size_t>(j)];
    for (Eigen::Index c = 0; c < vectors.cols(); ++c) {
      const double dx = (b >= 0 ? vectors(b, c) : 0.0) - (a >= 0 ? vectors(a, c) : 0.0);
      if (plane == Plane::InPlane) {
        const double dz = (b >= 0 ? vectors(b + 1, c) : 0.0) - (a >= 0 ? vectors(a + 1, c) : 0.0);
        S(r, c) = axial * (t.x() * dx + t.y() * dz);
        T(r, c) = string * (t.x() * dz - t.y() * dx);
      } else {
        S(r, c) = 0.0;
        T(r, c) = string * dx;
      }
    }
  }
}

// V^T K V element by element, in blocks of elements (each block's sum added to the total, which
// keeps the summation's own rounding ~ (block + N / block) eps).
Eigen::MatrixXd element_projected_stiffness(const FeChain& chain,
                                            Plane plane,
                                            const Eigen::MatrixXd& vectors) {
  constexpr int kBlock = 256;
  const Eigen::Index k = vectors.cols();
  const int dofs = plane == Plane::InPlane ? 2 : 1;
  Eigen::MatrixXd total = Eigen::MatrixXd::Zero(k, k), S, T;
  for (int first = 0; first < chain.elements; first += kBlock) {
    const int rows = std::min(kBlock, chain.elements - first);
    scaled_strains(chain, plane, vectors, first, rows, S, T);
    total.noalias() += S.transpose() * S;
    total.noalias() += T.transpose() * T;
  }
  if (chain.has_contact()) {
    for (int i = 1; i < chain.elements; ++i) {
      const double share = chain.grounded_share_m(i);
      const Eigen::Index row = static_cast<Eigen::Index>(dofs) * (i - 1);
      const Eigen::VectorXd x = vectors.row(row).transpose();
      total.noalias() += share * chain.foundation_tangential_n_per_m2 * x * x.transpose();
      if (dofs == 2) {
        const Eigen::VectorXd z = vectors.row(row + 1).transpose();
        total.noalias() += share * chain.foundation_vertical_n_per_m2 * z * z.transpose();
      }
    }
  }
  return total;
}

// V^T M V a block of rows at a time: M is symmetric, so the transpose of a block of its columns
// is the same block of its rows, and (M V) on those rows is a block x k temporary, not n x k.
// (A rank-one update per entry of M read V a row at a time, across k columns n apart: a TLB miss
// per entry at large n.)
Eigen::MatrixXd projected_mass(const SparseMatrix& mass, const Eigen::MatrixXd& vectors) {
  constexpr Eigen::Index kRows = 512;
  Eigen::MatrixXd total = Eigen::MatrixXd::Zero(vectors.cols(), vectors.cols()), MV;
  for (Eigen::Index r = 0; r < vectors.rows(); r += kRows) {
    const Eigen::Index rows = std::min(kRows, vectors.rows() - r);
    MV.noalias() = mass.middleCols(r, rows).transpose() * vectors;
    total.noalias() += vectors.middleRows(r, rows).transpose() * MV;
  }
  return total;
}

}  // namespace

bool element_rayleigh_ritz(const FeChain& chain,
                           Plane plane,
                           Eigen::MatrixXd& vectors,
                           const SparseMatrix& mass) {
  Eigen::MatrixXd Kr = element_projected_stiffness(chain, plane, vectors);
  Eigen::MatrixXd Mr = projected_mass(mass, vectors);
  Kr = 0.5 * (Kr + Kr.transpose()).eval();
  Mr = 0.5 * (Mr + Mr.transpose()).eval();
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> ritz(Kr, Mr);
  if (ritz.info() != Eigen::Success) return false;
  // Rotated in blocks of rows (a block x k temporary, not n x k).
  constexpr Eigen::Index kRows = 512;
  for (Eigen::Index r = 0; r < vectors.rows(); r += kRows) {
    const Eigen::Index rows = std::min(kRows, vectors.rows() - r);
    vectors.middleRows(r, rows) = (vectors.middleRows(r, rows) * ritz.eigenvectors()).eval();
  }
  return true;
}

RayleighQuotient element_rayleigh_quotient(const FeChain& chain,
                                           Plane plane,
                                           const Vector& phi,
                                           const SparseMatrix& mass) {
  const int N = chain.elements;
  const int dofs = plane == Plane::InPlane ? 2 : 1;
  // The sums in long double: N positive terms, whose own rounding stays far below the bound.
  long double energy = 0.0L;
  double stiffest = 0.0;
  for (int j = 0; j < N; ++j) {
    const Vec2 d = node_displacement(phi, j + 1, N, dofs) - node_displacement(phi, j, N, dofs);
    const double string = chain.tension_n[j] / chain.stretched_length_m[j];
    if (plane == Plane::InPlane) {
      const Vec2& t = chain.direction[static_cast<std::size_t>(j)];
      const double axial = chain.axial_stiffness_n[j] / chain.element_length_m[j];
      const double stretch = t.dot(d), turn = t.x() * d.y() - t.y() * d.x();
      energy += static_cast<long double>(axial * stretch * stretch) + string * turn * turn;
      stiffest = std::max({stiffest, axial, string});
    } else {
      energy += static_cast<long double>(string * d.x() * d.x());
      stiffest = std::max(stiffest, string);
    }
  }
  if (chain.has_contact()) {
    for (int i = 1; i < N; ++i) {
      const Vec2 p = node_displacement(phi, i, N, dofs);
      const double share = chain.grounded_share_m(i);
      energy += dofs == 2 ? share * (chain.foundation_tangential_n_per_m2 * p.x() * p.x() +
                                     chain.foundation_vertical_n_per_m2 * p.y() * p.y())
                          : share * chain.foundation_tangential_n_per_m2 * p.x() * p.x();
    }
  }
  long double kinetic = 0.0L;
  for (int k = 0; k < mass.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(mass, k); it; ++it)
      kinetic += static_cast<long double>(phi[it.row()] * it.value() * phi[it.col()]);
  RayleighQuotient q;
  q.value = static_cast<double>(energy / kinetic);
  const double eps = std::numeric_limits<double>::epsilon();
  const double e = static_cast<double>(energy);
  q.relative_rounding =
      e > 0.0 ? 2.0 * std::sqrt(2.0) * eps * std::sqrt(stiffest * phi.squaredNorm() / e) + 8.0 * eps
              : 0.0;
  return q;
}

}  // namespace catena::internal
