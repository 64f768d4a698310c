// SPDX-License-Identifier: MIT
// J0 and Y0 in modulus-phase form (see airy_bessel_phase.hpp): Boost.Math for small arguments,
// the Hankel expansion for large ones.
#include "solvers/airy/airy_bessel_phase.hpp"

#include <boost/math/special_functions/bessel.hpp>
#include <cmath>
#include <limits>

#include "catena/core/types.hpp"

namespace catena::internal {
namespace {

// H0^(1)(z) = sqrt(2/(pi z)) e^{i(z - pi/4)} (P + i Q) with P + i Q ~ sum_k i^k a_k / z^k,
// a_k = a_{k-1} (-(2k - 1)^2) / (8 k), a_0 = 1 (DLMF 10.17.1-10.17.3 at nu = 0). Summed while
// the terms decrease; at z >= 25 they fall below 1e-17 first.
BesselZeroPhase hankel_expansion(double z) {
  double p = 1.0;
  double q = 0.0;
  double a = 1.0;  // a_k / z^k
  double previous = 1.0;
  for (int k = 1; k < 200; ++k) {
    a *= -(2.0 * k - 1.0) * (2.0 * k - 1.0) / (8.0 * k * z);
    const double size = std::abs(a);
    if (size > previous || size < 1e-18) break;
    previous = size;
    // i^k: k = 1 -> i, 2 -> -1, 3 -> -i, 4 -> 1.
    switch (k % 4) {
      case 1:
        q += a;
        break;
      case 2:
        p -= a;
        break;
      case 3:
        q -= a;
        break;
      default:
        p += a;
        break;
    }
  }
  return {std::atan2(q, p), std::sqrt(2.0 / kPi) * std::hypot(p, q)};
}

// From Boost's J0, Y0: theta = atan2(Y0, J0) up to a multiple of 2 pi, which is fixed by
// |phi| < pi/4 (phi is the offset of the continuous phase from z - pi/4).
BesselZeroPhase from_boost(double z) {
  const double j0 = boost::math::cyl_bessel_j(0, z);
  const double y0 = boost::math::cyl_neumann(0, z);
  const double offset = std::remainder(std::atan2(y0, j0) - (z - 0.25 * kPi), 2.0 * kPi);
  return {offset, std::sqrt(z * (j0 * j0 + y0 * y0))};
}

}  // namespace

BesselZeroPhase bessel_zero_phase(double z) {
  // z -> 0: theta -> -pi/2 (Y0 -> -inf), sqrt(z) M(z) ~ sqrt(z) (2/pi) |ln z| -> 0.
  if (!(z > 0.0)) return {-0.25 * kPi, 0.0};
  if (z == std::numeric_limits<double>::infinity()) return {0.0, std::sqrt(2.0 / kPi)};
  return z >= kBesselHankelThreshold ? hankel_expansion(z) : from_boost(z);
}

}  // namespace catena::internal
