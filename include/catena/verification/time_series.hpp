// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// A time series of another program (a free decay) as the time-series check uses it
/// (docs/how-to/check-time-series.md): plain data, filled by the reader
/// (include/catena/io/timeseries_reader.hpp) or from samples in memory (the Python module).

#include <optional>
#include <string>
#include <vector>

#include "catena/core/types.hpp"

namespace catena {

/// The samples of a time-series file.
struct TimeSeries {
  /// The file, for messages ("decay.out").
  std::string source;
  /// "moordyn" or "csv".
  std::string format;
  /// Channel names as in the file, the time column excluded.
  std::vector<std::string> names;
  /// One per name: MoorDyn's units row without the parentheses ("N", "m"); "" when the file has
  /// no units row, or for a CSV column without a unit in its name.
  std::vector<std::string> units;
  /// Sample times [s], strictly increasing.
  Vector time_s;
  /// One per name, as long as time_s. May hold NaN or inf as read (MoorDyn prints `nan` when a
  /// run goes unstable): channel() refuses a channel that does, naming row and channel.
  std::vector<Vector> columns;
  /// The file's line number (1-based) of each sample, for messages (empty for samples from memory).
  std::vector<int> line_numbers;
  /// A MoorDyn line file (`Line<k>.out`): its number of segments N, from its node or segment
  /// columns (`Node0..NodeN`, `Seg1..SegN`); the resolution of a run. Absent otherwise.
  std::optional<int> num_segments;

  /// Index of the channel `name`: the exact name, else the only one equal ignoring case. Throws
  /// InvalidInput naming the file and listing the closest names when there is none (or several).
  std::size_t channel_index(const std::string& name) const;
  /// The samples of channel `name` (channel_index()). Throws InvalidInput naming the file, line,
  /// time and channel of the first NaN or infinite sample.
  const Vector& channel(const std::string& name) const;
};

/// A time series from samples already in memory (the Python module's arrays): format "csv", no
/// line numbers (messages name the 1-based sample). Throws InvalidInput naming `source`, the
/// channel and the sample for: no samples, columns of another length than time_s, a time not finite
/// or not strictly increasing, an empty or repeated name.
TimeSeries time_series_from_samples(const Vector& time_s,
                                    const std::vector<std::string>& names,
                                    const std::vector<Vector>& columns,
                                    const std::string& source);

}  // namespace catena
