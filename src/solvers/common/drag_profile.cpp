// SPDX-License-Identifier: MIT
// The linearised drag of one fixed-point iterate: see drag_profile.hpp.
#include "solvers/common/drag_profile.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace catena::internal {

DragProfile::DragProfile(const Problem& problem, Vector stations, DragLinearisation linearisation)
    : stations_(std::move(stations)),
      normal_scale_(Vector::Zero(stations_.size())),
      tangential_scale_(Vector::Zero(stations_.size())) {
  const double a = linearisation == DragLinearisation::Harmonic ? 8.0 / (3.0 * std::numbers::pi)
                                                                : std::sqrt(8.0 / std::numbers::pi);
  const double half_rho = 0.5 * problem.environment.water_density_kg_per_m3;
  const Line line = problem.as_line();
  double s = 0.0;
  for (const LineSegment& segment : line.segments) {
    const MorisonDrag& drag = segment.drag;
    segment_start_.push_back(s);
    normal_factor_.push_back(a * half_rho * drag.normal * drag.diameter_m);
    tangential_factor_.push_back(a * half_rho * drag.tangential * std::numbers::pi *
                                 drag.diameter_m);
    s += segment.length_m;
  }
}

void DragProfile::set_velocity_scales(const Vector& normal, const Vector& tangential) {
  normal_scale_ = normal;
  tangential_scale_ = tangential;
}

std::size_t DragProfile::segment_of(double s) const {
  const auto after = std::upper_bound(segment_start_.begin(), segment_start_.end(), s);
  return after == segment_start_.begin() ? 0 : std::size_t(after - segment_start_.begin()) - 1;
}

double DragProfile::value_of(const Vector& values, double s) const {
  const Eigen::Index n = stations_.size();
  if (s <= stations_[0]) return values[0];
  if (s >= stations_[n - 1]) return values[n - 1];
  const auto* begin = stations_.data();
  const Eigen::Index j = Eigen::Index(std::upper_bound(begin, begin + n, s) - begin) - 1;
  const double t = (s - stations_[j]) / (stations_[j + 1] - stations_[j]);
  return (1.0 - t) * values[j] + t * values[j + 1];
}

// The mean of the piecewise linear interpolant over [s0, s1]: the trapezoid rule on the stations
// inside and the two ends (exact for a piecewise linear function).
double DragProfile::mean_of(const Vector& values, double s0, double s1) const {
  if (!(s1 > s0)) return value_of(values, s0);
  double area = 0.0;
  double left = s0, left_value = value_of(values, s0);
  for (Eigen::Index j = 0; j < stations_.size(); ++j) {
    if (stations_[j] <= s0) continue;
    if (stations_[j] >= s1) break;
    area += 0.5 * (left_value + values[j]) * (stations_[j] - left);
    left = stations_[j];
    left_value = values[j];
  }
  area += 0.5 * (left_value + value_of(values, s1)) * (s1 - left);
  return area / (s1 - s0);
}

double DragProfile::normal_at(double s, std::size_t segment) const {
  return normal_factor_[segment] * value_of(normal_scale_, s);
}

double DragProfile::tangential_at(double s, std::size_t segment) const {
  return tangential_factor_[segment] * value_of(tangential_scale_, s);
}

double DragProfile::normal_mean(double s0, double s1, std::size_t segment) const {
  return normal_factor_[segment] * mean_of(normal_scale_, s0, s1);
}

double DragProfile::tangential_mean(double s0, double s1, std::size_t segment) const {
  return tangential_factor_[segment] * mean_of(tangential_scale_, s0, s1);
}

Vector DragProfile::normal_at_stations() const {
  Vector c(stations_.size());
  for (Eigen::Index j = 0; j < c.size(); ++j)
    c[j] = normal_factor_[segment_of(stations_[j])] * normal_scale_[j];
  return c;
}

Vector DragProfile::tangential_at_stations() const {
  Vector c(stations_.size());
  for (Eigen::Index j = 0; j < c.size(); ++j)
    c[j] = tangential_factor_[segment_of(stations_[j])] * tangential_scale_[j];
  return c;
}

bool DragProfile::has_drag() const {
  for (std::size_t i = 0; i < normal_factor_.size(); ++i) {
    if (normal_factor_[i] != 0.0 || tangential_factor_[i] != 0.0) return true;
  }
  return false;
}

}  // namespace catena::internal
