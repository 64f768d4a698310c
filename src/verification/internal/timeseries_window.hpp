// SPDX-License-Identifier: MIT
#pragma once
// The samples of a time series that the identification sees: the window of the free decay,
// checked to lie in the record and to be uniformly sampled to the rounding of the printed times.

#include <optional>

#include "catena/verification/time_series.hpp"

namespace catena::internal {

struct SampleWindow {
  Index first = 0;  // index of the first sample in the window
  Index count = 0;
  /// The samples' times on the exact uniform grid (the printed times are rounded: MoorDyn prints
  /// 4 decimals) [s].
  Vector time_s;
  double step_s = 0.0;
};

/// The window [start, end] of `series` (absent: the record's start or end). Throws InvalidInput
/// when it lies outside the record (beyond half a step), is empty or reversed, has fewer than
/// three samples, or its samples are not uniform within the rounding allowed: MoorDyn's 4 printed
/// decimals (0.5e-4 s), else 1e-3 of the step. Catena does not resample: interpolation would bias
/// the damping by an amount the identification's uncertainty does not include.
SampleWindow select_window(const TimeSeries& series,
                           std::optional<double> start_s,
                           std::optional<double> end_s);

}  // namespace catena::internal
