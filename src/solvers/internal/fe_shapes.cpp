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
    tau[j] = chain.axial_stiffness_n[j] * chain.direction[k].dot(D[k + 1] - D[k]) /
             chain.element_length_m[j];
  }
  return tau;
}

namespace {

// Where s falls between nodes: element i and the fraction f in it; and between element midpoints:
// element j and the fraction g toward j + 1 (extrapolated over the end half elements).
struct StationPlace {
  int i = 0, j = 0;
  double f = 0.0, g = 0.0;
};

StationPlace place_of(const FeChain& chain, double s) {
  const int N = chain.elements;
  StationPlace at;
  if (chain.equal_elements) {
    // Equal elements: the nodes are s_i = i l0 (the uniform cable's arithmetic, kept exactly).
    const double x = s / chain.element_length_m[0];
    at.i = std::clamp(static_cast<int>(std::floor(x)), 0, N - 1);
    at.f = x - at.i;
    const double y = x - 0.5;
    at.j = std::clamp(static_cast<int>(std::floor(y)), 0, N - 2);
    at.g = y - at.j;
    return at;
  }
  const double* nodes = chain.node_s_m.data();
  const auto i = static_cast<int>(std::upper_bound(nodes, nodes + N + 1, s) - nodes) - 1;
  at.i = std::clamp(i, 0, N - 1);
  at.f = (s - nodes[at.i]) / chain.element_length_m[at.i];
  auto middle = [&](int j) { return nodes[j] + 0.5 * chain.element_length_m[j]; };
  at.j = std::clamp(s < middle(at.i) ? at.i - 1 : at.i, 0, std::max(N - 2, 0));
  at.g = (s - middle(at.j)) / (middle(at.j + 1) - middle(at.j));
  return at;
}

}  // namespace

FeSampled sample_on_stations(Plane plane,
                             const FeChain& chain,
                             const std::vector<Vec2>& D,
                             const Vector* tau,
                             const Vector& stations,
                             const StaticSolution& statics) {
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
    const StationPlace at = place_of(chain, s);
    const double f = at.f;
    const Vec2 d = (1.0 - f) * D[static_cast<std::size_t>(at.i)] + f * D[static_cast<std::size_t>(at.i) + 1];
    if (plane == Plane::InPlane) {
      out.u[p] = d.dot(statics.tangent(s));
      out.w[p] = d.dot(statics.normal(s));
    } else {
      out.v[p] = d.x();
    }
    if (tau) out.tension[p] = (1.0 - at.g) * (*tau)[at.j] + at.g * (*tau)[at.j + 1];
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
