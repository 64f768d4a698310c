// SPDX-License-Identifier: MIT
#include "common/sigma_ode.hpp"

namespace catena_tools {

double clamped_end_determinant(bool inplane,
                               double s1,
                               double s2,
                               double omega,
                               const SigmaOdeSettings& settings,
                               bool normalised) {
  const double w2 = omega * omega;
  if (inplane) {
    const auto a = integrate_sigma_ode<4>({0, 0, 1, 0}, s1, s2, w2, settings);
    const auto b = integrate_sigma_ode<4>({0, 0, 0, 1}, s1, s2, w2, settings);
    const double det = a[0] * b[1] - a[1] * b[0];
    if (!normalised) return det;
    const double na = std::hypot(std::hypot(a[0], a[1]), std::hypot(a[2], a[3]));
    const double nb = std::hypot(std::hypot(b[0], b[1]), std::hypot(b[2], b[3]));
    return det / (na * nb);
  }
  const auto a = integrate_sigma_ode<2>({0, 1}, s1, s2, w2, settings);
  return normalised ? a[0] / std::hypot(a[0], a[1]) : a[0];
}

double bisect_natural_frequency(bool inplane,
                                double s1,
                                double s2,
                                double guess,
                                double half_width,
                                int iterations,
                                const SigmaOdeSettings& settings) {
  double lo = guess * (1 - half_width);
  double hi = guess * (1 + half_width);
  double flo = clamped_end_determinant(inplane, s1, s2, lo, settings);
  if ((flo < 0) == (clamped_end_determinant(inplane, s1, s2, hi, settings) < 0)) return NAN;
  for (int it = 0; it < iterations; ++it) {
    const double mid = 0.5 * (lo + hi);
    const double fm = clamped_end_determinant(inplane, s1, s2, mid, settings);
    if ((fm < 0) == (flo < 0)) {
      lo = mid;
      flo = fm;
    } else {
      hi = mid;
    }
  }
  return 0.5 * (lo + hi);
}

}  // namespace catena_tools
