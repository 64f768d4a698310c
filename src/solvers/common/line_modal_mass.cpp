// SPDX-License-Identifier: MIT
// The modal mass of a general line's mode: see line_modal_mass.hpp.
#include "solvers/common/line_modal_mass.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace catena::internal {

namespace {

// The mode's squared displacements at arc length s, interpolated linearly between stations:
// (u^2, w^2) in plane, (v^2, 0) out of plane.
Vec2 squared_motion_at(Plane plane, const Mode& mode, double s) {
  const Vector& x = mode.s_m;
  const Index n = x.size();
  const Index k = std::clamp<Index>(
      static_cast<Index>(std::upper_bound(x.data(), x.data() + n, s) - x.data()), 1, n - 1);
  const double f = (s - x[k - 1]) / (x[k] - x[k - 1]);
  auto at = [&](const Vector& y) { return (1.0 - f) * y[k - 1] + f * y[k]; };
  if (plane == Plane::OutOfPlane) return Vec2(std::pow(at(mode.v), 2), 0.0);
  return Vec2(std::pow(at(mode.u), 2), std::pow(at(mode.w), 2));
}

}  // namespace

double line_modal_mass(Plane plane,
                       const Mode& mode,
                       const Line& line,
                       const StaticSolution& statics) {
  if (mode.s_m.size() < 2) return -1.0;
  auto density = [&](double s, const Vec2& motion) {
    const LineSegment segment = statics.segment_at(s);
    return plane == Plane::InPlane ? segment.tangential_mass_kg_per_m() * motion.x() +
                                         segment.normal_mass_kg_per_m() * motion.y()
                                   : segment.normal_mass_kg_per_m() * motion.x();
  };
  double sum = 0.0;
  for (Index k = 1; k < mode.s_m.size(); ++k) {
    std::vector<double> cuts = {mode.s_m[k - 1]};
    for (std::size_t j = 1; j < line.segments.size(); ++j) {
      const double joint = line.segment_start_m(j);
      if (joint > cuts.front() && joint < mode.s_m[k]) cuts.push_back(joint);
    }
    cuts.push_back(mode.s_m[k]);
    for (std::size_t c = 1; c < cuts.size(); ++c) {
      const double a = cuts[c - 1], b = cuts[c], middle = 0.5 * (a + b);
      sum += 0.5 * (b - a) *
             (density(middle, squared_motion_at(plane, mode, a)) +
              density(middle, squared_motion_at(plane, mode, b)));
    }
  }
  for (const PointAttachment& point : line.points) {
    const Vec2 motion = squared_motion_at(plane, mode, point.s_m);
    sum += plane == Plane::InPlane
               ? (point.mass_kg + point.tangential_added_mass_kg()) * motion.x() +
                     (point.mass_kg + point.normal_added_mass_kg()) * motion.y()
               : (point.mass_kg + point.outofplane_added_mass_kg()) * motion.x();
  }
  return sum;
}

}  // namespace catena::internal
