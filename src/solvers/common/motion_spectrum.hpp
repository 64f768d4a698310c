// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The motion spectrum of end b of an irregular motion request on its quadrature grid
/// (docs/explanation/dynamic-tension.md, "Irregular motion"): a given spectrum table as it is, or
/// a JONSWAP wave spectrum times |RAO|^2 on `frequencies` equally spaced frequencies over the
/// RAO table's range (the RAO amplitude interpolated linearly). Integrals over omega are the
/// trapezoid rule on the grid.

#include "catena/core/types.hpp"
#include "catena/solvers/solve_request.hpp"

namespace catena::internal {

struct MotionSpectrum {
  Vector omega_rad_s;
  /// One-sided motion spectrum of end b along the motion direction [m^2 s/rad].
  Vector density_m2_s_per_rad;
  /// Trapezoid weights [rad/s]: int f domega ~ sum_k weight_k f(omega_k).
  Vector weight_rad_s;
};

/// JONSWAP wave elevation spectrum at omega [m^2 s/rad] (DNV-RP-C205 eq. 3.5.5, sigma = 0.07
/// below the peak and 0.09 above, A_gamma = 1 - 0.287 ln gamma).
double jonswap_density(const JonswapSpectrum& sea, double omega_rad_s);

/// The motion spectrum of an irregular request (MotionRequest::is_irregular()).
MotionSpectrum motion_spectrum(const MotionRequest& motion);

/// The trapezoid weights of an ascending grid.
Vector trapezoid_weights(const Vector& x);

}  // namespace catena::internal
