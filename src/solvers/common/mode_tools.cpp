// SPDX-License-Identifier: MIT
#include "solvers/common/mode_tools.hpp"

#include <cmath>
#include <limits>
#include <string>

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

void set_damped_root(Mode& mode, std::complex<double> lambda, const DimensionlessGroups& groups) {
  set_mode_frequency(mode, lambda.imag(), groups);
  const double modulus = std::abs(lambda);
  // A decay rate at the rounding level of |lambda| is zero (an undamped plane of a damped line,
  // e.g. out of plane with axial damping only): rounding must not make a passive mode grow.
  const bool rounding =
      std::abs(lambda.real()) <= 64.0 * std::numeric_limits<double>::epsilon() * modulus;
  mode.decay_rate_1_s = rounding ? 0.0 : -lambda.real();
  mode.damping_ratio = modulus > 0.0 ? mode.decay_rate_1_s / modulus : 0.0;
}

double normalise_complex_mode(Mode& mode, const std::string& by) {
  using Complex = std::complex<double>;
  const Vector& re = by == "u" ? mode.u : by == "v" ? mode.v : mode.w;
  const Vector& im = by == "u" ? mode.u_imag : by == "v" ? mode.v_imag : mode.w_imag;
  mode.normalised_by = by;
  if (re.size() == 0) return 1.0;
  const Vector modulus = im.size() ? Vector(re.cwiseAbs2() + im.cwiseAbs2()) : re.cwiseAbs2();
  const Index at = first_argmax_abs(modulus);
  const Complex peak(re[at], im.size() ? im[at] : 0.0);
  if (peak == 0.0) return 1.0;
  const Complex factor = 1.0 / peak;
  const std::pair<Vector*, Vector*> parts[] = {{&mode.u, &mode.u_imag},
                                               {&mode.w, &mode.w_imag},
                                               {&mode.v, &mode.v_imag},
                                               {&mode.tension_n, &mode.tension_imag_n}};
  for (const auto& [real, imag] : parts) {
    if (real->size() == 0) continue;
    if (imag->size() == 0) *imag = Vector::Zero(real->size());
    for (Index j = 0; j < real->size(); ++j) {
      const Complex value = Complex((*real)[j], (*imag)[j]) * factor;
      (*real)[j] = value.real();
      (*imag)[j] = value.imag();
    }
  }
  if (mode.tension_n.size()) {
    mode.max_abs_tension_n =
        (mode.tension_n.cwiseAbs2() + mode.tension_imag_n.cwiseAbs2()).cwiseSqrt().maxCoeff();
  }
  return std::abs(factor);
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
  mode.u_imag = Vector();
  mode.w_imag = Vector();
  mode.v_imag = Vector();
  mode.tension_imag_n = Vector();
  mode.modal_mass_kg = -1.0;
}

}  // namespace catena::internal
