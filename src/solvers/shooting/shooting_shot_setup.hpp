// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The set-up shared by the undamped shot (shooting_integrator.hpp) and the damped one
/// (shooting_damped_integrator.hpp): the breaks of a general line in the order of integration and
/// the constant axial frame of the carried variables. Private to the shooting solver.

#include <cstddef>
#include <vector>

#include "solvers/shooting/shooting_coefficients.hpp"
#include "solvers/shooting/shooting_system.hpp"

namespace catena::internal {

/// A break of a general line in the order of integration: a joint or a point attachment, where
/// the stepper is restarted on the next piece (and the internal force jumps at a point).
struct Break {
  double x = 1.0;
  std::size_t next_piece = 0;
  int point = -1;  ///< index in ShootingCoefficients::points, -1 at a joint
};

/// The breaks of the line in the order of integration (none for a uniform cable).
std::vector<Break> breaks_of(const ShootingCoefficients& k, bool from_b);

/// The axial frame (shooting_integrator.hpp, "Axial frame"): a constant rotation to the mean
/// tangent (the bisector of the end tangents) and the axial stretch sigma, set in `data` (left
/// the identity when sigma < kMinAxialStretch).
void set_axial_frame(const ShootingCoefficients& k, RhsData& data);

/// The angle the static tangent turns through along the line, max - min over the pieces [rad].
double tangent_turn_rad(const ShootingCoefficients& k);

/// The balancing of a shot (shooting_integrator.hpp, "Balancing") at the scaled frequency
/// Omega = w L sqrt(M / T_ref): kappa^2 = max(r, 1) / b with the normal compliance scale
/// b = max(1, T_ref / EA) and the phase rate r = Omega sqrt(b), set in `data` (kappa2 and
/// balance_moves, true where kappa^2 moves with w, i.e. r > 1). For a static strain below 1 this
/// is kappa^2 = max(Omega, 1).
void set_balance(const ShootingCoefficients& k, double omega_scaled, bool balance, RhsData& data);

}  // namespace catena::internal
