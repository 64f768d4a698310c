// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Reading another program's modal results for `catena check` (formats in docs/how-to/check.md):
///
/// - a CSV file with a header row: `plane`, `mode`, one of `frequency_hz` or `omega_rad_s`, and
///   optionally `resolution` (the other program's mesh count, larger = finer). `plane` is
///   in-plane / inplane / out-of-plane / outofplane, in any case. '#' lines are comments.
/// - optionally a second, long-format CSV of mode shapes, one row per station:
///   `plane`, `mode`, `resolution` (when the results have it), `station_s_m` (unstretched arc
///   length from end A [m]), and any of `u`, `w` (in-plane), `v` (out-of-plane), `tension_n`
///   (dynamic tension amplitude [N]); an empty cell means the component is not given.
/// - or one JSON file (extension .json) with the same fields:
///   `{"results": [{"plane": "in-plane", "mode": 1, "resolution": 40, "frequency_hz": 0.12,
///   "shape": {"s_m": [...], "u": [...], "w": [...], "tension_n": [...]}}]}`.
///
/// Bad content throws InvalidInput naming the file, the row (and its line) or JSON path, and the
/// column: missing or unknown columns, an unknown plane, non-numeric, NaN or infinite values, a
/// mode that is not a positive integer, duplicate rows, an empty file, shapes of a mode that has no
/// result row. An unreadable file throws ParseError.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "catena/verification/external_check.hpp"

namespace catena {

/// "in-plane", "inplane", "out-of-plane", "outofplane" in any case; nullopt otherwise.
std::optional<Plane> parse_plane(const std::string& text);

/// Reads `results` (CSV, or JSON when its extension is .json) and, when `shapes` is not empty,
/// the shapes CSV, attaching each shape to its result.
std::vector<ExternalMode> read_external_results(const std::filesystem::path& results,
                                                const std::filesystem::path& shapes = {});

/// The JSON form from text already in memory (e.g. built by the Python module from a list of
/// dicts): the same checks and messages as a .json file, with `origin` where the file name would
/// be.
std::vector<ExternalMode> parse_external_results_json(const std::string& text,
                                                      const std::string& origin);

}  // namespace catena
