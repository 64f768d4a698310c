// SPDX-License-Identifier: MIT
// Profiles along the cable from a shot: see shooting_profile.hpp.
#include "solvers/shooting/shooting_profile.hpp"

namespace catena::internal {

Profile evaluate_profile(const Shot& shot,
                         const Eigen::VectorXd& c,
                         const ShootingCoefficients& k,
                         const Vector& stations_m,
                         bool reversed,
                         Plane plane) {
  const Index n = stations_m.size();
  Profile p;
  if (plane == Plane::InPlane) {
    p.u.resize(n);
    p.w.resize(n);
    p.tension.resize(n);
  } else {
    p.v.resize(n);
  }
  for (Index j = 0; j < n; ++j) {
    // Shots from b record stations in reverse order.
    const std::size_t recorded = static_cast<std::size_t>(reversed ? n - 1 - j : j);
    const Eigen::VectorXd y = combine_at_station(shot, recorded, c);
    const double s = stations_m[j];
    if (plane == Plane::InPlane) {
      const Vec2 phi = k.length_m * y.head<2>();
      const Vec2 force = k.t_ref * y.tail<2>();
      const Vec2 t = k.tangent(s);
      p.u[j] = phi.dot(t);
      p.w[j] = phi.dot(k.normal(s));
      p.tension[j] = force.dot(t);
    } else {
      p.v[j] = k.length_m * y[0];
    }
  }
  return p;
}

ComplexProfile evaluate_damped_profile(const DampedShot& shot,
                                       const Eigen::VectorXcd& c,
                                       const ShootingCoefficients& k,
                                       const Vector& stations_m,
                                       bool reversed,
                                       Plane plane) {
  // The parts of the combination at each station as one-column shots of evaluate_profile.
  Shot parts[2];
  for (std::size_t j = 0; j < shot.station_y.size(); ++j) {
    const Eigen::VectorXcd y = combine_damped_at_station(shot, j, c);
    parts[0].station_y.emplace_back(y.real());
    parts[1].station_y.emplace_back(y.imag());
    parts[0].station_segment.push_back(0);
    parts[1].station_segment.push_back(0);
  }
  const Eigen::VectorXd one = Eigen::VectorXd::Ones(1);
  return {evaluate_profile(parts[0], one, k, stations_m, reversed, plane),
          evaluate_profile(parts[1], one, k, stations_m, reversed, plane)};
}

Profile string_as_inplane(const Profile& string) {
  Profile p;
  p.w = string.v;
  p.u = Vector::Zero(string.v.size());
  p.tension = Vector::Zero(string.v.size());
  return p;
}

std::vector<double> scaled_stations(const Vector& stations_m, double length_m, bool reversed) {
  std::vector<double> x(static_cast<std::size_t>(stations_m.size()));
  const Index n = stations_m.size();
  for (Index j = 0; j < n; ++j) {
    const double s = stations_m[reversed ? n - 1 - j : j];
    x[static_cast<std::size_t>(j)] = reversed ? 1.0 - s / length_m : s / length_m;
  }
  return x;
}

}  // namespace catena::internal
