// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The JSON of `catena check` on a free decay (docs/reference/json-layout.md, "Time-series
/// check"): every number of the comparison. The `modes` keys `plane`, `mode`,
/// `identified_frequency_hz`, `frequency_uncertainty_hz`, `identified_damping_ratio`,
/// `damping_ratio_uncertainty`, `catena_frequency_hz`, `catena_damping_ratio` and `verdict` are
/// issue 33's and stay.

#include <filesystem>
#include <string>
#include <vector>

#include "catena/verification/timeseries_check.hpp"

namespace catena {

/// Where the check's inputs came from.
struct TimeSeriesSources {
  std::string scene_name;
  std::string scene_file;
  /// The time-series files, one per run, in the order given.
  std::vector<std::string> files;
  std::vector<std::string> channels;
};

/// The check as a JSON document; absent values are null (never NaN).
std::string timeseries_check_to_json(const TimeSeriesCheck& check,
                                     const TimeSeriesSources& sources);

/// Writes timeseries_check_to_json() to `path` atomically. Throws InvalidInput naming the path.
void write_timeseries_check_json(const std::filesystem::path& path,
                                 const TimeSeriesCheck& check,
                                 const TimeSeriesSources& sources);

}  // namespace catena
