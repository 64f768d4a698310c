// SPDX-License-Identifier: MIT
#include "solvers/common/mode_tools.hpp"

#include <cmath>

namespace catena::internal {
namespace {

// Index of the first entry of largest magnitude (first: so that ties resolve the same way in
// every solver).
Index first_argmax_abs(const Vector& values) {
  Index best = 0;
  for (Index i = 1; i < values.size(); ++i) {
    if (std::abs(values[i]) > std::abs(values[best]) * (1.0 + 1e-9)) best = i;
  }
  return best;
}

double scale_mode(Mode& mode, const Vector& reference) {
  if (reference.size() == 0) return 1.0;
  const Index at = first_argmax_abs(reference);
  const double peak = reference[at];
  if (peak == 0.0) return 1.0;
  const double factor = 1.0 / peak;
  if (mode.u.size()) mode.u *= factor;
  if (mode.w.size()) mode.w *= factor;
  if (mode.v.size()) mode.v *= factor;
  if (mode.tension_n.size()) {
    mode.tension_n *= factor;
    mode.max_abs_tension_n = mode.tension_n.cwiseAbs().maxCoeff();
  }
  return factor;
}

}  // namespace

void set_mode_frequency(Mode& mode, double omega_rad_s, const DimensionlessGroups& groups) {
  mode.omega_rad_s = omega_rad_s;
  mode.frequency_hz = omega_rad_s / (2.0 * kPi);
  mode.k_l_over_pi = groups.k_l_over_pi(omega_rad_s);
  mode.gale_ratio = groups.gale_ratio(omega_rad_s);
}

double normalise_inplane_mode(Mode& mode) {
  const double max_w = mode.w.size() ? mode.w.cwiseAbs().maxCoeff() : 0.0;
  const double max_u = mode.u.size() ? mode.u.cwiseAbs().maxCoeff() : 0.0;
  if (max_w > 1e-6 * max_u) {
    mode.normalised_by = "w";
    return scale_mode(mode, mode.w);
  }
  mode.normalised_by = "u";
  return scale_mode(mode, mode.u);
}

double normalise_outofplane_mode(Mode& mode) {
  mode.normalised_by = "v";
  return scale_mode(mode, mode.v);
}

double integrate_on_stations(const Vector& s, const Vector& f) {
  double sum = 0.0;
  for (Index i = 1; i < s.size(); ++i) sum += 0.5 * (s[i] - s[i - 1]) * (f[i] + f[i - 1]);
  return sum;
}

double inplane_modal_mass(const Mode& mode, double mass_kg_per_m, double normal_mass_kg_per_m) {
  const Vector density =
      mass_kg_per_m * mode.u.array().square() + normal_mass_kg_per_m * mode.w.array().square();
  return integrate_on_stations(mode.s_m, density);
}

double outofplane_modal_mass(const Mode& mode, double normal_mass_kg_per_m) {
  const Vector density = normal_mass_kg_per_m * mode.v.array().square();
  return integrate_on_stations(mode.s_m, density);
}

void drop_shape_fields(Mode& mode) {
  mode.s_m = Vector();
  mode.u = Vector();
  mode.w = Vector();
  mode.v = Vector();
  mode.tension_n = Vector();
  mode.modal_mass_kg = -1.0;
}

}  // namespace catena::internal
