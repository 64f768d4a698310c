// SPDX-License-Identifier: MIT
// The in-plane forced residual from the chain's element data: fe_structured_residual.hpp.
#include "solvers/fe/fe_structured_residual.hpp"

#include <vector>

#include "solvers/fe/fe_shapes.hpp"

namespace catena::internal {

Vector inplane_structured_residual(const FeChain& chain,
                                   const FeMatrices& matrices,
                                   double omega,
                                   const Vector& x,
                                   const Vec2& end_a,
                                   const Vec2& end_b) {
  const int N = chain.elements;
  const std::vector<Vec2> D = node_displacements(Plane::InPlane, N, x, end_a, end_b);
  // -(K x) on the free nodes, element by element: element e pulls node e by +F and node e + 1 by
  // -F.
  std::vector<long double> force(static_cast<std::size_t>(x.size()), 0.0L);
  for (int e = 0; e < N; ++e) {
    const Vec2& t = chain.direction[static_cast<std::size_t>(e)];
    const long double tx = t.x(), tz = t.y(), nx = -tz, nz = tx;
    const long double a =
        static_cast<long double>(chain.axial_stiffness_n[e]) / chain.element_length_m[e];
    const long double b =
        static_cast<long double>(chain.tension_n[e]) / chain.stretched_length_m[e];
    const Vec2& from = D[static_cast<std::size_t>(e)];
    const Vec2& to = D[static_cast<std::size_t>(e) + 1];
    const long double dx = static_cast<long double>(to.x()) - from.x(),
                      dz = static_cast<long double>(to.y()) - from.y();
    const long double axial = a * (tx * dx + tz * dz), transverse = b * (nx * dx + nz * dz);
    const long double fx = axial * tx + transverse * nx, fz = axial * tz + transverse * nz;
    if (e >= 1) {
      force[static_cast<std::size_t>(2 * (e - 1))] += fx;
      force[static_cast<std::size_t>(2 * (e - 1) + 1)] += fz;
    }
    if (e + 1 <= N - 1) {
      force[static_cast<std::size_t>(2 * e)] -= fx;
      force[static_cast<std::size_t>(2 * e + 1)] -= fz;
    }
  }
  const Vector inertia = (omega * omega) * (matrices.mass * x);
  const std::vector<Eigen::Matrix2d> foundation = inplane_foundation(chain);
  Vector residual(x.size());
  for (int i = 1; i < N; ++i) {
    const auto k = static_cast<Eigen::Index>(2 * (i - 1));
    Eigen::Vector2d spring = Eigen::Vector2d::Zero();
    if (!foundation.empty()) spring = foundation[static_cast<std::size_t>(i)] * x.segment<2>(k);
    for (Eigen::Index d = 0; d < 2; ++d)
      residual[k + d] =
          static_cast<double>(force[static_cast<std::size_t>(k + d)] + inertia[k + d] - spring[d]);
  }
  return residual;
}

}  // namespace catena::internal
