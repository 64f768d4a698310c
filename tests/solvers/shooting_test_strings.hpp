#pragma once
// Exact test problems for the shooting solver's internal parts: a straight horizontal string
// under tension T with no weight, whose principal solutions are sines and cosines. One place, so
// the tests of the integrator, root finder, modes and forced response share it.

#include <cmath>

#include "solvers/internal/shooting_coefficients.hpp"

namespace catena::testing {

/// A weightless horizontal cable of length L under tension T (t_ref = T), mass m = M = 1 kg/m;
/// ea = 0 means inextensible. Tangent (1, 0), normal (0, 1).
inline internal::ShootingCoefficients horizontal_string(double tension_n, double length_m,
                                                        double ea_n = 0.0) {
  internal::ShootingCoefficients k;
  k.length_m = length_m;
  k.H = tension_n;
  k.V_A = 0.0;
  k.W0 = 0.0;
  k.compliance = ea_n > 0.0 ? 1.0 / ea_n : 0.0;
  k.m = 1.0;
  k.M = 1.0;
  k.t_ref = tension_n;
  return k;
}

/// Transverse wavenumber sqrt(M (1+e) / T) omega [1/m] of that string.
inline double transverse_wavenumber(const internal::ShootingCoefficients& k, double omega) {
  const double e = k.H * k.compliance;
  return omega * std::sqrt(k.M * (1.0 + e) / k.H);
}

}  // namespace catena::testing
