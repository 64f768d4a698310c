// SPDX-License-Identifier: MIT
// The scaled boundary matrix of the frobenius solver: see frobenius_boundary.hpp.
#include "solvers/frobenius/frobenius_boundary.hpp"

#include <algorithm>
#include <cmath>

namespace catena::internal {

namespace {

// Unqualified sqrt must find the floating-point overloads for double and long double (and
// Boost's by ADL for QuadFloat).
using std::sqrt;

// Divides each column by its norm (sqrt of `squares`, 1 for a zero column) and records the
// cancellation, the largest series term behind a column over that norm.
template <class Real>
void scale_columns(BoundaryMatrix<Real>& m, const std::vector<Real>& largest) {
  const std::size_t n = m.a.size();
  for (std::size_t j = 0; j < n; ++j) {
    const Real big = sqrt(m.column_scale[j]);
    m.column_scale[j] = big > Real(0) ? big : Real(1);
    m.cancellation = std::max(m.cancellation, static_cast<double>(largest[j] / m.column_scale[j]));
    for (std::size_t i = 0; i < n; ++i) {
      m.a[i][j] /= m.column_scale[j];
      m.error[i][j] /= m.column_scale[j];
    }
  }
}

}  // namespace

template <class Real>
BoundaryMatrix<Real> boundary_matrix(const PlaneSetup& setup, const Real& omega) {
  CatenaryBasis<Real> basis(setup.inplane, omega, Real(setup.mu), setup.eta_max, setup.settings);
  const std::size_t n = static_cast<std::size_t>(basis.size());
  const std::size_t derivatives = setup.inplane ? 1 : 0;
  BoundaryMatrix<Real> m;
  m.a.assign(n, std::vector<Real>(n));
  m.error = m.a;
  m.terms = basis.total_terms();
  m.centres = basis.num_centres();
  m.converged = basis.converged();
  // Column norms accumulate the squares of every derivative at both ends; scale_columns() takes
  // the root.
  m.column_scale.assign(n, Real(0));
  std::vector<Real> largest(n, Real(0));
  std::size_t row = 0;
  for (double sigma : {setup.sigma1, setup.sigma2}) {
    const auto v = basis.evaluate(Real(sigma), static_cast<int>(n) - 1);
    for (std::size_t j = 0; j < n; ++j) largest[j] = std::max(largest[j], v.largest_term[j]);
    for (std::size_t j = 0; j < n; ++j)
      for (std::size_t d = 0; d < n; ++d) m.column_scale[j] += v.value[j][d] * v.value[j][d];
    for (std::size_t d = 0; d <= derivatives; ++d, ++row)
      for (std::size_t j = 0; j < n; ++j) {
        m.a[row][j] = v.value[j][d];
        m.error[row][j] = v.error[j][d];
      }
  }
  scale_columns(m, largest);
  return m;
}

template BoundaryMatrix<double> boundary_matrix(const PlaneSetup&, const double&);
template BoundaryMatrix<long double> boundary_matrix(const PlaneSetup&, const long double&);
template BoundaryMatrix<QuadFloat> boundary_matrix(const PlaneSetup&, const QuadFloat&);

double scaled_determinant(Precision p, const PlaneSetup& setup, double omega, WorkCounter& work) {
  return with_precision(p, [&](auto zero) {
    using Real = decltype(zero);
    const auto m = boundary_matrix<Real>(setup, Real(omega));
    ++work.determinant_evaluations;
    work.terms = std::max(work.terms, m.terms);
    work.centres = std::max(work.centres, m.centres);
    work.truncated = work.truncated || !m.converged;
    work.cancellation = std::max(work.cancellation, m.cancellation);
    return static_cast<double>(determinant(m.a));
  });
}

}  // namespace catena::internal
