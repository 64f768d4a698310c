// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Closed-form in-plane mode shapes of Grinfogel (1984) used by the asymptotic solver (notation
/// in include/catena/solvers/asymptotic_solver.hpp and docs/explanation/methods/asymptotic.md).
/// What the asymptotic and airy solvers share (WKB out of plane, static strain) is in
/// taut_cable_theory.hpp.

#include "catena/core/types.hpp"

namespace catena {
/// Defined in catena/solvers/asymptotic_solver.hpp (the option that picks eq. 34 or 28); only
/// declared here so that this internal header does not depend on the solver's public API.
enum class AsymptoticShapeFormula;
}  // namespace catena

namespace catena::internal {

/// One in-plane mode evaluated on stations, in the units of the paper's brackets (the common
/// factor C4 Sf / det A is set to 1).
struct AsymptoticModeShape {
  /// Transverse (normal) displacement w(s_j): eq. (34) or (28).
  Vector w;
  /// Tangential displacement u(s_j): eq. (37) times eps cos(phi_a) / kL (= Sf'/Sf).
  Vector u;
  /// Leading-order slow transverse amplitude -w_slow = S2 + 7/4 e1 (eqs. 24, 29, 38), in the same
  /// units; the dynamic tension is M omega^2 slow_amplitude L / (eps cos phi_a).
  double slow_amplitude = 0.0;
};

/// Evaluates eqs. (34)/(28) and (37) at the stations s_j [m] of a cable of length L [m] for the
/// root kL. For a falling chord (sin phi_a < 0) the formulas, written with s from the lower end,
/// are evaluated on the mirrored cable (s -> L - s, u -> -u, w -> -w).
AsymptoticModeShape asymptotic_mode_shape(const Vector& stations_m,
                                          double length_m,
                                          double kl,
                                          double eps,
                                          double phi_rad,
                                          double lambda2,
                                          AsymptoticShapeFormula formula);

}  // namespace catena::internal
