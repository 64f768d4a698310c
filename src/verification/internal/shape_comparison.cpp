// SPDX-License-Identifier: MIT
#include "verification/internal/shape_comparison.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "catena/core/error.hpp"

namespace catena::internal {
namespace {

// Linear interpolation of `values` (on ascending `stations`) at s. Catena's stations are dense
// (docs/how-to/check.md: 2001 points), so the interpolation error is far below any MAC of interest.
double interpolate(const Vector& stations, const Vector& values, double s) {
  const Index n = stations.size();
  const double* begin = stations.data();
  Index j = static_cast<Index>(std::upper_bound(begin, begin + n, s) - begin);
  j = std::clamp<Index>(j, 1, n - 1);
  const double t = (s - stations[j - 1]) / (stations[j] - stations[j - 1]);
  return values[j - 1] + t * (values[j] - values[j - 1]);
}

Vector interpolate_all(const Vector& stations, const Vector& values, const Vector& at) {
  Vector out(at.size());
  for (Index i = 0; i < at.size(); ++i) out[i] = interpolate(stations, values, at[i]);
  return out;
}

// The displacement components the plane has, concatenated: the other's and Catena's at the same
// stations.
void displacement_vectors(const ExternalShape& shape,
                          Plane plane,
                          const ReferenceMode& ref,
                          Vector& other,
                          Vector& catena) {
  std::vector<std::pair<const Vector*, const Vector*>> parts;
  if (plane == Plane::InPlane) {
    if (shape.u.size() > 0) parts.push_back({&shape.u, &ref.u});
    if (shape.w.size() > 0) parts.push_back({&shape.w, &ref.w});
  } else {
    parts.push_back({&shape.v, &ref.v});
  }
  const Index n = shape.s_m.size();
  other.resize(n * static_cast<Index>(parts.size()));
  catena.resize(other.size());
  for (std::size_t k = 0; k < parts.size(); ++k) {
    other.segment(static_cast<Index>(k) * n, n) = *parts[k].first;
    catena.segment(static_cast<Index>(k) * n, n) =
        interpolate_all(ref.s_m, *parts[k].second, shape.s_m);
  }
}

}  // namespace

void validate_external_shape(const ExternalShape& shape,
                             Plane plane,
                             double length_m,
                             const std::string& origin) {
  const Index n = shape.s_m.size();
  auto fail = [&](const std::string& why) {
    throw InvalidInput(fmt::format("{}: shape: {}", origin, why));
  };
  if (n < 2) fail("needs at least two stations");
  for (Index i = 0; i < n; ++i) {
    if (!std::isfinite(shape.s_m[i]) || shape.s_m[i] < 0.0 ||
        shape.s_m[i] > length_m * (1.0 + 1e-9)) {
      fail(fmt::format("station s = {} m outside [0, L = {} m]", shape.s_m[i], length_m));
    }
    if (i > 0 && !(shape.s_m[i] > shape.s_m[i - 1]))
      fail(fmt::format("stations not ascending at s = {} m", shape.s_m[i]));
  }
  const bool inplane = plane == Plane::InPlane;
  if (inplane && shape.v.size() > 0) fail("an in-plane mode has no v (out-of-plane) displacement");
  if (!inplane && (shape.u.size() > 0 || shape.w.size() > 0))
    fail("an out-of-plane mode has only v, not u or w");
  if (inplane && shape.u.size() == 0 && shape.w.size() == 0) fail("an in-plane shape needs u or w");
  if (!inplane && shape.v.size() == 0) fail("an out-of-plane shape needs v");
  for (const auto& [name, values] : {std::pair{"u", &shape.u},
                                     {"w", &shape.w},
                                     {"v", &shape.v},
                                     {"tension_n", &shape.tension_n}}) {
    if (values->size() > 0 && values->size() != n) {
      fail(fmt::format("{} has {} values for {} stations", name, values->size(), n));
    }
    if (values->size() > 0 && !values->allFinite()) fail(fmt::format("{} is not finite", name));
  }
  Vector other;
  Vector unused;
  ReferenceMode dummy;
  dummy.s_m = shape.s_m;
  dummy.u = dummy.w = dummy.v = shape.s_m;
  displacement_vectors(shape, plane, dummy, other, unused);
  if (other.squaredNorm() == 0.0) fail("every displacement is zero");
}

ShapeComparison compare_shape(const ExternalShape& shape, Plane plane, const ReferenceMode& ref) {
  Vector other;
  Vector catena;
  displacement_vectors(shape, plane, ref, other, catena);
  ShapeComparison out;
  const double cross = other.dot(catena);
  out.mac = cross * cross / (other.squaredNorm() * catena.squaredNorm());
  if (shape.tension_n.size() > 0 && ref.tension_n.size() > 0) {
    const double alpha = cross / other.squaredNorm();
    const Vector tension = interpolate_all(ref.s_m, ref.tension_n, shape.s_m);
    const double scale = tension.cwiseAbs().maxCoeff();
    out.tension_relative =
        scale > 0.0 ? (alpha * shape.tension_n - tension).cwiseAbs().maxCoeff() / scale : 0.0;
  }
  return out;
}

}  // namespace catena::internal
