// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The fixed point u = G(u) of the drag linearisation, by SUNDIALS KINSOL's fixed-point iteration
/// with Anderson acceleration (KIN_FP, KINSetMAA): the linearised drag feeds back on the response
/// that sets it, often with a negative slope near a resonance (more drag, less motion, less drag),
/// where the plain iteration oscillates; Anderson's secant steps converge there.

#include <functional>
#include <string>

#include "catena/core/types.hpp"

namespace catena::internal {

struct FixedPointOutcome {
  /// The last iterate.
  Vector u;
  /// Evaluations of G.
  long evaluations = 0;
  /// True when KINSOL reached max |G(u) - u| <= tolerance.
  bool reached = false;
  /// Why not, when not reached.
  std::string reason;
};

/// Iterates u <- G(u) from u0 with Anderson acceleration of depth min(5, size) until
/// max |G(u) - u| <= tolerance or `max_evaluations` evaluations. An exception thrown by G stops
/// the iteration and propagates (after KINSOL is freed).
FixedPointOutcome anderson_fixed_point(const std::function<Vector(const Vector&)>& G,
                                       const Vector& u0,
                                       double tolerance,
                                       long max_evaluations);

}  // namespace catena::internal
