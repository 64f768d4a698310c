// SPDX-License-Identifier: MIT
#pragma once
// The JSON form of another program's results for `catena check` (layout in
// include/catena/io/external_results_reader.hpp and docs/how-to/check.md).

#include <filesystem>
#include <string>
#include <vector>

#include "catena/verification/external_check.hpp"

namespace catena::internal {

/// Reads the results and their shapes; InvalidInput naming the file and the JSON path.
std::vector<ExternalMode> read_external_results_json(const std::filesystem::path& path);
/// The same from text; `file` names it in messages.
std::vector<ExternalMode> parse_results_json_text(const std::string& text, const std::string& file);

/// `value` as a mode number (a whole number >= 1); InvalidInput naming `where` otherwise.
int mode_number(double value, const std::string& where);

}  // namespace catena::internal
