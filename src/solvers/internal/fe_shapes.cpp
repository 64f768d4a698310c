// From fe nodal displacements to stations: see fe_shapes.hpp and docs/methods/fe.md.
#include "solvers/internal/fe_shapes.hpp"

#include <algorithm>
#include <cmath>

#include "solvers/internal/mode_tools.hpp"

namespace catena::internal {

std::vector<Vec2> node_displacements(Plane plane,
                                     int elements,
                                     const Eigen::Ref<const Vector>& free,
                                     const Vec2& end_a,
                                     const Vec2& end_b) {
  std::vector<Vec2> D(static_cast<std::size_t>(elements) + 1, Vec2::Zero());
  D.front() = end_a;
  D.back() = end_b;
  for (int i = 1; i < elements; ++i) {
    D[static_cast<std::size_t>(i)] = plane == Plane::InPlane
                                         ? Vec2(free[2 * (i - 1)], free[2 * (i - 1) + 1])
                                         : Vec2(free[i - 1], 0.0);
  }
  return D;
}

Vector element_tension(const FeChain& chain, const std::vector<Vec2>& D) {
  Vector tau(chain.elements);
  for (int j = 0; j < chain.elements; ++j) {
    const auto k = static_cast<std::size_t>(j);
    tau[j] = chain.axial_stiffness_n * chain.direction[k].dot(D[k + 1] - D[k]) /
             chain.element_length_m;
  }
  return tau;
}

FeSampled sample_on_stations(Plane plane,
                             const FeChain& chain,
                             const std::vector<Vec2>& D,
                             const Vector* tau,
                             const Vector& stations,
                             const StaticSolution& statics) {
  const int N = chain.elements;
  const double l0 = chain.element_length_m;
  FeSampled out;
  const Index points = stations.size();
  if (plane == Plane::InPlane) {
    out.u.resize(points);
    out.w.resize(points);
  } else {
    out.v.resize(points);
  }
  if (tau) out.tension.resize(points);
  for (Index p = 0; p < points; ++p) {
    const double s = stations[p];
    const double x = s / l0;
    const int i = std::clamp(static_cast<int>(std::floor(x)), 0, N - 1);
    const double f = x - i;
    const Vec2 d = (1.0 - f) * D[static_cast<std::size_t>(i)] + f * D[static_cast<std::size_t>(i) + 1];
    if (plane == Plane::InPlane) {
      out.u[p] = d.dot(statics.tangent(s));
      out.w[p] = d.dot(statics.normal(s));
    } else {
      out.v[p] = d.x();
    }
    if (tau) {
      const double y = x - 0.5;
      const int j = std::clamp(static_cast<int>(std::floor(y)), 0, N - 2);
      const double g = y - j;
      out.tension[p] = (1.0 - g) * (*tau)[j] + g * (*tau)[j + 1];
    }
  }
  return out;
}

Mode mode_on_stations(Plane plane,
                      const FeChain& chain,
                      const Eigen::Ref<const Vector>& eigenvector,
                      const Vector& stations,
                      const StaticSolution& statics,
                      bool with_tension) {
  const std::vector<Vec2> D = node_displacements(plane, chain.elements, eigenvector);
  Vector tau;
  if (with_tension && plane == Plane::InPlane) tau = element_tension(chain, D);
  const FeSampled sampled = sample_on_stations(
      plane, chain, D, (with_tension && plane == Plane::InPlane) ? &tau : nullptr, stations, statics);
  Mode mode;
  mode.s_m = stations;
  if (plane == Plane::InPlane) {
    mode.u = sampled.u;
    mode.w = sampled.w;
    if (with_tension) mode.tension_n = sampled.tension;
    normalise_inplane_mode(mode);
  } else {
    mode.v = sampled.v;
    // Out-of-plane motion causes no first-order dynamic tension.
    if (with_tension) mode.tension_n = Vector::Zero(stations.size());
    normalise_outofplane_mode(mode);
  }
  return mode;
}

}  // namespace catena::internal
