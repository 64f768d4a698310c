// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The condition number of a forced response (docs/reference/verdicts.md, "Forced response:
/// conditioning"): near a natural frequency omega_n the response 1 / (omega_n^2 - Omega^2) moves by
/// 2 delta omega_n^2 / |omega_n^2 - Omega^2| for a relative change delta of omega_n, for ANY
/// solver. kappa(Omega) = max(1, max_n 2 omega_n^2 / |omega_n^2 - Omega^2|) is a property of the
/// physics, computed from the natural frequencies of the most accurate exact solver that ran, not
/// from any solver's self-reported error estimate.
///
/// A damped line's response 1 / (lambda_n^2 + Omega^2 ... ) is finite at resonance: with
/// lambda_n = -delta_n + i omega_n the resonant factor is |lambda_n|^2 - Omega^2 + 2 i delta_n
/// Omega, and kappa = max(1, max_n 2 |lambda_n|^2 / | |lambda_n|^2 - Omega^2 + 2 i delta_n Omega
/// |), at most about 1 / zeta_n: the same formula when every delta_n is 0.

#include <string>
#include <vector>

#include "catena/core/types.hpp"

namespace catena {

struct ForcedConditioning {
  /// The solver whose natural frequencies are used; empty when none could give them.
  std::string solver;
  Plane plane = Plane::InPlane;
  /// Its natural frequencies of the forced plane, lowest first and complete from mode 1 [rad/s].
  std::vector<double> omegas_rad_s;
  /// Their decay rates delta_n [1/s] on a damped line (same size), empty when undamped.
  std::vector<double> decay_rates_1_s;
  /// Where they came from, or why there are none.
  std::string note;

  /// True when the list reaches above `omega` (so the modes nearest to it are in it).
  bool covers(double omega) const;
  /// kappa(omega); 1 when the list does not cover omega (unknown: the strictest tolerance);
  /// infinite on a natural frequency.
  double condition(double omega) const;
};

}  // namespace catena
