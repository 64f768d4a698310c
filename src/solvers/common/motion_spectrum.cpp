// SPDX-License-Identifier: MIT
// The motion spectrum of an irregular motion request: see motion_spectrum.hpp.
#include "solvers/common/motion_spectrum.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace catena::internal {
namespace {

// Linear interpolation in an ascending table; 0 outside it.
double interpolate(const std::vector<double>& x, const std::vector<double>& y, double at) {
  if (at < x.front() || at > x.back()) return 0.0;
  const std::size_t j =
      std::min<std::size_t>(std::upper_bound(x.begin(), x.end(), at) - x.begin(), x.size() - 1);
  if (j == 0) return y[0];
  const double t = (at - x[j - 1]) / (x[j] - x[j - 1]);
  return (1.0 - t) * y[j - 1] + t * y[j];
}

}  // namespace

double jonswap_density(const JonswapSpectrum& sea, double omega) {
  if (!(omega > 0.0)) return 0.0;
  const double omega_p = 2.0 * std::numbers::pi / sea.tp_s;
  const double r = omega_p / omega;
  const double pierson_moskowitz = 5.0 / 16.0 * sea.hs_m * sea.hs_m * std::pow(omega_p, 4) *
                                   std::pow(omega, -5) * std::exp(-1.25 * std::pow(r, 4));
  const double sigma = omega <= omega_p ? 0.07 : 0.09;
  const double x = (omega - omega_p) / (sigma * omega_p);
  const double peak = std::pow(sea.gamma, std::exp(-0.5 * x * x));
  return (1.0 - 0.287 * std::log(sea.gamma)) * pierson_moskowitz * peak;
}

Vector trapezoid_weights(const Vector& x) {
  const Eigen::Index n = x.size();
  Vector w = Vector::Zero(n);
  for (Eigen::Index k = 0; k + 1 < n; ++k) {
    const double h = x[k + 1] - x[k];
    w[k] += 0.5 * h;
    w[k + 1] += 0.5 * h;
  }
  return w;
}

MotionSpectrum motion_spectrum(const MotionRequest& motion) {
  MotionSpectrum out;
  if (motion.spectrum) {
    const SpectrumTable& table = *motion.spectrum;
    out.omega_rad_s = Eigen::Map<const Vector>(table.omega_rad_s.data(), table.omega_rad_s.size());
    out.density_m2_s_per_rad =
        Eigen::Map<const Vector>(table.density_m2_s_per_rad.data(), table.omega_rad_s.size());
  } else {
    const RaoTable& rao = *motion.rao;
    out.omega_rad_s =
        Vector::LinSpaced(motion.frequencies, rao.omega_rad_s.front(), rao.omega_rad_s.back());
    out.density_m2_s_per_rad.resize(motion.frequencies);
    const double height_factor = rao.per_wave_height ? 4.0 : 1.0;  // H = 2 a
    for (int k = 0; k < motion.frequencies; ++k) {
      const double omega = out.omega_rad_s[k];
      const double amplitude = interpolate(rao.omega_rad_s, rao.amplitude, omega);
      out.density_m2_s_per_rad[k] =
          height_factor * amplitude * amplitude * jonswap_density(*motion.jonswap, omega);
    }
  }
  out.weight_rad_s = trapezoid_weights(out.omega_rad_s);
  return out;
}

}  // namespace catena::internal
