// SPDX-License-Identifier: MIT
// Richardson in h of the fe forced response: see fe_forced_richardson.hpp and
// docs/explanation/methods/fe.md.
#include "solvers/fe/fe_forced_richardson.hpp"

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
  const long nearest_left =
      static_cast<long>(std::floor(u)) - (static_cast<long>(st.count) / 2 - 1);
  const long last_start = static_cast<long>(points - st.count);
  st.first = static_cast<std::size_t>(std::clamp(nearest_left, 0L, std::max(0L, last_start)));
  const double t = u - static_cast<double>(st.first);
  for (std::size_t i = 0; i < st.count; ++i) {
    double w = 1.0;
    for (std::size_t j = 0; j < st.count; ++j) {
      if (j != i)
        w *= (t - static_cast<double>(j)) / (static_cast<double>(i) - static_cast<double>(j));
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

double max_abs_difference(const Vector& a, const Vector& b) {
  return (a.size() && a.size() == b.size()) ? (a - b).cwiseAbs().maxCoeff() : 0.0;
}

}  // namespace

double cubic_interpolate(
    const double* values, std::size_t count, double first, double spacing, double x) {
  if (count == 0) return 0.0;
  const Stencil st = stencil_at(count, first, spacing, x);
  double sum = 0.0;
  for (std::size_t i = 0; i < st.count; ++i) sum += st.weight[i] * values[st.first + i];
  return sum;
}

double cubic_interpolate(const std::vector<double>& values,
                         double first,
                         double spacing,
                         double x) {
  return cubic_interpolate(values.data(), values.size(), first, spacing, x);
}

FeResponseField extrapolate_field_in_kappa(const FeResponseField& at_kappa,
                                           const FeResponseField& at_2kappa) {
  FeResponseField out = at_kappa;
  for (std::size_t i = 0; i < out.nodes.size(); ++i)
    out.nodes[i] = 2.0 * at_kappa.nodes[i] - at_2kappa.nodes[i];
  if (out.tension.size()) out.tension = 2.0 * at_kappa.tension - at_2kappa.tension;
  return out;
}

FeResponseField quadratic_field_in_kappa(const FeResponseField& at_kappa,
                                         const FeResponseField& at_2kappa,
                                         const FeResponseField& at_4kappa) {
  FeResponseField out = at_kappa;
  for (std::size_t i = 0; i < out.nodes.size(); ++i)
    out.nodes[i] = (8.0 * at_kappa.nodes[i] - 6.0 * at_2kappa.nodes[i] + at_4kappa.nodes[i]) / 3.0;
  if (out.tension.size())
    out.tension = (8.0 * at_kappa.tension - 6.0 * at_2kappa.tension + at_4kappa.tension) / 3.0;
  return out;
}

FeResponseField richardson_field(const FeResponseField& coarse, const FeResponseField& fine) {
  const std::size_t elements = coarse.nodes.size() - 1;
  bool nested = fine.nodes.size() == 2 * elements + 1 && fine.pieces.size() == coarse.pieces.size();
  for (std::size_t k = 0; nested && k < coarse.pieces.size(); ++k)
    nested = fine.pieces[k].elements == 2 * coarse.pieces[k].elements;
  if (!nested)
    throw std::logic_error(
        "richardson_field: the fine mesh must have twice the coarse mesh's elements in every "
        "piece");
  FeResponseField out = coarse;
  for (std::size_t i = 0; i <= elements; ++i)
    out.nodes[i] = (4.0 * fine.nodes[2 * i] - coarse.nodes[i]) / 3.0;
  if (coarse.tension.size() == 0) return out;
  for (std::size_t k = 0; k < coarse.pieces.size(); ++k) {
    // The fine tensions of the same piece, at their midpoints, brought to the coarse midpoints.
    const FeFieldPiece& c = coarse.pieces[k];
    const FeFieldPiece& f = fine.pieces[k];
    const double* fine_tension = fine.tension.data() + f.first_element;
    const double h = f.element_length_m;
    for (int jj = 0; jj < c.elements; ++jj) {
      const Index j = c.first_element + jj;
      const double s = c.start_m + (static_cast<double>(jj) + 0.5) * c.element_length_m;
      const double at_s = cubic_interpolate(fine_tension, static_cast<std::size_t>(f.elements),
                                            f.start_m + 0.5 * h, h, s);
      out.tension[j] = (4.0 * at_s - coarse.tension[j]) / 3.0;
    }
  }
  return out;
}

namespace {

// The piece of `pieces` that holds s: the last one starting at or before it.
const FeFieldPiece& piece_at(const std::vector<FeFieldPiece>& pieces, double s) {
  const auto after =
      std::upper_bound(pieces.begin() + 1, pieces.end(), s,
                       [](double x, const FeFieldPiece& piece) { return x < piece.start_m; });
  return *(after - 1);
}

}  // namespace

FeSampled sample_field(Plane plane,
                       const FeResponseField& field,
                       const Vector& stations,
                       const StaticSolution& statics) {
  const std::vector<double> x = component(field.nodes, 0), z = component(field.nodes, 1);
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
    const FeFieldPiece& piece = piece_at(field.pieces, s);
    const double h = piece.element_length_m, start = piece.start_m;
    const auto first = static_cast<std::size_t>(piece.first_element);
    const auto nodes = static_cast<std::size_t>(piece.elements) + 1;
    const Vec2 d(cubic_interpolate(x.data() + first, nodes, start, h, s),
                 cubic_interpolate(z.data() + first, nodes, start, h, s));
    if (plane == Plane::InPlane) {
      out.u[p] = d.dot(statics.tangent(s));
      out.w[p] = d.dot(statics.normal(s));
      if (field.tension.size())
        out.tension[p] =
            cubic_interpolate(field.tension.data() + first, nodes - 1, start + 0.5 * h, h, s);
    } else {
      out.v[p] = d.x();
    }
  }
  return out;
}

double max_station_difference(const FeSampled& a, const FeSampled& b, bool tension) {
  if (tension) return max_abs_difference(a.tension, b.tension);
  return std::max(
      {max_abs_difference(a.u, b.u), max_abs_difference(a.w, b.w), max_abs_difference(a.v, b.v)});
}

}  // namespace catena::internal
