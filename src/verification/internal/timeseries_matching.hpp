// SPDX-License-Identifier: MIT
#pragma once
// Matching identified modes to Catena's damped modes of the same plane, and the verdict of each
// (docs/how-to/check-time-series.md, "Verdicts").

#include <vector>

#include "catena/verification/modal_identification.hpp"
#include "catena/verification/timeseries_check.hpp"
#include "verification/internal/timeseries_reference.hpp"

namespace catena::internal {

/// One record per identified mode (ascending frequency), matched to the nearest Catena mode; no
/// Catena mode takes two (the identifiable modes nearest their partner choose first, the others
/// are "unmatched"). Catena's modes below the highest matched one that nothing matched are
/// appended to `not_present`.
std::vector<TimeSeriesModeCheck> match_modes(const Identification& identification,
                                             const DampedReference& reference,
                                             std::vector<TimeSeriesModeNotPresent>& not_present);

}  // namespace catena::internal
