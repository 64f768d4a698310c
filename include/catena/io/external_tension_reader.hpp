// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Reading another program's dynamic tension along a line for `catena check`
/// (docs/how-to/check-dynamic-tension.md, "Input"): a CSV with a header row, one row per station
/// (and resolution), `#` lines comments. Columns:
/// - `s_m` (unstretched arc length from end a [m]), or `node` and `nodes` (node i of nodes - 1
///   equal segments: s = i L / (nodes - 1));
/// - `tension_std_n` (irregular motion) or `tension_amplitude_n` (regular motion) [N];
/// - optional: `period_s` (regular motion, the same on every row), `resolution` (mesh count,
///   larger = finer), `tension_uncertainty_n` (the other program's own uncertainty [N]).
/// Any other column is an error. Every message names the file, the row (and its line) and the
/// column. What needs the line's length (s within [0, L], node within [0, nodes - 1] as a station)
/// is checked by validate_external_tension() (catena/verification/tension_check.hpp).

#include <filesystem>
#include <string>

#include "catena/io/csv_table.hpp"
#include "catena/verification/tension_check.hpp"

namespace catena {

/// True when `path` is a CSV whose header has a `tension_std_n` or `tension_amplitude_n` column
/// (a tension file, not a frequencies file). False for unreadable files (the frequencies reader
/// then reports the error).
bool is_tension_results_file(const std::filesystem::path& path);

/// Reads and checks `path`. Throws InvalidInput (or ParseError for a ragged CSV) naming the file,
/// row and column.
ExternalTension read_external_tension(const std::filesystem::path& path);

/// The same from a table held in memory; `file` names it in messages.
ExternalTension external_tension_from_table(const CsvTable& table, const std::string& file);

}  // namespace catena
