// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The condition number of a forced response (docs/reference/verdicts.md, "Forced response:
/// conditioning"): near a natural frequency omega_n the response 1 / (omega_n^2 - Omega^2) moves by
/// 2 delta omega_n^2 / |omega_n^2 - Omega^2| for a relative change delta of omega_n, for ANY
/// solver. kappa(Omega) = max(1, max_n 2 omega_n^2 / |omega_n^2 - Omega^2|) is a property of the
/// physics, computed from the natural frequencies of the most accurate exact solver that ran, not
/// from any solver's self-reported error estimate.

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
  /// Where they came from, or why there are none.
  std::string note;

  /// True when the list reaches above `omega` (so the modes nearest to it are in it).
  bool covers(double omega) const;
  /// kappa(omega); 1 when the list does not cover omega (unknown: the strictest tolerance);
  /// infinite on a natural frequency.
  double condition(double omega) const;
};

}  // namespace catena
