// SPDX-License-Identifier: MIT
// Mode shapes of the Airy model from the null vector of its boundary system.
#include "solvers/airy/airy_mode_shape.hpp"

#include <Eigen/SVD>
#include <boost/math/quadrature/gauss.hpp>
#include <cmath>

#include "solvers/airy/airy_boundary_system.hpp"

namespace catena::internal {

Vector transverse_travel_times(const StaticSolution& statics,
                               double normal_mass_kg_per_m,
                               const Vector& stations_m) {
  Vector times(stations_m.size());
  double travel = 0.0;
  double previous = 0.0;
  auto slowness = [&](double s) { return std::sqrt(normal_mass_kg_per_m / statics.tension_n(s)); };
  for (Index j = 0; j < stations_m.size(); ++j) {
    if (stations_m[j] > previous) {
      travel +=
          boost::math::quadrature::gauss<double, 20>::integrate(slowness, previous, stations_m[j]);
    }
    previous = stations_m[j];
    times[j] = travel;
  }
  return times;
}

AiryModeShape airy_mode_shape(const AiryModel& model,
                              const StaticSolution& statics,
                              double omega,
                              const Vector& stations_m,
                              const Vector& phases) {
  const BoundarySystem system = boundary_system(model, omega);
  Eigen::JacobiSVD<Eigen::Matrix4d> svd(system.matrix, Eigen::ComputeFullV);
  const Eigen::Vector4d singular = svd.singularValues();
  // The null vector of the equilibrated system, back in the raw columns' units.
  const Eigen::Vector4d coefficients = system.column_scale.cwiseProduct(svd.matrixV().col(3));
  AiryModeShape shape;
  shape.residual = singular[3] / singular[0];
  const Index n = stations_m.size();
  shape.w.resize(n);
  shape.u.resize(n);
  shape.tension_n.resize(n);
  for (Index j = 0; j < n; ++j) {
    const double s = stations_m[j];
    const double c = std::sqrt(statics.tension_n(s) / model.normal_mass);
    const StationRows rows =
        station_rows(model, omega, s, static_curvature(statics, s), c, phases[j], system.exponents);
    shape.w[j] = Eigen::Map<const Eigen::RowVector4d>(rows.w.data()).dot(coefficients);
    shape.u[j] = Eigen::Map<const Eigen::RowVector4d>(rows.u.data()).dot(coefficients);
    // tau = m omega^2 v with v = C1 Ai + C2 Bi (w_slow = -h alpha v).
    shape.tension_n[j] = model.mass * omega * omega *
                         (rows.slow_ai * coefficients[0] + rows.slow_bi * coefficients[1]);
  }
  return shape;
}

}  // namespace catena::internal
