// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Closed forms of one piece of elastic catenary with end forces (H, V_A) at its start
/// (docs/explanation/physics.md): its offset, the Jacobian of its end offset, its stretched length.
/// The weight per length may be positive (sagging), zero (a straight bar) or negative (hogging), so
/// the same forms serve the uniform cable and every piece of a general line.

#include <Eigen/Dense>

#include "catena/core/types.hpp"
#include "catena/models/cable.hpp"

namespace catena::internal {

/// 1/EA, 0 when inextensible [1/N].
inline double inverse_stiffness(const CableProperties& cable) {
  return cable.is_inextensible() ? 0.0 : 1.0 / cable.axial_stiffness_n;
}

/// asinh(V/H) - asinh(V_A/H), written so that neither branch cancels (W0s = V - V_A).
double asinh_difference(double H, double V_A, double V, double T_A, double T, double W0s);

/// r(s) - r(0) of the piece with force (H, V_A) at its start, s in [0, cable.length_m] [m].
Vec2 offset(const CableProperties& cable, double H, double V_A, double s);

/// d r(L) / d(H, V_A) of the piece (L = cable.length_m).
Eigen::Matrix2d offset_jacobian(const CableProperties& cable, double H, double V_A);

/// Stretched length of [0, s] of the piece [m].
double stretched_increment(const CableProperties& cable, double H, double V_A, double s);

}  // namespace catena::internal
