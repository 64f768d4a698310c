// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Least-squares refinement of the poles of a free decay, with the amplitudes eliminated (variable
/// projection), and the poles' covariance from its Jacobian
/// (docs/explanation/methods/identification.md, "Refinement" and "Uncertainty").

#include <Eigen/Core>
#include <complex>
#include <vector>

#include "catena/core/types.hpp"

namespace catena::internal {

/// The fitted model: each channel c is a_c0 + sum_k Re(amplitudes[c][k] exp(lambda_k tau)).
struct PoleFit {
  std::vector<std::complex<double>> poles_1_s;  // lambda_k = -delta_k + i omega_k, omega_k > 0
  /// Covariance of (delta_k, omega_k) [1/s^2], sigma^2 (J^T J)^-1 with sigma^2 the residual
  /// variance: the Cramer-Rao bound's estimate for white noise. Infinite where J^T J is singular.
  std::vector<Eigen::Matrix2d> covariance;
  std::vector<std::vector<std::complex<double>>> amplitudes;  // [channel][pole], at tau = 0
  std::vector<double> residual_variance;                      // per channel, of y - model
  bool converged = false;
};

/// Fits poles shared by all channels to y_c(tau) (same length as tau, tau [s] from the first
/// sample), starting from `initial` (Im > 0), by Levenberg-Marquardt (Eigen's MINPACK port) on the
/// variable-projection functional (Golub & Pereyra 1973, Kaufman's Jacobian). With several channels
/// a second pass weights each by the inverse of its residual standard deviation.
PoleFit refine_poles(const Vector& tau_s,
                     const std::vector<Vector>& channels,
                     const std::vector<std::complex<double>>& initial);

}  // namespace catena::internal
