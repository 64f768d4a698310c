// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The JSON of `catena check` on another program's dynamic tension
/// (docs/how-to/check-dynamic-tension.md, "Output"): every number of the comparison.

#include <filesystem>
#include <string>

#include "catena/io/check_report.hpp"
#include "catena/verification/tension_check.hpp"

namespace catena {

/// The comparison as a JSON document; absent values are null (never NaN).
std::string tension_check_to_json(const TensionCheck& check, const CheckSources& sources);

/// Writes tension_check_to_json() to `path` atomically. Throws InvalidInput naming the path.
void write_tension_check_json(const std::filesystem::path& path,
                              const TensionCheck& check,
                              const CheckSources& sources);

}  // namespace catena
