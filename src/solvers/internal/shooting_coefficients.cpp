// Static coefficients of the shooting solver: see shooting_coefficients.hpp.
#include "solvers/internal/shooting_coefficients.hpp"

#include <algorithm>
#include <cmath>

namespace catena::internal {

ShootingCoefficients ShootingCoefficients::from_statics(const StaticSolution& statics) {
  const CableProperties& cable = statics.cable();
  ShootingCoefficients c;
  c.length_m = cable.length_m;
  c.H = statics.horizontal_force_n();
  c.V_A = statics.vertical_force_a_n();
  c.W0 = cable.weight_n_per_m;
  c.compliance = cable.is_inextensible() ? 0.0 : 1.0 / cable.axial_stiffness_n;
  c.m = cable.mass_kg_per_m;
  c.M = cable.normal_mass_kg_per_m();
  c.t_ref = std::max(statics.tension_n(0.0), statics.tension_n(cable.length_m));
  return c;
}

double ShootingCoefficients::tension(double s) const { return std::hypot(H, V_A + W0 * s); }

Vec2 ShootingCoefficients::tangent(double s) const {
  const double V = V_A + W0 * s;
  const double T = std::hypot(H, V);
  return Vec2(H / T, V / T);
}

Vec2 ShootingCoefficients::normal(double s) const {
  const double V = V_A + W0 * s;
  const double T = std::hypot(H, V);
  return Vec2(-V / T, H / T);
}

double ShootingCoefficients::scaled_omega2(double omega_rad_s) const {
  return omega_rad_s * omega_rad_s * length_m * length_m * M / t_ref;
}

bool is_straight_inextensible(const ShootingCoefficients& k) {
  return k.H == 0.0 && k.compliance == 0.0;
}

double transverse_travel_time(const ShootingCoefficients& k) {
  constexpr int kIntervals = 64;
  const double h = k.length_m / kIntervals;
  double sum = 0.0;
  for (int i = 0; i <= kIntervals; ++i) {
    const double s = i * h;
    const double T = k.tension(s);
    const double value = std::sqrt(k.M * (1.0 + T * k.compliance) / T);
    const double weight = (i == 0 || i == kIntervals) ? 1.0 : (i % 2 ? 4.0 : 2.0);
    sum += weight * value;
  }
  return sum * h / 3.0;
}

}  // namespace catena::internal
