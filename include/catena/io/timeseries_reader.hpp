// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Time series written by another program, for `catena check` on a free decay
/// (docs/how-to/check-time-series.md): a MoorDyn output file or a CSV with a time column, told
/// apart by content, never by the extension.
///
/// MoorDyn (v1 and v2, the main `<deck>.out` and the per-line `Line<k>.out`): columns separated by
/// tabs or runs of spaces; a header row of channel names whose first is `Time`; an optional units
/// row in parentheses (`(s)`, `(N)`, `(m)`; v2 writes it when `WriteUnits` is set); then one row
/// of numbers per output time. Channel names are as the deck or MoorDyn wrote them: `FAIRTEN1`,
/// `ANCHTEN1`, `L1N5PX`, `POINT2PZ` in the main file; `Node0px` ... `NodeNpz`, `Seg1Te` ...
/// `SegNTe` in a line file.
///
/// CSV: comma-separated, a header row with a time column named `time`, any case, optionally with a
/// unit (`time_s`, `Time [s]`, `time (s)`); the time unit must be seconds. Other columns are the
/// channels.
///
/// The samples are a TimeSeries (include/catena/verification/time_series.hpp, next to the check
/// that uses them: the verification layer comes before io).

#include <cstdint>
#include <filesystem>
#include <string>

#include "catena/verification/time_series.hpp"

namespace catena {

/// Largest time-series file read [bytes]: 512 MiB. A 10-minute MoorDyn line file of 100 nodes at
/// 20 Hz is about 75 MB; the limit stops a device or a mistaken path, not a real record.
inline constexpr std::uintmax_t kMaxTimeSeriesFileBytes = std::uintmax_t{1} << 29;

/// Reads `file` (MoorDyn or CSV by content). Throws ParseError when the file cannot be read (or is
/// larger than kMaxTimeSeriesFileBytes) and InvalidInput naming the file and line for: no header,
/// no time column, no data rows, a ragged row (cells counted), a cell that is not a number, a
/// time that is not finite or not strictly increasing, a time unit other than seconds.
TimeSeries read_time_series(const std::filesystem::path& file);

/// The same from text already read; `source` names it in messages.
TimeSeries parse_time_series_text(const std::string& text, const std::string& source);

/// True when `file` starts like a time series (a MoorDyn header whose first name is `Time`, or a
/// CSV header with a time column and no column of the modal or tension results files), so that
/// `catena check` dispatches to the time-series check. False for unreadable files (the results
/// reader then reports the error).
bool looks_like_time_series(const std::filesystem::path& file);

}  // namespace catena
