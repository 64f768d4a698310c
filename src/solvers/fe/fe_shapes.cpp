// SPDX-License-Identifier: MIT
// From fe nodal displacements to stations: see fe_shapes.hpp and docs/explanation/methods/fe.md.
#include "solvers/fe/fe_shapes.hpp"

#include <algorithm>
#include <cmath>

#include "solvers/common/mode_tools.hpp"

namespace catena::internal {

namespace {

// Node i's displacement read from the free unknowns in place (the end nodes' given): the samples
// of a mode need a few nodes per station, not a copy of all N + 1.
struct FreeNodes {
  Plane plane;
  int elements;
  const double* free;
  Vec2 end_a, end_b;
  Vec2 operator[](std::size_t node) const {
    const auto i = static_cast<int>(node);
    if (i == 0) return end_a;
    if (i == elements) return end_b;
    return plane == Plane::InPlane ? Vec2(free[2 * (i - 1)], free[2 * (i - 1) + 1])
                                   : Vec2(free[i - 1], 0.0);
  }
};

// tau_j = EA t_j . (D_{j+1} - D_j) / l0 for any node access D.
template <typename Nodes>
double tension_of_element(const FeChain& chain, const Nodes& D, int j) {
  const auto k = static_cast<std::size_t>(j);
  return chain.axial_stiffness_n[j] * chain.direction[k].dot(D[k + 1] - D[k]) /
         chain.element_length_m[j];
}

}  // namespace

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
  for (int j = 0; j < chain.elements; ++j) tau[j] = tension_of_element(chain, D, j);
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

namespace {

// The samples for any node access D; `tension_at(j)` gives element j's tension (a null pointer:
// no tension asked).
template <typename Nodes, typename TensionAt>
FeSampled sample_nodes(Plane plane,
                       const FeChain& chain,
                       const Nodes& D,
                       const TensionAt* tension_at,
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
  if (tension_at) out.tension.resize(points);
  for (Index p = 0; p < points; ++p) {
    const double s = stations[p];
    const StationPlace at = place_of(chain, s);
    const double f = at.f;
    const Vec2 d =
        (1.0 - f) * D[static_cast<std::size_t>(at.i)] + f * D[static_cast<std::size_t>(at.i) + 1];
    if (plane == Plane::InPlane) {
      out.u[p] = d.dot(statics.tangent(s));
      out.w[p] = d.dot(statics.normal(s));
    } else {
      out.v[p] = d.x();
    }
    if (tension_at)
      out.tension[p] = (1.0 - at.g) * (*tension_at)(at.j) + at.g * (*tension_at)(at.j + 1);
  }
  return out;
}

}  // namespace

FeSampled sample_on_stations(Plane plane,
                             const FeChain& chain,
                             const std::vector<Vec2>& D,
                             const Vector* tau,
                             const Vector& stations,
                             const StaticSolution& statics) {
  const auto tension_at = [tau](int j) { return (*tau)[j]; };
  return sample_nodes(plane, chain, D, tau ? &tension_at : nullptr, stations, statics);
}

Mode mode_on_stations(Plane plane,
                      const FeChain& chain,
                      const Eigen::Ref<const Vector>& eigenvector,
                      const Vector& stations,
                      const StaticSolution& statics,
                      bool with_tension) {
  // The nodes and element tensions next to each station only (at N = 1e6 a copy of every node per
  // mode costs more than the sampling).
  const FreeNodes D{plane, chain.elements, eigenvector.data(), Vec2::Zero(), Vec2::Zero()};
  const auto tension_at = [&](int j) { return tension_of_element(chain, D, j); };
  const FeSampled sampled = sample_nodes(
      plane, chain, D, (with_tension && plane == Plane::InPlane) ? &tension_at : nullptr, stations,
      statics);
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

Mode damped_mode_on_stations(Plane plane,
                             const FeChain& chain,
                             const Eigen::VectorXcd& eigenvector,
                             std::complex<double> lambda,
                             const Vector& stations,
                             const StaticSolution& statics,
                             bool with_tension) {
  const Vector re = eigenvector.real(), im = eigenvector.imag();
  const std::vector<Vec2> D_re = node_displacements(plane, chain.elements, re);
  const std::vector<Vec2> D_im = node_displacements(plane, chain.elements, im);
  Vector tau_re, tau_im;
  const bool tension = with_tension && plane == Plane::InPlane;
  if (tension) {
    tau_re.resize(chain.elements);
    tau_im.resize(chain.elements);
    for (int j = 0; j < chain.elements; ++j) {
      const auto k = static_cast<std::size_t>(j);
      const Vec2& t = chain.direction[k];
      const std::complex<double> strain(t.dot(D_re[k + 1] - D_re[k]), t.dot(D_im[k + 1] - D_im[k]));
      const std::complex<double> tau =
          (chain.axial_stiffness_n[j] + chain.axial_damping_n_s[j] * lambda) * strain /
          chain.element_length_m[j];
      tau_re[j] = tau.real();
      tau_im[j] = tau.imag();
    }
  }
  const FeSampled a =
      sample_on_stations(plane, chain, D_re, tension ? &tau_re : nullptr, stations, statics);
  const FeSampled b =
      sample_on_stations(plane, chain, D_im, tension ? &tau_im : nullptr, stations, statics);
  Mode mode;
  mode.s_m = stations;
  std::string by = "v";
  if (plane == Plane::InPlane) {
    mode.u = a.u;
    mode.w = a.w;
    mode.u_imag = b.u;
    mode.w_imag = b.w;
    const double w_max = std::sqrt((a.w.array().square() + b.w.array().square()).maxCoeff());
    const double u_max = std::sqrt((a.u.array().square() + b.u.array().square()).maxCoeff());
    by = w_max <= 1e-6 * u_max ? "u" : "w";
    if (with_tension) {
      mode.tension_n = a.tension;
      mode.tension_imag_n = b.tension;
    }
  } else {
    mode.v = a.v;
    mode.v_imag = b.v;
    if (with_tension) {
      mode.tension_n = Vector::Zero(stations.size());
      mode.tension_imag_n = Vector::Zero(stations.size());
    }
  }
  normalise_complex_mode(mode, by);
  return mode;
}

}  // namespace catena::internal
