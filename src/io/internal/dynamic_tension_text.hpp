// SPDX-License-Identifier: MIT
#pragma once
// `catena solve`'s text for one solver's dynamic tension in waves (docs/reference/json-layout.md,
// "Dynamic tension in waves", has every value): the fairlead and the anchor, beside the mean
// (static) tension, and the fixed point of the drag linearisation (iterations, residual).

#include <string>
#include <vector>

#include "catena/solvers/modal_result.hpp"

namespace catena::internal {

/// The lines printed under a solver (each starting with `indent`), empty when `tensions` is:
///   regular, one row per period and end: T, s, mean, amplitude, phase, max = mean + amplitude,
///   iterations, residual;
///   irregular, one row per end: s, mean, std, Tz, the most probable maximum in `duration_s`.
/// A fixed point that did not converge says so with its diagnostic; it is never printed as one.
std::string dynamic_tension_text(const std::vector<DynamicTension>& tensions,
                                 double duration_s,
                                 const std::string& indent);

}  // namespace catena::internal
