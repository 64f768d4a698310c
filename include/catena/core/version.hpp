// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Library version and build provenance (reports print these).

#include <string>

namespace catena {

/// "0.2.0"
std::string version();
/// Short git hash of the source tree at configure time, or "unknown".
std::string git_hash();
/// Compiler id and version, e.g. "GNU 12.2.0".
std::string compiler();
/// CMake build type and instruction set (cmake/instruction_set.cmake), e.g.
/// "Release (-march=x86-64-v3)": results differ between instruction sets in the last bits.
std::string build_type();
/// "catena 0.2.0 (git 1a2b3c4d5e, GNU 12.2.0, Release (compiler default))": the provenance
/// every generated file and report carries.
std::string provenance();
/// The current time in UTC, ISO 8601: "2026-11-23T06:58:00Z".
std::string utc_timestamp();

}  // namespace catena
