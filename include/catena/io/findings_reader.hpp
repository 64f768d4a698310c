// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Reading the reviewed findings (verification/findings.toml; format in
/// catena/verification/findings.hpp). Strict: every entry has exactly its seven keys.

#include <filesystem>
#include <string>

#include "catena/verification/findings.hpp"

namespace catena {

/// Parses TOML text; `origin` names it in error messages.
FindingsTable parse_findings_table(const std::string& text, const std::string& origin);
/// Reads a findings file.
FindingsTable read_findings_file(const std::filesystem::path& path);
/// verification/findings.toml as it was when the library was built: the default of
/// `catena verify` and `catena solve`.
FindingsTable builtin_findings_table();

}  // namespace catena
