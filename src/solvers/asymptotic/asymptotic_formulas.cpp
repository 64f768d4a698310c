// SPDX-License-Identifier: MIT
// Grinfogel's shape formulas (34), (28), (37). Transcribed from the
// paper's printed equations after checking them against their own derivation (eqs. 24, 27, 29,
// 32): w(0) = 0 exactly, and the second-order near-cross-over bracket of (34) is multiplied by
// eps^2 sin^2(phi_a) as in (29) and (32) (the printed (34) shows eps^2 sin(phi_a)).
#include "solvers/asymptotic/asymptotic_formulas.hpp"

#include <cmath>

#include "catena/solvers/asymptotic_solver.hpp"  // the enumerators of AsymptoticShapeFormula

namespace catena::internal {

AsymptoticModeShape asymptotic_mode_shape(const Vector& stations_m,
                                          double length_m,
                                          double kl,
                                          double eps,
                                          double phi_rad,
                                          double lambda2,
                                          AsymptoticShapeFormula formula) {
  const bool mirrored = std::sin(phi_rad) < 0.0;
  const double e1 = eps * std::abs(std::sin(phi_rad));
  const double inv_lambda2 = std::isinf(lambda2) ? 0.0 : 1.0 / lambda2;
  const double detuning = kl * kl * inv_lambda2 - 1.0;  // k^2 L^2 / lambda^2 - 1
  const double half_sin = std::sin(0.5 * kl);
  const double s2 = 2.0 * half_sin * half_sin;  // 2 sin^2(kL/2) = 1 - cos kL, without cancellation
  const double cos_kl = std::cos(kl);
  const double b = std::sin(kl) + kl * detuning;
  const double u_over_w = eps * std::cos(phi_rad) / kl;

  AsymptoticModeShape shape;
  const Index n = stations_m.size();
  shape.w.resize(n);
  shape.u.resize(n);
  for (Index j = 0; j < n; ++j) {
    const double xi_raw = stations_m[j] / length_m;
    const double xi = mirrored ? 1.0 - xi_raw : xi_raw;
    const double theta = kl * xi;
    const double c = std::cos(theta);
    const double s = std::sin(theta);
    // Eq. (28): the zeroth-order transverse shape.
    double w = s2 * (c - 1.0) - s * b;
    if (formula == AsymptoticShapeFormula::Eq34) {
      const double first =
          0.25 * e1 *
          (s2 * (theta * (xi - 1.0) * s - (xi - 0.5) * c) + 0.5 * c * (15.0 - cos_kl) +
           (-0.5 * s + (xi - 1.0) * theta * c + (xi - 0.5) * s) * b +
           4.0 * (-1.0 - 0.75 * cos_kl + 2.0 * s2 * (xi - 0.5)));
      const double second = e1 * e1 *
                            (3.5 * (xi - 0.5) + 1.75 * c - (7.0 / 16.0) * (xi - 0.5) * c -
                             7.0 / 32.0 + (7.0 / 16.0) * theta * (xi - 1.0) * s);
      w += first + second;
    }
    // Eq. (37), the leading-order longitudinal shape.
    const double u = b * (c - 1.0) + s2 * (kl * detuning * xi + s) + 1.75 * e1 * s;
    shape.w[j] = mirrored ? -w : w;
    shape.u[j] = (mirrored ? -u : u) * u_over_w;
  }
  shape.slow_amplitude = s2 + 1.75 * e1;
  return shape;
}

}  // namespace catena::internal
