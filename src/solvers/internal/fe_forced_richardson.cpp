// Richardson in h of the fe forced response: see fe_forced_richardson.hpp and docs/methods/fe.md.
#include "solvers/internal/fe_forced_richardson.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace catena::internal {
namespace {

// The stencil of cubic_interpolate: the first of (up to) 4 points and their Lagrange weights.
struct Stencil {
  std::size_t first = 0;
  std::size_t count = 0;
  double weight[4] = {0.0, 0.0, 0.0, 0.0};
};

Stencil stencil_at(std::size_t points, double first, double spacing, double x) {
  Stencil st;
  st.count = std::min<std::size_t>(4, points);
  const double u = (x - first) / spacing;
  const long nearest_left = static_cast<long>(std::floor(u)) - (static_cast<long>(st.count) / 2 - 1);
  const long last_start = static_cast<long>(points - st.count);
  st.first = static_cast<std::size_t>(std::clamp(nearest_left, 0L, std::max(0L, last_start)));
  const double t = u - static_cast<double>(st.first);
  for (std::size_t i = 0; i < st.count; ++i) {
    double w = 1.0;
    for (std::size_t j = 0; j < st.count; ++j) {
      if (j != i) w *= (t - static_cast<double>(j)) / (static_cast<double>(i) - static_cast<double>(j));
    }
    st.weight[i] = w;
  }
  return st;
}

std::vector<double> component(const std::vector<Vec2>& nodes, int c) {
  std::vector<double> out(nodes.size());
  for (std::size_t i = 0; i < nodes.size(); ++i) out[i] = nodes[i][c];
  return out;
}

std::vector<double> as_std(const Vector& v) { return std::vector<double>(v.data(), v.data() + v.size()); }

double max_abs_difference(const Vector& a, const Vector& b) {
  return (a.size() && a.size() == b.size()) ? (a - b).cwiseAbs().maxCoeff() : 0.0;
}

// cubic_interpolate on the `count` values from `values`.
double cubic_interpolate_span(const double* values, std::size_t count, double first, double spacing, double x) {
  if (count == 0) return 0.0;
  const Stencil st = stencil_at(count, first, spacing, x);
  double sum = 0.0;
  for (std::size_t i = 0; i < st.count; ++i) sum += st.weight[i] * values[st.first + i];
  return sum;
}

using Piece = FeResponseField::Piece;

// The piece containing s (at a boundary: the one toward b).
const Piece& piece_at(const std::vector<Piece>& pieces, double s) {
  const auto after = std::upper_bound(pieces.begin(), pieces.end(), s,
                                      [](double x, const Piece& piece) { return x < piece.s_begin_m; });
  return after == pieces.begin() ? pieces.front() : *(after - 1);
}

// Within `piece`: the nodal values (elements + 1 of them) and the element-midpoint values at s.
double at_nodes(const std::vector<double>& values, const Piece& piece, double s) {
  return cubic_interpolate_span(values.data() + piece.first, piece.elements + 1, piece.s_begin_m,
                                piece.element_length_m, s);
}
double at_midpoints(const std::vector<double>& values, const Piece& piece, double s) {
  return cubic_interpolate_span(values.data() + piece.first, piece.elements,
                                piece.s_begin_m + 0.5 * piece.element_length_m, piece.element_length_m, s);
}

}  // namespace

double cubic_interpolate(const std::vector<double>& values, double first, double spacing, double x) {
  return cubic_interpolate_span(values.data(), values.size(), first, spacing, x);
}

FeResponseField extrapolate_field_in_kappa(const FeResponseField& at_kappa, const FeResponseField& at_2kappa) {
  FeResponseField out = at_kappa;
  for (std::size_t i = 0; i < out.nodes.size(); ++i) out.nodes[i] = 2.0 * at_kappa.nodes[i] - at_2kappa.nodes[i];
  if (out.tension.size()) out.tension = 2.0 * at_kappa.tension - at_2kappa.tension;
  return out;
}

FeResponseField richardson_field(const FeResponseField& coarse, const FeResponseField& fine) {
  const std::size_t elements = coarse.nodes.size() - 1;
  if (fine.nodes.size() != 2 * elements + 1 || fine.pieces.size() != coarse.pieces.size())
    throw std::logic_error("richardson_field: the fine mesh must have twice the coarse mesh's elements");
  FeResponseField out = coarse;
  // Every piece doubles its elements, so coarse node i is fine node 2 i.
  for (std::size_t i = 0; i <= elements; ++i) out.nodes[i] = (4.0 * fine.nodes[2 * i] - coarse.nodes[i]) / 3.0;
  if (coarse.tension.size()) {
    const std::vector<double> fine_tension = as_std(fine.tension);
    for (std::size_t p = 0; p < coarse.pieces.size(); ++p) {
      const Piece& piece = coarse.pieces[p];
      for (std::size_t k = 0; k < piece.elements; ++k) {
        const double s = piece.s_begin_m + (static_cast<double>(k) + 0.5) * piece.element_length_m;
        const auto j = static_cast<Index>(piece.first + k);
        out.tension[j] = (4.0 * at_midpoints(fine_tension, fine.pieces[p], s) - coarse.tension[j]) / 3.0;
      }
    }
  }
  return out;
}

FeSampled sample_field(Plane plane, const FeResponseField& field, const Vector& stations,
                       const StaticSolution& statics) {
  const std::vector<double> x = component(field.nodes, 0), z = component(field.nodes, 1);
  const std::vector<double> tension = as_std(field.tension);
  const Index points = stations.size();
  FeSampled out;
  if (plane == Plane::InPlane) {
    out.u.resize(points);
    out.w.resize(points);
  } else {
    out.v.resize(points);
  }
  out.tension = Vector::Zero(points);
  for (Index p = 0; p < points; ++p) {
    const double s = stations[p];
    const Piece& piece = piece_at(field.pieces, s);
    const Vec2 d(at_nodes(x, piece, s), at_nodes(z, piece, s));
    if (plane == Plane::InPlane) {
      out.u[p] = d.dot(statics.tangent(s));
      out.w[p] = d.dot(statics.normal(s));
      if (!tension.empty()) out.tension[p] = at_midpoints(tension, piece, s);
    } else {
      out.v[p] = d.x();
    }
  }
  return out;
}

double max_station_difference(const FeSampled& a, const FeSampled& b, bool tension) {
  if (tension) return max_abs_difference(a.tension, b.tension);
  return std::max({max_abs_difference(a.u, b.u), max_abs_difference(a.w, b.w), max_abs_difference(a.v, b.v)});
}

}  // namespace catena::internal
