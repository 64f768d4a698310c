// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The error estimate as a checked claim (docs/reference/verdicts.md, "The estimate as a claim"):
/// each frequency, forced response and dynamic tension (at the fairlead and the anchor) a solver
/// returns with an error estimate is compared with the reference, the most accurate other exact
/// solver that converged on the same scene and plane.

#include <vector>

#include "verification/internal/check_builder.hpp"

namespace catena::internal {

/// An estimate at or above this multiple of the resolvable error, and above the solver's requested
/// accuracy, says too little to be useful (WARN "estimate uninformative").
inline constexpr double kUninformativeRatio = 1000.0;

/// One "estimate" check per value with an estimate that has a reference.
void estimate_checks(const std::vector<const SolverOutput*>& usable, CheckBuilder& builder);

}  // namespace catena::internal
