// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Reading the tolerance table (verification/tolerances.toml; format in
/// catena/verification/tolerance_table.hpp). Strict: an unknown key, a wrong type or a missing
/// field is a ParseError, an out-of-range value an InvalidInput, each naming the file and the rule.

#include <filesystem>
#include <string>

#include "catena/verification/tolerance_table.hpp"

namespace catena {

/// Parses TOML text; `origin` names it in error messages.
ToleranceTable parse_tolerance_table(const std::string& text, const std::string& origin);
/// Reads a tolerance file.
ToleranceTable read_tolerance_file(const std::filesystem::path& path);
/// verification/tolerances.toml as it was when the library was built: the default of
/// `catena verify` and `catena solve`.
ToleranceTable builtin_tolerance_table();

}  // namespace catena
