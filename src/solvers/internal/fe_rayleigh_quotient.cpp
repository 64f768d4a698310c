// The element-wise Rayleigh quotient of an fe mode: see fe_rayleigh_quotient.hpp.
#include "solvers/internal/fe_rayleigh_quotient.hpp"

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

}  // namespace

RayleighQuotient element_rayleigh_quotient(const FeChain& chain, Plane plane, const Vector& phi,
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
