// SPDX-License-Identifier: MIT
#pragma once
// Exact test problems for the shooting solver's internal parts: a straight horizontal string
// under tension T with no weight, whose principal solutions are sines and cosines. One place, so
// the tests of the integrator, root finder, modes and forced response share it.

#include <cmath>

#include "catena/core/types.hpp"
#include "solvers/shooting/shooting_coefficients.hpp"
#include "solvers/shooting/shooting_conjugate_count.hpp"
#include "solvers/shooting/shooting_integrator.hpp"

namespace catena::testing {

/// A weightless horizontal cable of length L under tension T (t_ref = T), mass m = M = 1 kg/m;
/// ea = 0 means inextensible. Tangent (1, 0), normal (0, 1).
inline internal::ShootingCoefficients horizontal_string(double tension_n,
                                                        double length_m,
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

/// The exact end frame of D uncoupled strings on a unit length whose phases are
/// pi rates[j] phase(omega): Phi = diag(sin), F = diag(cos), the integrated phase and the count,
/// angles and determinant of count_conjugate_points, as a shot of the integrator would give them.
/// String j's eigenfrequencies are where rates[j] phase(omega) is an integer.
template <int D, typename Phase>
internal::Shot exact_string_frame(const Phase& phase, double omega, const double (&rates)[D]) {
  internal::FrameBlock<D> Phi = internal::FrameBlock<D>::Zero(),
                          F = internal::FrameBlock<D>::Zero();
  double theta = internal::initial_phase(D);
  for (int j = 0; j < D; ++j) {
    const double x = kPi * rates[j] * phase(omega);
    Phi(j, j) = std::sin(x);
    F(j, j) = std::cos(x);
    theta -= x;
  }
  const internal::ConjugateCount c = internal::count_conjugate_points<D>(Phi, F, theta);
  internal::Shot shot;
  shot.omega_rad_s = omega;
  shot.count = c.count;
  shot.angle_min = c.angle_min;
  shot.angle_max = c.angle_max;
  shot.determinant = c.determinant;
  shot.phase_defect = c.phase_defect;
  return shot;
}

}  // namespace catena::testing
